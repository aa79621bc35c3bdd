"""2D position plots: the XY trail seen from above, and X/Y/Z against time."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QResizeEvent
from PySide6.QtWidgets import QHBoxLayout, QPushButton, QSplitter, QVBoxLayout, QWidget

from widgets._axes import AXES, target_point
from widgets._view_common import BufferedViewMixin
from widgets.position_buffer import PositionBuffer

GRID_COLOUR = (60, 60, 60)
TIME_WINDOWS_S = (10.0, 30.0, 60.0)  # the time plot's span grows in these steps
FOLLOW_PADDING = 0.25
MIN_MARGIN_MM = 1.0
AXIS_COLOURS = {"x": "#e53935", "y": "#43a047", "z": "#1e88e5"}
TRAIL_COLOUR = "#5c6bc0"
CURRENT_COLOUR = "#ffb300"
TARGET_COLOUR = "#d81b60"


def _padded(values: np.ndarray) -> tuple[float, float]:
    """The span of `values` with a quarter of it (at least 1 mm) added on each side."""
    low, high = float(values.min()), float(values.max())
    margin = max((high - low) * FOLLOW_PADDING, MIN_MARGIN_MM)
    return low - margin, high + margin


def _grid() -> pg.GridItem:
    """A background grid; unlike the axes' own grid (showGrid), it does not repaint the axes'
    cached pictures on every frame, which cost 30 ms a frame under a software rasteriser."""
    grid = pg.GridItem()
    grid.setPen(pg.mkPen(GRID_COLOUR))
    grid.setTextPen(None)
    return grid


class PositionView2D(BufferedViewMixin, QWidget):
    """XY trail with current and target markers, and a position-time chart, from a buffer."""

    def __init__(self, buffer: PositionBuffer, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("positionView2d")
        self.buffer = buffer
        self._target: tuple[float, float, float] | None = None

        self.xy_plot = pg.PlotWidget()
        self.xy_plot.setObjectName("positionXYPlot")
        self.xy_plot.setToolTip("Stage seen from above: trail, current position (dot), target (+)")
        xy = self.xy_plot.getPlotItem()
        xy.setTitle("XY (from above)")
        xy.setLabel("bottom", "X (mm)")
        xy.setLabel("left", "Y (mm)")
        xy.addItem(_grid(), ignoreBounds=True)
        xy.setAspectLocked(True)
        self.trail = xy.plot(pen=pg.mkPen(TRAIL_COLOUR, width=1.5), name="trail")
        self.current_marker = pg.ScatterPlotItem(
            size=12, brush=pg.mkBrush(CURRENT_COLOUR), pen=pg.mkPen("k", width=1)
        )
        self.target_marker = pg.ScatterPlotItem(
            size=18, symbol="+", brush=pg.mkBrush(TARGET_COLOUR), pen=pg.mkPen(TARGET_COLOUR)
        )
        xy.addItem(self.current_marker)
        xy.addItem(self.target_marker)

        self.time_plot = pg.PlotWidget()
        self.time_plot.setObjectName("positionTimePlot")
        self.time_plot.setToolTip("X, Y and Z against time; dashed lines: target")
        tp = self.time_plot.getPlotItem()
        tp.setTitle("Position against time")
        tp.setLabel("bottom", "time (s, 0 = latest sample)")
        tp.setLabel("left", "position (mm)")
        tp.addItem(_grid(), ignoreBounds=True)
        tp.addLegend(offset=(-10, 10))
        tp.setClipToView(True)
        tp.setDownsampling(auto=True, mode="peak")
        self.curves = {
            axis: tp.plot(pen=pg.mkPen(AXIS_COLOURS[axis], width=1.5), name=axis.upper())
            for axis in AXES
        }
        self.target_lines = {}
        for axis in AXES:
            line = pg.InfiniteLine(
                angle=0, pen=pg.mkPen(AXIS_COLOURS[axis], style=Qt.PenStyle.DashLine)
            )
            line.setVisible(False)
            tp.addItem(line, ignoreBounds=True)
            self.target_lines[axis] = line

        clear_button = QPushButton("Clear trail")
        clear_button.setObjectName("clearTrailButton")
        clear_button.setToolTip("Forget the path so far (the current position stays)")
        clear_button.clicked.connect(self.clear_trail)
        reset_button = QPushButton("Reset view")
        reset_button.setObjectName("resetViewButton")
        reset_button.setToolTip("Zoom both plots to fit the data again")
        reset_button.clicked.connect(self.reset_view)
        buttons = QHBoxLayout()
        buttons.addStretch(1)
        buttons.addWidget(clear_button)
        buttons.addWidget(reset_button)

        for plot in (self.xy_plot, self.time_plot):
            for side in ("left", "bottom"):
                plot.getPlotItem().getAxis(side).enableAutoSIPrefix(False)  # no "(x0.001)"
        self.splitter = QSplitter(Qt.Orientation.Horizontal)
        self.splitter.addWidget(self.xy_plot)
        self.splitter.addWidget(self.time_plot)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.splitter, 1)
        layout.addLayout(buttons)

        for plot in (self.xy_plot, self.time_plot):
            plot.getPlotItem().getViewBox().sigRangeChangedManually.connect(self._stop_following)
        self._following = True
        self.start_refresh_timer()
        self.reset_view()

    def refresh(self) -> None:
        """Redraw from the buffer if it changed since the last refresh."""
        rows = self.changed_rows()
        if rows is None:
            return
        if not len(rows):
            self.trail.setData([], [])
            self.current_marker.setData([], [])
            for curve in self.curves.values():
                curve.setData([], [])
            return
        t = rows[:, 0] - rows[-1, 0]
        self.trail.setData(rows[:, 1], rows[:, 2])
        self.current_marker.setData([rows[-1, 1]], [rows[-1, 2]])
        for index, axis in enumerate(AXES, start=1):
            self.curves[axis].setData(t, rows[:, index])
        if self._following:
            self._follow(rows, t)

    def _follow(self, rows: np.ndarray, t: np.ndarray) -> None:
        """Widen the views only when the data leaves them, with room to spare.

        pyqtgraph's auto-range moved the range on almost every frame while jogging, and every
        move rebuilt the axes' and grid's pictures: most of the GUI thread's time.
        """
        xy = self.xy_plot.getPlotItem()
        (x0, x1), (y0, y1) = xy.viewRange()
        xs, ys = rows[:, 1], rows[:, 2]
        if xs.min() < x0 or xs.max() > x1 or ys.min() < y0 or ys.max() > y1:
            xy.setRange(xRange=_padded(xs), yRange=_padded(ys), padding=0)
        span = -float(t[0])
        window = next((w for w in TIME_WINDOWS_S if w >= span), TIME_WINDOWS_S[-1])
        tp = self.time_plot.getPlotItem()
        if window != self._time_window:
            self._time_window = window
            tp.setXRange(-window, 0, padding=0.02)
        recent = rows[t >= -window, 1:4]
        low, high = tp.viewRange()[1]
        if recent.min() < low or recent.max() > high:
            tp.setYRange(*_padded(recent.ravel()), padding=0)

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

    def reset_view(self) -> None:
        """Zoom both plots to fit their data, following new data again.

        The time axis shows the last 10, 30 or 60 s: a range that moved every frame made
        pyqtgraph rebuild the axis and grid pictures every frame (most of the GUI thread's time).
        """
        self._following = True
        self._time_window = 0.0
        for plot in (self.xy_plot, self.time_plot):
            plot.getPlotItem().disableAutoRange()
        rows = self.buffer.view()
        if len(rows):
            self._follow(rows, rows[:, 0] - rows[-1, 0])
        else:
            self.xy_plot.getPlotItem().setRange(xRange=(-1, 1), yRange=(-1, 1), padding=0)
            self.time_plot.getPlotItem().setRange(xRange=(-TIME_WINDOWS_S[0], 0), yRange=(-1, 1))

    def _stop_following(self) -> None:
        """The user zoomed or panned: leave the ranges alone until Reset view."""
        self._following = False

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Plots side by side when there is width for it, else one above the other."""
        super().resizeEvent(event)
        wide = event.size().width() >= 1.3 * event.size().height()
        orientation = Qt.Orientation.Horizontal if wide else Qt.Orientation.Vertical
        if self.splitter.orientation() != orientation:
            self.splitter.setOrientation(orientation)
