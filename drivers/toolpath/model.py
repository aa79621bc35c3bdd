"""The program model every format is read into: straight lines, arcs and dwells, with speeds.

A Toolpath is a list of steps, each going from where the one before it ended (the first from
`Toolpath.start`). Each step names its `source`: an index into `Toolpath.sources`, the line,
entity, element or point of the file it was made from, which messages and the window's program
list show. Coordinates are mm in the device's frame, speeds mm/s; a speed of None is the speed set
on the panel (the device's, for moves the file gives none: DXF, SVG, G0 rapids).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from drivers.errors import BadFile
from drivers.messages import Message

Point = tuple[float, float, float]
CHORD_TOLERANCE = 0.01
"""mm: how far the straight pieces of a flattened curve may stray from it (the user can change
it for arcs; splines and ellipses from DXF and SVG curves are flattened with it when read)."""


class ToolpathError(BadFile):
    """A program file refused whole: which file, which line or element, and why."""


@dataclass(frozen=True, slots=True)
class Line:
    """A straight move to `end`; `rapid`: a travel move (G0, or between disjoint paths)."""

    end: Point
    speed: float | None
    source: int
    rapid: bool = False


@dataclass(frozen=True, slots=True)
class ArcTo:
    """A circular move in the XY plane from where the stage is to `end` around `centre` (x, y);
    a full circle when it ends where it starts; Z goes linearly to `end`'s Z (a helix)."""

    end: Point
    centre: tuple[float, float]
    ccw: bool
    speed: float | None
    source: int


@dataclass(frozen=True, slots=True)
class Dwell:
    """A pause of `seconds` at the point reached."""

    seconds: float
    source: int


Step = Line | ArcTo | Dwell


@dataclass(frozen=True, slots=True)
class Source:
    """What a step comes from: `kind` is "line" (G-code, CSV), "entity" (DXF), "element"
    (SVG) or "point" (JSON); `number` counts from 1; `text` is shown in the program list."""

    kind: str
    number: int
    text: str


@dataclass
class Toolpath:
    """A program: its steps, their sources, and what reading the file noticed."""

    name: str
    steps: list[Step]
    sources: list[Source]
    start: Point = (0.0, 0.0, 0.0)
    notices: list[Message] = field(default_factory=list)
    layers: tuple[str, ...] = ()
    """Every layer the file has (DXF), whether chosen or not."""

    def where(self, source: int) -> Message:
        """The file and the line, entity, element or point `source` names, for messages."""
        item = self.sources[source]
        if item.kind == "entity":
            return Message(
                "{name} entity {number} ({text})",
                name=self.name,
                number=item.number,
                text=item.text,
            )
        if item.kind == "element":
            return Message(
                "{name} element {number} ({text})",
                name=self.name,
                number=item.number,
                text=item.text,
            )
        if item.kind == "point":
            return Message("{name} point {number}", name=self.name, number=item.number)
        return Message("{name} line {number}", name=self.name, number=item.number)


def arc_angles(start: Point, arc: ArcTo) -> tuple[float, float, float]:
    """The arc's radius and its start and end angles (radians, counter-clockwise from +X)."""
    cx, cy = arc.centre
    radius = math.hypot(start[0] - cx, start[1] - cy)
    return (
        radius,
        math.atan2(start[1] - cy, start[0] - cx),
        math.atan2(arc.end[1] - cy, arc.end[0] - cx),
    )


def arc_sweep(start: Point, arc: ArcTo) -> float:
    """The signed angle an arc turns through (radians; positive counter-clockwise); a full
    turn when it ends where it starts."""
    _, a0, a1 = arc_angles(start, arc)
    sweep = (a1 - a0) % math.tau if arc.ccw else -((a0 - a1) % math.tau)
    if abs(sweep) < 1e-12 and math.dist(start[:2], arc.end[:2]) < 1e-9:
        sweep = math.tau if arc.ccw else -math.tau
    return sweep
