"""Traffic timeline: bytes per second each way and command latency against session time.

For firmware developers: two stacked plots sharing the time axis (seconds since the session
started). Top: bytes per second sent to the device (TX) and received (RX), in one-second bins.
Bottom: how long each request took to be answered, in ms. A click on a bin or a point emits
`line_clicked` with its line in the traffic console, so the console can jump there.

Adding data is cheap (numpy arrays grown by doubling, no redraw per call); a timer redraws a
few times a second while something changed and the widget is shown. pyqtgraph's clip-to-view
and peak downsampling keep a redraw fast with a million latency points.

The parts are in widgets.timeline: the data (stores), the plots (plots), following the latest
minute (following), clicks to console lines (clicks).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import QTimer, Signal
from PySide6.QtGui import QHideEvent, QShowEvent
from PySide6.QtWidgets import QCheckBox, QHBoxLayout, QVBoxLayout, QWidget

from widgets._i18n import fill
from widgets._pacer import run_paced
from widgets.timeline.clicks import CLICK_TOLERANCE_PX, ClicksMixin
from widgets.timeline.following import FOLLOW_WINDOW_S, SYMBOL_LIMIT, Y_HEADROOM, FollowingMixin
from widgets.timeline.plots import (
    GRID_COLOUR,
    LATENCY_COLOUR,
    LEFT_AXIS_WIDTH_PX,
    LEGEND,
    RX_COLOUR,
    TX_COLOUR,
    PlotsMixin,
)
from widgets.timeline.stores import DIRECTIONS, INITIAL_CAPACITY, MAX_BINS, ByteBins, Latencies

if TYPE_CHECKING:  # imported where the plots are built: pyqtgraph takes a third of a second
    import pyqtgraph as pg

__all__ = [  # what other modules take from here; the parts are in widgets.timeline
    "CLICK_TOLERANCE_PX",
    "DIRECTIONS",
    "FOLLOW_WINDOW_S",
    "GRID_COLOUR",
    "INITIAL_CAPACITY",
    "LATENCY_COLOUR",
    "LEFT_AXIS_WIDTH_PX",
    "LEGEND",
    "MAX_BINS",
    "REDRAW_INTERVAL_MS",
    "RX_COLOUR",
    "SYMBOL_LIMIT",
    "TX_COLOUR",
    "Y_HEADROOM",
    "TrafficTimeline",
]

REDRAW_INTERVAL_MS = 125  # 8 Hz, and only when something changed


class TrafficTimeline(PlotsMixin, FollowingMixin, ClicksMixin, QWidget):
    """Bytes/s each way and command latency against time; a click emits the console line.

    With `deferred`, the plots (pyqtgraph) are built when `build_plots()` is called: data is
    taken meanwhile, and drawn then. The window calls it just after its first paint, so that it
    shows before pyqtgraph is imported.

    The parts are in widgets.timeline: the plots (PlotsMixin), the ranges followed and the
    latency dots (FollowingMixin), the clicks (ClicksMixin), the data (ByteBins, Latencies).
    """

    line_clicked = Signal(int)

    def __init__(self, parent: QWidget | None = None, deferred: bool = False) -> None:
        super().__init__(parent)
        self.setObjectName("trafficTimeline")
        self._bins = ByteBins()
        self._latencies = Latencies()
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
        self._bins = ByteBins()  # new arrays: pyqtgraph may still hold views of the old ones
        self._latencies = Latencies()
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
