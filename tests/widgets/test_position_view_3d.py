"""PositionView3D: the placeholder path everywhere; the real GL view only with a display."""

from __future__ import annotations

import os

import numpy as np
import pytest
from PySide6.QtCore import QRectF, QSize, Qt
from PySide6.QtGui import QColor, QFontMetrics, QGuiApplication, QVector3D
from PySide6.QtWidgets import QLabel, QToolButton, QWidget

from widgets import position_view_3d
from widgets._gl_scene import box_edges, grid_for, nice_spacing
from widgets.position_buffer import PositionBuffer
from widgets.position_view_3d import (
    PositionView3DPlaceholder,
    make_position_view_3d,
    opengl_available,
)

NO_DISPLAY = "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen"
needs_display = pytest.mark.skipif(
    NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)"
)


@pytest.fixture
def buffer() -> PositionBuffer:
    buffer = PositionBuffer(capacity=50)
    for i in range(5):
        buffer.append(float(i), float(i), 2.0 * i, 3.0 * i)
    return buffer


def _check_placeholder(widget: QWidget, parent: QWidget | None = None) -> None:
    assert isinstance(widget, QLabel)
    assert isinstance(widget, PositionView3DPlaceholder)
    assert widget.objectName() == "positionView3d"
    assert "OpenGL" in widget.text()
    assert widget.parent() is parent
    for call in (widget.refresh, widget.clear_trail, widget.reset_view):
        call()  # the same API, doing nothing
    widget.set_target(1.0, 2.0, 3.0)
    widget.set_target((1.0, 2.0, 3.0))
    widget.set_target(None)


def test_factory_without_gl_gives_a_placeholder(qtbot, buffer) -> None:
    parent = QWidget()
    qtbot.addWidget(parent)
    widget = make_position_view_3d(buffer, parent, probe=lambda: False)
    _check_placeholder(widget, parent)


def test_factory_when_the_probe_raises(qtbot, buffer) -> None:
    def probe() -> bool:
        raise RuntimeError("GLX missing")

    widget = make_position_view_3d(buffer, probe=probe)
    qtbot.addWidget(widget)
    _check_placeholder(widget)
    assert "GLX missing" in widget.text()


def test_factory_when_the_view_fails_to_build(qtbot, buffer, monkeypatch) -> None:
    def broken(*args, **kwargs):
        raise OSError("no GL library")

    monkeypatch.setattr(position_view_3d, "PositionView3D", broken)
    widget = make_position_view_3d(buffer, probe=lambda: True)
    qtbot.addWidget(widget)
    _check_placeholder(widget)
    assert "no GL library" in widget.text()


def test_offscreen_gives_the_placeholder(qtbot, buffer) -> None:
    if QGuiApplication.platformName() != "offscreen":
        pytest.skip("only meaningful on the offscreen platform")
    assert opengl_available() is False
    widget = make_position_view_3d(buffer)
    qtbot.addWidget(widget)
    _check_placeholder(widget)


@pytest.fixture
def gl_view(qtbot, buffer):
    widget = make_position_view_3d(buffer)
    qtbot.addWidget(widget)
    assert isinstance(widget, position_view_3d.PositionView3D), getattr(widget, "reason", "")
    widget.resize(320, 240)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


@pytest.mark.gl
@needs_display
def test_real_view_object_name_and_api(gl_view, buffer) -> None:
    assert gl_view.objectName() == "positionView3d"
    gl_view.refresh()
    assert gl_view.trail.visible()
    assert np.allclose(gl_view.trail.pos[-1], [4.0, 8.0, 12.0])
    assert np.allclose(gl_view.current_marker.pos, [[4.0, 8.0, 12.0]])
    gl_view.set_target(1.0, 2.0, None)
    assert gl_view.target() == (1.0, 2.0, 0.0)
    gl_view.set_target((3.0, 4.0, 5.0))
    assert gl_view.target() == (3.0, 4.0, 5.0)
    assert gl_view.target_marker.visible()
    gl_view.set_target(None)
    assert not gl_view.target_marker.visible()
    gl_view.clear_trail()
    assert len(buffer) == 1
    assert not gl_view.trail.visible()
    assert gl_view.current_marker.visible()
    gl_view.reset_view()
    assert gl_view.timer.isActive()


@pytest.mark.gl
@needs_display
def test_real_view_renders(gl_view) -> None:
    gl_view.refresh()
    image = gl_view.grabFramebuffer()
    assert not image.isNull()
    colours = {image.pixel(x, y) for x in range(0, image.width(), 8) for y in range(0, 240, 8)}
    assert len(colours) > 2  # background, grid, trail: not a blank frame


@pytest.mark.gl
@needs_display
def test_mouse_drag_and_wheel_move_the_camera(gl_view, qtbot) -> None:
    from PySide6.QtCore import QPoint

    azimuth = gl_view.scene.opts["azimuth"]
    before = gl_view.grabFramebuffer()
    qtbot.mousePress(gl_view, Qt.MouseButton.LeftButton, pos=QPoint(100, 100))
    qtbot.mouseMove(gl_view, QPoint(160, 110))
    qtbot.mouseRelease(gl_view, Qt.MouseButton.LeftButton, pos=QPoint(160, 110))
    assert gl_view.scene.opts["azimuth"] != azimuth
    assert gl_view.grabFramebuffer() != before


def test_placeholder_has_the_new_api_as_no_ops(qtbot) -> None:
    widget = PositionView3DPlaceholder("no GL")
    qtbot.addWidget(widget)
    widget.set_workspace(((0.0, 100.0), (0.0, 50.0), (0.0, 10.0)))
    widget.set_workspace(None)
    for name in ("top", "front", "side", "iso", "fit"):
        widget.set_view_preset(name)
    widget.set_follow(True)
    widget.set_estimated(True)
    assert widget.grid_spacing() == 0.0
    assert widget.is_following() is False
    assert widget.is_estimated() is False


# -- scene geometry (no OpenGL needed) ---------------------------------------------------------
@pytest.mark.parametrize(
    ("span", "spacing"), [(10, 1), (25, 2), (112, 10), (300, 20), (1000, 100), (0.3, 0.02)]
)
def test_nice_spacing_gives_about_ten_cells(span: float, spacing: float) -> None:
    assert nice_spacing(span) == pytest.approx(spacing)
    assert 4 <= span / nice_spacing(span) <= 16


def test_grid_covers_the_origin_and_the_data() -> None:
    grid = grid_for(np.array([[112.0, 3.0, 0.0]]))
    assert grid.x0 == 0.0 and grid.y0 == 0.0
    assert grid.x1 >= 112.0 and grid.contains(np.array([[112.0, 3.0, 0.0]]))
    assert grid.spacing == 10.0
    assert grid.x1 % grid.spacing == 0 and grid.y1 % grid.spacing == 0
    negative = grid_for(np.array([[-30.0, -5.0, 0.0]]))
    assert negative.x0 <= -30.0 and negative.x1 == 0.0 and negative.y0 <= -5.0
    assert not negative.contains(np.array([[-40.0, 0.0, 0.0]]))


def test_box_edges_are_twelve_axis_aligned_edges() -> None:
    edges = box_edges(((0.0, 3.0), (0.0, 2.0), (0.0, 1.0))).reshape(12, 2, 3)
    lengths = sorted(float(np.linalg.norm(b - a)) for a, b in edges)
    assert lengths == [1.0] * 4 + [2.0] * 4 + [3.0] * 4


# -- the OpenGL view ---------------------------------------------------------------------------
def _project(view, point) -> tuple[float, float]:
    """Where a scene point lands in the widget, in logical pixels, with the current camera."""
    w, h = view.width(), view.height()
    matrix = view.scene.projectionMatrix((0, 0, w, h), (0, 0, w, h)) * view.scene.viewMatrix()
    ndc = matrix.map(QVector3D(*map(float, point)))
    return (ndc.x() + 1) / 2 * w, (1 - ndc.y()) / 2 * h


def _label_rects(view) -> list[QRectF]:
    """The rectangles the axis labels are drawn in, as GLTextItem places them."""
    metrics = QFontMetrics(view.labels[0].font)
    rects = []
    for label in view.labels:
        x, y = _project(view, label.pos)
        rect = metrics.tightBoundingRect(label.text)
        rects.append(QRectF(x, y - rect.height(), rect.width(), rect.height()))
    return rects


def _near(colour: QColor, rgb: tuple[float, ...], tolerance: int = 60) -> bool:
    return (
        sum(abs(a - int(255 * b)) for a, b in zip(colour.getRgb()[:3], rgb[:3], strict=True))
        < tolerance
    )


def _has_colour(image, rect: QRectF, rgb: tuple[float, ...]) -> bool:
    """Whether a pixel near `rgb` is inside `rect` (logical pixels) of `image`."""
    ratio = image.devicePixelRatio()
    r = rect.toAlignedRect()
    return any(
        _near(image.pixelColor(int(x * ratio), int(y * ratio)), rgb)
        for x in range(max(0, r.left()), min(image.width() // int(ratio), r.right()))
        for y in range(max(0, r.top()), min(image.height() // int(ratio), r.bottom()))
    )


@pytest.mark.gl
@needs_display
def test_growing_the_widget_fills_the_image_and_keeps_the_labels(gl_view, qtbot) -> None:
    gl_view.refresh()
    gl_view.grabFramebuffer()
    gl_view.resize(900, 700)
    qtbot.waitUntil(lambda: gl_view.size() == QSize(900, 700))
    image = gl_view.grabFramebuffer()
    ratio = image.devicePixelRatio()
    assert image.deviceIndependentSize().toSize() == QSize(900, 700)
    right = range(int(image.width() * 0.9), image.width(), 3)
    black = [
        (x, y)
        for x in right
        for y in range(0, image.height(), 7)
        if image.pixelColor(x, y).getRgb()[:3] == (0, 0, 0)
    ]
    assert not black, f"{len(black)} black pixels in the right-most strip"
    assert image.pixelColor(image.width() - 2, 2).getRgb()[:3] == (24, 24, 28)
    # the labels are drawn where the camera puts the axis ends, in the grown image
    shown = QRectF(0, 0, 900, 700)
    for rect, colour in zip(_label_rects(gl_view), position_view_3d.AXIS_COLOURS, strict=True):
        assert shown.contains(rect)
        assert _has_colour(image, rect.adjusted(2, 0, 0, 0), colour)
    assert ratio == gl_view.scene.devicePixelRatioF()
    grabbed = gl_view.grab().toImage()  # the painted widget, not only the framebuffer
    assert grabbed.pixelColor(grabbed.width() - 3, grabbed.height() // 2).getRgb()[:3] != (
        0,
        0,
        0,
    )


@pytest.mark.gl
@needs_display
@pytest.mark.parametrize("preset", ["iso", "top", "front", "side"])
@pytest.mark.parametrize("far_x", [None, 60.0])
def test_labels_stay_inside_the_view(gl_view, buffer, preset: str, far_x: float | None) -> None:
    if far_x is not None:  # a long, flat grid: the X label at the right edge
        buffer.append(5.0, far_x, 1.0, 1.0)
    gl_view.refresh()
    gl_view.set_view_preset(preset)
    image = gl_view.grabFramebuffer()
    shown = QRectF(0, 0, gl_view.width(), gl_view.height())
    for rect, colour in zip(_label_rects(gl_view), position_view_3d.AXIS_COLOURS, strict=True):
        assert shown.contains(rect), (preset, rect)
        if preset == "iso":  # elsewhere an axis may point at the camera, under another label
            assert _has_colour(image, rect.adjusted(2, 0, 0, 0), colour)


@pytest.mark.gl
@needs_display
def test_the_grid_grows_when_the_data_leaves_it(gl_view, buffer) -> None:
    gl_view.refresh()
    assert gl_view.grid_spacing() == 1.0  # the data spans 8 mm
    lines = gl_view.grid_item.pos
    buffer.append(5.0, 3.0, 3.0, 3.0)  # inside the grid: left alone
    gl_view.refresh()
    assert gl_view.grid_item.pos is lines
    buffer.append(6.0, 112.0, 3.0, 3.0)
    gl_view.refresh()
    assert gl_view.grid_spacing() == 10.0
    xs = gl_view.grid_item.pos[:, 0]
    assert xs.min() <= 0.0 and xs.max() >= 112.0
    assert gl_view.axes_item.pos[:, 0].max() >= 112.0  # the X axis spans the grid
    x, y = _project(gl_view, (112.0, 3.0, 3.0))
    assert 0 <= x < gl_view.width() and 0 <= y < gl_view.height()  # the preset refitted


@pytest.mark.gl
@needs_display
def test_workspace_box_is_drawn_and_sizes_the_grid(gl_view) -> None:
    gl_view.refresh()
    gl_view.set_workspace(((0.0, 300.0), (0.0, 200.0), (0.0, 50.0)))
    assert gl_view.workspace_item.visible()
    assert gl_view.workspace_item.pos.shape == (24, 3)
    assert gl_view.grid_spacing() == 20.0
    xs, ys = gl_view.grid_item.pos[:, 0], gl_view.grid_item.pos[:, 1]
    assert (xs.min(), xs.max(), ys.min(), ys.max()) == (0.0, 300.0, 0.0, 200.0)
    image = gl_view.grabFramebuffer()
    shown = QRectF(0, 0, gl_view.width(), gl_view.height())
    corner = _project(gl_view, (300.0, 200.0, 50.0))
    assert shown.contains(*corner)
    box_rgb = position_view_3d.WORKSPACE_COLOUR
    assert _has_colour(image, shown, box_rgb)
    gl_view.set_workspace(None)
    assert not gl_view.workspace_item.visible()
    assert gl_view.grid_spacing() == 1.0
    assert not _has_colour(gl_view.grabFramebuffer(), shown, box_rgb)


@pytest.mark.gl
@needs_display
@pytest.mark.parametrize(
    ("name", "preset", "angles"),
    [
        ("view3dTop", "top", (90.0, -90.0)),
        ("view3dFront", "front", (0.0, -90.0)),
        ("view3dSide", "side", (0.0, 0.0)),
        ("view3dIso", "iso", (30.0, -60.0)),
    ],
)
def test_view_buttons_set_the_presets(gl_view, qtbot, name, preset, angles) -> None:
    gl_view.scene.setCameraPosition(elevation=45.0, azimuth=10.0)
    button = gl_view.findChild(QToolButton, name)
    assert button is not None and button.parent() is gl_view
    assert button.toolTip() and button.focusPolicy() == Qt.FocusPolicy.NoFocus
    assert button.autoRaise()
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    assert (gl_view.scene.opts["elevation"], gl_view.scene.opts["azimuth"]) == angles
    assert not button.hasFocus()


@pytest.mark.gl
@needs_display
def test_fit_shows_trail_target_and_workspace(gl_view, qtbot) -> None:
    gl_view.refresh()
    gl_view.set_target(-20.0, 40.0, 5.0)
    gl_view.set_workspace(((-30.0, 60.0), (0.0, 50.0), (0.0, 20.0)))
    gl_view.scene.setCameraPosition(distance=5.0, elevation=20.0, azimuth=-30.0)
    qtbot.mouseClick(gl_view.findChild(QToolButton, "view3dFit"), Qt.MouseButton.LeftButton)
    assert (gl_view.scene.opts["elevation"], gl_view.scene.opts["azimuth"]) == (20.0, -30.0)
    shown = QRectF(0, 0, gl_view.width(), gl_view.height())
    for point in [(-20.0, 40.0, 5.0), (4.0, 8.0, 12.0), (-30.0, 0.0, 20.0), (60.0, 50.0, 0.0)]:
        assert shown.contains(*_project(gl_view, point)), point
    with pytest.raises(ValueError):
        gl_view.set_view_preset("bottom")


@pytest.mark.gl
@needs_display
def test_follow_keeps_the_current_position_centred(gl_view, buffer, qtbot) -> None:
    gl_view.refresh()
    button = gl_view.findChild(QToolButton, "view3dFollow")
    assert button.isCheckable() and button.focusPolicy() == Qt.FocusPolicy.NoFocus
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    assert gl_view.is_following() and button.isChecked()
    assert gl_view.scene.opts["center"] == QVector3D(4.0, 8.0, 12.0)
    buffer.append(5.0, 3.0, 1.0, 2.0)  # on the grid: the camera moves only to follow
    gl_view.refresh()
    assert gl_view.scene.opts["center"] == QVector3D(3.0, 1.0, 2.0)
    gl_view.set_follow(False)
    assert not gl_view.is_following() and not button.isChecked()
    buffer.append(6.0, 3.0, 3.0, 3.0)
    gl_view.refresh()
    assert gl_view.scene.opts["center"] == QVector3D(3.0, 1.0, 2.0)


@pytest.mark.gl
@needs_display
def test_estimated_position_is_drawn_faded(gl_view) -> None:
    gl_view.refresh()
    gl_view.set_view_preset("top")
    x, y = _project(gl_view, (4.0, 8.0, 12.0))

    def marker_pixel() -> QColor:
        image = gl_view.grabFramebuffer()
        ratio = image.devicePixelRatio()
        return image.pixelColor(int(x * ratio), int(y * ratio))

    measured = marker_pixel()
    assert _near(measured, position_view_3d.CURRENT_COLOUR)
    gl_view.set_estimated(True)
    assert gl_view.is_estimated()
    assert gl_view.current_marker.color[3] == pytest.approx(0.5)
    estimated = marker_pixel()
    assert not _near(estimated, position_view_3d.CURRENT_COLOUR)
    assert estimated.red() < measured.red() and estimated.red() > 100
    gl_view.set_estimated(False)
    assert not gl_view.is_estimated()
    assert marker_pixel() == measured


@pytest.mark.gl
@needs_display
@pytest.mark.timeout(30)
def test_a_change_is_rendered_in_a_turn_of_its_own_not_in_the_paint(
    gl_view, qtbot, monkeypatch
) -> None:
    gl_view.refresh()
    gl_view.grabFramebuffer()
    rendered = []
    original = gl_view.render_scene
    monkeypatch.setattr(gl_view, "render_scene", lambda: rendered.append(1) or original())
    gl_view.set_target(3.0, 4.0, 5.0)
    assert gl_view._render_timer.isActive()
    gl_view.repaint()  # the window's repaint paints the image it has, renders nothing
    assert rendered == []
    qtbot.waitUntil(lambda: bool(rendered), timeout=5000)  # then the render timer's turn
    assert not gl_view._stale
    gl_view.resize(400, 300)  # an image of the wrong size is rendered at the paint
    gl_view.repaint()
    assert len(rendered) == 2
