"""The 2D view's time plot: X, Y and Z against time, drawn a moment after the XY plot."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QTimer

from widgets._axes import AXES
from widgets._fast_grid import FastGrid
from widgets._pacer import run_paced
from widgets._plot_fit import PlotFit, fitted_plot_widget
from widgets._view_common import REFRESH_INTERVAL_MS
from widgets.position_buffer import PositionBuffer
from widgets.view2d.following import TIME_WINDOWS_S
from widgets.view2d.style import AXIS_COLOURS

TIME_TICK_SAMPLE = "-1000.0"  # the time plot's left axis has room for this tick label
TIME_PLOT_DELAY_MS = REFRESH_INTERVAL_MS // 3  # the timer draws the time plot this much later


class TimePlotMixin:
    """The time plot of PositionView2D: its widget, curves, legend and target lines, and the
    refresh timer's turns (the XY plot at once, the time plot TIME_PLOT_DELAY_MS later)."""

    buffer: PositionBuffer
    time_grid: FastGrid
    timer: QTimer
    _seen_version: int
    _following: bool

    def _make_time_plot(self) -> None:
        """Make the time plot, its grid, curves and legend (in its title row), target lines."""
        self.time_plot = fitted_plot_widget()
        self.time_plot.setObjectName("positionTimePlot")
        self.time_plot.setToolTip(
            QCoreApplication.translate(
                "PositionView2D", "X, Y and Z against time; dashed lines: target"
            )
        )
        tp = self.time_plot.getPlotItem()
        tp.addItem(self.time_grid, ignoreBounds=True)
        tp.setClipToView(True)
        tp.setDownsampling(auto=True, mode="peak")
        self.curves = {
            axis: tp.plot(
                pen=pg.mkPen(AXIS_COLOURS[axis], width=1.5), name=axis.upper(), connect="finite"
            )
            for axis in AXES
        }
        self.legend = pg.LegendItem(colCount=len(AXES), horSpacing=4)
        self.legend.layout.setContentsMargins(4, 2, 4, 2)  # 24 px high: fits the title row
        for axis in AXES:
            self.legend.addItem(self.curves[axis], axis.upper())
        # The legend in the title row, above the data area, so it never covers a line. Fixed
        # left axis room: a tick label of another width (the window stepping to 30 s, a range
        # growing past 10 mm) otherwise re-lays the plot out, and the window's docks with it.
        self.time_fit = PlotFit(
            self.time_plot,
            QCoreApplication.translate("PositionView2D", "Position against time"),
            self._time_labels(),
            legend=self.legend,
            left_ticks=TIME_TICK_SAMPLE,
            keep_header=True,
        )
        self._make_target_lines(tp)

    def _make_time_timers(self) -> None:
        """Route the refresh timer through `_timed_refresh`, and make the time plot's timer."""
        self.timer.timeout.disconnect(self.refresh)
        self.timer.timeout.connect(self._timed_refresh)
        # The timer's refresh draws the XY plot at once and the time plot TIME_PLOT_DELAY_MS
        # later: each plot's change makes Qt repaint the window there and then, and the two
        # repaints with the refresh were one of the window's longest stalls.
        self._time_timer = QTimer(self)
        self._time_timer.setObjectName("timePlotRefreshTimer")
        self._time_timer.setSingleShot(True)
        self._time_timer.setInterval(TIME_PLOT_DELAY_MS)
        self._time_timer.timeout.connect(self._timed_time_plot)
        self._xy_retry = QTimer(self)  # the XY plot's turn, when the pacer refused it one
        self._xy_retry.setSingleShot(True)
        self._xy_retry.timeout.connect(self._timed_refresh)

    def _timed_refresh(self) -> None:
        """The timer's refresh: the XY plot now, the time plot TIME_PLOT_DELAY_MS later; each
        paced (not in the same turn of the event loop as other heavy work)."""
        if self.buffer.version == self._seen_version or not run_paced(self._xy_retry):
            return
        if self._refresh_xy() and not self._time_timer.isActive():
            self._time_timer.start(TIME_PLOT_DELAY_MS)

    def _timed_time_plot(self) -> None:
        """The time plot's delayed turn, paced."""
        if run_paced(self._time_timer):
            self._refresh_time_plot()

    def _refresh_time_plot(self) -> None:
        """Redraw the time plot from the buffer."""
        self._time_timer.stop()
        if not len(self.buffer.view()):
            for curve in self.curves.values():
                curve.setData([], [])
            return
        rows = self._time_rows()
        t = rows[:, 0] - rows[-1, 0]
        for index, axis in enumerate(AXES, start=1):
            self.curves[axis].setData(t, rows[:, index])
        if self._following:
            self._follow_time(rows, t)

    def _time_rows(self) -> np.ndarray:
        """The rows of the time plot: every row of the longest time window, decimated before.

        Rows come in time order (session time), so the window starts at a binary search.
        """
        lod, rows = self.buffer.lod, self.buffer.view()
        start = lod.recent_start
        if start:
            since = rows[-1, 0] - TIME_WINDOWS_S[-1]
            start = int(np.searchsorted(rows[:start, 0], since, side="left"))
        return lod.rows_since(start)
