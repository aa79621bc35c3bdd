"""PositionView2D: refresh from the buffer, markers, margins, legend, workspace, clear, reset."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QApplication

from widgets._view_common import REFRESH_INTERVAL_MS
from widgets.position_buffer import PositionBuffer
from widgets.position_view_2d import CURRENT_COLOUR, PositionView2D


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


def _assert_clear_of_the_edges(view: PositionView2D, xs: list[float], ys: list[float]) -> None:
    """Every point keeps 8% of the span (at least 1 mm) from each edge of the XY view."""
    (x0, x1), (y0, y1) = view.xy_plot.getPlotItem().viewRange()
    mx, my = max(0.08 * (x1 - x0), 1.0), max(0.08 * (y1 - y0), 1.0)
    tol = 1e-9
    assert min(xs) - x0 >= mx - tol and x1 - max(xs) >= mx - tol, ((x0, x1), xs)
    assert min(ys) - y0 >= my - tol and y1 - max(ys) >= my - tol, ((y0, y1), ys)


def test_a_point_near_the_edge_widens_the_view(view: PositionView2D) -> None:
    view.refresh()
    plot = view.xy_plot.getPlotItem()
    (x0, x1), _ = plot.viewRange()
    last = view.buffer.last()
    assert last is not None
    edge_x = x1 - 0.01 * (x1 - x0)  # inside the range, but the marker would be half outside
    view.buffer.append(last[0] + 0.1, edge_x, last[2], last[3])
    view.refresh()
    rows = view.buffer.view()
    _assert_clear_of_the_edges(view, rows[:, 1].tolist(), rows[:, 2].tolist())


def test_a_new_target_outside_the_view_widens_it_at_once(view: PositionView2D) -> None:
    view.refresh()
    plot = view.xy_plot.getPlotItem()
    before = plot.viewRange()
    view.set_target(3.0, 4.0, 0.0)  # well inside: no range change
    assert plot.viewRange() == before
    view.set_target(-80.0, 250.0, 1.0)  # no refresh: set_target itself widens the view
    rows = view.buffer.view()
    _assert_clear_of_the_edges(view, [*rows[:, 1], -80.0], [*rows[:, 2], 250.0])
    after = plot.viewRange()
    view.refresh()  # unchanged buffer, target inside: nothing moves
    assert plot.viewRange() == after


def test_a_target_does_not_move_a_view_the_user_zoomed(view: PositionView2D) -> None:
    view.refresh()
    plot = view.xy_plot.getPlotItem()
    plot.getViewBox().sigRangeChangedManually.emit([True, True])
    plot.setRange(xRange=(0, 10), yRange=(0, 10), padding=0)
    before = plot.viewRange()
    view.set_target(500.0, 500.0)
    assert plot.viewRange() == before
    view.reset_view()
    rows = view.buffer.view()
    _assert_clear_of_the_edges(view, [*rows[:, 1], 500.0], [*rows[:, 2], 500.0])


def test_markers_are_drawn_wholly_inside_the_view(qtbot) -> None:
    buffer = PositionBuffer(capacity=10)
    buffer.append(0.0, 0.0, 0.0, 0.0)
    buffer.append(1.0, 40.0, 0.0, 0.0)  # the current position at the right of the trail
    widget = PositionView2D(buffer)
    qtbot.addWidget(widget)
    widget.set_target(40.0, -30.0, 0.0)  # at the bottom-right corner of the data
    widget.resize(900, 500)
    widget.show()
    qtbot.waitExposed(widget)
    widget.refresh()
    plot = widget.xy_plot.getPlotItem()
    plot.setRange(xRange=(0.0, 40.0), yRange=(-30.0, 0.0), padding=0)  # points on the edges
    buffer.append(2.0, 40.0, 0.0, 0.0)  # standing still: the next frame must make room
    widget.refresh()
    vb = plot.getViewBox()
    area = vb.sceneBoundingRect()
    for marker in (widget.current_marker, widget.target_marker):
        (x,), (y,) = marker.getData()
        centre = vb.mapViewToScene(QPointF(x, y))
        half = marker.opts["size"] / 2 + 1  # + the pen
        box = QRectF(centre.x() - half, centre.y() - half, 2 * half, 2 * half)
        assert area.contains(box), (marker, box, area)


def test_legend_is_clear_of_the_data_area(view: PositionView2D, qtbot) -> None:
    tp = view.time_plot.getPlotItem()
    assert [label.text for _, label in view.legend.items] == ["X", "Y", "Z"]
    for size in ((900, 500), (400, 700), (1400, 300)):  # side by side, stacked, wide and low
        view.resize(*size)
        view.show()
        qtbot.waitExposed(view)
        view.refresh()
        view.time_plot.viewport().update()
        QApplication.processEvents()
        legend = view.legend.sceneBoundingRect()
        data = tp.getViewBox().sceneBoundingRect()
        assert view.legend.isVisible() and legend.width() > 0 and legend.height() > 0
        assert not legend.intersects(data), (size, legend, data)
        assert legend.bottom() <= data.top()  # above the data, in the title row


def test_workspace_outline(view: PositionView2D) -> None:
    assert view.workspace() is None
    assert not view.workspace_outline.isVisible()
    view.set_workspace(((-5.0, 20.0), (30.0, -2.0), (-1.0, 1.0)))  # limits in either order
    assert view.workspace() == ((-5.0, 20.0), (-2.0, 30.0), (-1.0, 1.0))
    x, y = view.workspace_outline.getData()
    assert list(zip(x.tolist(), y.tolist(), strict=True)) == [
        (-5.0, -2.0),
        (20.0, -2.0),
        (20.0, 30.0),
        (-5.0, 30.0),
        (-5.0, -2.0),
    ]
    assert view.workspace_outline.isVisible()
    pen = view.workspace_outline.opts["pen"]
    assert pen.style() == Qt.PenStyle.DashLine
    assert pen.color().name() not in {view.trail.opts["pen"].color().name(), "#000000"}
    vb = view.xy_plot.getPlotItem().getViewBox()
    assert view.workspace_outline not in vb.addedItems  # no part in pyqtgraph's auto-range
    view.set_workspace(None)
    assert view.workspace() is None
    assert not view.workspace_outline.isVisible()
    with pytest.raises(ValueError):
        view.set_workspace(((0.0, 1.0), (0.0, 1.0)))  # type: ignore[arg-type]


def test_reset_view_fits_the_workspace_too(view: PositionView2D) -> None:
    view.refresh()
    plot = view.xy_plot.getPlotItem()
    plot.getViewBox().sigRangeChangedManually.emit([True, True])
    view.set_workspace(((-100.0, 100.0), (-50.0, 60.0), (0.0, 10.0)))  # not following: no fit
    (x0, x1), _ = plot.viewRange()
    assert x0 > -100.0
    view.reset_view()
    (x0, x1), (y0, y1) = plot.viewRange()
    assert x0 < -100.0 and x1 > 100.0 and y0 < -50.0 and y1 > 60.0
    before = plot.viewRange()
    view.refresh()
    assert plot.viewRange() == before  # the fit is stable: no per-frame range changes


def test_a_workspace_set_while_following_is_brought_into_view(view: PositionView2D) -> None:
    view.refresh()
    view.set_workspace(((0.0, 300.0), (0.0, 200.0), (0.0, 10.0)))
    (x0, x1), (y0, y1) = view.xy_plot.getPlotItem().viewRange()
    assert x0 <= 0.0 and x1 >= 300.0 and y0 <= 0.0 and y1 >= 200.0


def test_reset_view_of_an_empty_buffer_fits_the_workspace(qtbot) -> None:
    widget = PositionView2D(PositionBuffer(capacity=5))
    qtbot.addWidget(widget)
    widget.set_workspace(((10.0, 20.0), (30.0, 40.0), (0.0, 1.0)))
    widget.reset_view()
    (x0, x1), (y0, y1) = widget.xy_plot.getPlotItem().viewRange()
    assert x0 < 10.0 and x1 > 20.0 and y0 < 30.0 and y1 > 40.0


def _pixel_at(view: PositionView2D, x: float, y: float) -> QColor:
    """The colour drawn at (x, y) mm of the XY plot."""
    plot = view.xy_plot
    scene = plot.getPlotItem().getViewBox().mapViewToScene(QPointF(x, y))
    pixel = plot.mapFromScene(scene)
    return plot.grab().toImage().pixelColor(pixel)


def test_estimated_position_is_drawn_hollow(view: PositionView2D, qtbot) -> None:
    view.resize(900, 500)
    view.show()
    qtbot.waitExposed(view)
    view.refresh()
    amber = QColor(CURRENT_COLOUR)
    assert not view.is_estimated()

    def is_amber(colour: QColor) -> bool:
        pairs = zip(colour.getRgb()[:3], amber.getRgb()[:3], strict=True)
        return all(abs(a - b) < 40 for a, b in pairs)

    assert is_amber(_pixel_at(view, 9.0, 18.0))  # filled: the centre is the marker's colour
    view.set_estimated(True)
    assert view.is_estimated()
    assert view.current_marker.opts["brush"].style() == Qt.BrushStyle.NoBrush
    assert view.current_marker.opts["pen"].color() == amber
    assert not is_amber(_pixel_at(view, 9.0, 18.0))  # hollow: the centre shows through
    view.buffer.append(200.0, 9.0, 18.0, 0.0)  # new data keeps the hollow marker
    view.refresh()
    assert view.current_marker.opts["brush"].style() == Qt.BrushStyle.NoBrush
    view.set_estimated(False)
    assert not view.is_estimated()
    assert is_amber(_pixel_at(view, 9.0, 18.0))


def test_a_shifted_buffer_redraws_the_trail_in_the_new_coordinates(view, buffer) -> None:
    view.refresh()
    buffer.shift(-9.0, -18.0, 9.0)  # the current position becomes the new home
    view.refresh()
    x, y = view.trail.getData()
    assert x.tolist() == [i - 9.0 for i in range(10)]
    assert y.tolist() == [2 * i - 18.0 for i in range(10)]
    assert view.current_marker.getData()[0].tolist() == [0.0]
    _assert_clear_of_the_edges(view, x.tolist(), y.tolist())


def test_a_position_without_y_does_not_break_the_fit(view: PositionView2D, buffer) -> None:
    view.refresh()
    buffer.append(200.0, 300.0, float("nan"), 0.0)  # a glitch: no Y in one sample
    buffer.append(201.0, 300.0, 5.0, 0.0)
    view.refresh()
    (x0, x1), (y0, y1) = view.xy_plot.getPlotItem().viewRange()
    assert np.isfinite([x0, x1, y0, y1]).all()
    assert x0 < 300.0 < x1


# -- preview of a planned path ---------------------------------------------------------------
def _quarter_circle(radius: float = 5.0) -> list[tuple[float, float, float]]:
    angles = np.linspace(0.0, np.pi / 2, 50)
    return [(radius * np.cos(a), radius * np.sin(a), 0.1 * i) for i, a in enumerate(angles)]


def test_preview_set_and_cleared(view: PositionView2D) -> None:
    assert view.preview() == []
    assert not view.preview_curve.isVisible()
    points = _quarter_circle()
    view.set_preview(points)
    assert np.allclose(view.preview(), points)
    assert all(isinstance(p, tuple) and len(p) == 3 for p in view.preview())
    assert view.preview_curve.isVisible()
    x, y = view.preview_curve.getData()
    assert x.tolist() == pytest.approx([p[0] for p in points])
    assert y.tolist() == pytest.approx([p[1] for p in points])
    pen = view.preview_curve.opts["pen"]
    assert pen.style() == Qt.PenStyle.DashLine
    others = {
        view.trail.opts["pen"].color().name(),
        view.workspace_outline.opts["pen"].color().name(),
        CURRENT_COLOUR,
    }
    assert pen.color().name() not in others
    vb = view.xy_plot.getPlotItem().getViewBox()
    assert view.preview_curve not in vb.addedItems  # no part in pyqtgraph's auto-range
    view.set_preview([])
    assert view.preview() == []
    assert not view.preview_curve.isVisible()
    view.set_preview(points)
    view.set_preview(None)
    assert view.preview() == []
    assert not view.preview_curve.isVisible()
    x, _ = view.preview_curve.getData()
    assert x is None or len(x) == 0
    assert view.trail.isVisible()  # the rest of the plot is untouched


def test_preview_rejects_bad_points(view: PositionView2D) -> None:
    with pytest.raises(ValueError):
        view.set_preview([(1.0, 2.0)])
    with pytest.raises(ValueError):
        view.set_preview([(float("nan"), 2.0, 0.0), (1.0, 2.0, 0.0)])
    view.set_preview([(0.0, 0.0, float("nan")), (1.0, 1.0, float("nan"))])  # a device without Z
    assert view.preview() == [(0.0, 0.0, 0.0), (1.0, 1.0, 0.0)]


def test_a_preview_outside_the_view_widens_it(view: PositionView2D) -> None:
    view.refresh()
    far = [(300.0 + x, -200.0 + y, z) for x, y, z in _quarter_circle(20.0)]
    view.set_preview(far)
    rows = view.buffer.view()
    xs, ys = [p[0] for p in far], [p[1] for p in far]
    _assert_clear_of_the_edges(view, [*rows[:, 1], *xs], [*rows[:, 2], *ys])
    before = view.xy_plot.getPlotItem().viewRange()
    view.refresh()
    assert view.xy_plot.getPlotItem().viewRange() == before
    view.reset_view()
    _assert_clear_of_the_edges(view, [*rows[:, 1], *xs], [*rows[:, 2], *ys])


def test_preview_is_drawn(view: PositionView2D, qtbot) -> None:
    view.resize(900, 500)
    view.show()
    qtbot.waitExposed(view)
    view.set_preview([(x, 30.0, 0.0) for x in np.linspace(-20.0, 20.0, 81)])
    view.reset_view()
    colour = view.preview_curve.opts["pen"].color()
    image = view.xy_plot.grab().toImage()
    ratio = image.devicePixelRatio()
    vb = view.xy_plot.getPlotItem().getViewBox()
    left = view.xy_plot.mapFromScene(vb.mapViewToScene(QPointF(-15.0, 30.0)))
    right = view.xy_plot.mapFromScene(vb.mapViewToScene(QPointF(15.0, 30.0)))
    drawn = []
    for px in range(left.x(), right.x()):  # every pixel along the line
        near = False
        for dy in (-1, 0, 1):
            found = image.pixelColor(int(px * ratio), int((left.y() + dy) * ratio))
            pairs = zip(found.getRgb()[:3], colour.getRgb()[:3], strict=True)
            near = near or sum(abs(a - b) for a, b in pairs) < 90
        drawn.append(near)
    assert len(drawn) > 50
    assert sum(drawn) > len(drawn) / 3  # drawn
    gaps = sum(1 for a, b in itertools.pairwise(drawn) if a and not b)
    assert gaps >= 5, drawn  # dashed: the line breaks again and again


def test_the_xy_layout_settles_at_every_size(qtbot) -> None:
    """With the aspect locked, a narrower Y tick label widened the view, which changed the
    ticks and the label back: the layout swung between two widths on every frame, rebuilding
    the axes and the grid ~30 times a second with nothing moving (issue 11)."""
    buffer = PositionBuffer(capacity=10)
    buffer.append(100.0, 0.0, 0.0, 0.0)  # fitted to -2..2 mm: ticks of 1 or 0.5 mm
    widget = PositionView2D(buffer)
    qtbot.addWidget(widget)
    widget.show()
    axis = widget.xy_plot.getPlotItem().getAxis("left")
    swinging = []
    for height, width in itertools.product((350, 360), range(520, 600, 8)):
        widget.resize(width, height)
        for _ in range(3):
            QApplication.processEvents()
        widths = set()
        for _ in range(4):
            QApplication.processEvents()
            widths.add(round(axis.width(), 2))
        if len(widths) > 1:
            swinging.append((width, height, sorted(widths)))
    assert not swinging


@pytest.mark.timeout(30)
@pytest.mark.parametrize(
    ("x_range", "y_range"),
    [((-10, 0), (-1, 1)), ((-30, 0), (-2.5, 3.7)), ((-4.3, 5.1), (-2, 3)), ((-1e3, 2e3), (-5, 5))],
)
def test_the_fast_grid_draws_what_pyqtgraphs_grid_draws(qtbot, x_range, y_range) -> None:
    import pyqtgraph as pg

    from widgets._fast_grid import FastGrid
    from widgets.position_view_2d import GRID_COLOUR

    images = []
    for grid in (pg.GridItem(), FastGrid(GRID_COLOUR)):
        if not isinstance(grid, FastGrid):
            grid.setPen(pg.mkPen(GRID_COLOUR))
            grid.setTextPen(None)
        plot = pg.PlotWidget()
        qtbot.addWidget(plot)
        plot.resize(600, 400)
        plot.getPlotItem().addItem(grid, ignoreBounds=True)
        plot.getPlotItem().setRange(xRange=x_range, yRange=y_range, padding=0)
        images.append(plot.grab().toImage())
    assert images[0] == images[1]  # the same pixels


@pytest.mark.timeout(30)
def test_a_first_position_at_the_origin_and_a_small_jog_keep_the_empty_views_range(
    qtbot,
) -> None:
    buffer = PositionBuffer(capacity=10)
    view = PositionView2D(buffer)
    qtbot.addWidget(view)
    plot = view.xy_plot.getPlotItem()
    empty = plot.viewRange()
    buffer.append(0.0, 0.0, 0.0, 0.0)
    view.refresh()
    buffer.append(0.5, 1.0, 0.0, 0.0)  # a 1 mm jog: inside the margin, no refit
    view.refresh()
    assert plot.viewRange() == empty


@pytest.mark.timeout(30)
def test_the_timer_draws_the_time_plot_a_moment_after_the_xy_plot(view, buffer, qtbot) -> None:
    from widgets.position_view_2d import TIME_PLOT_DELAY_MS

    view.show()
    qtbot.waitExposed(view)
    view.refresh()
    buffer.append(200.0, 50.0, 60.0, 70.0)
    view._timed_refresh()  # as the refresh timer does
    assert view.trail.getData()[0][-1] == 50.0  # the XY plot at once
    assert view.curves["x"].getData()[1][-1] != 50.0  # the time plot waits its turn
    assert view._time_timer.isActive() and view._time_timer.interval() == TIME_PLOT_DELAY_MS
    qtbot.waitUntil(lambda: view.curves["x"].getData()[1][-1] == 50.0, timeout=5000)
    view.refresh()  # a direct refresh draws both at once
    buffer.append(201.0, 51.0, 60.0, 70.0)
    view.refresh()
    assert view.curves["x"].getData()[1][-1] == 51.0
