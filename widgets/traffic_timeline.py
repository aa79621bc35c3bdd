"""Traffic timeline: bytes per second each way and command latency against session time.

For firmware developers: two stacked plots sharing the time axis (seconds since the session
started). Top: bytes per second sent to the device (TX) and received (RX), in one-second bins.
Bottom: how long each request took to be answered, in ms. A click on a bin or a point emits
`line_clicked` with its line in the traffic console, so the console can jump there.

Adding data is cheap (numpy arrays grown by doubling, no redraw per call); a timer redraws a
few times a second while something changed and the widget is shown. pyqtgraph's clip-to-view
and peak downsampling keep a redraw fast with a million latency points.
"""

from __future__ import annotations

import logging
import math
from typing import TYPE_CHECKING, Protocol

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QPointF, Qt, QTimer, Signal
from PySide6.QtGui import QHideEvent, QShowEvent
from PySide6.QtWidgets import QCheckBox, QHBoxLayout, QVBoxLayout, QWidget

from widgets._i18n import fill
from widgets._pacer import run_paced

if TYPE_CHECKING:  # imported where the plots are built: pyqtgraph takes a third of a second
    import pyqtgraph as pg

log = logging.getLogger(__name__)

TX_COLOUR = "#1565c0"  # as the traffic console draws sent bytes
RX_COLOUR = "#2e7d32"  # as the traffic console draws received bytes
LATENCY_COLOUR = "#ef6c00"
GRID_COLOUR = (60, 60, 60)
DIRECTIONS = ("tx", "rx")
LEGEND = {  # the directions' names in the legend, translated at use (TrafficTimeline)
    "tx": QT_TRANSLATE_NOOP("TrafficTimeline", "TX"),
    "rx": QT_TRANSLATE_NOOP("TrafficTimeline", "RX"),
}
_DIRECTION_INDEX = {direction: index for index, direction in enumerate(DIRECTIONS)}
REDRAW_INTERVAL_MS = 125  # 8 Hz, and only when something changed
FOLLOW_WINDOW_S = 60.0  # while following, the X range shows the latest minute
CLICK_TOLERANCE_PX = 8.0  # a click this close to a bin or point picks it
SYMBOL_LIMIT = 1000  # latency points get a symbol each while at most this many are in view
INITIAL_CAPACITY = 1024
MAX_BINS = 7 * 24 * 3600  # a week of one-second bins (10 MB); later times are dropped
Y_HEADROOM = 1.1  # the followed Y range leaves 10% above the highest value in view
LEFT_AXIS_WIDTH_PX = 64  # one width for both plots, so one time lines up above the other


class _SceneClick(Protocol):
    """What the click handler needs of pyqtgraph's MouseClickEvent."""

    def button(self) -> Qt.MouseButton: ...

    def double(self) -> bool: ...

    def scenePos(self) -> QPointF: ...


def _nice_ceiling(value: float) -> float:
    """The smallest of 1, 2, 5 × 10^k that is at least `value` (1 for nothing above 1)."""
    if not math.isfinite(value) or value <= 1.0:
        return 1.0
    scale = 10.0 ** math.floor(math.log10(value))
    return next(step * scale for step in (1.0, 2.0, 5.0, 10.0, 20.0) if step * scale >= value)


def _grid() -> pg.GridItem:
    """A background grid that, unlike showGrid, does not repaint the axes on every frame (and
    draws its picture, made again at every step of the followed range, in about 1 ms)."""
    from widgets._fast_grid import FastGrid

    return FastGrid(GRID_COLOUR)


def _dropped(store: _ByteBins | _Latencies, what: str) -> None:
    """Log a rejected sample: a warning for a store's first, debug messages after it."""
    store.dropped += 1
    level = logging.WARNING if store.dropped == 1 else logging.DEBUG
    log.log(level, "traffic timeline: dropped %s (further drops are logged at debug)", what)


# The stores are plain classes, not QObjects: an attribute of a PySide widget costs 4-15 times
# as much to read or write, and `add_*` may be called for every record of a busy link.
class _ByteBins:
    """Bytes per one-second bin each way, and each bin's first console line."""

    __slots__ = ("bytes", "count", "dropped", "first_line", "latest", "version")

    def __init__(self) -> None:
        self.bytes = np.zeros((2, INITIAL_CAPACITY))  # [direction, second]
        self.first_line = np.full((2, INITIAL_CAPACITY), -1, dtype=np.int64)
        self.count = 0  # bins in use: seconds 0 .. the latest
        self.latest = 0.0  # the latest time added, s
        self.version = 0
        self.dropped = 0

    def add(self, time_s: float, direction: str, count: int, line: int) -> None:
        """Add `count` bytes to the bin of `time_s`; see TrafficTimeline.add_bytes."""
        d = _DIRECTION_INDEX.get(direction)
        if d is None:
            raise ValueError(f"direction must be 'tx' or 'rx', not {direction!r}")
        if count <= 0:
            if count < 0:
                raise ValueError(f"a byte count cannot be negative: {count}")
            return  # nothing crossed: no rate, no line to jump to
        if not 0.0 <= time_s < MAX_BINS:  # also false for NaN
            _dropped(self, f"{count} {direction} bytes at {time_s!r} s")
            return
        second = int(time_s)
        if second >= self.bytes.shape[1]:
            self._grow(second + 1)
        self.bytes[d, second] += count
        first = self.first_line[d, second]
        if first < 0 or line < first:
            self.first_line[d, second] = line
        if second >= self.count:
            self.count = second + 1
        if time_s > self.latest:
            self.latest = time_s
        self.version += 1

    def _grow(self, needed: int) -> None:
        """Make room for `needed` bins, at least doubling."""
        capacity = min(max(needed, 2 * self.bytes.shape[1]), MAX_BINS)
        grown = np.zeros((2, capacity))
        grown[:, : self.count] = self.bytes[:, : self.count]
        lines = np.full((2, capacity), -1, dtype=np.int64)
        lines[:, : self.count] = self.first_line[:, : self.count]
        self.bytes, self.first_line = grown, lines


class _Latencies:
    """Latency points (time s, ms, console line), kept in time order for drawing and lookup."""

    __slots__ = ("dropped", "lines", "max_t", "ms", "n", "t", "unsorted_from", "version")

    def __init__(self) -> None:
        self.t = np.empty(INITIAL_CAPACITY)
        self.ms = np.empty(INITIAL_CAPACITY)
        self.lines = np.empty(INITIAL_CAPACITY, dtype=np.int64)
        self.n = 0
        self.max_t = -math.inf
        self.unsorted_from: int | None = None  # the first index appended out of time order
        self.version = 0
        self.dropped = 0

    def add(self, time_s: float, ms: float, line: int) -> None:
        """Append one point; see TrafficTimeline.add_latency."""
        if not (math.isfinite(time_s) and math.isfinite(ms)):
            _dropped(self, f"latency {ms!r} ms at {time_s!r} s")
            return
        n = self.n
        if n == len(self.t):
            self._grow(n + 1)
        self.t[n] = time_s
        self.ms[n] = ms
        self.lines[n] = line
        if time_s >= self.max_t:
            self.max_t = time_s
        elif self.unsorted_from is None:
            self.unsorted_from = n
        self.n = n + 1
        self.version += 1

    def add_many(self, times_s: np.ndarray, ms: np.ndarray, lines: np.ndarray) -> None:
        """Append many points; see TrafficTimeline.add_latencies."""
        t = np.asarray(times_s, dtype=float)
        values = np.asarray(ms, dtype=float)
        numbers = np.asarray(lines, dtype=np.int64)
        if not t.shape == values.shape == numbers.shape or t.ndim != 1:
            raise ValueError("times, latencies and lines must be 1-D arrays of one length")
        keep = np.isfinite(t) & np.isfinite(values)
        if not keep.all():
            _dropped(self, f"{int((~keep).sum())} latencies without a finite time or value")
            t, values, numbers = t[keep], values[keep], numbers[keep]
        if not len(t):
            return
        n, end = self.n, self.n + len(t)
        if end > len(self.t):
            self._grow(end)
        self.t[n:end] = t
        self.ms[n:end] = values
        self.lines[n:end] = numbers
        in_order = t[0] >= self.max_t and bool(np.all(t[1:] >= t[:-1]))
        if not in_order and self.unsorted_from is None:
            self.unsorted_from = n
        self.max_t = max(self.max_t, float(t.max()))
        self.n = end
        self.version += 1

    def _grow(self, needed: int) -> None:
        """Make room for `needed` points, at least doubling."""
        capacity = max(needed, 2 * len(self.t))
        n = self.n
        for name in ("t", "ms", "lines"):
            old = getattr(self, name)
            new = np.empty(capacity, dtype=old.dtype)
            new[:n] = old[:n]
            setattr(self, name, new)

    def sort(self) -> None:
        """Put late-arriving points in time order; only the tail from the earliest one moves."""
        start = self.unsorted_from
        if start is None:
            return
        n = self.n
        earliest = self.t[start:n].min()
        begin = int(np.searchsorted(self.t[:start], earliest, side="right"))
        order = np.argsort(self.t[begin:n], kind="stable")
        for values in (self.t, self.ms, self.lines):
            values[begin:n] = values[begin:n][order]
        self.unsorted_from = None
        self.version += 1  # the drawn arrays were rearranged in place: redraw

    def between(self, low: float, high: float) -> tuple[int, int]:
        """The index range [start, end) of the points with low <= time <= high."""
        self.sort()
        times = self.t[: self.n]
        start = int(np.searchsorted(times, low, side="left"))
        end = int(np.searchsorted(times, high, side="right"))
        return start, max(start, end)


class TrafficTimeline(QWidget):
    """Bytes/s each way and command latency against time; a click emits the console line.

    With `deferred`, the plots (pyqtgraph) are built when `build_plots()` is called: data is
    taken meanwhile, and drawn then. The window calls it just after its first paint, so that it
    shows before pyqtgraph is imported.
    """

    line_clicked = Signal(int)

    def __init__(self, parent: QWidget | None = None, deferred: bool = False) -> None:
        super().__init__(parent)
        self.setObjectName("trafficTimeline")
        self._bins = _ByteBins()
        self._latencies = _Latencies()
        self._drawn: tuple[int, int, int, int] | None = None  # the stores' (id, version) drawn
        self._following = True

        self.follow_box = QCheckBox(self.tr("Follow"))
        self.follow_box.setObjectName("timelineFollow")
        self.follow_box.setToolTip(
            fill(
                self.tr("Keep the latest %1 s in view; zooming or panning stops it"),
                f"{FOLLOW_WINDOW_S:.0f}",
            )
        )
        self.follow_box.setChecked(True)
        self.follow_box.toggled.connect(self.set_following)
        controls = QHBoxLayout()
        controls.addStretch(1)
        controls.addWidget(self.follow_box)
        self._layout = QVBoxLayout(self)
        self._layout.setContentsMargins(0, 0, 0, 0)
        self._layout.addLayout(controls)

        self.timer = QTimer(self)
        self.timer.setInterval(REDRAW_INTERVAL_MS)
        self.timer.timeout.connect(self._paced_redraw)
        self._retry = QTimer(self)  # the redraw's turn, when the pacer refused it one
        self._retry.setSingleShot(True)
        self._retry.timeout.connect(self._paced_redraw)
        self.plots: pg.GraphicsLayoutWidget | None = None
        if not deferred:
            self.build_plots()

    def build_plots(self) -> None:
        """Build the plots (once) and draw what has come so far."""
        if self.plots is not None:
            return
        import pyqtgraph as pg

        self.plots = pg.GraphicsLayoutWidget()
        self.plots.setObjectName("trafficTimelinePlots")
        self.bytes_plot: pg.PlotItem = self.plots.addPlot(row=1, col=0)
        self.latency_plot: pg.PlotItem = self.plots.addPlot(row=2, col=0)

        bp = self.bytes_plot
        bp.setToolTip(
            self.tr(
                "Bytes per second each way, in one-second bins: TX (blue) sent to the device,"
                " RX (green) received. Click a bin to show its first line in the console."
            )
        )
        bp.setLabel("left", self.tr("rate"), units="B/s")  # SI prefixes welcome: kB/s, MB/s
        bp.addItem(_grid(), ignoreBounds=True)
        bp.setClipToView(True)
        bp.setDownsampling(auto=True, mode="peak")
        self.curves = {
            "tx": bp.plot(pen=pg.mkPen(TX_COLOUR, width=1.5), name="TX"),
            "rx": bp.plot(pen=pg.mkPen(RX_COLOUR, width=1.5), name="RX"),
        }
        self.legend = self._header_row(self.tr("Bytes per second"))

        lp = self.latency_plot
        lp.setTitle(self.tr("Command latency"))
        lp.setToolTip(
            self.tr(
                "Time from a request to its reply, in ms: one point per answered request"
                " (drawn as dots when few are in view). Click a point to show its line in the"
                " console."
            )
        )
        lp.setLabel("left", self.tr("latency"), units="ms")
        lp.setLabel("bottom", self.tr("time since the session started"), units="s")
        lp.addItem(_grid(), ignoreBounds=True)
        lp.setClipToView(True)
        lp.setDownsampling(auto=True, mode="peak")
        self.latency_curve = lp.plot(
            pen=pg.mkPen(LATENCY_COLOUR, width=1),
            symbol=None,  # see _update_symbols
            symbolSize=5,
            symbolPen=None,
            symbolBrush=pg.mkBrush(LATENCY_COLOUR),
            name="latency",
        )
        lp.setXLink(bp)
        bp.hideAxis("bottom")  # the shared time axis is drawn once, below the latency plot
        lp.getAxis("left").enableAutoSIPrefix(False)  # "ms" must not become "kms"
        lp.getAxis("bottom").enableAutoSIPrefix(False)  # seconds, not "ks"
        for plot in (bp, lp):
            plot.getAxis("left").setWidth(LEFT_AXIS_WIDTH_PX)
            plot.hideButtons()  # Follow replaces the auto-range button
            plot.getViewBox().disableAutoRange()  # follow sets the ranges; clip-to-view needs it
            plot.getViewBox().sigRangeChangedManually.connect(self._user_moved_view)
        lp.getViewBox().sigXRangeChanged.connect(self._update_symbols)
        self.plots.scene().sigMouseClicked.connect(self._on_scene_clicked)
        self._layout.insertWidget(0, self.plots, 1)
        self.refresh()

    def _header_row(self, title: str) -> pg.LegendItem:
        """A row above the bytes plot with its title and a one-row legend, clear of the data.

        The row is an item of the layout widget: moving the plot's own title label into a
        header (as PositionView2D does) crashed the interpreter on exit in a layout widget.
        """
        import pyqtgraph as pg

        legend = pg.LegendItem(colCount=len(DIRECTIONS), horSpacing=4)
        legend.layout.setContentsMargins(4, 2, 4, 2)
        for direction in DIRECTIONS:
            legend.addItem(self.curves[direction], self.tr(LEGEND[direction]))
        header = pg.GraphicsLayout()
        header.setContentsMargins(0, 0, 0, 0)
        self.bytes_title = pg.LabelItem(title, size="11pt")  # as PlotItem.setTitle draws it
        header.addItem(self.bytes_title, row=0, col=0)
        header.addItem(legend, row=0, col=1)
        header.layout.setColumnStretchFactor(0, 1)
        header.setMaximumHeight(30)
        self.plots.addItem(header, row=0, col=0)
        return legend

    # -- data --------------------------------------------------------------------------------
    def add_bytes(self, time_s: float, direction: str, count: int, line: int) -> None:
        """Count `count` bytes sent ("tx") or received ("rx") at `time_s`, from console `line`.

        Bytes are summed per second since the session start; a bin keeps its first (lowest)
        line. Times outside [0 s, a week) are dropped and logged.
        """
        self._bins.add(time_s, direction, count, line)

    def add_latency(self, time_s: float, ms: float, line: int) -> None:
        """A request answered `ms` milliseconds after it was sent; `line` is its console line.

        Points may come slightly out of time order; a point without a finite time or value is
        dropped and logged.
        """
        self._latencies.add(time_s, ms, line)

    def add_latencies(self, times_s: np.ndarray, ms: np.ndarray, lines: np.ndarray) -> None:
        """Many `add_latency` calls at once (e.g. from a log): equal-length 1-D arrays."""
        self._latencies.add_many(times_s, ms, lines)

    def bytes_per_second(self, direction: str) -> np.ndarray:
        """A copy of one direction's bins: bytes in second 0, 1, 2, … up to the latest."""
        bins = self._bins
        return bins.bytes[DIRECTIONS.index(direction), : bins.count].copy()

    def latency_points(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Copies of the latency points in time order: (time s, latency ms, console line)."""
        points = self._latencies
        points.sort()
        n = points.n
        return points.t[:n].copy(), points.ms[:n].copy(), points.lines[:n].copy()

    def clear(self) -> None:
        """Forget all bins and points, and redraw empty."""
        self._bins = _ByteBins()  # new arrays: pyqtgraph may still hold views of the old ones
        self._latencies = _Latencies()
        self.refresh()

    # -- drawing -----------------------------------------------------------------------------
    def _versions(self) -> tuple[int, int, int, int]:
        """What identifies the data drawn: the stores and their versions."""
        bins, points = self._bins, self._latencies
        return id(bins), bins.version, id(points), points.version

    def refresh(self) -> None:
        """Redraw now (the timer calls this only when something changed); nothing to draw on
        before the plots are built."""
        if self.plots is None:
            return
        bins, points = self._bins, self._latencies
        points.sort()
        self._drawn = self._versions()
        if self._following:
            self._follow()  # ranges and symbols first: dots on 10,000 points would cost 50 ms
        self._update_symbols()
        count = bins.count
        centres = np.arange(count) + 0.5  # a bin's bytes are drawn at the middle of its second
        for d, direction in enumerate(DIRECTIONS):
            self.curves[direction].setData(centres, bins.bytes[d, :count].copy())
        # Views, not copies: points are only written past `n`, or sorted just before a redraw.
        self.latency_curve.setData(points.t[: points.n], points.ms[: points.n])

    def _redraw_if_changed(self) -> None:
        """The timer's tick: redraw only when data came in since the last redraw."""
        if self._versions() != self._drawn:
            self.refresh()

    def _paced_redraw(self) -> None:
        """`_redraw_if_changed`, not in the same turn of the event loop as other heavy work."""
        if self._versions() != self._drawn and run_paced(self._retry):
            self.refresh()

    def _update_symbols(self) -> None:
        """Dots on the latency points while few are in view; many dots cost 5 ms a thousand."""
        (x0, x1), _ = self.latency_plot.viewRange()
        start, end = self._latencies.between(x0, x1)
        symbol = "o" if end - start <= SYMBOL_LIMIT else None
        if self.latency_curve.opts["symbol"] != symbol:
            self.latency_curve.setSymbol(symbol)

    def _follow(self) -> None:
        """Show the latest minute, and fit Y to what is in it; ranges move in coarse steps.

        The right edge moves in whole seconds and the Y tops are 1, 2, 5 × 10^k: a range that
        changes every frame makes pyqtgraph rebuild the axes' pictures every frame.
        """
        bins, points = self._bins, self._latencies
        latest = max(bins.latest, points.max_t)
        right = max(FOLLOW_WINDOW_S, math.floor(latest) + 1.0)  # the end of the latest bin
        left = right - FOLLOW_WINDOW_S
        self._set_range(self.bytes_plot, (left, right), None)
        in_view = bins.bytes[:, max(0, int(left)) : bins.count]
        top = float(in_view.max()) if in_view.size else 0.0
        self._set_range(self.bytes_plot, None, (0.0, _nice_ceiling(top * Y_HEADROOM)))
        start, end = points.between(left, math.inf)
        top = float(points.ms[start:end].max()) if end > start else 0.0
        self._set_range(self.latency_plot, None, (0.0, _nice_ceiling(top * Y_HEADROOM)))

    @staticmethod
    def _set_range(
        plot: pg.PlotItem, x: tuple[float, float] | None, y: tuple[float, float] | None
    ) -> None:
        """Set a plot's X or Y range unless it is that already."""
        (x0, x1), (y0, y1) = plot.viewRange()
        if x is not None and (x0, x1) != x:
            plot.setXRange(*x, padding=0)
        if y is not None and (y0, y1) != y:
            plot.setYRange(*y, padding=0)

    def set_following(self, following: bool) -> None:
        """Keep the latest minute in view (True), or leave the ranges where they are."""
        self._following = bool(following)
        if self.follow_box.isChecked() != self._following:
            self.follow_box.setChecked(self._following)  # calls back here with the same value
        if self._following and self.plots is not None:
            self._follow()

    def is_following(self) -> bool:
        """Whether the view follows the latest minute."""
        return self._following

    def _user_moved_view(self) -> None:
        """The user zoomed or panned: leave the ranges alone until Follow is ticked again."""
        self.set_following(False)

    # -- clicks ------------------------------------------------------------------------------
    def _on_scene_clicked(self, event: _SceneClick) -> None:
        """A left click on a plot emits the console line of the bin or point nearest to it."""
        if event.button() != Qt.MouseButton.LeftButton or event.double():
            return
        line = self.line_at(event.scenePos())
        if line is not None:
            log.debug("traffic timeline: click → console line %d", line)
            self.line_clicked.emit(line)

    def line_at(self, scene_pos: QPointF) -> int | None:
        """The console line of the bin or point nearest to a scene position, or None."""
        if self.plots is None:
            return None
        for plot, find in (
            (self.bytes_plot, self._bin_line_near),
            (self.latency_plot, self._latency_line_near),
        ):
            vb = plot.getViewBox()
            if vb.sceneBoundingRect().contains(scene_pos):
                pixel = vb.viewPixelSize()
                if not all(math.isfinite(p) and p > 0 for p in pixel):
                    return None  # not laid out yet
                return find(vb.mapSceneToView(scene_pos), pixel)
        return None

    def _bin_line_near(self, point: QPointF, pixel: tuple[float, float]) -> int | None:
        """The first line of the bin nearest in X (either direction; nearer in Y breaks ties)."""
        bins = self._bins
        x, y = point.x(), point.y()
        tolerance = CLICK_TOLERANCE_PX * pixel[0]
        low = max(0, math.ceil(x - tolerance - 1.0))
        high = min(bins.count, math.floor(x + tolerance) + 1)
        if high <= low:
            return None
        seconds = np.arange(low, high)
        # Distance in X to the second a bin covers: zero anywhere inside it.
        dx = np.maximum(np.maximum(seconds - x, x - (seconds + 1.0)), 0.0)
        best: tuple[float, float, int] | None = None
        for d in range(len(DIRECTIONS)):
            lines = bins.first_line[d, low:high]
            used = lines >= 0
            if not used.any():
                continue
            dy = np.abs(bins.bytes[d, low:high] - y) / pixel[1]
            i = np.lexsort((dy[used], dx[used]))[0]  # nearest in X, then nearest in Y
            candidate = (float(dx[used][i]), float(dy[used][i]), int(lines[used][i]))
            if best is None or candidate < best:
                best = candidate
        return None if best is None else best[2]

    def _latency_line_near(self, point: QPointF, pixel: tuple[float, float]) -> int | None:
        """The line of the latency point nearest on screen, within the click tolerance."""
        points = self._latencies
        x, y = point.x(), point.y()
        tolerance = CLICK_TOLERANCE_PX * pixel[0]
        start, end = points.between(x - tolerance, x + tolerance)
        if end <= start:
            return None
        dx = (points.t[start:end] - x) / pixel[0]
        dy = (points.ms[start:end] - y) / pixel[1]
        distance = dx * dx + dy * dy
        i = int(np.argmin(distance))
        if distance[i] > CLICK_TOLERANCE_PX**2:
            return None
        return int(points.lines[start + i])

    # -- visibility --------------------------------------------------------------------------
    def showEvent(self, event: QShowEvent) -> None:
        """Redraw, then keep redrawing changes while visible (deferred plots: once built)."""
        super().showEvent(event)
        self.refresh()
        self.timer.start()

    def hideEvent(self, event: QHideEvent) -> None:
        """No redrawing while hidden."""
        self.timer.stop()
        self._retry.stop()
        super().hideEvent(event)
