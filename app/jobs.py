"""Jobs: what the window asks the worker to do, as plain values with a human description."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from drivers.commands import Arc
from drivers.program import ProgramPoint

if TYPE_CHECKING:
    from app.macros import Macro


@dataclass(frozen=True)
class Job:
    """Base of every job; `describe()` is what the user is told about it."""

    def describe(self) -> str:
        """A short human description."""
        return type(self).__name__


@dataclass(frozen=True)
class MoveToJob(Job):
    """Absolute move (mm)."""

    x: float
    y: float
    z: float

    def describe(self) -> str:
        """E.g. `move to (10, -5, 2.5) mm`."""
        return f"move to ({self.x:g}, {self.y:g}, {self.z:g}) mm"


@dataclass(frozen=True)
class MoveByJob(Job):
    """Relative move (mm)."""

    dx: float
    dy: float
    dz: float
    kind: str = "linear"  # or the protocol's rotational (degrees) or steps

    def describe(self) -> str:
        """E.g. `jog by (1, 0, 0) mm`."""
        unit = "mm" if self.kind == "linear" else self.kind
        return f"jog by ({self.dx:g}, {self.dy:g}, {self.dz:g}) {unit}"


@dataclass(frozen=True)
class HomeJob(Job):
    """Go to (0, 0, 0)."""

    def describe(self) -> str:
        """`go home`."""
        return "go home"


@dataclass(frozen=True)
class SetHomeJob(Job):
    """Make the current position the origin."""

    def describe(self) -> str:
        """`set home`."""
        return "set home here"


@dataclass(frozen=True)
class SetSpeedJob(Job):
    """Set the speed (mm/s)."""

    speed: float

    def describe(self) -> str:
        """E.g. `set speed 20 mm/s`."""
        return f"set speed {self.speed:g} mm/s"


@dataclass(frozen=True, eq=False)
class SetParameterJob(Job):
    """Write one device parameter (by id), in its unit."""

    param_id: int
    value: float
    name: str = ""
    unit: str = ""

    def describe(self) -> str:
        """E.g. `set pulley_diameter_x = 38.2 mm`."""
        return f"set {self.name or self.param_id} = {self.value:g} {self.unit}".rstrip()


@dataclass(frozen=True, eq=False)
class ArcJob(Job):
    """An arc move (pi-frame)."""

    arc: Arc

    def describe(self) -> str:
        """E.g. `arc around (0, 0) r 10 mm from 0° to 90° CCW`."""
        a = self.arc
        turn = "CCW" if a.ccw else "CW"
        angles = f"from {a.start:g}° to {a.end:g}° {turn}"
        return f"arc around ({a.cx:g}, {a.cy:g}) mm, radius {a.radius:g} mm, {angles}"


@dataclass(frozen=True, eq=False)
class DwellJob(Job):
    """Pause the device's queue (pi-frame)."""

    ms: int

    def describe(self) -> str:
        """E.g. `dwell 500 ms`."""
        return f"dwell {self.ms} ms"


@dataclass(frozen=True, eq=False)
class SettingsJob(Job):
    """New protocol settings (ticks per mm, steps per mm...)."""

    values: dict[str, float]

    def describe(self) -> str:
        """E.g. `set ticks_per_mm = 100`."""
        return "set " + ", ".join(f"{k} = {v:g}" for k, v in self.values.items())


@dataclass(frozen=True, eq=False)
class StepperConfigJob(Job):
    """Configure the Firmata stepper (and read the library version back)."""

    steps_per_rev: int
    pins: tuple[int, ...]

    def describe(self) -> str:
        """E.g. `configure the stepper: 200 steps/rev on pins 8 9`."""
        pins = " ".join(str(p) for p in self.pins)
        return f"configure the stepper: {self.steps_per_rev} steps/rev on pins {pins}"


@dataclass(frozen=True, eq=False)
class StepperVersionJob(Job):
    """Ask the Firmata stepper library's version."""

    def describe(self) -> str:
        """`ask the stepper library version`."""
        return "ask the stepper library version"


@dataclass(frozen=True, eq=False)
class StreamJob(Job):
    """Stream a program to the device's queue."""

    points: tuple[ProgramPoint, ...]
    name: str = "program"

    def describe(self) -> str:
        """E.g. `run square.csv (1000 points)`."""
        return f"run {self.name} ({len(self.points)} points)"


@dataclass(frozen=True)
class RawJob(Job):
    """Send raw bytes typed in the console."""

    data: bytes

    def describe(self) -> str:
        """E.g. `send "GET_ID\\n"`, with the console's escapes."""
        from drivers.traffic_index import escape  # imports numpy: not before the first paint

        return f'send "{escape(self.data)}"'


@dataclass(frozen=True)
class RefreshJob(Job):
    """Read position, speed and limits again."""

    def describe(self) -> str:
        """`refresh`."""
        return "refresh position and speed"


@dataclass(frozen=True)
class MacroJob(Job):
    """Run a macro's steps in order, each waiting for the device."""

    macro: Macro

    def describe(self) -> str:
        """E.g. `macro probe (4 steps)`."""
        return self.macro.describe()
