"""PositionView3D.set_preview: a planned path as a line in the scene (the GL parts need Xvfb)."""

from __future__ import annotations

import os

import numpy as np
import pytest

from widgets import position_view_3d
from widgets.position_buffer import PositionBuffer
from widgets.position_view_3d import PositionView3DPlaceholder, make_position_view_3d

NO_DISPLAY = "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen"
needs_display = pytest.mark.skipif(
    NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)"
)


def _helix(cx: float = 0.0, radius: float = 5.0) -> list[tuple[float, float, float]]:
    angles = np.linspace(0.0, 2 * np.pi, 100)
    return [
        (cx + radius * np.cos(a), radius * np.sin(a), 3.0 * i / 99) for i, a in enumerate(angles)
    ]


@pytest.fixture
def buffer() -> PositionBuffer:
    buffer = PositionBuffer(capacity=50)
    for i in range(5):
        buffer.append(float(i), float(i), 2.0 * i, 3.0 * i)
    return buffer


@pytest.fixture
def gl_view(qtbot, buffer):
    widget = make_position_view_3d(buffer)
    qtbot.addWidget(widget)
    assert isinstance(widget, position_view_3d.PositionView3D), getattr(widget, "reason", "")
    widget.resize(320, 240)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


def test_placeholder_preview_is_a_no_op(qtbot) -> None:
    widget = PositionView3DPlaceholder("no GL")
    qtbot.addWidget(widget)
    widget.set_preview(_helix())
    widget.set_preview(None)
    assert widget.preview() == []


@pytest.mark.gl
@needs_display
def test_preview_set_and_cleared(gl_view) -> None:
    assert gl_view.preview() == []
    assert not gl_view.preview_item.visible()
    points = _helix()
    gl_view.set_preview(points)
    assert np.allclose(gl_view.preview(), points)
    assert gl_view.preview_item.visible()
    assert np.allclose(gl_view.preview_item.pos, np.array(points, dtype=np.float32))
    assert gl_view.preview_item.mode == "line_strip"
    assert tuple(gl_view.preview_item.color) == position_view_3d.PREVIEW_COLOUR
    assert position_view_3d.PREVIEW_COLOUR not in (
        position_view_3d.TRAIL_COLOUR,
        position_view_3d.CURRENT_COLOUR,
        position_view_3d.TARGET_COLOUR,
        position_view_3d.WORKSPACE_COLOUR,
    )
    gl_view.set_preview([])
    assert gl_view.preview() == [] and not gl_view.preview_item.visible()
    gl_view.set_preview(points)
    gl_view.set_preview(None)
    assert gl_view.preview() == [] and not gl_view.preview_item.visible()


@pytest.mark.gl
@needs_display
def test_preview_grows_the_grid_and_is_drawn(gl_view) -> None:
    gl_view.refresh()
    far = _helix(cx=150.0, radius=20.0)
    gl_view.set_preview(far)
    assert gl_view._grid.contains(np.array(far))
    gl_view.set_view_preset("top")
    with_preview = gl_view.grabFramebuffer()
    gl_view.set_preview(None)
    without = gl_view.grabFramebuffer()
    assert with_preview != without

    def orange_pixels(image) -> int:
        r, g, b = (int(255 * c) for c in position_view_3d.PREVIEW_COLOUR[:3])
        count = 0
        for x in range(0, image.width(), 2):
            for y in range(0, image.height(), 2):
                c = image.pixelColor(x, y)
                count += abs(c.red() - r) + abs(c.green() - g) + abs(c.blue() - b) < 60
        return count

    assert orange_pixels(with_preview) > orange_pixels(without)
