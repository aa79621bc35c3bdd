"""A click on the traffic timeline: the console line of the bin or latency point under it."""

from __future__ import annotations

import logging
import math
from typing import TYPE_CHECKING, Protocol

import numpy as np
from PySide6.QtCore import QPointF, Qt, Signal

from widgets.timeline.stores import DIRECTIONS, ByteBins, Latencies

if TYPE_CHECKING:  # imported where the plots are built: pyqtgraph takes a third of a second
    import pyqtgraph as pg

log = logging.getLogger("widgets.traffic_timeline")  # the timeline's logger, as before the split

CLICK_TOLERANCE_PX = 8.0  # a click this close to a bin or point picks it


class SceneClick(Protocol):
    """What the click handler needs of pyqtgraph's MouseClickEvent."""

    def button(self) -> Qt.MouseButton: ...

    def double(self) -> bool: ...

    def scenePos(self) -> QPointF: ...


class ClicksMixin:
    """The clicks of TrafficTimeline: a left click on a plot emits `line_clicked`."""

    line_clicked: Signal
    plots: pg.GraphicsLayoutWidget | None
    bytes_plot: pg.PlotItem
    latency_plot: pg.PlotItem
    _bins: ByteBins
    _latencies: Latencies

    def _on_scene_clicked(self, event: SceneClick) -> None:
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
