"""A stop the operator asked for is said as a stop, and a stopped move's target goes (issue 28,
items 23 and 25)."""

from __future__ import annotations

import threading

import pytest
from PySide6.QtCore import Qt

from app.common.macros import Macro
from app.window.device import jobs
from app.window.main_window import MainWindow
from widgets import status_line as status

pytestmark = pytest.mark.timeout(40)


def _connect(qtbot, win: MainWindow, url: str, protocol: str) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(url, protocol, 115200)


def _idle(win: MainWindow) -> bool:
    return win.status_line.state() == status.IDLE and not win.job_desk.running_alone


def test_a_held_laser_jog_let_go_is_a_stop_not_an_error(qtbot, window: MainWindow) -> None:
    """Two jog steps queued, the stop of a release: the first halts, the second is not sent;
    the status line says so as information, the state is Idle, and no target is drawn."""
    _connect(qtbot, window, "sim://laser-frame", "laser-frame")
    window.speed.set_value(10)
    window.speed.apply()
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    assert window.submit_job(jobs.MoveByJob(10.0, 0.0, 0.0))
    assert window.submit_job(jobs.MoveByJob(10.0, 0.0, 0.0))
    qtbot.waitUntil(lambda: window.view2d.target() is not None, timeout=5000)
    qtbot.waitUntil(lambda: (window.readout.position() or (0, 0, 0))[0] > 1.0, timeout=5000)
    window.worker.stop_now()  # what letting go of a held jog does on a device with a stop
    said = window.status_line.message
    qtbot.waitUntil(lambda: "stopped before it was sent" in said(), timeout=5000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    assert window.status_line.message_kind() == status.INFO, window.status_line.message()
    assert "failed" not in window.status_line.message()
    assert window.status_line.state() == status.IDLE
    assert window.view2d.target() is None
    assert window.view3d.target() is None
    assert not window.machine.failed


def test_a_macro_stopped_with_esc_is_said_as_a_stop(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://coxiris", "coxiris")
    macro = Macro("square", "coxiris", ("wait 5", "move 1 0 0"))
    assert window.submit_job(jobs.MacroJob(macro))
    qtbot.waitUntil(lambda: "step 1/2" in window.status_line.message(), timeout=5000)
    window.stop_action.trigger()  # Esc
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    assert window.status_line.message_kind() == status.INFO, window.status_line.message()
    assert window.status_line.message() == "macro square stopped during step 1"
    assert window.status_line.state() == status.IDLE


def test_a_macro_stopped_before_it_started_leaves_nothing_busy(qtbot, window: MainWindow) -> None:
    """Stop while the macro is still queued: it is dropped unrun, and the state is Idle."""
    _connect(qtbot, window, "sim://coxiris", "coxiris")
    held, release = threading.Event(), threading.Event()

    def hold(busy: bool) -> None:  # in the worker's thread: it runs the refresh, then waits
        if busy and not held.is_set():
            held.set()
            release.wait(5.0)

    window.worker.busy_changed.connect(hold, Qt.ConnectionType.DirectConnection)
    window.worker.submit(jobs.RefreshJob())  # ahead of it: the macro waits in the queue
    assert held.wait(5.0)
    assert window.submit_job(jobs.MacroJob(Macro("square", "coxiris", ("wait 5",))))
    window.stop_action.trigger()
    release.set()
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=5000)
    assert "not sent: macro square" in window.status_line.message()
    assert window.machine.busy_job is None
