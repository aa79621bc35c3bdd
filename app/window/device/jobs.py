"""Jobs: what the window asks the worker to do, as plain values with a human description."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from drivers.protocols.commands import Arc
from drivers.toolpath.model import CHORD_TOLERANCE, Toolpath
from widgets._i18n import fill

if TYPE_CHECKING:
    from app.common.macros import Macro


def _t(template: str, *values: object) -> str:
    """A job's description in the interface's language (the templates are marked below)."""
    return fill(QCoreApplication.translate("Jobs", template), *values)


# The templates, for lupdate (translated at use by `_t`).
_TEMPLATES = (
    QT_TRANSLATE_NOOP("Jobs", "move to (%1, %2, %3) mm"),
    QT_TRANSLATE_NOOP("Jobs", "jog by (%1, %2, %3) %4"),
    QT_TRANSLATE_NOOP("Jobs", "relative move by (%1, %2, %3) %4"),
    QT_TRANSLATE_NOOP("Jobs", "go home"),
    QT_TRANSLATE_NOOP("Jobs", "set home here"),
    QT_TRANSLATE_NOOP("Jobs", "set speed %1 mm/s"),
    QT_TRANSLATE_NOOP("Jobs", "set %1 = %2 %3"),
    QT_TRANSLATE_NOOP("Jobs", "arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CCW"),
    QT_TRANSLATE_NOOP("Jobs", "arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CW"),
    QT_TRANSLATE_NOOP("Jobs", "dwell %1 ms"),
    QT_TRANSLATE_NOOP("Jobs", "set %1"),
    QT_TRANSLATE_NOOP("Jobs", "configure the stepper: %1 steps/rev on pins %2"),
    QT_TRANSLATE_NOOP("Jobs", "ask the stepper library version"),
    QT_TRANSLATE_NOOP("Jobs", "run %1 (%2 points)"),
    QT_TRANSLATE_NOOP("Jobs", "run %1 (%2 lines)"),
    QT_TRANSLATE_NOOP("Jobs", "run %1 (%2 entities)"),
    QT_TRANSLATE_NOOP("Jobs", "run %1 (%2 elements)"),
    QT_TRANSLATE_NOOP("Jobs", 'send "%1"'),
    QT_TRANSLATE_NOOP("Jobs", "refresh position and speed"),
)
_RUN = {  # a program's run, by what its sources are
    "point": "run %1 (%2 points)",
    "line": "run %1 (%2 lines)",
    "entity": "run %1 (%2 entities)",
    "element": "run %1 (%2 elements)",
}


@dataclass(frozen=True)
class Job:
    """Base of every job; `describe()` is what the user is told about it."""

    moves: ClassVar[bool] = False
    """Whether the job may move the stage (a stop asked after it was queued drops it)."""

    def describe(self) -> str:
        """A short human description."""
        return type(self).__name__


@dataclass(frozen=True)
class MoveToJob(Job):
    """Absolute move (mm)."""

    moves = True

    x: float
    y: float
    z: float

    def describe(self) -> str:
        """E.g. `move to (10, -5, 2.5) mm`."""
        return _t("move to (%1, %2, %3) mm", f"{self.x:g}", f"{self.y:g}", f"{self.z:g}")


@dataclass(frozen=True)
class MoveByJob(Job):
    """Relative move (mm)."""

    moves = True

    dx: float
    dy: float
    dz: float
    kind: str = "linear"  # or the protocol's rotational (degrees) or steps
    jog: bool = True  # False: a relative Go to, named "relative move" (not "jog")

    def describe(self) -> str:
        """E.g. `jog by (1, 0, 0) mm`, or `relative move by (1, 0, 0) mm` (a Go to)."""
        unit = "mm" if self.kind == "linear" else self.kind
        deltas = (f"{self.dx:g}", f"{self.dy:g}", f"{self.dz:g}", unit)
        if not self.jog:
            return _t("relative move by (%1, %2, %3) %4", *deltas)
        return _t("jog by (%1, %2, %3) %4", *deltas)


@dataclass(frozen=True)
class HomeJob(Job):
    """Go to (0, 0, 0)."""

    moves = True

    def describe(self) -> str:
        """`go home`."""
        return _t("go home")


@dataclass(frozen=True)
class SetHomeJob(Job):
    """Make the current position the origin."""

    def describe(self) -> str:
        """`set home`."""
        return _t("set home here")


@dataclass(frozen=True)
class SetSpeedJob(Job):
    """Set the speed (mm/s)."""

    speed: float

    def describe(self) -> str:
        """E.g. `set speed 20 mm/s`."""
        return _t("set speed %1 mm/s", f"{self.speed:g}")


@dataclass(frozen=True, eq=False)
class SetParameterJob(Job):
    """Write one device parameter (by id), in its unit."""

    param_id: int
    value: float
    name: str = ""
    unit: str = ""

    def describe(self) -> str:
        """E.g. `set pulley_diameter_x = 38.2 mm`."""
        return _t(
            "set %1 = %2 %3", self.name or self.param_id, f"{self.value:g}", self.unit
        ).rstrip()


@dataclass(frozen=True, eq=False)
class ArcJob(Job):
    """An arc move (pi-frame)."""

    moves = True

    arc: Arc

    def describe(self) -> str:
        """E.g. `arc around (0, 0) r 10 mm from 0° to 90° CCW`."""
        a = self.arc
        template = (
            "arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CCW"
            if a.ccw
            else "arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CW"
        )
        values = (a.cx, a.cy, a.radius, a.start, a.end)
        return _t(template, *(f"{v:g}" for v in values))


@dataclass(frozen=True, eq=False)
class DwellJob(Job):
    """Pause the device's queue (pi-frame)."""

    ms: int

    def describe(self) -> str:
        """E.g. `dwell 500 ms`."""
        return _t("dwell %1 ms", self.ms)


@dataclass(frozen=True, eq=False)
class SettingsJob(Job):
    """New protocol settings (ticks per mm, steps per mm...)."""

    values: dict[str, float]

    def describe(self) -> str:
        """E.g. `set ticks_per_mm = 100`."""
        return _t("set %1", ", ".join(f"{k} = {v:g}" for k, v in self.values.items()))


@dataclass(frozen=True, eq=False)
class StepperConfigJob(Job):
    """Configure the Firmata stepper (and read the library version back)."""

    steps_per_rev: int
    pins: tuple[int, ...]

    def describe(self) -> str:
        """E.g. `configure the stepper: 200 steps/rev on pins 8 9`."""
        pins = " ".join(str(p) for p in self.pins)
        return _t("configure the stepper: %1 steps/rev on pins %2", self.steps_per_rev, pins)


@dataclass(frozen=True, eq=False)
class StepperVersionJob(Job):
    """Ask the Firmata stepper library's version."""

    def describe(self) -> str:
        """`ask the stepper library version`."""
        return _t("ask the stepper library version")


@dataclass(frozen=True, eq=False)
class StreamJob(Job):
    """Run a program (any device: streamed to a queue, arcs as arcs, or move by move); arcs
    are cut into chords within `tolerance` mm where the device has none."""

    moves = True

    toolpath: Toolpath
    tolerance: float = CHORD_TOLERANCE
    name: str = "program"

    def describe(self) -> str:
        """E.g. `run square.csv (1000 points)`, `run part.nc (420 lines)`."""
        sources = self.toolpath.sources
        kind = sources[0].kind if sources else "point"
        return _t(_RUN.get(kind, _RUN["point"]), self.name, len(sources))


@dataclass(frozen=True)
class RawJob(Job):
    """Send raw bytes typed in the console (through the motion guard; `force`: the operator
    confirmed bytes the protocol cannot read while a travel box is set)."""

    moves = True

    data: bytes
    force: bool = False

    def describe(self) -> str:
        """E.g. `send "GET_ID\\n"`, with the console's escapes."""
        from drivers.traffic.lines import escape

        return _t('send "%1"', escape(self.data))


@dataclass(frozen=True)
class RefreshJob(Job):
    """Read position, speed and limits again."""

    def describe(self) -> str:
        """`refresh`."""
        return _t("refresh position and speed")


@dataclass(frozen=True)
class MacroJob(Job):
    """Run a macro's steps in order, each waiting for the device."""

    moves = True

    macro: Macro

    def describe(self) -> str:
        """E.g. `macro probe (4 steps)`."""
        from app.common.messages import localized

        return localized(self.macro.describe())
