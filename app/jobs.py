"""Jobs: what the window asks the worker to do, as plain values with a human description."""

from __future__ import annotations

from dataclasses import dataclass

from widgets.traffic_format import escape


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


@dataclass(frozen=True)
class RawJob(Job):
    """Send raw bytes typed in the console."""

    data: bytes

    def describe(self) -> str:
        """E.g. `send "GET_ID\\n"`, with the console's escapes."""
        return f'send "{escape(self.data)}"'


@dataclass(frozen=True)
class RefreshJob(Job):
    """Read position, speed and limits again."""

    def describe(self) -> str:
        """`refresh`."""
        return "refresh position and speed"
