"""A toolpath as points: flattened (arcs to chords within a tolerance), measured and checked
against the travel box before anything is sent.

The flat path is numpy arrays, one row a point, so that a 100,000-line program is previewed and
checked in a fraction of a second: `points[0]` is where the program starts, each later row ends
a straight segment, which keeps its source, speed and whether it is a travel move.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from drivers.device.travel import TravelLimits
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.toolpath.model import (
    CHORD_TOLERANCE,
    ArcTo,
    Dwell,
    Line,
    Point,
    Toolpath,
    arc_angles,
    arc_sweep,
)

MAX_CHORDS = 100_000  # per arc: a huge arc at a tiny tolerance stays bounded
FloatArray = npt.NDArray[np.float64]


class ProgramOutside(BadInput):
    """A program that would leave the travel box, refused before the first byte."""


@dataclass(frozen=True)
class FlatPath:
    """A toolpath as straight segments between points."""

    points: FloatArray
    """(N, 3) mm; row 0 is the start, row i ends segment i."""
    rapid: npt.NDArray[np.bool_]
    """(N,) whether segment i is a travel move (row 0: False)."""
    source: npt.NDArray[np.int32]
    """(N,) the source of segment i (row 0: the first step's)."""
    speed: FloatArray
    """(N,) mm/s of segment i; NaN: the speed set on the panel."""
    step_end: npt.NDArray[np.int64]
    """(steps,) the row where each step ends (a dwell: the row it waits at)."""

    def __len__(self) -> int:
        return len(self.points)


@dataclass(frozen=True)
class Summary:
    """A program's figures for the operator."""

    length: float  # mm, travel moves included
    travel_length: float  # mm of travel (rapid) moves
    low: Point  # the bounding box's corners, mm
    high: Point
    seconds: float  # at the program's speeds, the panel's where it gives none, dwells included
    segments: int


def chord_count(radius: float, sweep: float, tolerance: float) -> int:
    """How many chords follow an arc of `radius` turning `sweep` radians within `tolerance`."""
    if radius <= tolerance or tolerance <= 0:
        return max(1, math.ceil(abs(sweep) / (math.pi / 2)))
    step = 2 * math.acos(1 - tolerance / radius)
    return max(1, min(MAX_CHORDS, math.ceil(abs(sweep) / step)))


def arc_chord_points(start: Point, arc: ArcTo, tolerance: float) -> FloatArray:
    """The chords' ends along an arc (its start excluded, its end exactly included)."""
    radius, a0, _ = arc_angles(start, arc)
    sweep = arc_sweep(start, arc)
    count = chord_count(radius, sweep, tolerance)
    fractions = np.arange(1, count + 1, dtype=np.float64) / count
    angles = a0 + sweep * fractions
    out = np.empty((count, 3))
    out[:, 0] = arc.centre[0] + radius * np.cos(angles)
    out[:, 1] = arc.centre[1] + radius * np.sin(angles)
    out[:, 2] = start[2] + (arc.end[2] - start[2]) * fractions
    out[-1] = arc.end
    return out


def flatten(toolpath: Toolpath, tolerance: float = CHORD_TOLERANCE) -> FlatPath:
    """The toolpath as straight segments, arcs cut into chords within `tolerance` mm."""
    if not tolerance > 0:
        raise BadInput(
            Message("chord tolerance {value:g} mm refused: it must be above 0", value=tolerance)
        )
    xs, ys, zs = [toolpath.start[0]], [toolpath.start[1]], [toolpath.start[2]]
    rapid: list[bool] = [False]
    first = toolpath.steps[0].source if toolpath.steps else 0
    sources: list[int] = [first]
    speeds: list[float] = [math.nan]
    ends: list[int] = []
    here = toolpath.start
    nan = math.nan
    for step in toolpath.steps:
        if type(step) is Line:
            end = step.end
            xs.append(end[0])
            ys.append(end[1])
            zs.append(end[2])
            rapid.append(step.rapid)
            sources.append(step.source)
            speeds.append(nan if step.speed is None else step.speed)
            here = end
        elif type(step) is ArcTo:
            chords = arc_chord_points(here, step, tolerance)
            count = len(chords)
            xs.extend(chords[:, 0].tolist())
            ys.extend(chords[:, 1].tolist())
            zs.extend(chords[:, 2].tolist())
            rapid.extend([False] * count)
            sources.extend([step.source] * count)
            speeds.extend([nan if step.speed is None else step.speed] * count)
            here = step.end
        ends.append(len(xs) - 1)
    points = np.column_stack(
        (np.asarray(xs, np.float64), np.asarray(ys, np.float64), np.asarray(zs, np.float64))
    )
    return FlatPath(
        points,
        np.asarray(rapid, np.bool_),
        np.asarray(sources, np.int32),
        np.asarray(speeds, np.float64),
        np.asarray(ends, np.int64),
    )


def summarize(toolpath: Toolpath, flat: FlatPath, panel_speed: float) -> Summary:
    """Length, bounding box and the time the program should take at `panel_speed` mm/s where
    it gives no speed (travel moves included), dwells included."""
    points = flat.points
    lengths = np.linalg.norm(np.diff(points, axis=0), axis=1)
    speeds = flat.speed[1:].copy()
    speeds[np.isnan(speeds)] = panel_speed if panel_speed > 0 else math.inf
    seconds = float(np.sum(lengths / speeds)) if len(lengths) else 0.0
    seconds += sum(s.seconds for s in toolpath.steps if type(s) is Dwell)
    low = points.min(axis=0)
    high = points.max(axis=0)
    return Summary(
        length=float(lengths.sum()),
        travel_length=float(lengths[flat.rapid[1:]].sum()),
        low=(float(low[0]), float(low[1]), float(low[2])),
        high=(float(high[0]), float(high[1]), float(high[2])),
        seconds=seconds,
        segments=len(lengths),
    )


def check_travel(toolpath: Toolpath, flat: FlatPath, travel: TravelLimits | None) -> None:
    """Refuse a program any point of which (an arc's widest points included) is outside the
    box, naming the first line and point; the start is where the stage is, not checked."""
    if travel is None or len(flat) < 2:
        return
    box = np.asarray(travel.box, np.float64)
    points = flat.points[1:]
    outside = np.any((points < box[:, 0]) | (points > box[:, 1]), axis=1)
    first = int(np.argmax(outside)) + 1 if outside.any() else None
    arc_first = _first_arc_outside(toolpath, flat, travel)
    if arc_first is not None and (first is None or arc_first[0] < first):
        _refuse(toolpath, travel, arc_first[1], arc_first[2])
    if first is not None:
        point = flat.points[first]
        _refuse(
            toolpath,
            travel,
            int(flat.source[first]),
            (float(point[0]), float(point[1]), float(point[2])),
        )


def check_axes(toolpath: Toolpath, flat: FlatPath, axes: tuple[str, ...]) -> None:
    """Refuse a program that moves an axis the device does not have (Visiomex has no Z,
    Firmata only X), naming the first line that does."""
    for column, axis in enumerate(("x", "y", "z")):
        if axis in axes or len(flat) < 2:
            continue
        moved = flat.points[1:, column] != flat.points[0, column]
        if moved.any():
            row = int(np.argmax(moved)) + 1
            raise BadInput(
                Message(
                    "{where}: the program moves {axis} to {value:g} mm, an axis the device "
                    "does not have (it has {axes}); nothing was sent",
                    where=toolpath.where(int(flat.source[row])),
                    axis=axis.upper(),
                    value=round(float(flat.points[row, column]), 6),
                    axes=", ".join(a.upper() for a in axes),
                )
            )


def check_fits(
    toolpath: Toolpath, flat: FlatPath, axes: tuple[str, ...], travel: TravelLimits | None
) -> None:
    """Refuse a program that moves an axis the device lacks or leaves the travel box."""
    check_axes(toolpath, flat, axes)
    check_travel(toolpath, flat, travel)


def check_speeds(toolpath: Toolpath, low: float, high: float, decimals: int) -> None:
    """Refuse a program a speed of which (as the device takes it: rounded to `decimals`) is
    outside `low` to `high` mm/s, naming the first line that asks it."""
    for step in toolpath.steps:
        if isinstance(step, Dwell) or step.speed is None:
            continue
        if not low <= round(step.speed, decimals) <= high:
            raise BadInput(
                Message(
                    "{where}: speed {speed:g} mm/s refused: the device allows "
                    "{low:g} to {high:g} mm/s; nothing was sent",
                    where=toolpath.where(step.source),
                    speed=step.speed,
                    low=low,
                    high=high,
                )
            )


def _first_arc_outside(
    toolpath: Toolpath, flat: FlatPath, travel: TravelLimits
) -> tuple[int, int, Point] | None:
    """The first arc whose widest point (at 0°, 90°, 180°, 270°) lies outside the box, which
    its chords may cut inside: (row, source, point)."""
    for index, step in enumerate(toolpath.steps):
        if type(step) is not ArcTo:
            continue
        row = int(flat.step_end[index - 1]) if index else 0
        start = tuple(float(v) for v in flat.points[row])
        start3 = (start[0], start[1], start[2])
        radius, a0, _ = arc_angles(start3, step)
        sweep = arc_sweep(start3, step)
        for quarter in range(4):
            angle = quarter * math.pi / 2
            turned = (angle - a0) % math.tau if sweep > 0 else (a0 - angle) % math.tau
            if turned <= abs(sweep):
                fraction = turned / abs(sweep)
                point = (
                    step.centre[0] + radius * math.cos(angle),
                    step.centre[1] + radius * math.sin(angle),
                    start3[2] + (step.end[2] - start3[2]) * fraction,
                )
                if not travel.contains(point):
                    return row + 1, step.source, point
    return None


def _refuse(toolpath: Toolpath, travel: TravelLimits, source: int, point: Point) -> None:
    raise ProgramOutside(
        Message(
            "{where}: the program would leave the travel box at ({x:g}, {y:g}, {z:g}) mm "
            "({box}); nothing was sent",
            where=toolpath.where(source),
            x=round(point[0], 6),
            y=round(point[1], 6),
            z=round(point[2], 6),
            box=travel.describe(),
        )
    )
