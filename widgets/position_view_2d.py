"""2D position plots: the XY trail seen from above, and X/Y/Z against time."""

from __future__ import annotations

import logging

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QBrush, QResizeEvent
from PySide6.QtWidgets import (
    QGraphicsItem,
    QHBoxLayout,
    QPushButton,
    QSplitter,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, Box, target_point
from widgets._fast_grid import FastGrid
from widgets._gl_scene import preview_array, preview_tuples
from widgets._pacer import run_paced
from widgets._plot_fit import PlotFit, fitted_plot_widget
from widgets._program_path import ProgramPath, program_arrays
from widgets._units import INCH, MM, MM_PER_INCH, check_units
from widgets._view_common import REFRESH_INTERVAL_MS, BufferedViewMixin
from widgets.position_buffer import PositionBuffer

log = logging.getLogger(__name__)

GRID_COLOUR = (60, 60, 60)
TIME_WINDOWS_S = (10.0, 30.0, 60.0)  # the time plot's span grows in these steps
TIME_TICK_SAMPLE = "-1000.0"  # the time plot's left axis has room for this tick label
TIME_PLOT_DELAY_MS = REFRESH_INTERVAL_MS // 3  # the timer draws the time plot this much later
FOLLOW_PADDING = 0.25  # room added on each side when a view is widened
MIN_MARGIN_MM = 1.0
XY_MARGIN = 0.08  # the XY view widens when a point comes closer to its edge than this share
XY_FIT_MIN_MARGIN_MM = 2.0  # twice MIN_MARGIN_MM: a fresh fit never sits on the threshold
AXIS_COLOURS = {"x": "#e53935", "y": "#43a047", "z": "#1e88e5"}
TRAIL_COLOUR = "#5c6bc0"
CURRENT_COLOUR = "#ffb300"
TARGET_COLOUR = "#d81b60"
WORKSPACE_COLOUR = "#26a69a"
PREVIEW_COLOUR = "#ffcc80"  # light orange: a planned path, not yet run
THEME_ROLE = "theme_role"  # an item's colour role in app.window.theme.PlotColors: recoloured


def _padded(values: np.ndarray) -> tuple[float, float]:
    """The span of `values` with a quarter of it (at least 1 mm) added on each side."""
    return _fit(float(values.min()), float(values.max()), MIN_MARGIN_MM)


def _fit(low: float, high: float, min_margin: float) -> tuple[float, float]:
    """[low, high] with a quarter of its span (at least `min_margin`) added on each side."""
    margin = max((high - low) * FOLLOW_PADDING, min_margin)
    return low - margin, high + margin


def _grid() -> pg.GridItem:
    """A background grid; unlike the axes' own grid (showGrid), it does not repaint the axes'
    cached pictures on every frame, which cost 30 ms a frame under a software rasteriser."""
    return FastGrid(GRID_COLOUR)


def _steady_axes(plot: pg.PlotItem) -> None:
    """Axes whose size and label change only when they must.

    No SI prefix ("(x0.001)"; on the hidden axes too, which else rebuilt their label's HTML on
    every range change). The tick labels' space only grows: with the XY view's aspect locked, a
    narrower Y label widened the view, which changed the ranges and the labels back, and the
    layout swung between the two every frame (the axes, the grid and the layout rebuilt ~30
    times a second with nothing moving).
    """
    for side in ("left", "bottom", "right", "top"):
        axis = plot.getAxis(side)
        axis.enableAutoSIPrefix(False)
        axis.setStyle(autoReduceTextSpace=False)


class PositionView2D(BufferedViewMixin, QWidget):
    """XY trail with current and target markers, and a position-time chart, from a buffer."""

    def __init__(self, buffer: PositionBuffer, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("positionView2d")
        self.buffer = buffer
        self._target: tuple[float, float, float] | None = None
        self._workspace: Box | None = None
        self._estimated = False
        self._preview = np.zeros((0, 3))
        self._program: ProgramPath | None = None
        self._program_done = 0
        self._units = MM  # what the axes are written in (the data, the items: mm)
        self.xy_grid, self.time_grid = _grid(), _grid()

        self.xy_plot = fitted_plot_widget()
        self.xy_plot.setObjectName("positionXYPlot")
        self.xy_plot.setToolTip(
            self.tr(
                "Stage seen from above: trail, current position (dot; hollow when estimated),"
                " target (+), travel limits (dashed)"
            )
        )
        xy = self.xy_plot.getPlotItem()
        self.xy_fit = PlotFit(self.xy_plot, self.tr("XY (from above)"), self._xy_labels())
        xy.addItem(self.xy_grid, ignoreBounds=True)
        xy.setAspectLocked(True)
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
        # connect="finite": a NaN row (a break: a new connection) joins nothing.
        self.trail = xy.plot(pen=pg.mkPen(TRAIL_COLOUR, width=1.5), name="trail", connect="finite")
        self.current_marker = pg.ScatterPlotItem(
            size=12, brush=pg.mkBrush(CURRENT_COLOUR), pen=pg.mkPen("k", width=1)
        )
        self.target_marker = pg.ScatterPlotItem(
            size=18, symbol="+", brush=pg.mkBrush(TARGET_COLOUR), pen=pg.mkPen(TARGET_COLOUR)
        )
        xy.addItem(self.current_marker)
        xy.addItem(self.target_marker)

        self.time_plot = fitted_plot_widget()
        self.time_plot.setObjectName("positionTimePlot")
        self.time_plot.setToolTip(self.tr("X, Y and Z against time; dashed lines: target"))
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
            self.tr("Position against time"),
            self._time_labels(),
            legend=self.legend,
            left_ticks=TIME_TICK_SAMPLE,
            keep_header=True,
        )
        self.target_lines = {}
        for axis in AXES:
            line = pg.InfiniteLine(
                angle=0, pen=pg.mkPen(AXIS_COLOURS[axis], style=Qt.PenStyle.DashLine)
            )
            line.setVisible(False)
            tp.addItem(line, ignoreBounds=True)
            self.target_lines[axis] = line

        clear_button = QPushButton(self.tr("Clear trail"))
        clear_button.setObjectName("clearTrailButton")
        clear_button.setToolTip(self.tr("Forget the path so far (the current position stays)"))
        clear_button.clicked.connect(self.clear_trail)
        reset_button = QPushButton(self.tr("Reset view"))
        reset_button.setObjectName("resetViewButton")
        reset_button.setToolTip(self.tr("Zoom both plots to fit the data again"))
        reset_button.clicked.connect(self.reset_view)
        buttons = QHBoxLayout()
        buttons.addStretch(1)
        buttons.addWidget(clear_button)
        buttons.addWidget(reset_button)

        for plot in (self.xy_plot, self.time_plot):
            _steady_axes(plot.getPlotItem())
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
        self.reset_view()

    # -- units ---------------------------------------------------------------------------------
    def set_units(self, units: str) -> None:
        """Write the lengths on the axes in "mm" or "in": labels, ticks and grid lines (round
        inches); what is drawn stays where it is (the data and the view ranges are in mm)."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        per_unit = 1.0 / MM_PER_INCH if units == INCH else 1.0  # values shown per mm
        for side in ("bottom", "left"):
            self.xy_plot.getPlotItem().getAxis(side).setScale(per_unit)
        self.time_plot.getPlotItem().getAxis("left").setScale(per_unit)
        self.xy_grid.set_value_scale(per_unit, per_unit)
        self.time_grid.set_value_scale(1.0, per_unit)
        self.xy_fit.set_labels(self._xy_labels())
        self.time_fit.set_labels(self._time_labels())

    def units(self) -> str:
        """The units the axes are written in: "mm" or "in"."""
        return self._units

    def _xy_labels(self) -> dict[str, list[str]]:
        """The XY plot's axis labels (long, short) in the units shown."""
        if self._units == INCH:
            return {
                "bottom": [self.tr("X (in)"), self.tr("X")],
                "left": [self.tr("Y (in)"), self.tr("Y")],
            }
        return {
            "bottom": [self.tr("X (mm)"), self.tr("X")],
            "left": [self.tr("Y (mm)"), self.tr("Y")],
        }

    def _time_labels(self) -> dict[str, list[str]]:
        """The time plot's axis labels (long, short) in the units shown."""
        time = [self.tr("time (s, 0 = latest sample)"), self.tr("t (s)")]
        if self._units == INCH:
            return {"bottom": time, "left": [self.tr("position (in)"), self.tr("in")]}
        return {"bottom": time, "left": [self.tr("position (mm)"), self.tr("mm")]}

    def refresh(self) -> None:
        """Redraw both plots from the buffer if it changed since the last refresh.

        What is drawn is the buffer's decimated trail (`buffer.lod`): every recent point, and
        the first, last and extreme points of each block of older ones, so a long trail keeps its
        shape and extent at the cost of a few thousand points.
        """
        if self._refresh_xy() or self._time_timer.isActive():  # a time plot due, drawn now
            self._time_timer.stop()
            self._refresh_time_plot()

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

    def _drawn(self) -> np.ndarray:
        """The trail as drawn: (n, 4) rows (t, x, y, z), every recent one and the first, last
        and extreme ones of each block of older ones (so the whole trail's extent)."""
        return self.buffer.lod.update()

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

    def _follow_time(self, rows: np.ndarray, t: np.ndarray, force: bool = False) -> None:
        """Step the time window through 10, 30, 60 s; widen Y when the recent data leaves it.

        The views are widened only when the data leaves them, with room to spare: pyqtgraph's
        auto-range moved the range on almost every frame while jogging, and every move rebuilt
        the axes' and grid's pictures, most of the GUI thread's time.
        """
        span = -float(t[0])
        window = next((w for w in TIME_WINDOWS_S if w >= span), TIME_WINDOWS_S[-1])
        tp = self.time_plot.getPlotItem()
        if window != self._time_window:
            log.debug("time window %s s", window)
            self._time_window = window
            tp.setXRange(-window, 0, padding=0.02)
        recent = rows[t >= -window, 1:4]
        recent = recent[np.isfinite(recent)]
        if not len(recent):
            return
        low, high = tp.viewRange()[1]
        if force or recent.min() < low or recent.max() > high:
            log.debug("time plot Y fitted to %s..%s", recent.min(), recent.max())
            tp.setYRange(*_padded(recent), padding=0)

    def _follow_xy(self, rows: np.ndarray, force: bool = False) -> None:
        """Widen the XY view when a point nears its edge, so the markers stay wholly inside.

        The trail, the current position and the target must keep a margin of `XY_MARGIN` of the
        span (at least `MIN_MARGIN_MM`) from every edge: the markers are 12-18 px wide, and a
        point on the edge would be half hidden. A new fit adds `FOLLOW_PADDING` on each side and
        includes the travel box, so it moves again only when the data leaves that room.
        """
        lows, highs = [], []
        points = rows[:, 1:3]
        if len(points):
            low, high = points.min(axis=0), points.max(axis=0)
            if not (np.isfinite(low).all() and np.isfinite(high).all()):  # rare: drop NaN rows
                points = points[np.isfinite(points).all(axis=1)]
                if len(points):
                    low, high = points.min(axis=0), points.max(axis=0)
            if len(points):
                lows.append(low)
                highs.append(high)
        if self._target is not None:
            lows.append(np.array(self._target[:2]))
            highs.append(np.array(self._target[:2]))
        if len(self._preview):
            lows.append(self._preview_bounds[0])
            highs.append(self._preview_bounds[1])
        if self._program is not None:  # the whole program's, done part included: no jumps
            lows.append(self._program.low[:2])
            highs.append(self._program.high[:2])
        if not lows and self._workspace is None:
            return
        xy = self.xy_plot.getPlotItem()
        (x0, x1), (y0, y1) = xy.viewRange()
        if lows and not force:
            low, high = np.min(lows, axis=0), np.max(highs, axis=0)
            mx = max((x1 - x0) * XY_MARGIN, MIN_MARGIN_MM)
            my = max((y1 - y0) * XY_MARGIN, MIN_MARGIN_MM)
            inside = low[0] >= x0 + mx and high[0] <= x1 - mx
            force = not (inside and low[1] >= y0 + my and high[1] <= y1 - my)
        if self._workspace is not None and not force:
            (bx0, bx1), (by0, by1), _ = self._workspace
            force = bx0 < x0 or bx1 > x1 or by0 < y0 or by1 > y1
        if not force:
            return
        if self._workspace is not None:
            (bx0, bx1), (by0, by1), _ = self._workspace
            lows.append(np.array([bx0, by0]))
            highs.append(np.array([bx1, by1]))
        low, high = np.min(lows, axis=0), np.max(highs, axis=0)
        log.debug("XY view fitted to x %s..%s, y %s..%s", low[0], high[0], low[1], high[1])
        xy.setRange(
            xRange=_fit(low[0], high[0], XY_FIT_MIN_MARGIN_MM),
            yRange=_fit(low[1], high[1], XY_FIT_MIN_MARGIN_MM),
            padding=0,
        )

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

    def reset_view(self) -> None:
        """Zoom both plots to fit their data, following new data again.

        The time axis shows the last 10, 30 or 60 s: a range that moved every frame made
        pyqtgraph rebuild the axis and grid pictures every frame (most of the GUI thread's time).
        """
        self._following = True
        self._time_window = 0.0
        for plot in (self.xy_plot, self.time_plot):
            plot.getPlotItem().disableAutoRange()
        rows = self._drawn()
        fit = (
            self._target is not None
            or self._workspace is not None
            or len(self._preview)
            or self._program is not None
        )
        if len(rows) or fit:
            self._follow_xy(rows, force=True)
        else:  # what a fit of the origin gives: a first point there is not on the margin
            around = _fit(0.0, 0.0, XY_FIT_MIN_MARGIN_MM)
            self.xy_plot.getPlotItem().setRange(xRange=around, yRange=around, padding=0)
        if len(rows):
            self._follow_time(rows, rows[:, 0] - rows[-1, 0], force=True)
        else:
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
