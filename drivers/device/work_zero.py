"""A work zero kept by the panel (as G54 is in CNC controllers): work = machine - zero, per axis.

The device knows only machine coordinates (from its home); the work zero never reaches it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from drivers.errors import BadInput
from drivers.messages import Message

Point = tuple[float, float, float]
_INDEX = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class WorkZero:
    """Where the work zero is, in machine coordinates (mm)."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0

    @property
    def point(self) -> Point:
        """The zero as (x, y, z) in machine mm."""
        return (self.x, self.y, self.z)

    def is_machine(self) -> bool:
        """True when the work frame is the machine frame (no zero set)."""
        return self.point == (0.0, 0.0, 0.0)

    def to_work(self, machine: Point) -> Point:
        """A machine position in the work frame."""
        return (machine[0] - self.x, machine[1] - self.y, machine[2] - self.z)

    def to_machine(self, work: Point) -> Point:
        """A work position in the machine frame (what the device is sent)."""
        return (work[0] + self.x, work[1] + self.y, work[2] + self.z)

    def zeroed(self, axes: str, machine: Point) -> WorkZero:
        """The zero with `axes` (e.g. "x" or "xyz") moved to the machine position given."""
        changes = {}
        for axis in axes.lower():
            if axis not in _INDEX:
                raise BadInput(Message("no axis {axis!r}: x, y or z", axis=axis))
            changes[axis] = machine[_INDEX[axis]]
        return replace(self, **changes)

    def after_set_home(self, machine: Point) -> WorkZero:
        """The same physical zero once the device's home has moved to `machine` (Set Home)."""
        return WorkZero(self.x - machine[0], self.y - machine[1], self.z - machine[2])

    def describe(self) -> str:
        """E.g. `work zero at (10, 5, 0) mm machine`."""
        if self.is_machine():
            return Message("work zero at home (work = machine)")
        return Message(
            "work zero at ({x:g}, {y:g}, {z:g}) mm machine", x=self.x, y=self.y, z=self.z
        )


def parse_work_zero(text: str) -> WorkZero:
    """`x,y,z` (as the settings keep it) into a WorkZero; BadInput if malformed."""
    parts = text.split(",")
    try:
        values = [float(part) for part in parts]
    except ValueError:
        raise BadInput(
            Message("work zero {text!r} is not three numbers x,y,z", text=text)
        ) from None
    if len(values) != 3 or any(v != v or abs(v) == float("inf") for v in values):
        raise BadInput(Message("work zero {text!r} is not three finite numbers x,y,z", text=text))
    return WorkZero(*values)


def format_work_zero(zero: WorkZero) -> str:
    """The settings' form of a work zero: `x,y,z`."""
    return ",".join(repr(v) for v in zero.point)
