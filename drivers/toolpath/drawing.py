"""A Toolpath from a drawing's paths (DXF, SVG): travel moves between them, sources, limits.

A drawing is a sequence of paths, each made of pieces run in the file's order. `PathBuilder` turns
them into steps: a travel move (`Line(..., rapid=True)`, its source the path it leads to) from
where the stage is to the start of a path or piece that does not join it (within `JOIN` mm; the
first from the toolpath's start), then the path's lines and arcs. Every point is checked to be a
finite number, and the steps are bounded (`MAX_STEPS`), so a drawing refused is refused whole.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from drivers.messages import Message
from drivers.toolpath.model import ArcTo, Line, Point, Source, Step, Toolpath, ToolpathError
from drivers.toolpath.point_program import MAX_POINTS

JOIN = 1e-6  # mm: a piece starting this close to where the last one ended needs no travel move
DEGENERATE = 1e-9  # mm: a line or arc shorter than this is left out
MAX_STEPS = MAX_POINTS  # as many steps as the panel's CSV programs may have points


def bezier_chords(controls: npt.ArrayLike, tolerance: float, limit: int = MAX_STEPS) -> np.ndarray:
    """The ends of the chords of a Bézier curve of any degree (its control points, in 2D or 3D,
    mm), none farther than `tolerance` from the curve: n equal parameter steps, the error of each
    below max|B''| / (8 n²), and max|B''| <= degree (degree - 1) max|second difference|. The
    curve's start is left out, its end is exactly the last control point. More than `limit`
    chords: ValueError."""
    points = np.asarray(controls, dtype=float)
    degree = len(points) - 1
    if degree < 2:
        return points[1:]
    second = points[2:] - 2 * points[1:-1] + points[:-2]
    bound = degree * (degree - 1) * float(np.max(np.sqrt((second**2).sum(axis=1))))
    count = max(1, math.ceil(math.sqrt(bound / (8 * tolerance))))
    if count > limit:
        raise ValueError(f"a curve of more than {limit:,} chords at this tolerance")
    t = np.linspace(0.0, 1.0, count + 1)[1:, None, None]
    steps = np.broadcast_to(points, (count, *points.shape))
    for _ in range(degree):  # de Casteljau, for every t at once
        steps = (1 - t) * steps[:, :-1] + t * steps[:, 1:]
    chords = steps[:, 0].copy()
    chords[-1] = points[-1]
    return chords


class PathBuilder:
    """The steps of a drawing being read, path by path."""

    def __init__(self, name: str, start: Point = (0.0, 0.0, 0.0)) -> None:
        """An empty toolpath named `name` (the file's name) starting at `start`."""
        self.name = name
        self.start = start
        self.steps: list[Step] = []
        self.sources: list[Source] = []
        self.position = start
        self._source: Source | None = None
        self._index = -1

    def begin(self, source: Source) -> None:
        """The entity or element the next steps come from (kept only if it makes a step)."""
        self._source = source
        self._index = -1

    def where(self) -> Message:
        """The file and the entity or element being read, for refusals."""
        if self._source is None:
            return Message("{name}", name=self.name)
        return Toolpath(self.name, [], [self._source]).where(0)

    def reserve(self, count: int) -> None:
        """Refuse the drawing before `count` more steps would pass `MAX_STEPS`."""
        if len(self.steps) + count > MAX_STEPS:
            raise ToolpathError(
                Message(
                    "{where}: more than {count:,} steps (lines, arcs and travel moves)",
                    where=self.where(),
                    count=MAX_STEPS,
                )
            )

    def move_to(self, point: Point) -> None:
        """Start a path or piece at `point`: a travel move there unless the stage is there."""
        point = self._checked(point)
        if math.dist(point, self.position) > JOIN:
            self._add(Line(point, None, self._current(), rapid=True))
            self.position = point

    def line_to(self, point: Point) -> None:
        """A straight line from where the stage is to `point`."""
        point = self._checked(point)
        if math.dist(point, self.position) > DEGENERATE:
            self._add(Line(point, None, self._current()))
            self.position = point

    def arc_to(
        self, end: Point, centre: tuple[float, float], ccw: bool, full: bool = False
    ) -> None:
        """A circular arc from where the stage is to `end` around `centre`; `full`: a whole
        circle (it ends exactly where it starts)."""
        end = self.position if full else self._checked(end)
        self._checked((centre[0], centre[1], 0.0))
        radius = math.dist(self.position[:2], centre)
        if radius <= DEGENERATE:
            self.line_to(end)
            return
        if not full and math.dist(end, self.position) <= DEGENERATE:
            return
        self._add(ArcTo(end, centre, ccw, None, self._current()))
        self.position = end

    def toolpath(self, notices: list[Message], layers: tuple[str, ...] = ()) -> Toolpath:
        """The toolpath built so far, with what reading the file noticed."""
        return Toolpath(self.name, self.steps, self.sources, self.start, notices, layers)

    def _current(self) -> int:
        if self._index < 0:
            if self._source is None:
                raise RuntimeError("PathBuilder: a step before begin()")
            self.sources.append(self._source)
            self._index = len(self.sources) - 1
        return self._index

    def _add(self, step: Step) -> None:
        self.reserve(1)
        self.steps.append(step)

    def _checked(self, point: Point) -> Point:
        if not all(math.isfinite(value) for value in point):
            raise ToolpathError(
                Message("{where}: a coordinate that is not a finite number", where=self.where())
            )
        return (float(point[0]), float(point[1]), float(point[2]))
