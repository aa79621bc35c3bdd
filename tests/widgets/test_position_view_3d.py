"""PositionView3D: the placeholder path everywhere; the real GL view only with a display."""

from __future__ import annotations

import os

import numpy as np
import pytest
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QLabel, QWidget

from widgets import position_view_3d
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
    from PySide6.QtCore import QPoint, Qt

    azimuth = gl_view.scene.opts["azimuth"]
    before = gl_view.grabFramebuffer()
    qtbot.mousePress(gl_view, Qt.MouseButton.LeftButton, pos=QPoint(100, 100))
    qtbot.mouseMove(gl_view, QPoint(160, 110))
    qtbot.mouseRelease(gl_view, Qt.MouseButton.LeftButton, pos=QPoint(160, 110))
    assert gl_view.scene.opts["azimuth"] != azimuth
    assert gl_view.grabFramebuffer() != before
