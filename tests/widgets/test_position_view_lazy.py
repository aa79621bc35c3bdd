"""The views built after the window's first paint: stand-ins keep the calls and replay them."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QMainWindow, QSplitter, QWidget

from widgets.lazy_view import DeferredViews, LazyView
from widgets.position_buffer import PositionBuffer
from widgets.traffic_timeline import TrafficTimeline

pytestmark = pytest.mark.timeout(60)

ROOT = Path(__file__).resolve().parents[2]
BOX = ((0.0, 100.0), (0.0, 50.0), (0.0, 10.0))


class FakeView(QWidget):
    """A view that notes what is called on it."""

    built = 0

    def __init__(self) -> None:
        super().__init__()
        FakeView.built += 1
        self.setObjectName("fakeView")
        self.calls: list[tuple[str, tuple]] = []
        self._target = None

    def set_target(self, *args: object) -> None:
        self.calls.append(("set_target", args))
        self._target = args

    def set_workspace(self, box: object) -> None:
        self.calls.append(("set_workspace", (box,)))

    def reset_view(self) -> None:
        self.calls.append(("reset_view", ()))

    def refresh(self) -> None:
        self.calls.append(("refresh", ()))

    def clear_trail(self) -> None:
        self.calls.append(("clear_trail", ()))

    def target(self) -> object:
        return self._target


@pytest.fixture
def stand_in(qtbot) -> tuple[LazyView, QSplitter]:
    splitter = QSplitter(Qt.Orientation.Horizontal)
    qtbot.addWidget(splitter)
    splitter.addWidget(QWidget())
    lazy = LazyView("fakeView", FakeView, Qt.GlobalColor.black, splitter)
    splitter.addWidget(lazy)
    FakeView.built = 0
    return lazy, splitter


def test_calls_are_kept_and_replayed_last_first(stand_in) -> None:
    lazy, splitter = stand_in
    lazy.set_target(1.0, 2.0, 3.0)
    lazy.reset_view()
    lazy.set_workspace(BOX)
    lazy.set_target(4.0, 5.0, 6.0)  # only the last target counts, and it comes last
    lazy.refresh()  # nothing to draw yet
    clear = lazy.clear_trail  # kept before the view exists, as a menu keeps it
    assert FakeView.built == 0 and lazy.real() is None
    view = lazy.build()
    assert FakeView.built == 1 and lazy.build() is view
    assert view.calls == [
        ("reset_view", ()),
        ("set_workspace", (BOX,)),
        ("set_target", (4.0, 5.0, 6.0)),
    ]
    assert splitter.indexOf(view) == 1 and splitter.widget(1) is view  # in the stand-in's place
    assert splitter.findChild(QWidget, "fakeView") is view
    clear()  # reaches the real view
    assert view.calls[-1] == ("clear_trail", ())


def test_a_question_builds_the_view(stand_in) -> None:
    lazy, _ = stand_in
    lazy.set_target(1.0, 2.0, 3.0)
    assert lazy.target() == (1.0, 2.0, 3.0)  # built to answer, with the calls replayed
    assert FakeView.built == 1


def test_the_window_builds_its_views_after_the_first_paint(qtbot) -> None:
    window = QMainWindow()
    qtbot.addWidget(window)
    buffer = PositionBuffer(capacity=None)
    buffer.append(0.0, 1.0, 2.0, 3.0)
    views = DeferredViews(window, buffer)
    window.view3d, window.view2d = views.view3d, views.view2d
    splitter = QSplitter()
    splitter.addWidget(views.view3d)
    splitter.addWidget(views.view2d)
    window.setCentralWidget(splitter)
    timeline = TrafficTimeline(window, deferred=True)
    views.add(timeline.build_plots)
    timeline.add_latency(1.0, 5.0, 7)
    window.view2d.set_workspace(BOX)
    window.view3d.set_workspace(BOX)
    assert timeline.plots is None and not views.is_ready()
    with qtbot.waitSignal(views.ready, timeout=10_000):
        window.show()
    assert views.is_ready()
    assert window.view2d.objectName() == "positionView2d" and window.view2d.workspace() == BOX
    assert window.view3d.objectName() == "positionView3d"
    assert window.findChild(QWidget, "positionView2d") is window.view2d
    assert timeline.plots is not None
    assert timeline.latency_curve.getData()[1].tolist() == [5.0]  # what came before is drawn


def _window_with_views(qtbot) -> tuple[QMainWindow, DeferredViews]:
    """A window whose centre is the 2D view's stand-in, not shown yet."""
    window = QMainWindow()
    qtbot.addWidget(window)
    views = DeferredViews(window, PositionBuffer(capacity=None))
    window.setCentralWidget(views.view2d)
    return window, views


def test_the_steps_run_one_a_turn_so_what_arrives_meanwhile_waits_for_one_step(qtbot) -> None:
    """A timer due during a step (as a device shown connected, or a key) runs before the next
    step, not after all of them."""
    window, views = _window_with_views(qtbot)
    order: list[str] = []

    def first() -> None:
        order.append("first")
        QTimer.singleShot(0, lambda: order.append("meanwhile"))

    views.add(first, first=True)
    views.add(lambda: order.append("last"))
    with qtbot.waitSignal(views.ready, timeout=20_000):
        window.show()
    assert order == ["first", "meanwhile", "last"]
    assert window.findChild(QWidget, "positionView2d") is not None


def test_usable_comes_after_the_steps_and_before_the_views_and_plots(qtbot) -> None:
    window, views = _window_with_views(qtbot)
    order: list[str] = []
    views.add(lambda: order.append("plots"), plots=True)
    views.add(lambda: order.append("dock"))
    views.usable.connect(
        lambda: order.append(f"usable, 2D built: {views.view2d.real() is not None}")
    )
    assert not views.building()
    with qtbot.waitSignal(views.ready, timeout=20_000):
        window.show()
    assert order == ["dock", "usable, 2D built: False", "plots"]
    assert views.is_usable() and not views.building()


def test_build_now_runs_the_steps_left_at_once(qtbot) -> None:
    _window, views = _window_with_views(qtbot)
    order: list[str] = []
    views.add(lambda: order.append("a"))
    views.add(lambda: order.append("b"))
    with qtbot.waitSignal(views.ready, timeout=20_000):
        views.build_now()
    assert order == ["a", "b"] and views.is_ready()
    views.build_now()  # once only
    assert order == ["a", "b"]


def test_the_window_shows_before_opengl_is_imported(tmp_path: Path) -> None:
    code = """
import json, sys
from PySide6.QtWidgets import QApplication
from widgets.position_view_3d import share_opengl_contexts
share_opengl_contexts()
app = QApplication([])
import app.main
from app.window.main_window import MainWindow
window = MainWindow()
before = sorted(m for m in ("OpenGL", "pyqtgraph.opengl") if m in sys.modules)
window.views.build_now()
print(json.dumps({"before": before, "view2d": type(window.view2d).__name__}))
window.close()
"""
    env = {
        **os.environ,
        "QT_QPA_PLATFORM": "offscreen",
        "MOTIONPANEL_SETTINGS": str(tmp_path / "settings.ini"),
        "MOTIONPANEL_LOG_DIR": str(tmp_path / "logs"),
    }
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, timeout=50
    )
    assert out.returncode == 0, out.stderr
    result = json.loads(out.stdout.strip().splitlines()[-1])
    assert result == {"before": [], "view2d": "PositionView2D"}
