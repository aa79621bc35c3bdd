"""Following the latest minute in the traffic timeline, with ranges that move in coarse steps."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from PySide6.QtWidgets import QCheckBox

from widgets.timeline.stores import ByteBins, Latencies

if TYPE_CHECKING:  # imported where the plots are built: pyqtgraph takes a third of a second
    import pyqtgraph as pg

FOLLOW_WINDOW_S = 60.0  # while following, the X range shows the latest minute
SYMBOL_LIMIT = 1000  # latency points get a symbol each while at most this many are in view
Y_HEADROOM = 1.1  # the followed Y range leaves 10% above the highest value in view


def nice_ceiling(value: float) -> float:
    """The smallest of 1, 2, 5 × 10^k that is at least `value` (1 for nothing above 1)."""
    if not math.isfinite(value) or value <= 1.0:
        return 1.0
    scale = 10.0 ** math.floor(math.log10(value))
    return next(step * scale for step in (1.0, 2.0, 5.0, 10.0, 20.0) if step * scale >= value)


class FollowingMixin:
    """The ranges of TrafficTimeline's plots, following the latest minute until the user moves
    them, and the latency points' dots while few are in view."""

    plots: pg.GraphicsLayoutWidget | None
    bytes_plot: pg.PlotItem
    latency_plot: pg.PlotItem
    latency_curve: pg.PlotDataItem
    follow_box: QCheckBox
    _bins: ByteBins
    _latencies: Latencies
    _following: bool

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
        self._set_range(self.bytes_plot, None, (0.0, nice_ceiling(top * Y_HEADROOM)))
        start, end = points.between(left, math.inf)
        top = float(points.ms[start:end].max()) if end > start else 0.0
        self._set_range(self.latency_plot, None, (0.0, nice_ceiling(top * Y_HEADROOM)))

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
