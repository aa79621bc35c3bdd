"""The window paints before its heavy parts are built: numpy, pyqtgraph, the traffic console,
the parameter and device docks, the serial worker and the protocol modules come just after the
first paint, and get the calls made before."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from PySide6.QtWidgets import QDockWidget

from app.window.main_window import MainWindow
from drivers.protocols.registry import get_protocol_class, has_variants, protocol_names
from widgets.lazy_view import LazyPart, built

ROOT = Path(__file__).resolve().parents[3]

HEAVY = (
    "numpy",
    "pyqtgraph",
    "OpenGL",
    "app.window.console.traffic_console",
    "app.window.console.display",
    "app.window.console.export",
    "app.window.console.filter_bar",
    "app.window.console.navigation",
    "app.window.console.pacing",
    "app.window.console.status",
    "app.window.docks.device_docks",
    "app.window.docks.parameter_dock",
    "app.window.console.log_viewer",
    "drivers.traffic.index",
    "drivers.traffic.lines",
    "drivers.traffic.pairing",
    "drivers.traffic.search",
    "drivers.traffic.spool",
    "serial.tools.list_ports",
    # the serial worker, its thread, the jobs and the motion engine under them
    "app.window.device.worker",
    "app.window.device.worker_thread",
    "app.window.device.jobs",
    "app.window.device.move_estimate",
    "drivers.device.motion",
    "drivers.device.client",
    "drivers.link.transport",
    "serial",
    # the protocols (the connection bar knows which have wire variants without them)
    "drivers.protocols.base",
    "drivers.protocols.coxiris",
    "drivers.protocols.commands",
    "drivers.protocols.events",
)


def test_nothing_heavy_is_imported_before_the_first_paint(tmp_path: Path) -> None:
    code = f"""
import json, sys
from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QApplication
app = QApplication([])
from app.window.main_window import MainWindow
window = MainWindow()
window.connect_device("loop://", "coxiris", 115200)  # (a simulator imports numpy)
seen = {{}}


class Painted(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint and "painted" not in seen:
            seen["painted"] = sorted(m for m in {HEAVY!r} if m in sys.modules)
        return False


def ready():
    seen["ready"] = sorted(
        m for m in ("numpy", "app.window.console.traffic_console", "app.window.device.worker") if m
        in sys.modules
    )
    QTimer.singleShot(0, app.quit)


watcher = Painted()
window.installEventFilter(watcher)
window.views.ready.connect(ready)
window.show()
QTimer.singleShot(20_000, app.quit)
app.exec()
window.close()
print(json.dumps(seen))
"""
    env = {
        **os.environ,
        "QT_QPA_PLATFORM": "offscreen",
        "MOTIONPANEL_SETTINGS": str(tmp_path / "settings.ini"),
        "MOTIONPANEL_LOG_DIR": str(tmp_path / "logs"),
    }
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, timeout=60
    )
    assert out.returncode == 0, out.stderr
    seen = json.loads(out.stdout.strip().splitlines()[-1])
    assert seen == {
        "painted": [],
        "ready": ["app.window.console.traffic_console", "app.window.device.worker", "numpy"],
    }


@pytest.fixture
def unshown(qtbot, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> MainWindow:
    """A main window not shown yet (nothing deferred is built), settings in a temporary file."""
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(tmp_path / "settings.ini"))
    win = MainWindow()
    qtbot.addWidget(win)
    return win


def test_the_device_is_shown_once_the_docks_are_built_and_the_views_follow(
    qtbot, unshown: MainWindow
) -> None:
    """Shown connected means usable: the console, the device docks and the menus are in; the
    views (and the timeline's plots) may come a few steps later."""
    seen: list[tuple[bool, bool, bool]] = []
    unshown.connection.device_shown.connect(
        lambda: seen.append(
            (unshown.views.is_usable(), built(unshown.console), built(unshown.devices))
        )
    )
    unshown.show()
    unshown.connect_device("sim://coxiris?instant=1", "coxiris", 115200)
    qtbot.waitUntil(lambda: bool(seen) and unshown.views.is_ready(), timeout=20_000)
    assert seen == [(True, True, True)]
    assert unshown.timeline is not None and unshown.timeline.plots is not None
    assert unshown.view2d.objectName() == "positionView2d"


def test_the_deferred_parts_get_the_calls_made_before_them(qtbot, unshown: MainWindow) -> None:
    win = unshown
    assert not built(win.console) and not built(win.devices) and not built(win.parameters)
    assert not win.views.is_ready()
    assert win.link.thread is None  # the serial worker too
    win.connect_device("loop://", "coxiris", 115200)
    win.console.append_note("before the console")
    win.show()
    qtbot.waitUntil(win.views.is_ready, timeout=10_000)
    assert win.link.thread is not None and win.worker_thread.thread.isRunning()
    for part in (win.console, win.devices, win.parameters, win.buffer):
        assert built(part) and not isinstance(part, LazyPart)
    assert win.findChild(QDockWidget, "rawConsoleDock").widget() is win.console
    assert win.console.objectName() == "rawConsole"
    assert win.findChild(QDockWidget, "parameterEditor").widget() is win.parameters.editor
    for name in ("firmataPanelDock", "piFramePanelDock", "arcEntryDock", "dwellEntryDock"):
        assert win.findChild(QDockWidget, name).widget() is not None
    assert win.timeline_dock.widget() is win.timeline
    win.console.flush()
    text = win.console.text()
    connecting = text.index("connecting to loop:// (coxiris")
    assert connecting < text.index("before the console")
    assert "session log:" in text.splitlines()[0]  # stamped when made, before the connection
    # the connection asked for before the worker existed is made once it is: the worker asks
    # (loop:// echoes it; no device answers)

    def asked() -> None:
        win.console.flush()
        assert "GET_ID" in win.console.text()

    qtbot.waitUntil(asked, timeout=10_000)
    assert win.console.index.protocol is not None  # the console decodes it
    win.close()


def test_a_window_closed_before_its_first_paint_builds_nothing(unshown: MainWindow) -> None:
    win = unshown
    win.connect_device("loop://", "coxiris", 115200)
    win.close()
    assert not built(win.console)
    assert win.link.thread is None  # no worker, no thread: the connection is not made
    assert win.link.pending_log is None or win.link.pending_log.closed  # the session log is closed
    # Built after the close (a late paint's building: the docks want the worker), it is a
    # stopped one, and it was asked for nothing.
    win.views.build_now()
    assert not win.worker_thread.thread.isRunning()
    win.console.flush()
    assert "GET_ID" not in win.console.text()


def test_the_worker_is_built_when_asked_for_before_the_first_paint(
    qtbot, unshown: MainWindow
) -> None:
    win = unshown
    assert win.link.thread is None
    worker = win.worker  # (a test, or a part built early, may need it)
    assert win.worker_thread.thread.isRunning() and worker is win.worker_thread.worker
    with qtbot.waitSignal(win.settled, timeout=10_000):
        win.connect_device("sim://coxiris", "coxiris", 115200)  # done at once
    win.close()
    assert not win.worker_thread.thread.isRunning()


@pytest.mark.parametrize("name", protocol_names())
def test_the_registry_knows_which_protocols_have_variants(name: str) -> None:
    assert has_variants(name) == bool(get_protocol_class(name).variants)
