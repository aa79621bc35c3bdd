"""After the device hangs and resumes (`motionsim --control`), the machine state follows it as
soon as it answers again: never Busy with a command that was dropped while it hung."""

from __future__ import annotations

import pytest

from app.window.main_window import MainWindow
from tests.support.simproc import SimProcess
from widgets import status_line as status

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60)]

WAIT_MS = 20_000


def _sent(window: MainWindow) -> bytes:
    window.console.flush()
    return b"".join(data for direction, data, _ in window.console.records() if direction == "tx")


def test_a_command_dropped_while_the_device_hung_leaves_no_busy_state(
    qtbot, window: MainWindow
) -> None:
    sim = SimProcess("coxiris", "--instant", control=True)
    try:
        with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
            window.connect_device(sim.path, "coxiris", 115200)
        window.worker.poll_idle_s = 0.2
        sim.fault("hang")
        # The idle position read goes out and is not answered: the worker waits for it.
        before = _sent(window).count(b"GET_POSITION")
        qtbot.waitUntil(lambda: _sent(window).count(b"GET_POSITION") > before, timeout=WAIT_MS)
        assert window.connection_bar.state() == "connected"
        window.jog_panel.jog_requested.emit("x", 1.0)  # queued behind the unanswered read
        assert window.status_line.state() == status.BUSY
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=WAIT_MS)
        window.console.flush()
        assert "not sent: jog" in window.console.text()  # dropped, and said so
        sim.fault("resume")
        qtbot.waitUntil(lambda: window.connection_bar.state() == "connected", timeout=WAIT_MS)
        # As soon as it answers: idle, not busy with the jog that was never sent.
        qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=3000)
        assert window.jog_panel.isEnabled()
    finally:
        window.disconnect_device()
        if sim.proc.poll() is None:
            sim.stop()


def test_the_idle_reads_go_on_at_once_after_a_resume(qtbot, window: MainWindow) -> None:
    sim = SimProcess("coxiris", "--instant", control=True)
    try:
        with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
            window.connect_device(sim.path, "coxiris", 115200)
        window.worker.poll_idle_s = 0.2
        sim.fault("hang")
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=WAIT_MS)
        sim.fault("resume")
        qtbot.waitUntil(lambda: window.connection_bar.state() == "connected", timeout=WAIT_MS)
        assert window.status_line.state() == status.IDLE
        reads = _sent(window).count(b"GET_POSITION")
        # idle reads every 0.2 s again: several within a second or two
        qtbot.waitUntil(lambda: _sent(window).count(b"GET_POSITION") >= reads + 3, timeout=3000)
        assert window.status_line.state() == status.IDLE
    finally:
        window.disconnect_device()
        if sim.proc.poll() is None:
            sim.stop()
