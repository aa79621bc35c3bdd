"""A program's whole path prepared once for the position views: its cut (feed) and travel
(rapid) segments apart, each sliced cheaply from the row the run has reached.

Row 0 of `points` is where the program starts and row i ends segment i (as
drivers.toolpath.geometry.FlatPath). "Done up to row r" leaves the segments from row r on: the
segment from row j to row j + 1 for every j >= r. The 2D arrays keep segment order, so what is
left is a suffix; the 3D vertices are stored in reverse segment order, so what is left is a
prefix, and the vertices already on the GPU stay there as the run goes on (none is uploaded).

The 3D cut segments are simplified, as the trail's history is decimated: a run of points in one
cell of a grid of GL_CELLS across the program's extent keeps its first point only (an error
under two cells: a pixel or two in a view of the whole program). Software OpenGL spends its time
on the vertices: 200,000 of them added 8-14 ms to a frame of a 1,000,000-point trail (~12 ms),
so a dense program is simplified on a coarser grid until at most MAX_GL_SEGMENTS remain.
The 2D segments are exact.
"""

from __future__ import annotations

import numpy as np

DASHES_PER_SPAN = 60  # a travel move across the program's whole extent: this many dashes (3D)
MAX_DASHES = 200_000  # the 3D travel dashes of a whole program, at most (longer dashes else)
GL_CELLS = 500  # the 3D cut segments are simplified to about this many cells across
MAX_GL_SEGMENTS = 30_000  # ... or fewer, down to MIN_GL_CELLS, while more segments remain
MIN_GL_CELLS = 60


def program_arrays(
    points: np.ndarray | None, rapid: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """A program's points as (n, 3) float64 mm (a NaN z counts as 0) and whether each segment
    is a travel move as (n,) bool (row 0 False); None gives empty arrays.

    X and Y must be finite; `rapid` None means no travel moves.
    """
    if points is None:
        return np.zeros((0, 3)), np.zeros(0, dtype=bool)
    array = np.array(points, dtype=np.float64)  # a copy: the caller's stays as it is
    if array.size == 0:
        return np.zeros((0, 3)), np.zeros(0, dtype=bool)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"a program's points are (n, 3), not shape {array.shape}")
    if not np.isfinite(array[:, :2]).all():
        raise ValueError("a program's X and Y must be finite")
    array[~np.isfinite(array[:, 2]), 2] = 0.0
    if rapid is None:
        moves = np.zeros(len(array), dtype=bool)
    else:
        moves = np.array(rapid, dtype=bool).reshape(-1)
        if len(moves) != len(array):
            raise ValueError(f"{len(moves)} rapid flags for {len(array)} points")
        moves[0] = False
    return array, moves


def _pair_rows(xyz: np.ndarray, starts: np.ndarray, dtype: type) -> np.ndarray:
    """The segments starting at rows `starts` as (2k, columns) rows: start, end, start, end..."""
    out = np.empty((2 * len(starts), xyz.shape[1]), dtype=dtype)
    out[0::2] = xyz[starts]
    out[1::2] = xyz[starts + 1]
    return out


def dash_vertices(
    starts: np.ndarray, ends: np.ndarray, period: float
) -> tuple[np.ndarray, np.ndarray]:
    """Each segment `starts[i]`-`ends[i]` ((k, 3) each) as dashes about `period` / 2 long with
    gaps as long, a dash at each end: the dashes' (2d, 3) float32 vertices and the count of
    dashes of each segment."""
    lengths = np.linalg.norm(ends - starts, axis=1)
    counts = np.maximum(1, np.ceil(lengths / period)).astype(np.int64)
    total = int(counts.sum())
    segment = np.repeat(np.arange(len(counts)), counts)
    first = np.cumsum(counts) - counts
    k = np.arange(total) - np.repeat(first, counts)
    pieces = np.repeat(2 * counts - 1, counts).astype(np.float64)  # n dashes, n - 1 gaps
    a, step = starts[segment], (ends - starts)[segment]
    out = np.empty((2 * total, 3), dtype=np.float32)
    out[0::2] = a + step * (2 * k / pieces)[:, None]
    out[1::2] = a + step * ((2 * k + 1) / pieces)[:, None]
    return out, counts


class ProgramPath:
    """A program's points and travel flags, with its cut and travel segments ready to draw."""

    def __init__(self, points: np.ndarray, rapid: np.ndarray) -> None:
        self.points = points
        self.rapid = rapid
        self.low = points.min(axis=0)
        self.high = points.max(axis=0)
        travel = rapid[1:]  # travel[j]: the segment from row j to row j + 1
        cut_starts = np.flatnonzero(~travel)
        rapid_starts = np.flatnonzero(travel)
        # how many cut / travel segments start before row r, for r in 0 .. n - 1
        self._cut_before = np.concatenate(([0], np.cumsum(~travel)))
        self._rapid_before = np.concatenate(([0], np.cumsum(travel)))
        cut = _pair_rows(points[:, :2], cut_starts, np.float64).T.copy()
        self.cut_x, self.cut_y = cut  # contiguous rows: their slices are contiguous views
        travel_pairs = _pair_rows(points[:, :2], rapid_starts, np.float64).T.copy()
        self.rapid_x, self.rapid_y = travel_pairs
        self._cut_gl, self._cut_left = self._simplified_cut()
        self._dash_gl, self._dashes_before = self._dashes(rapid_starts)

    def _simplified_cut(self) -> tuple[np.ndarray, np.ndarray]:
        """The cut segments simplified (see the module's docstring) as "lines" vertices in
        reverse order, and how many of them end after each row: a coarser grid while more than
        MAX_GL_SEGMENTS remain (a dense program would cost the 3D frame its budget)."""
        span = float(np.max(self.high - self.low))
        across = GL_CELLS
        while True:
            vertices, left = self._cut_on_grid(span / across if span > 0 else 1.0)
            if len(vertices) <= 2 * MAX_GL_SEGMENTS or across <= MIN_GL_CELLS:
                return vertices, left
            across //= 2

    def _cut_on_grid(self, cell: float) -> tuple[np.ndarray, np.ndarray]:
        """The cut segments simplified on a grid of `cell` mm (see `_simplified_cut`)."""
        points, travel = self.points, self.rapid[1:]
        cells = np.floor((points - self.low) / cell).astype(np.int64)
        keep = np.ones(len(points), dtype=bool)
        keep[1:-1] = (cells[1:-1] != cells[:-2]).any(axis=1)
        keep[:-1] |= travel  # both ends of every travel move: no cut segment spans one
        keep[1:] |= travel
        rows = np.flatnonzero(keep)
        starts, ends = rows[:-1], rows[1:]
        cut = ~((ends == starts + 1) & travel[starts])
        starts, ends = starts[cut], ends[cut]
        vertices = np.empty((2 * len(starts), 3), dtype=np.float32)
        vertices[0::2] = points[starts[::-1]]
        vertices[1::2] = points[ends[::-1]]
        left = len(ends) - np.searchsorted(ends, np.arange(len(points)), side="right")
        return vertices, left

    def _dashes(self, rapid_starts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The travel segments as dashes, in reverse segment order, and how many dashes the
        travel segments before each row make."""
        span = float(np.max(self.high - self.low))
        period = span / DASHES_PER_SPAN if span > 0 else 1.0
        backwards = rapid_starts[::-1]
        starts, ends = self.points[backwards], self.points[backwards + 1]
        vertices, counts = dash_vertices(starts, ends, period)
        if len(counts) and counts.sum() > MAX_DASHES:
            vertices, counts = dash_vertices(starts, ends, period * counts.sum() / MAX_DASHES)
        per_segment = np.zeros(len(self.points) - 1, dtype=np.int64)
        per_segment[backwards] = counts
        return vertices, np.concatenate(([0], np.cumsum(per_segment)))

    def __len__(self) -> int:
        return len(self.points)

    def clamp(self, row: int) -> int:
        """`row` within 0 .. n - 1."""
        return max(0, min(int(row), len(self.points) - 1))

    def cut_xy(self, row: int) -> tuple[np.ndarray, np.ndarray]:
        """X and Y of the cut segments from `row` on, as pairs (start, end) of rows (views)."""
        skip = 2 * int(self._cut_before[row])
        return self.cut_x[skip:], self.cut_y[skip:]

    def rapid_xy(self, row: int) -> tuple[np.ndarray, np.ndarray]:
        """X and Y of the travel segments from `row` on, as pairs (start, end) of rows."""
        skip = 2 * int(self._rapid_before[row])
        return self.rapid_x[skip:], self.rapid_y[skip:]

    def cut_vertices(self, row: int = 0) -> np.ndarray:
        """The cut segments (simplified) that end after `row`, as (2k, 3) float32 "lines"
        vertices in reverse order: a prefix of the whole program's."""
        return self._cut_gl[: 2 * int(self._cut_left[row])]

    def dash_vertices(self, row: int = 0) -> np.ndarray:
        """The travel segments' dashes from `row` on as (2d, 3) float32 "lines" vertices, in
        reverse order: a prefix of the whole program's."""
        left = int(self._dashes_before[-1] - self._dashes_before[row])
        return self._dash_gl[: 2 * left]
