"""The 2D and 3D views in inches: axis labels, tick values, grid lines and the 3D grid's scale
follow the units, while what is drawn (data in mm) stays where it is; mm again restores all."""

from __future__ import annotations

import numpy as np
import pytest

from tests.widgets.test_position_view_3d import gl_view, needs_display
from widgets._gl_scene import grid_for, spacing_text
from widgets.position_buffer import PositionBuffer
from widgets.position_view_2d import PositionView2D
from widgets.position_view_3d import PositionView3DPlaceholder

pytestmark = pytest.mark.timeout(60)
INCH = 25.4
__all__ = ["gl_view"]  # the 3D view fixture, on this module's buffer


@pytest.fixture
def buffer() -> PositionBuffer:
    buffer = PositionBuffer(capacity=100)
    for i in range(10):
        buffer.append(100.0 + i, 3.0 * i, 2.0 * i, -float(i))  # to (27, 18, -9) mm
    return buffer


@pytest.fixture
def view2d(qtbot, buffer: PositionBuffer) -> PositionView2D:
    widget = PositionView2D(buffer)
    qtbot.addWidget(widget)
    widget.resize(900, 400)
    widget.show()
    qtbot.waitExposed(widget)
    widget.refresh()
    return widget


def _ticks(plot, side: str) -> list[tuple[float, str]]:
    """(position in view units, text) of the major and minor ticks `side`'s axis draws."""
    axis = plot.getPlotItem().getAxis(side)
    low, high = axis.range
    length = axis.size().width() if side == "bottom" else axis.size().height()
    ticks = []
    for spacing, values in axis.tickValues(low, high, length)[:2]:
        texts = axis.tickStrings(values, axis.autoSIPrefixScale * axis.scale, spacing)
        ticks.extend(zip(values, texts, strict=True))
    return ticks


def _assert_ticks_in(ticks: list[tuple[float, str]], per_unit: float) -> None:
    """Every tick's text is its position in the unit (mm: 1 per mm, in: 1/25.4)."""
    assert len(ticks) >= 3
    for value, text in ticks:
        assert float(text) == pytest.approx(value * per_unit, abs=1e-6), (value, text)


def test_the_2d_axes_say_inches_and_tick_in_inches(view2d: PositionView2D) -> None:
    ranges = view2d.xy_plot.getPlotItem().viewRange()
    view2d.set_units("in")
    assert view2d.units() == "in"
    assert view2d.xy_fit.shown == {"bottom": "X (in)", "left": "Y (in)"}
    assert view2d.time_fit.shown["left"] == "position (in)"
    for plot, side in ((view2d.xy_plot, "bottom"), (view2d.xy_plot, "left")):
        _assert_ticks_in(_ticks(plot, side), 1 / INCH)
    _assert_ticks_in(_ticks(view2d.time_plot, "left"), 1 / INCH)
    _assert_ticks_in(_ticks(view2d.time_plot, "bottom"), 1.0)  # time stays in seconds
    texts = [text for _, text in _ticks(view2d.xy_plot, "bottom")]
    assert "0.5" in texts and "1.0" in texts  # the trail reaches 27 mm: just over an inch
    # What is drawn stays in mm, at the same place: the trail, the marker, the view.
    assert view2d.trail.getData()[0][-1] == 27.0
    assert view2d.current_marker.getData()[1].tolist() == [18.0]
    assert view2d.xy_plot.getPlotItem().viewRange() == ranges


def test_the_2d_grid_lines_fall_on_round_inches(view2d: PositionView2D) -> None:
    view2d.set_units("in")
    levels = view2d.xy_grid.line_levels()
    assert levels
    for _, _, values in levels:  # values shown: 0.1, 1, 10 in steps
        assert np.allclose(values * 10, np.round(values * 10), atol=1e-6)
    steps = {round(float(np.diff(values)[0]), 6) for _, _, values in levels if len(values) > 1}
    assert steps and steps <= {0.1, 1.0, 10.0}, steps
    assert view2d.time_grid.value_scale() == (1.0, pytest.approx(1 / INCH))  # t in s
    view2d.set_units("mm")
    levels = view2d.xy_grid.line_levels()
    steps = {round(float(np.diff(values)[0]), 6) for _, _, values in levels if len(values) > 1}
    assert steps and steps <= {1.0, 10.0, 100.0}, steps  # round mm again


def test_the_2d_axes_back_in_mm(view2d: PositionView2D) -> None:
    before = (_ticks(view2d.xy_plot, "bottom"), dict(view2d.xy_fit.shown))
    view2d.set_units("in")
    view2d.set_units("mm")
    assert view2d.xy_fit.shown == {"bottom": "X (mm)", "left": "Y (mm)"}
    assert view2d.time_fit.shown["left"] == "position (mm)"
    assert (_ticks(view2d.xy_plot, "bottom"), dict(view2d.xy_fit.shown)) == before
    _assert_ticks_in(_ticks(view2d.time_plot, "left"), 1.0)
    assert view2d.xy_grid.value_scale() == (1.0, 1.0)
    with pytest.raises(ValueError):
        view2d.set_units("cm")


@pytest.mark.parametrize(
    ("span_mm", "spacing_in"),
    [(25.4, 0.1), (50.8, 0.25), (100.0, 0.5), (200.0, 1.0), (10.0, 0.05), (600.0, 2.5)],
)
def test_the_3d_grid_in_inches_steps_01_025_05_1(span_mm: float, spacing_in: float) -> None:
    points = np.array([[span_mm, span_mm / 2, 0.0]])
    grid = grid_for(points, units="in")
    assert grid.spacing == pytest.approx(spacing_in * INCH)
    for edge in grid[:4]:  # the edges on grid lines, counted from the origin in inches
        cells = edge / grid.spacing
        assert cells == pytest.approx(round(cells), abs=1e-6)
    assert grid.contains(points)
    assert spacing_text(grid.spacing, "in") == f"{spacing_in:g}"
    assert grid_for(points).spacing == grid_for(points, units="mm").spacing  # mm unchanged


def test_the_placeholder_takes_the_units(qtbot) -> None:
    placeholder = PositionView3DPlaceholder("no OpenGL")
    qtbot.addWidget(placeholder)
    placeholder.set_units("in")
    with pytest.raises(ValueError):
        placeholder.set_units("cm")


@pytest.mark.gl
@needs_display
def test_the_3d_view_in_inches_and_back(gl_view) -> None:
    gl_view.refresh()
    box = ((-10.0, 40.0), (-5.0, 30.0), (-10.0, 5.0))
    gl_view.set_workspace(box)
    gl_view.set_target(20.0, 10.0, 0.0)
    target, edges = gl_view.target_marker.pos.copy(), gl_view.workspace_item.pos.copy()
    assert gl_view.scale_text() == "grid 5 mm"
    gl_view.set_units("in")
    assert gl_view.units() == "in"
    assert gl_view.scale_text() == "grid 0.25 in"
    assert [label.text for label in gl_view.labels] == ["X (in)", "Y (in)", "Z (in)"]
    assert gl_view.grid_spacing() == pytest.approx(0.25 * INCH)  # the API stays in mm
    lines = gl_view.grid_item.pos[:, :2] / gl_view.grid_spacing()
    assert np.allclose(lines, np.round(lines), atol=1e-4)  # on quarter inches
    grid = gl_view._grid
    assert grid.x0 <= -10.0 and grid.x1 >= 40.0 and grid.y0 <= -5.0 and grid.y1 >= 30.0
    # The target and the travel box are drawn where they were, in mm.
    assert np.array_equal(gl_view.target_marker.pos, target)
    assert np.array_equal(gl_view.workspace_item.pos, edges)
    assert not gl_view.render_scene().isNull()
    gl_view.set_units("mm")
    assert gl_view.scale_text() == "grid 5 mm"
    assert [label.text for label in gl_view.labels] == ["X (mm)", "Y (mm)", "Z (mm)"]
    assert gl_view.grid_spacing() == 5.0
