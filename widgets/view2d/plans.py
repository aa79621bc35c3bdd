"""What the 2D view draws of the plans: the travel box, a preview path, a program left to run."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QGraphicsItem

from widgets._axes import Box
from widgets._gl_scene import preview_array, preview_tuples
from widgets._program_path import ProgramPath, program_arrays
from widgets.view2d.style import PREVIEW_COLOUR, THEME_ROLE, WORKSPACE_COLOUR


class PlansMixin:
    """The travel box, preview and program API of PositionView2D, and their XY plot items."""

    _following: bool
    _workspace: Box | None
    _preview: np.ndarray
    _program: ProgramPath | None
    _program_done: int

    def _make_plan_items(self, xy: pg.PlotItem) -> None:
        """Add the travel box outline, the preview and the program's items to the XY plot."""
        self.workspace_outline = pg.PlotCurveItem(
            pen=pg.mkPen(WORKSPACE_COLOUR, width=1.5, style=Qt.PenStyle.DashLine)
        )
        self.workspace_outline.setVisible(False)
        xy.addItem(self.workspace_outline, ignoreBounds=True)  # fitted by _follow_xy, not auto
        self.preview_curve = pg.PlotCurveItem(
            pen=pg.mkPen(PREVIEW_COLOUR, width=1.5, style=Qt.PenStyle.DashLine)
        )
        self.preview_curve.setVisible(False)
        setattr(self.preview_curve, THEME_ROLE, "preview")
        xy.addItem(self.preview_curve, ignoreBounds=True)  # fitted by _follow_xy, not auto
        # A program's path: its cut segments solid, its travel (rapid) moves dashed, each item
        # holding (start, end) pairs of its segments ("pairs"), from the row the run is at on.
        self.program_cut = pg.PlotCurveItem(
            pen=pg.mkPen(PREVIEW_COLOUR, width=1), connect="pairs", skipFiniteCheck=True
        )
        self.program_cut.setSegmentedLineMode("on")  # one drawLines: no path to build
        self.program_rapid = pg.PlotCurveItem(
            pen=pg.mkPen(PREVIEW_COLOUR, width=1, style=Qt.PenStyle.DashLine),
            connect="pairs",
            skipFiniteCheck=True,
        )
        # Kept as an image (Qt's device coordinate cache) between their changes: the trail's
        # every frame repaints the plot, and drawing 100,000 segments took 6 ms each time
        # (1 px wide: 1.5 px went through Qt's general stroker, 37 ms).
        for item in (self.program_cut, self.program_rapid):
            item.setVisible(False)
            item.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
            setattr(item, THEME_ROLE, "preview")
            xy.addItem(item, ignoreBounds=True)  # fitted by _follow_xy, not auto

    def set_workspace(self, box: Box | None) -> None:
        """Outline the travel box's XY rectangle (dashed), in mm; None hides it.

        The outline does not take part in pyqtgraph's auto-range; while following, the XY view
        widens to hold it, and Reset view fits it with the data.
        """
        if box is None:
            self._workspace = None
            self.workspace_outline.setData([], [])
            self.workspace_outline.setVisible(False)
            return
        if len(box) != 3 or any(len(pair) != 2 for pair in box):
            raise ValueError(f"a travel box is three (min, max) pairs, not {box!r}")
        (x0, x1), (y0, y1), (z0, z1) = (sorted((float(a), float(b))) for a, b in box)
        if not np.isfinite([x0, x1, y0, y1]).all():
            raise ValueError(f"a travel box needs finite X and Y limits, not {box!r}")
        self._workspace = ((x0, x1), (y0, y1), (z0, z1))
        self.workspace_outline.setData([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0])
        self.workspace_outline.setVisible(True)
        if self._following:
            self._follow_xy(self._drawn())

    def workspace(self) -> Box | None:
        """The travel box shown, or None."""
        return self._workspace

    def set_preview(self, points: object) -> None:
        """Draw a planned path, dashed, in the XY plot: a list of (x, y, z) in mm; None or []
        removes it.

        Like the target, while following the XY view widens to hold it.
        """
        self._preview = preview_array(points)
        if not len(self._preview):
            self.preview_curve.setData([], [])
            self.preview_curve.setVisible(False)
            return
        xy = self._preview[:, :2]
        self._preview_bounds = (xy.min(axis=0), xy.max(axis=0))
        self.preview_curve.setData(xy[:, 0], xy[:, 1])
        self.preview_curve.setVisible(True)
        if self._following:
            self._follow_xy(self._drawn())

    def preview(self) -> list[tuple[float, float, float]]:
        """The planned path shown, as (x, y, z) points in mm; [] when none."""
        return preview_tuples(self._preview)

    def set_program(self, points: np.ndarray | None, rapid: np.ndarray | None = None) -> None:
        """Draw a whole program in the XY plot: `points` (n, 3) mm, row 0 its start and row i
        the end of segment i; `rapid` (n,) whether segment i is a travel move (dashed; the
        others solid). None or fewer than 2 points removes it.

        Like the preview, while following the XY view widens to hold it.
        """
        array, moves = program_arrays(points, rapid)
        self._program = ProgramPath(array, moves) if len(array) >= 2 else None
        self._program_done = 0
        self._draw_program()
        if self._program is not None and self._following:
            self._follow_xy(self._drawn())

    def set_program_done(self, row: int) -> None:
        """The program has run up to `row` (the trail shows it): draw only rows >= `row`."""
        if self._program is None:
            return
        row = self._program.clamp(row)
        if row != self._program_done:
            self._program_done = row
            self._draw_program()

    def program(self) -> np.ndarray:
        """The program's points drawn, (n, 3) mm from the row it is done up to; (0, 3) when
        none."""
        if self._program is None:
            return np.zeros((0, 3))
        return self._program.points[self._program_done :]

    def _draw_program(self) -> None:
        """Give the program's items what is left of it (slices: nothing is copied)."""
        program, row = self._program, self._program_done
        for item, part in ((self.program_cut, "cut_xy"), (self.program_rapid, "rapid_xy")):
            x, y = getattr(program, part)(row) if program is not None else ([], [])
            item.setData(x, y)
            item.setVisible(len(x) >= 2)
