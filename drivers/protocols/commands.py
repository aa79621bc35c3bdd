"""Typed commands: what the application asks of a device, independent of any wire format."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Command:
    """Base of every typed command."""


@dataclass(frozen=True)
class GetId(Command):
    """Ask for the device's identifier."""


@dataclass(frozen=True)
class Help(Command):
    """Ask the device for its help text."""


@dataclass(frozen=True)
class GetPosition(Command):
    """Ask for the current position."""


@dataclass(frozen=True)
class Home(Command):
    """Move to the home position (0, 0, 0)."""


@dataclass(frozen=True)
class SetHome(Command):
    """Make the current position the origin."""


@dataclass(frozen=True)
class MoveTo(Command):
    """Absolute move, in the protocol's length unit (mm unless its capabilities say otherwise).

    `speed` (mm/s) is filled in where the device takes the speed with every move (pi-frame,
    Firmata); None: the device's own speed.
    """

    x: float
    y: float
    z: float = 0.0
    speed: float | None = None


@dataclass(frozen=True)
class MoveBy(Command):
    """Relative move by the given deltas; `kind` is one of the protocol's `move_kinds`.

    Linear deltas are in the length unit (mm); `rotational` ones in degrees of the motor's
    cycle, `steps` in motor steps (Visiomex `MR`, `MS`).
    """

    dx: float
    dy: float
    dz: float = 0.0
    kind: str = "linear"
    speed: float | None = None  # as for MoveTo


@dataclass(frozen=True)
class SetSpeed(Command):
    """Set the movement speed (length unit per second)."""

    speed: float


@dataclass(frozen=True)
class GetSpeed(Command):
    """Ask for the current speed."""


@dataclass(frozen=True)
class GetMinSpeed(Command):
    """Ask for the lowest speed the device allows."""


@dataclass(frozen=True)
class GetMaxSpeed(Command):
    """Ask for the highest speed the device allows."""


@dataclass(frozen=True)
class CheckErrors(Command):
    """Ask the device to run its diagnostics."""


@dataclass(frozen=True)
class Stop(Command):
    """Stop motion and flush queued motion (where the protocol has it)."""


@dataclass(frozen=True)
class Dwell(Command):
    """Wait on the device for a time, in milliseconds."""

    ms: int


@dataclass(frozen=True)
class Arc(Command):
    """A circular move in the XY plane around (cx, cy), from angle `start` to `end` (degrees,
    counter-clockwise from +X), clockwise unless `ccw`; Z goes to `z` on the way."""

    cx: float
    cy: float
    radius: float
    start: float
    end: float
    ccw: bool
    z: float = 0.0
    speed: float | None = None  # mm/s along the arc

    def point(self, angle: float) -> tuple[float, float]:
        """The point of the circle at `angle` degrees."""
        rad = math.radians(angle)
        return (self.cx + self.radius * math.cos(rad), self.cy + self.radius * math.sin(rad))

    def sweep(self) -> float:
        """Degrees travelled (positive), a full circle when start equals end."""
        turn = (self.end - self.start) % 360 if self.ccw else (self.start - self.end) % 360
        return turn or 360.0


@dataclass(frozen=True)
class SetParameter(Command):
    """Write a numbered device parameter, in its interface unit (the protocol scales it)."""

    param_id: int
    value: float


@dataclass(frozen=True)
class Raw(Command):
    """Send bytes as they are; the protocol decides what ends the reply."""

    data: bytes
