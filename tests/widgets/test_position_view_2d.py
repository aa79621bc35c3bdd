"""PositionView2D: refresh from the buffer, markers, clear, reset, timer."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt

from widgets._view_common import REFRESH_INTERVAL_MS
from widgets.position_buffer import PositionBuffer
from widgets.position_view_2d import PositionView2D


@pytest.fixture
def buffer() -> PositionBuffer:
    buffer = PositionBuffer(capacity=100)
    for i in range(10):
        buffer.append(100.0 + i, i, 2 * i, -i)
    return buffer


@pytest.fixture
def view(qtbot, buffer: PositionBuffer) -> PositionView2D:
    widget = PositionView2D(buffer)
    qtbot.addWidget(widget)
    return widget


def test_object_name(view: PositionView2D) -> None:
    assert view.objectName() == "positionView2d"
    assert not view.timer.isActive()  # not shown yet


def test_refresh_draws_trail_marker_and_curves(view: PositionView2D) -> None:
    view.refresh()
    x, y = view.trail.getData()
    assert x.tolist() == list(range(10))
    assert y.tolist() == [2 * i for i in range(10)]
    mx, my = view.current_marker.getData()
    assert (mx.tolist(), my.tolist()) == ([9.0], [18.0])
    t, z = view.curves["z"].getData()
    assert t[-1] == 0.0  # time relative to the latest sample
    assert t[0] == -9.0
    assert z[-1] == -9.0


def test_refresh_follows_new_data_and_skips_unchanged(view, buffer) -> None:
    view.refresh()
    buffer.append(200.0, 50.0, 60.0, 70.0)
    view.refresh()
    assert view.current_marker.getData()[0].tolist() == [50.0]
    view.trail.setData([], [])  # a refresh without new data must not redraw
    view.refresh()
    assert view.trail.getData()[0] is None or len(view.trail.getData()[0]) == 0


def test_target(view: PositionView2D) -> None:
    view.set_target(3.0, 4.0, 5.0)
    tx, ty = view.target_marker.getData()
    assert (tx.tolist(), ty.tolist()) == ([3.0], [4.0])
    assert view.target_lines["z"].isVisible()
    assert view.target_lines["z"].value() == 5.0
    view.set_target(1.0, 2.0, None)  # no Z on this device
    assert view.target() is not None
    assert np.isnan(view.target()[2])
    assert not view.target_lines["z"].isVisible()
    assert view.target_lines["x"].isVisible()
    view.set_target((7.0, 8.0, 9.0))  # one tuple, as the worker's target_changed carries
    assert view.target() == (7.0, 8.0, 9.0)
    assert view.target_marker.getData()[0].tolist() == [7.0]
    view.set_target([1, 2])
    assert view.target()[:2] == (1.0, 2.0)
    with pytest.raises(ValueError):
        view.set_target((1.0,))
    view.set_target(None)
    assert view.target() is None
    assert len(view.target_marker.getData()[0]) == 0


def test_clear_trail_keeps_the_current_position(view, buffer) -> None:
    view.refresh()
    view.clear_trail()
    assert len(buffer) == 1
    x, _ = view.trail.getData()
    assert x.tolist() == [9.0]
    assert view.current_marker.getData()[0].tolist() == [9.0]


def test_empty_buffer(qtbot) -> None:
    widget = PositionView2D(PositionBuffer(capacity=5))
    qtbot.addWidget(widget)
    widget.refresh()
    assert len(widget.current_marker.getData()[0]) == 0


def test_reset_view_fits_the_data_again_after_a_manual_zoom(view: PositionView2D) -> None:
    view.refresh()
    plot = view.xy_plot.getPlotItem()
    plot.getViewBox().sigRangeChangedManually.emit([True, True])  # as a mouse zoom does
    plot.setXRange(1000, 2000)
    assert not view._following
    view.reset_view()
    assert view._following
    (x0, x1), (y0, y1) = plot.viewRange()
    rows = view.buffer.view()
    assert x0 <= rows[:, 1].min() and rows[:, 1].max() <= x1
    assert y0 <= rows[:, 2].min() and rows[:, 2].max() <= y1


def test_ranges_move_only_when_the_data_leaves_them(view: PositionView2D) -> None:
    view.refresh()
    plot = view.xy_plot.getPlotItem()
    before = plot.viewRange()
    last = view.buffer.last()
    assert last is not None
    view.buffer.append(last[0] + 0.1, last[1] + 0.01, last[2], last[3])  # a tiny step inside
    view.refresh()
    assert plot.viewRange() == before
    view.buffer.append(last[0] + 0.2, last[1] + 500.0, last[2], last[3])  # far outside
    view.refresh()
    (x0, x1), _ = plot.viewRange()
    assert x0 <= last[1] + 500.0 <= x1


def test_timer_runs_only_while_shown(view: PositionView2D, qtbot) -> None:
    assert REFRESH_INTERVAL_MS <= 40  # about 30 Hz
    view.show()
    assert view.timer.isActive()
    view.hide()
    assert not view.timer.isActive()


def test_plots_stack_when_narrow(view: PositionView2D) -> None:
    view.show()
    view.resize(900, 300)
    assert view.splitter.orientation() == Qt.Orientation.Horizontal
    view.resize(400, 600)
    assert view.splitter.orientation() == Qt.Orientation.Vertical
