"""The 3D scene's geometry: an XY grid sized to the data, the axes' ends, a travel box."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from widgets._axes import Box
from widgets._i18n import number_text
from widgets._units import INCH, MM, MM_PER_INCH, check_units

MIN_SPAN_MM = 10.0
GRID_CELLS = 10
MM_STEPS = (1.0, 2.0, 5.0, 10.0)  # grid spacings in mm: 1-2-5 x 10^n
INCH_STEPS = (1.0, 2.5, 5.0, 10.0)  # in inches: 0.1, 0.25, 0.5, 1, 2.5 ...


class Grid(NamedTuple):
    """An XY grid in mm: x0..x1, y0..y1 with lines every `spacing`."""

    x0: float
    x1: float
    y0: float
    y1: float
    spacing: float

    def contains(self, points: np.ndarray) -> bool:
        """Whether every (x, y, ...) row lies on the grid."""
        if not len(points):
            return True
        tol = self.spacing * 1e-6
        lo, hi = points[:, :2].min(axis=0), points[:, :2].max(axis=0)
        return bool(
            lo[0] >= self.x0 - tol
            and hi[0] <= self.x1 + tol
            and lo[1] >= self.y0 - tol
            and hi[1] <= self.y1 + tol
        )

    def lines(self) -> np.ndarray:
        """The grid's line segments as (2n, 3) float32 vertices at z = 0."""
        xs = np.arange(self.x0, self.x1 + self.spacing / 2, self.spacing)
        ys = np.arange(self.y0, self.y1 + self.spacing / 2, self.spacing)
        vertical = [((x, self.y0, 0.0), (x, self.y1, 0.0)) for x in xs]
        horizontal = [((self.x0, y, 0.0), (self.x1, y, 0.0)) for y in ys]
        return np.array(vertical + horizontal, dtype=np.float32).reshape(-1, 3)


def nice_spacing(
    span: float, cells: int = GRID_CELLS, steps: tuple[float, ...] = MM_STEPS
) -> float:
    """The spacing of `steps` x 10^n (1-2-5 by default) that divides `span` into about `cells`
    cells."""
    raw = max(float(span), 1e-9) / cells
    decade = 10.0 ** math.floor(math.log10(raw))
    candidates = [m * decade for m in steps]
    return min(candidates, key=lambda c: abs(math.log(raw / c)))


def grid_for(points: np.ndarray, pad: float = 0.05, units: str = MM) -> Grid:
    """A grid covering the origin and the XY of `points` ((n, 3) mm), with `pad` headroom.

    Each side is at least half the longest one; the edges fall on grid lines. The grid is in
    mm; with `units` "in" its lines are 0.1, 0.25, 0.5, 1... inch apart, from the origin.
    """
    check_units(units)
    unit = MM_PER_INCH if units == INCH else 1.0
    xy = np.vstack([np.zeros((1, 2)), np.asarray(points, dtype=float).reshape(-1, 3)[:, :2]])
    xy = xy / unit
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    span = max(float(np.max(hi - lo)), MIN_SPAN_MM / unit)
    spacing = nice_spacing(span, steps=INCH_STEPS if units == INCH else MM_STEPS)
    lo = np.where(lo < 0, lo - pad * span, lo)
    hi = np.where(hi > 0, hi + pad * span, hi)
    for axis in range(2):
        short = span / 2 - (hi[axis] - lo[axis])
        if short > 0:
            if hi[axis] > 0 or lo[axis] >= 0:
                hi[axis] += short
            else:
                lo[axis] -= short
    lo = np.floor(lo / spacing + 1e-9) * spacing * unit + 0.0  # + 0.0: no -0.0
    hi = np.ceil(hi / spacing - 1e-9) * spacing * unit + 0.0
    return Grid(float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1]), spacing * unit)


def spacing_text(spacing_mm: float, units: str = MM) -> str:
    """A grid spacing in `units` as the scale writes it ("0.25", "0,25" in French)."""
    check_units(units)
    return number_text(spacing_mm / (MM_PER_INCH if units == INCH else 1.0), 6)


def axis_ends(grid: Grid, top: float) -> np.ndarray:
    """The ends of the X, Y and Z axes (rows of a diagonal 3x3), scaled to the grid.

    X and Y reach the grid's far edge; Z reaches `top` (the highest data), at least a quarter
    of the grid.
    """
    span = max(grid.x1 - grid.x0, grid.y1 - grid.y0)
    lengths = (
        grid.x1 if grid.x1 > 0 else span / 2,
        grid.y1 if grid.y1 > 0 else span / 2,
        max(span / 4, top),
    )
    return np.diag(lengths).astype(np.float32)


def box_corners(box: Box) -> np.ndarray:
    """The 8 corners of a travel box as (8, 3) float32."""
    (x0, x1), (y0, y1), (z0, z1) = box
    return np.array(
        [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)], dtype=np.float32
    )


def box_edges(box: Box) -> np.ndarray:
    """The 12 edges of a travel box as (24, 3) float32 vertices for a "lines" plot."""
    corners = box_corners(box)
    pairs = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]
    return np.array([corners[i] for pair in pairs for i in pair], dtype=np.float32)
