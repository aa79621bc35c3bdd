"""The 2D view's markers: the current position (hollow when estimated) and the target."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QBrush

from widgets._axes import AXES, target_point
from widgets.view2d.style import AXIS_COLOURS, CURRENT_COLOUR, TARGET_COLOUR


class MarkersMixin:
    """The markers of PositionView2D: the current and target dots in XY, the target's lines
    against time."""

    _following: bool
    _target: tuple[float, float, float] | None
    _estimated: bool

    def _make_markers(self, xy: pg.PlotItem) -> None:
        """Add the current position's and the target's markers to the XY plot."""
        self.current_marker = pg.ScatterPlotItem(
            size=12, brush=pg.mkBrush(CURRENT_COLOUR), pen=pg.mkPen("k", width=1)
        )
        self.target_marker = pg.ScatterPlotItem(
            size=18, symbol="+", brush=pg.mkBrush(TARGET_COLOUR), pen=pg.mkPen(TARGET_COLOUR)
        )
        xy.addItem(self.current_marker)
        xy.addItem(self.target_marker)

    def _make_target_lines(self, tp: pg.PlotItem) -> None:
        """Add the target's dashed line for each axis to the time plot, hidden."""
        self.target_lines = {}
        for axis in AXES:
            line = pg.InfiniteLine(
                angle=0, pen=pg.mkPen(AXIS_COLOURS[axis], style=Qt.PenStyle.DashLine)
            )
            line.setVisible(False)
            tp.addItem(line, ignoreBounds=True)
            self.target_lines[axis] = line

    def set_target(self, x: object, y: float | None = None, z: float | None = None) -> None:
        """Mark the target: `set_target(x, y, z)` or `set_target((x, y, z))` in mm; None hides it.

        z may be None (a device without Z): then no Z target line is drawn.
        """
        point = target_point(x, y, z)
        if point is None:
            self._target = None
            self.target_marker.setData([], [])
            for line in self.target_lines.values():
                line.setVisible(False)
            return
        tx, ty, tz = point
        self._target = (tx, ty, np.nan if tz is None else tz)
        self.target_marker.setData([tx], [ty])
        for axis, value in zip(AXES, self._target, strict=True):
            line = self.target_lines[axis]
            line.setVisible(not np.isnan(value))
            if not np.isnan(value):
                line.setValue(value)
        if self._following:
            self._follow_xy(self._drawn())  # a target outside the view widens it at once

    def set_estimated(self, estimated: bool) -> None:
        """Draw the current-position marker hollow while the position is estimated, not read."""
        self._estimated = bool(estimated)
        if self._estimated:
            self.current_marker.setPen(pg.mkPen(CURRENT_COLOUR, width=2.5))
            self.current_marker.setBrush(QBrush(Qt.BrushStyle.NoBrush))
        else:
            self.current_marker.setPen(pg.mkPen("k", width=1))
            self.current_marker.setBrush(pg.mkBrush(CURRENT_COLOUR))

    def is_estimated(self) -> bool:
        """Whether the current position is shown as estimated (hollow marker)."""
        return self._estimated
