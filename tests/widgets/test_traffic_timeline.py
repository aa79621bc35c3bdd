"""TrafficTimeline: binning, drawing, throttled redraws, clicks to console lines, follow, size."""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import QApplication, QCheckBox

from widgets.traffic_timeline import (
    FOLLOW_WINDOW_S,
    RX_COLOUR,
    SYMBOL_LIMIT,
    TX_COLOUR,
    TrafficTimeline,
)

pytestmark = pytest.mark.timeout(60)
log = logging.getLogger(__name__)


@pytest.fixture
def timeline(qtbot) -> TrafficTimeline:
    widget = TrafficTimeline()
    qtbot.addWidget(widget)
    widget.resize(900, 600)
    return widget


def _show(timeline: TrafficTimeline, qtbot) -> None:
    timeline.show()
    qtbot.waitExposed(timeline)
    QApplication.processEvents()  # lay the plots out: clicks map through their geometry


def _viewport_pos(timeline: TrafficTimeline, plot, x: float, y: float) -> QPoint:
    """The viewport pixel of view coordinates (x, y) in one of the timeline's plots."""
    scene = plot.getViewBox().mapViewToScene(QPointF(x, y))
    return timeline.plots.mapFromScene(scene)


def _click(qtbot, timeline: TrafficTimeline, plot, x: float, y: float) -> None:
    """A real left click (press and release) on the plots' viewport at (x, y) of `plot`."""
    pos = _viewport_pos(timeline, plot, x, y)
    qtbot.mouseClick(timeline.plots.viewport(), Qt.MouseButton.LeftButton, pos=pos)


def _data(curve) -> tuple[list[float], list[float]]:
    """A curve's whole data (not the part clipped to the view and downsampled), as lists."""
    x, y = curve.getOriginalDataset()
    return ([] if x is None else x.tolist()), ([] if y is None else y.tolist())


@dataclass
class _FakeClick:
    """A stand-in for pyqtgraph's MouseClickEvent, for the scene handler."""

    pos: QPointF
    which: Qt.MouseButton = Qt.MouseButton.LeftButton
    is_double: bool = False

    def button(self) -> Qt.MouseButton:
        return self.which

    def double(self) -> bool:
        return self.is_double

    def scenePos(self) -> QPointF:
        return self.pos


def _scene_pos(plot, x: float, y: float) -> QPointF:
    return plot.getViewBox().mapViewToScene(QPointF(x, y))


# -- the widget -------------------------------------------------------------------------------
def test_names_labels_colours_and_tooltips(timeline: TrafficTimeline) -> None:
    assert timeline.objectName() == "trafficTimeline"
    follow = timeline.findChild(QCheckBox, "timelineFollow")
    assert follow is timeline.follow_box
    assert follow.isChecked() and timeline.is_following()
    assert follow.toolTip()
    assert timeline.curves["tx"].opts["pen"].color().name() == TX_COLOUR
    assert timeline.curves["rx"].opts["pen"].color().name() == RX_COLOUR
    assert [label.text for _, label in timeline.legend.items] == ["TX", "RX"]
    assert timeline.bytes_plot.getAxis("left").labelUnits == "B/s"
    assert timeline.latency_plot.getAxis("left").labelUnits == "ms"
    assert timeline.latency_plot.getAxis("bottom").labelUnits == "s"
    assert "TX" in timeline.bytes_plot.toolTip() and "RX" in timeline.bytes_plot.toolTip()
    assert "ms" in timeline.latency_plot.toolTip()
    assert not timeline.timer.isActive()  # not shown yet
    bytes_vb = timeline.bytes_plot.getViewBox()
    assert timeline.latency_plot.getViewBox().linkedView(0) is bytes_vb  # one time axis


def test_timer_runs_only_while_shown(timeline: TrafficTimeline, qtbot) -> None:
    _show(timeline, qtbot)
    assert timeline.timer.isActive()
    assert 100 <= timeline.timer.interval() <= 200  # 5-10 Hz
    timeline.hide()
    assert not timeline.timer.isActive()


def test_the_plots_line_up_in_time(timeline: TrafficTimeline, qtbot) -> None:
    timeline.add_bytes(3.0, "rx", 2_000_000, 0)  # wide tick labels on one plot only
    timeline.add_latency(3.0, 0.5, 1)
    _show(timeline, qtbot)
    timeline.refresh()
    QApplication.processEvents()
    top = timeline.bytes_plot.getViewBox().sceneBoundingRect()
    bottom = timeline.latency_plot.getViewBox().sceneBoundingRect()
    assert (top.left(), top.right()) == (bottom.left(), bottom.right())


def test_legend_is_clear_of_the_data(timeline: TrafficTimeline, qtbot) -> None:
    _show(timeline, qtbot)
    legend = timeline.legend.sceneBoundingRect()
    data = timeline.bytes_plot.getViewBox().sceneBoundingRect()
    assert legend.width() > 0 and legend.height() > 0
    assert legend.bottom() <= data.top()


# -- bytes per second -------------------------------------------------------------------------
def test_binning_sums_bytes_per_second_per_direction(timeline: TrafficTimeline) -> None:
    timeline.add_bytes(0.1, "tx", 5, 0)
    timeline.add_bytes(0.9, "tx", 7, 1)
    timeline.add_bytes(0.5, "rx", 20, 2)
    timeline.add_bytes(3.0, "rx", 4, 3)  # the start of second 3
    timeline.add_bytes(3.999, "rx", 6, 4)
    timeline.add_bytes(2.5, "tx", 0, 5)  # nothing crossed: ignored
    assert timeline.bytes_per_second("tx").tolist() == [12.0, 0.0, 0.0, 0.0]
    assert timeline.bytes_per_second("rx").tolist() == [20.0, 0.0, 0.0, 10.0]


def test_bad_bytes_are_refused_or_dropped(timeline: TrafficTimeline, caplog) -> None:
    with pytest.raises(ValueError):
        timeline.add_bytes(1.0, "up", 3, 0)
    with pytest.raises(ValueError):
        timeline.add_bytes(1.0, "tx", -3, 0)
    with caplog.at_level(logging.WARNING, logger="widgets.traffic_timeline"):
        timeline.add_bytes(-0.5, "tx", 3, 0)
        timeline.add_bytes(float("nan"), "tx", 3, 0)
        timeline.add_latency(float("nan"), 3.0, 0)
    assert len(timeline.bytes_per_second("tx")) == 0
    assert len(timeline.latency_points()[0]) == 0
    assert "dropped" in caplog.text


def test_refresh_draws_the_bins(timeline: TrafficTimeline) -> None:
    for second in range(5):
        timeline.add_bytes(second + 0.2, "tx", 10 * (second + 1), 2 * second)
        timeline.add_bytes(second + 0.7, "rx", 100, 2 * second + 1)
    timeline.refresh()
    x, y = _data(timeline.curves["tx"])
    assert x == [0.5, 1.5, 2.5, 3.5, 4.5]  # the middle of each second
    assert y == [10.0, 20.0, 30.0, 40.0, 50.0]
    x, y = _data(timeline.curves["rx"])
    assert x == [0.5, 1.5, 2.5, 3.5, 4.5]
    assert y == [100.0] * 5


def test_adding_does_not_redraw_until_the_timer(timeline: TrafficTimeline, qtbot) -> None:
    _show(timeline, qtbot)
    curve = timeline.curves["tx"]
    timeline.add_bytes(1.5, "tx", 42, 0)
    timeline.add_latency(1.6, 12.0, 1)
    assert _data(curve) == ([], [])  # no redraw per call
    qtbot.waitUntil(lambda: _data(curve)[1] == [0.0, 42.0])  # the timer's next tick
    assert _data(timeline.latency_curve) == ([1.6], [12.0])
    curve.setData([], [])  # a tick with nothing new must not redraw
    timeline._redraw_if_changed()
    assert _data(curve) == ([], [])
    timeline.add_bytes(1.7, "tx", 1, 2)  # the next tick with something new does
    timeline._redraw_if_changed()
    assert _data(curve)[1] == [0.0, 43.0]


def test_a_click_on_a_bin_emits_its_first_line(timeline: TrafficTimeline, qtbot, record) -> None:
    timeline.add_bytes(10.5, "tx", 300, 41)
    timeline.add_bytes(10.2, "tx", 100, 40)  # earlier in the second: the bin's first line
    timeline.add_bytes(10.9, "tx", 100, 44)
    timeline.add_bytes(10.6, "rx", 1500, 42)
    timeline.add_bytes(20.3, "rx", 800, 50)
    _show(timeline, qtbot)
    timeline.refresh()
    bp = timeline.bytes_plot
    with qtbot.waitSignal(timeline.line_clicked, timeout=2000) as blocker:
        _click(qtbot, timeline, bp, 10.5, 500.0)  # on the TX curve
    assert blocker.args == [40]
    with qtbot.waitSignal(timeline.line_clicked, timeout=2000) as blocker:
        _click(qtbot, timeline, bp, 10.5, 1500.0)  # on the RX curve, same second
    assert blocker.args == [42]
    with qtbot.waitSignal(timeline.line_clicked, timeout=2000) as blocker:
        _click(qtbot, timeline, bp, 20.6, 700.0)  # a little off the bin: within tolerance
    assert blocker.args == [50]
    calls = record(timeline.line_clicked)
    _click(qtbot, timeline, bp, 40.0, 500.0)  # far from every bin with traffic
    QApplication.processEvents()
    assert calls == []


def test_the_scene_handler_with_synthetic_clicks(timeline: TrafficTimeline, qtbot, record) -> None:
    timeline.add_bytes(5.2, "rx", 64, 7)
    timeline.add_latency(30.0, 8.0, 9)
    _show(timeline, qtbot)
    calls = record(timeline.line_clicked)
    timeline._on_scene_clicked(_FakeClick(_scene_pos(timeline.bytes_plot, 5.5, 64.0)))
    timeline._on_scene_clicked(_FakeClick(_scene_pos(timeline.latency_plot, 30.0, 8.0)))
    right = Qt.MouseButton.RightButton  # the context menu's button: no jump
    timeline._on_scene_clicked(_FakeClick(_scene_pos(timeline.bytes_plot, 5.5, 64.0), right))
    double = _FakeClick(_scene_pos(timeline.bytes_plot, 5.5, 64.0), is_double=True)
    timeline._on_scene_clicked(double)  # the first click of the two already jumped
    axis = timeline.latency_plot.getAxis("bottom").sceneBoundingRect().center()
    timeline._on_scene_clicked(_FakeClick(axis))  # on an axis, not in a plot
    assert calls == [(7,), (9,)]


# -- latency ----------------------------------------------------------------------------------
def test_latency_points_are_drawn_in_time_order(timeline: TrafficTimeline) -> None:
    timeline.add_latency(1.0, 5.0, 10)
    timeline.add_latency(3.0, 7.0, 12)
    timeline.add_latency(2.0, 6.0, 11)  # a reply logged late
    timeline.add_latency(2.0, 6.5, 13)  # same time: stays after the one added before it
    timeline.refresh()
    t, ms, lines = timeline.latency_points()
    assert t.tolist() == [1.0, 2.0, 2.0, 3.0]
    assert ms.tolist() == [5.0, 6.0, 6.5, 7.0]
    assert lines.tolist() == [10, 11, 13, 12]
    assert _data(timeline.latency_curve) == ([1.0, 2.0, 2.0, 3.0], [5.0, 6.0, 6.5, 7.0])
    assert timeline.latency_curve.opts["symbol"] == "o"  # few points: drawn as dots


def test_add_latencies_in_bulk(timeline: TrafficTimeline) -> None:
    timeline.add_latency(5.0, 1.0, 1)
    timeline.add_latencies(np.array([7.0, 4.0, np.nan]), np.array([2.0, 3.0, 4.0]), [2, 3, 4])
    t, ms, lines = timeline.latency_points()
    assert t.tolist() == [4.0, 5.0, 7.0]
    assert ms.tolist() == [3.0, 1.0, 2.0]
    assert lines.tolist() == [3, 1, 2]
    with pytest.raises(ValueError):
        timeline.add_latencies(np.zeros(2), np.zeros(3), np.zeros(2))


def test_a_click_on_a_latency_point_emits_its_line(
    timeline: TrafficTimeline, qtbot, record
) -> None:
    timeline.add_latency(20.0, 5.0, 100)
    timeline.add_latency(20.05, 40.0, 101)  # nearer in X to the first click, far in Y
    timeline.add_latency(45.0, 12.0, 102)
    _show(timeline, qtbot)
    timeline.refresh()
    lp = timeline.latency_plot
    with qtbot.waitSignal(timeline.line_clicked, timeout=2000) as blocker:
        _click(qtbot, timeline, lp, 20.05, 5.0)
    assert blocker.args == [100]  # nearest on screen, in X and Y
    with qtbot.waitSignal(timeline.line_clicked, timeout=2000) as blocker:
        _click(qtbot, timeline, lp, 20.0, 40.0)
    assert blocker.args == [101]
    with qtbot.waitSignal(timeline.line_clicked, timeout=2000) as blocker:
        _click(qtbot, timeline, lp, 45.0, 12.0)
    assert blocker.args == [102]
    calls = record(timeline.line_clicked)
    _click(qtbot, timeline, lp, 45.0, 35.0)  # above the point, beyond the tolerance
    _click(qtbot, timeline, lp, 32.0, 12.0)  # between points
    QApplication.processEvents()
    assert calls == []


# -- clear, follow ----------------------------------------------------------------------------
def test_clear_empties_everything(timeline: TrafficTimeline, qtbot, record) -> None:
    timeline.add_bytes(1.0, "tx", 10, 0)
    timeline.add_bytes(1.0, "rx", 10, 1)
    timeline.add_latency(1.0, 3.0, 1)
    _show(timeline, qtbot)
    timeline.clear()
    assert len(timeline.bytes_per_second("tx")) == 0
    assert len(timeline.bytes_per_second("rx")) == 0
    assert all(len(values) == 0 for values in timeline.latency_points())
    for curve in (*timeline.curves.values(), timeline.latency_curve):
        assert _data(curve) == ([], [])
    calls = record(timeline.line_clicked)
    _click(qtbot, timeline, timeline.bytes_plot, 1.5, 10.0)
    _click(qtbot, timeline, timeline.latency_plot, 1.0, 3.0)
    QApplication.processEvents()
    assert calls == []
    timeline.add_bytes(2.5, "tx", 8, 5)  # usable again after a clear
    timeline.refresh()
    assert _data(timeline.curves["tx"])[1] == [0.0, 0.0, 8.0]


def test_follow_the_latest_minute_until_the_user_zooms(timeline: TrafficTimeline, qtbot) -> None:
    _show(timeline, qtbot)
    vb = timeline.bytes_plot.getViewBox()
    assert vb.viewRange()[0] == [0.0, FOLLOW_WINDOW_S]
    timeline.add_bytes(199.3, "tx", 2500, 0)
    timeline.add_latency(199.4, 180.0, 1)
    timeline.refresh()
    assert vb.viewRange()[0] == [200.0 - FOLLOW_WINDOW_S, 200.0]
    assert vb.viewRange()[1][1] >= 2500
    assert timeline.latency_plot.viewRange()[1][1] >= 180.0
    assert timeline.latency_plot.viewRange()[0] == vb.viewRange()[0]  # shared X

    centre = timeline.plots.mapFromScene(vb.sceneBoundingRect().center())
    wheel = QWheelEvent(
        QPointF(centre),
        QPointF(timeline.plots.viewport().mapToGlobal(centre)),
        QPoint(0, 0),
        QPoint(0, 120),  # one notch: zoom in
        Qt.MouseButton.NoButton,
        Qt.KeyboardModifier.NoModifier,
        Qt.ScrollPhase.NoScrollPhase,
        False,
    )
    QApplication.sendEvent(timeline.plots.viewport(), wheel)
    assert not timeline.is_following()
    assert not timeline.follow_box.isChecked()
    zoomed = vb.viewRange()[0]
    assert zoomed[1] - zoomed[0] < FOLLOW_WINDOW_S
    timeline.add_bytes(400.0, "rx", 10, 2)
    timeline.refresh()
    assert vb.viewRange()[0] == zoomed  # stays where the user put it

    timeline.follow_box.click()  # the user ticks Follow again
    assert timeline.is_following()
    assert vb.viewRange()[0] == [401.0 - FOLLOW_WINDOW_S, 401.0]
    timeline.set_following(False)
    assert not timeline.follow_box.isChecked()


def test_a_manual_pan_signal_stops_following(timeline: TrafficTimeline) -> None:
    timeline.latency_plot.getViewBox().sigRangeChangedManually.emit([True, False])
    assert not timeline.is_following()
    assert not timeline.follow_box.isChecked()


def test_dots_only_while_few_points_are_in_view(timeline: TrafficTimeline) -> None:
    times = np.linspace(0.0, 59.0, SYMBOL_LIMIT + 1)
    timeline.add_latencies(times, np.ones_like(times), np.arange(len(times)))
    timeline.refresh()
    assert timeline.latency_curve.opts["symbol"] is None
    timeline.set_following(False)
    timeline.latency_plot.setXRange(0.0, 5.0, padding=0)  # zoomed in: dots again
    assert timeline.latency_curve.opts["symbol"] == "o"


# -- size -------------------------------------------------------------------------------------
def test_a_million_latency_points_and_an_hour_of_bins(
    timeline: TrafficTimeline, qtbot, record
) -> None:
    rng = np.random.default_rng(7)
    count = 1_000_000
    times = np.sort(rng.uniform(0.0, 3600.0, count)).tolist()
    values = rng.gamma(2.0, 4.0, count).tolist()
    _show(timeline, qtbot)
    add = timeline.add_latency
    start = time.perf_counter()
    for i in range(count):
        add(times[i], values[i], i)
    added = time.perf_counter() - start
    start = time.perf_counter()
    line = count
    for second in range(3600):
        timeline.add_bytes(second + 0.1, "tx", 20 + second % 5, line)
        timeline.add_bytes(second + 0.2, "rx", 200 + second % 11, line + 1)
        line += 2
    binned = time.perf_counter() - start
    start = time.perf_counter()
    timeline.refresh()
    refreshed = time.perf_counter() - start
    start = time.perf_counter()
    timeline.plots.grab()
    painted = time.perf_counter() - start
    timeline.set_following(False)
    timeline.bytes_plot.setXRange(0.0, 3600.0, padding=0)  # the whole hour
    start = time.perf_counter()
    timeline.plots.grab()
    painted_all = time.perf_counter() - start
    start = time.perf_counter()
    timeline.refresh()
    refreshed_all = time.perf_counter() - start
    log.info(
        "1M add_latency calls %.2f s, 7,200 add_bytes %.3f s, refresh %.1f ms,"
        " paint (60 s) %.1f ms, paint (3,600 s) %.1f ms, refresh (3,600 s) %.1f ms",
        added,
        binned,
        refreshed * 1e3,
        painted * 1e3,
        painted_all * 1e3,
        refreshed_all * 1e3,
    )

    assert len(timeline.latency_points()[0]) == count
    assert len(timeline.bytes_per_second("tx")) == 3600
    assert len(_data(timeline.latency_curve)[0]) == count
    displayed, _ = timeline.latency_curve.getData()  # what is drawn: the view, downsampled
    assert 0 < len(displayed) < 20_000
    timeline.set_following(True)
    assert timeline.bytes_plot.viewRange()[0] == [3600.0 - FOLLOW_WINDOW_S, 3600.0]
    t, ms, _ = timeline.latency_points()
    i = int(np.searchsorted(t, 3570.0))
    with qtbot.waitSignal(timeline.line_clicked, timeout=5000) as blocker:
        _click(qtbot, timeline, timeline.latency_plot, t[i], ms[i])
    nearest = blocker.args[0]
    assert abs(t[nearest] - t[i]) < 0.5  # a neighbour on screen at most
    with qtbot.waitSignal(timeline.line_clicked, timeout=5000) as blocker:
        _click(qtbot, timeline, timeline.bytes_plot, 3550.5, 20.0)
    assert blocker.args == [count + 2 * 3550]  # the TX bin of second 3550
