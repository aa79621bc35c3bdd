"""The 2D view's XY plot: the stage seen from above, with its trail drawn from the buffer."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication

from widgets._fast_grid import FastGrid
from widgets._plot_fit import PlotFit, fitted_plot_widget
from widgets.position_buffer import PositionBuffer
from widgets.view2d.style import TRAIL_COLOUR


class XYPlotMixin:
    """The XY plot of PositionView2D: its widget, its fit, its trail, and the trail's redraw."""

    buffer: PositionBuffer
    xy_grid: FastGrid
    _following: bool

    def _make_xy_plot(self) -> None:
        """Make the XY plot, its grid, the plans' items, the trail and the markers, in order."""
        self.xy_plot = fitted_plot_widget()
        self.xy_plot.setObjectName("positionXYPlot")
        self.xy_plot.setToolTip(
            QCoreApplication.translate(
                "PositionView2D",
                "Stage seen from above: trail, current position (dot; hollow when estimated),"
                " target (+), travel limits (dashed)",
            )
        )
        xy = self.xy_plot.getPlotItem()
        self.xy_fit = PlotFit(
            self.xy_plot,
            QCoreApplication.translate("PositionView2D", "XY (from above)"),
            self._xy_labels(),
        )
        xy.addItem(self.xy_grid, ignoreBounds=True)
        xy.setAspectLocked(True)
        self._make_plan_items(xy)
        # connect="finite": a NaN row (a break: a new connection) joins nothing.
        self.trail = xy.plot(pen=pg.mkPen(TRAIL_COLOUR, width=1.5), name="trail", connect="finite")
        self._make_markers(xy)

    def _refresh_xy(self) -> bool:
        """Redraw the XY plot if the buffer changed; whether it did (the time plot is due)."""
        if self.changed_rows() is None:
            return False
        rows = self._drawn()
        if not len(rows):
            self.trail.setData([], [])
            self.current_marker.setData([], [])
        else:
            self.trail.setData(rows[:, 1], rows[:, 2])
            self.current_marker.setData([rows[-1, 1]], [rows[-1, 2]])
            if self._following:
                self._follow_xy(rows)
        return True

    def _drawn(self) -> np.ndarray:
        """The trail as drawn: (n, 4) rows (t, x, y, z), every recent one and the first, last
        and extreme ones of each block of older ones (so the whole trail's extent)."""
        return self.buffer.lod.update()
