"""What the 3D view draws of the plans: a preview path, and a program left to run."""

from __future__ import annotations

import numpy as np

from widgets._program_path import ProgramPath, program_arrays
from widgets.view3d.geometry import Grid, box_corners


def preview_array(points: object) -> np.ndarray:
    """A planned path's points as (n, 3) float64 mm; None or [] give (0, 3).

    Each point is (x, y, z); x and y must be finite, a missing (NaN) z counts as 0.
    """
    if points is None:
        return np.zeros((0, 3))
    array = np.asarray(points, dtype=float)
    if array.size == 0:
        return np.zeros((0, 3))
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"a preview is a list of (x, y, z) points, not shape {array.shape}")
    if not np.isfinite(array[:, :2]).all():
        raise ValueError("a preview's X and Y must be finite")
    array = array.copy()
    array[~np.isfinite(array[:, 2]), 2] = 0.0
    return array


def preview_tuples(array: np.ndarray) -> list[tuple[float, float, float]]:
    """The rows of a preview array as (x, y, z) tuples."""
    return [(float(x), float(y), float(z)) for x, y, z in array]


class ProgramOverlayMixin:
    """The preview and program API of PositionView3D, drawing into its `preview_item`,
    `program_cut` and `program_rapid` (made by SceneItemsMixin)."""

    _grid: Grid
    _preview: np.ndarray
    _program: ProgramPath | None
    _program_done: int

    def set_preview(self, points: object) -> None:
        """Draw a planned path (a list of (x, y, z) in mm) as a light orange line; None or []
        removes it. The grid grows to hold it."""
        self._preview = preview_array(points)
        shown = len(self._preview) >= 2
        self.preview_item.setVisible(shown)
        if shown:
            self.preview_item.setData(pos=self._preview.astype(np.float32))
        if not self._grid.contains(self._preview):
            self._fit_grid()
        self._redraw()

    def preview(self) -> list[tuple[float, float, float]]:
        """The planned path shown, as (x, y, z) points in mm; [] when none."""
        return preview_tuples(self._preview)

    def set_program(self, points: np.ndarray | None, rapid: np.ndarray | None = None) -> None:
        """Draw a whole program: `points` (n, 3) mm, row 0 its start and row i the end of
        segment i; `rapid` (n,) whether segment i is a travel move (dashed; the others solid).
        None or fewer than 2 points removes it. The grid grows to hold it."""
        array, moves = program_arrays(points, rapid)
        self._program = ProgramPath(array, moves) if len(array) >= 2 else None
        self._program_done = 0
        self._draw_program(fresh=True)
        if self._program is not None:
            corners = box_corners(tuple(zip(self._program.low, self._program.high, strict=True)))
            if not self._grid.contains(corners):
                self._fit_grid()
        self._redraw()

    def set_program_done(self, row: int) -> None:
        """The program has run up to `row` (the trail shows it): draw only rows >= `row`."""
        if self._program is None:
            return
        row = self._program.clamp(row)
        if row != self._program_done:
            self._program_done = row
            self._draw_program(fresh=False)
            self._redraw()

    def program(self) -> np.ndarray:
        """The program's points drawn, (n, 3) mm from the row it is done up to; (0, 3) when
        none."""
        if self._program is None:
            return np.zeros((0, 3))
        return self._program.points[self._program_done :]

    def _draw_program(self, fresh: bool) -> None:
        """Give the program's items what is left of it; `fresh`: a new program (uploaded
        whole), else the same one further on (a shorter prefix: nothing uploaded)."""
        program, row = self._program, self._program_done
        for item, part in (
            (self.program_cut, "cut_vertices"),
            (self.program_rapid, "dash_vertices"),
        ):
            vertices = getattr(program, part)(row) if program is not None else np.zeros((0, 3))
            item.set_vertices(vertices, 0 if fresh else len(vertices))
            item.setVisible(len(vertices) >= 2)
