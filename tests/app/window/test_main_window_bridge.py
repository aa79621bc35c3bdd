"""Bridge mode in the window: motionsim as the device, motionctl as the other program, every
frame shown decoded, motion controls off, the session log keeping every byte."""

from __future__ import annotations

import subprocess

import pytest
from PySide6.QtCore import Qt

from app.window.main_window import MainWindow
from drivers.traffic.log_reader import read_log
from tests.support.motionctl_run import run_motionctl
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.timeout(60)


@pytest.fixture
def sim():
    process = SimProcess("coxiris", "--instant")
    yield process
    process.kill()


def _motionctl(qtbot, port: str, *args: str) -> subprocess.CompletedProcess[str]:
    """Run the other program while the window's event loop keeps going."""
    return run_motionctl(qtbot, "--port", port, "--protocol", "coxiris", *args)


def test_a_program_drives_the_device_through_the_bridge(qtbot, window: MainWindow, sim) -> None:
    bar = window.connection_bar
    bar.set_port(sim.path)
    bar.set_protocol("coxiris")
    bar.set_bridge_mode(True)
    qtbot.mouseClick(bar.connect_button, Qt.MouseButton.LeftButton)
    assert window.connection.bridge is not None, window.status_line.message()
    path = window.connection.bridge.bridge.path
    assert bar.state() == "connected" and bar.connect_button.text() == "Disconnect"
    assert not window.jog_panel.isEnabled() and not window.coordinates.isEnabled()
    assert not bar.bridge_check.isEnabled()

    moved = _motionctl(qtbot, path, "move", "1", "2", "3")
    assert moved.returncode == 0, moved.stderr

    def shown() -> None:
        window.console.flush()
        text = window.console.text()
        assert "TX  ABSOLUTE_MOVE 1 2 3\\n" in text
        # (without its line end where the reply came in two reads split at its CR: the line end
        # that comes in a later read than its line is not shown with it; the log has it)
        assert "RX  ACK ABSOLUTE_MOVE" in text

    qtbot.waitUntil(shown, timeout=5000)
    index = window.console.index
    move = next(n for n in range(len(index)) if index.line(n).meaning == "ABSOLUTE_MOVE 1 2 3")
    assert index.line(index.line(move).pair).meaning == "ACK ABSOLUTE_MOVE"

    qtbot.mouseClick(bar.connect_button, Qt.MouseButton.LeftButton)  # Disconnect
    qtbot.waitUntil(lambda: window.connection.bridge is None, timeout=5000)
    assert bar.state() == "disconnected"
    records = read_log(window.link.session_log_path)
    sent = b"".join(r.data for r in records if r.direction == "tx")
    assert b"ABSOLUTE_MOVE 1 2 3\n" in sent  # the session log has every byte
    received = b"".join(r.data for r in records if r.direction == "rx")
    assert b"ACK ABSOLUTE_MOVE\r\n" in received  # the line end the console may show apart


def test_the_device_vanishing_ends_the_bridge_with_an_error(qtbot, window: MainWindow, sim):
    window.connection_bar.set_bridge_mode(True)
    assert window.connection.start_bridge(sim.path, "coxiris", 115200)
    sim.kill()
    qtbot.waitUntil(lambda: window.connection.bridge is None, timeout=10_000)
    assert window.connection_bar.state() == "error"
    assert "went away" in window.status_line.message()


def test_a_missing_device_is_refused_clearly(window: MainWindow) -> None:
    assert window.connection.start_bridge("/dev/does-not-exist", "coxiris", 115200) is None
    assert window.connection_bar.state() == "error"
    assert "does-not-exist" in window.status_line.message()
