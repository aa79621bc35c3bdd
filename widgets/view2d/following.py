"""Following the data in the 2D view: ranges widened only when the data leaves them."""

from __future__ import annotations

import logging

import numpy as np
import pyqtgraph as pg

from widgets._axes import Box
from widgets._program_path import ProgramPath

log = logging.getLogger("widgets.position_view_2d")  # the view's logger, as before the split

TIME_WINDOWS_S = (10.0, 30.0, 60.0)  # the time plot's span grows in these steps
FOLLOW_PADDING = 0.25  # room added on each side when a view is widened
MIN_MARGIN_MM = 1.0
XY_MARGIN = 0.08  # the XY view widens when a point comes closer to its edge than this share
XY_FIT_MIN_MARGIN_MM = 2.0  # twice MIN_MARGIN_MM: a fresh fit never sits on the threshold


def padded(values: np.ndarray) -> tuple[float, float]:
    """The span of `values` with a quarter of it (at least 1 mm) added on each side."""
    return fit_range(float(values.min()), float(values.max()), MIN_MARGIN_MM)


def fit_range(low: float, high: float, min_margin: float) -> tuple[float, float]:
    """[low, high] with a quarter of its span (at least `min_margin`) added on each side."""
    margin = max((high - low) * FOLLOW_PADDING, min_margin)
    return low - margin, high + margin


class FollowingMixin:
    """The ranges of PositionView2D's plots: followed until the user zooms or pans, and reset."""

    xy_plot: pg.PlotWidget
    time_plot: pg.PlotWidget
    _following: bool
    _time_window: float
    _target: tuple[float, float, float] | None
    _workspace: Box | None
    _preview: np.ndarray
    _preview_bounds: tuple[np.ndarray, np.ndarray]
    _program: ProgramPath | None

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
            tp.setYRange(*padded(recent), padding=0)

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
            xRange=fit_range(low[0], high[0], XY_FIT_MIN_MARGIN_MM),
            yRange=fit_range(low[1], high[1], XY_FIT_MIN_MARGIN_MM),
            padding=0,
        )

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
            around = fit_range(0.0, 0.0, XY_FIT_MIN_MARGIN_MM)
            self.xy_plot.getPlotItem().setRange(xRange=around, yRange=around, padding=0)
        if len(rows):
            self._follow_time(rows, rows[:, 0] - rows[-1, 0], force=True)
        else:
            self.time_plot.getPlotItem().setRange(xRange=(-TIME_WINDOWS_S[0], 0), yRange=(-1, 1))

    def _stop_following(self) -> None:
        """The user zoomed or panned: leave the ranges alone until Reset view."""
        self._following = False
