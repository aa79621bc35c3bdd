"""The window on a pi-frame (no position feedback, absolute targets only): where nothing is
kept for the port the position is unknown and a jog is refused before anything is sent; where
motionctl (or another panel) left the stage, the window goes on from there, and a jog moves
by the step from that place, as the simulator's own axes show (motionsim in another process)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.window.main_window import MainWindow
from tests.support import e2e as e2e_support
from tests.support.simproc import SimProcess
from widgets import status_line as status

pytestmark = [pytest.mark.timeout(60), pytest.mark.e2e]
TICKS_PER_MM = 100  # the pi-frame's default: `where` answers ticks


FRAME = 25  # bytes of a pi-frame frame


@pytest.fixture
def record(tmp_path: Path) -> Path:
    """Where the simulator records what it reads."""
    return tmp_path / "device.log"


@pytest.fixture
def device(record: Path) -> Iterator[SimProcess]:
    """motionsim pi-frame on a pty, with its control channel (`where`) and its record."""
    sim = SimProcess("pi-frame", "--instant", "--record", str(record), control=True)
    try:
        yield sim
    finally:
        sim.stop()


def _where_mm(sim: SimProcess) -> tuple[float, ...]:
    answer = sim.fault("where").split()
    return tuple(float(value) / TICKS_PER_MM for value in answer[-3:])


def _connect(qtbot, window: MainWindow, path: str) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device(path, "pi-frame", 115200)
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=8000)


def _jog_x(qtbot, window: MainWindow) -> None:
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)


def test_a_jog_from_an_unknown_place_is_refused_and_nothing_is_sent(
    qtbot, window: MainWindow, device: SimProcess, record: Path
) -> None:
    _connect(qtbot, window, device.path)
    assert window.readout.status() == "uncounted"
    _jog_x(qtbot, window)
    refusal = "jog by (1, 0, 0) mm refused: the position is unknown"
    qtbot.waitUntil(lambda: refusal in window.status_line.message(), timeout=5000)
    assert "moves only to absolute targets" in window.status_line.message()
    # A Go to after it: the worker runs jobs in order, so a jog sent would have come first.
    window.coordinates.go_requested.emit("absolute", (0.5, 0.0, 0.0))
    qtbot.waitUntil(lambda: _where_mm(device) == (0.5, 0.0, 0.0), timeout=8000)
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=8000)
    assert len(e2e_support.device_received(record)) == FRAME  # the Go to's frame alone
    assert window.readout.status() == "live"  # an absolute target: a known place again


def test_the_window_goes_on_from_where_motionctl_left_the_stage(
    qtbot, window: MainWindow, device: SimProcess
) -> None:
    # motionctl runs with the window's settings file (MOTIONPANEL_SETTINGS, set for the window).
    for args in (("set-home",), ("move", "2", "1", "0.5")):
        done = e2e_support.motionctl("pi-frame", device.path, *args, timeout=30)
        assert done.returncode == 0, done.stderr
    assert _where_mm(device) == (2.0, 1.0, 0.5)
    _connect(qtbot, window, device.path)
    assert window.readout.position() == (2.0, 1.0, 0.5)
    assert window.readout.status() == "live"
    _jog_x(qtbot, window)
    qtbot.waitUntil(lambda: _where_mm(device) == (3.0, 1.0, 0.5), timeout=8000)
    qtbot.waitUntil(lambda: window.readout.position() == (3.0, 1.0, 0.5), timeout=8000)
