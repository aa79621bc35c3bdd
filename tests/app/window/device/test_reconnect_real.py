"""The device vanishes and comes back under the same name (`motionsim --link`): the window
connects again by itself, with nothing faked: real processes, a real pty, no emitted signals."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from app.window.main_window import MainWindow
from tests.support.relay import GuiRelay, wait_in_gui
from tests.support.simproc import SimProcess

pytestmark = [
    pytest.mark.e2e,
    pytest.mark.timeout(90),
    pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX"),
]

DEADLINE_MS = 20_000


def _connected(window: MainWindow) -> bool:
    return window.connection_bar.state() == "connected" and window.jog_panel.isEnabled()


def _console(window: MainWindow) -> str:
    window.console.flush()
    return window.console.text()


@pytest.mark.parametrize("how", ("killed", "vanish mid-move"))
def test_a_device_that_comes_back_under_its_name_is_connected_again(
    qtbot, window: MainWindow, tmp_path: Path, how: str
) -> None:
    link = str(tmp_path / "stage")
    sim = SimProcess("coxiris", "--speed", "5", "--link", link, control=True)
    again: SimProcess | None = None
    try:
        with qtbot.waitSignal(window.settled, timeout=DEADLINE_MS):
            window.connect_device(link, "coxiris", 115200)
        if how == "killed":
            sim.kill()
        else:
            window.jog_panel.jog_requested.emit("x", 10.0)  # 2 s at 5 mm/s
            qtbot.waitUntil(lambda: window.machine.moving, timeout=DEADLINE_MS)
            sim.fault("vanish")
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=DEADLINE_MS)
        assert f"connecting again when {link} is back" in window.status_line.message()
        again = SimProcess("coxiris", "--instant", "--link", link)  # a new device process
        qtbot.waitUntil(lambda: _connected(window), timeout=DEADLINE_MS)
        assert f"{link} is back: connecting again" in _console(window)
        assert window.readout.position() == (0.0, 0.0, 0.0)  # read from the new device
        assert window.readout.status() == "live"
        with wait_in_gui(qtbot, window.worker.job_finished, timeout=DEADLINE_MS):
            window.jog_panel.jog_requested.emit("x", 1.0)  # and it works
        qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=5000)
    finally:
        window.disconnect_device()
        for process in (sim, again):
            if process is not None and process.proc.poll() is None:
                process.stop()


def test_disconnecting_stops_watching_for_the_port(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    link = str(tmp_path / "stage")
    sim = SimProcess("coxiris", "--instant", "--link", link)
    again: SimProcess | None = None
    try:
        with qtbot.waitSignal(window.settled, timeout=DEADLINE_MS):
            window.connect_device(link, "coxiris", 115200)
        sim.kill()
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=DEADLINE_MS)
        window.disconnect_device()  # the operator gives up on it
        qtbot.waitUntil(lambda: window.worker._watch is None, timeout=5000)
        states = GuiRelay(window.worker.state_changed)
        again = SimProcess("coxiris", "--instant", "--link", link)
        # Longer than the watch's retry (PORT_RETRY_S): the worker says nothing, tries nothing.
        with qtbot.waitSignal(states.fired, timeout=7000, raising=False) as changed:
            pass
        assert not changed.signal_triggered
        assert window.connection_bar.state() == "error"
    finally:
        for process in (sim, again):
            if process is not None and process.proc.poll() is None:
                process.stop()
