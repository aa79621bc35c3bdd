"""No OpenGL, or an OpenGL that fails: the window runs with a notice instead of the 3D view.

Issue 11: under a running X server, Qt's offscreen platform created GLX contexts that report
OpenGL 2.0, pyqtgraph's initializeGL raised, and the process died in a segmentation fault.
"""

from __future__ import annotations

import logging
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QPushButton, QToolButton, QWidget

from app.window.main_window import MainWindow
from widgets import _gl_scene, position_view_3d
from widgets.position_buffer import PositionBuffer
from widgets.position_view_3d import PositionView3D, PositionView3DPlaceholder
from widgets.view_tabs import VIEW_2D

pytestmark = pytest.mark.timeout(60)

ROOT = Path(__file__).resolve().parents[3]
FORCED = "forced by the test"
BOX = ((0.0, 100.0), (0.0, 50.0), (0.0, 10.0))
real_gl = pytest.mark.skipif(
    "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen",
    reason="needs a display with OpenGL (run under xvfb-run)",
)


def _disabled_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if "3D view disabled" in line]


# -- the whole program, in a process of its own -----------------------------------------------
@pytest.mark.skipif(
    "DISPLAY" not in os.environ,
    reason="needs a running X display (the crash needed one): run under xvfb-run",
)
def test_screenshot_on_the_offscreen_platform_under_a_display(tmp_path: Path) -> None:
    shot = tmp_path / "shot.png"
    env = {
        **os.environ,
        "QT_QPA_PLATFORM": "offscreen",
        "MOTIONPANEL_SETTINGS": str(tmp_path / "settings.ini"),
        "MOTIONPANEL_LOG_DIR": str(tmp_path / "logs"),
    }
    result = subprocess.run(
        [sys.executable, "-m", "app.main", "--screenshot", str(shot)],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=50,
    )
    assert result.returncode == 0, result.stderr
    assert shot.is_file() and shot.stat().st_size > 0
    assert not QImage(str(shot)).isNull()
    lines = _disabled_lines(result.stderr)
    assert len(lines) == 1, result.stderr  # logged once
    assert "offscreen" in lines[0]
    assert "initializeGL" not in result.stderr  # no GL call was made at all


# -- the window, with the detection forced to fail ----------------------------------------------
@pytest.fixture
def gl_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """The OpenGL check says no, as it does on a machine without OpenGL."""
    monkeypatch.setattr(position_view_3d, "opengl_unavailable_reason", lambda: FORCED)


@pytest.fixture
def window_without_gl(gl_refused: None, window: MainWindow) -> MainWindow:
    return window


def test_window_runs_with_the_notice(qtbot, window_without_gl: MainWindow) -> None:
    win = window_without_gl
    notice = win.findChild(QWidget, "positionView3d")
    assert isinstance(notice, PositionView3DPlaceholder)
    assert notice is win.view3d
    assert notice.isVisible() and not notice.size().isEmpty()
    assert FORCED in notice.text() and "OpenGL" in notice.text()
    win.view_tabs.setCurrentIndex(VIEW_2D)  # the 2D plots: the other tab of the centre
    assert win.findChild(QWidget, "positionView2d").isVisible()

    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device("sim://coxiris?speed=100", "coxiris", 115200)
    win.jog_panel.set_step(10)
    qtbot.mouseClick(win.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: win.readout.position() == (10.0, 0.0, 0.0), timeout=5000)
    win.view2d.refresh()
    notice.refresh()
    assert not win.grab().isNull()


def test_the_detection_is_logged_once(
    qtbot, gl_refused: None, caplog: pytest.LogCaptureFixture
) -> None:
    with caplog.at_level(logging.WARNING, logger=position_view_3d.__name__):
        widget = position_view_3d.make_position_view_3d(PositionBuffer(capacity=10))
    qtbot.addWidget(widget)
    assert isinstance(widget, PositionView3DPlaceholder)
    assert widget.objectName() == "positionView3d"
    assert [r.getMessage() for r in caplog.records] == [f"3D view disabled: {FORCED}"]


def test_an_old_context_version_is_refused_before_pyqtgraph_sees_it() -> None:
    """The offscreen platform's GLX context: version 2.0 reported, whatever the driver."""
    context = SimpleNamespace(
        isOpenGLES=lambda: False,
        format=lambda: SimpleNamespace(version=lambda: (2, 0)),
        functions=lambda: SimpleNamespace(glGetString=lambda _: "4.5 Mesa 22.3.6"),
    )
    reason = _gl_scene._version_problem(context)  # type: ignore[arg-type]
    assert reason is not None and "2.0" in reason and "4.5 Mesa" in reason
    context.format = lambda: SimpleNamespace(version=lambda: (4, 5))
    assert _gl_scene._version_problem(context) is None  # type: ignore[arg-type]


# -- a real OpenGL that fails at initialisation or while rendering ------------------------------
def _raise(*args: object, **kwargs: object) -> None:
    raise RuntimeError("GL broke on purpose")


def _break(monkeypatch: pytest.MonkeyPatch, method: str) -> None:
    """Make pyqtgraph's `method` (initializeGL or paintGL) raise."""
    from pyqtgraph.opengl.GLViewWidget import GLViewMixin

    monkeypatch.setattr(GLViewMixin, method, _raise)


@pytest.mark.gl
@real_gl
def test_a_failing_initialise_gives_the_notice(
    qtbot, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    assert position_view_3d.opengl_available()  # the check passes: the failure comes later
    _break(monkeypatch, "initializeGL")
    with caplog.at_level(logging.WARNING, logger=position_view_3d.__name__):
        widget = position_view_3d.make_position_view_3d(PositionBuffer(capacity=10))
    qtbot.addWidget(widget)
    assert isinstance(widget, PositionView3DPlaceholder)
    assert "GL broke on purpose" in widget.text()
    assert len(_disabled_lines(caplog.text)) == 1


@pytest.mark.gl
@real_gl
def test_a_failing_render_turns_the_view_into_the_notice(
    qtbot, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    buffer = PositionBuffer(capacity=10)
    buffer.append(0.0, 1.0, 2.0, 3.0)
    view = position_view_3d.make_position_view_3d(buffer)
    qtbot.addWidget(view)
    assert isinstance(view, PositionView3D) and view.failure is None
    view.resize(320, 240)
    view.show()
    qtbot.waitExposed(view)
    assert not view.grabFramebuffer().isNull()

    _break(monkeypatch, "paintGL")
    view.set_target(1.0, 2.0, 3.0)
    with caplog.at_level(logging.WARNING, logger=position_view_3d.__name__):
        assert view.grabFramebuffer().isNull()
        view.grabFramebuffer()
        view.repaint()
    assert view.failure is not None and "GL broke on purpose" in view.failure
    assert len(_disabled_lines(caplog.text)) == 1
    assert view.objectName() == "positionView3d"
    assert not view.timer.isActive()
    assert all(not button.isVisible() for button in view.findChildren(QToolButton))
    # the API keeps working, drawing nothing
    buffer.append(1.0, 4.0, 5.0, 6.0)
    view.refresh()
    view.set_workspace(BOX)
    view.set_preview([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)])
    view.set_view_preset("top")
    view.set_follow(True)
    view.set_estimated(True)
    view.reset_view()
    image = view.grab().toImage()
    assert not image.isNull()
    colours = {image.pixel(x, y) for x in range(0, 320, 4) for y in range(0, 240, 4)}
    assert len(colours) > 1  # the notice's text and border on the background
