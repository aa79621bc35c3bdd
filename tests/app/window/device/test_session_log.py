"""The session log: every byte on disk as it crosses, even when the panel is killed."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from app.common.session_log import PATTERN, open_session_log, prune
from drivers.traffic.log_reader import LogError
from tests.support.e2e import stream as _bytes
from tests.support.simproc import ROOT, SimProcess

pytestmark = pytest.mark.timeout(60)


def _polls_received(record: Path) -> int:
    """GET_POSITION commands the device has received so far (its replies name it too)."""
    try:
        return _bytes(record, "RX").count(b"GET_POSITION\n")
    except LogError:  # a line still being written
        return 0


def test_old_sessions_are_pruned_to_the_budget(tmp_path: Path) -> None:
    for index in range(5):
        path = tmp_path / f"session-2026010{index}-000000-1.log"
        path.write_bytes(b"x" * 1000)
        os.utime(path, (index, index))
    path, stream = open_session_log(tmp_path)
    stream.close()
    deleted = prune(tmp_path, budget=2500, keep=path)
    assert [p.name[8:16] for p in deleted] == ["20260100", "20260101", "20260102"]
    assert path.exists() and len(list(tmp_path.glob(PATTERN))) == 3


@pytest.mark.e2e
def test_a_killed_panel_leaves_its_log_complete(tmp_path: Path) -> None:
    record = tmp_path / "device.log"
    sim = SimProcess("coxiris", "--record", str(record))
    logs = tmp_path / "logs"
    env = dict(os.environ, MOTIONPANEL_LOG_DIR=str(logs), QT_QPA_PLATFORM="offscreen")
    env["MOTIONPANEL_SETTINGS"] = str(tmp_path / "settings.ini")
    env.pop("DISPLAY", None)  # offscreen under a display crashes in pyqtgraph's GL (issue 11)
    panel = subprocess.Popen(
        [sys.executable, "-m", "app.main", "--port", sim.path, "--protocol", "coxiris"],
        cwd=ROOT,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:  # the idle poll asks GET_POSITION every second
            if _polls_received(record) >= 6:
                break
            time.sleep(0.1)  # polling another process's file: nothing to wait on
        panel.send_signal(signal.SIGKILL)
        panel.wait(10)
    finally:
        if panel.poll() is None:
            panel.kill()
        sim.stop()
    (session,) = logs.glob(PATTERN)
    # Every byte the device received is in the panel's log (logged before it is written, so
    # the log may end with one write the kill cut short), and what the panel read is what the
    # device sent (the device may have sent a last reply the panel never read).
    sent, received = _bytes(session, "TX"), _bytes(session, "RX")
    assert sent.startswith(_bytes(record, "RX"))
    assert len(sent) - len(_bytes(record, "RX")) <= len(b"GET_POSITION\n")
    assert _bytes(record, "TX").startswith(received)
    assert sent.count(b"GET_POSITION") >= 6


def test_a_disconnect_and_a_quit_are_noted_as_such(qtbot, tmp_path: Path, monkeypatch) -> None:
    from app.window.main_window import MainWindow  # (the window's tests only need Qt)
    from drivers.traffic.log_reader import read_log

    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(tmp_path / "settings.ini"))
    window = MainWindow()
    qtbot.addWidget(window)
    window.show()
    with qtbot.waitSignal(window.settled, timeout=10_000):
        window.connect_device("sim://coxiris?speed=100", "coxiris", 115200)
    path = window.link.session_log_path
    assert path is not None
    window.disconnect_device()
    qtbot.waitUntil(lambda: window.connection_bar.state() == "disconnected", timeout=10_000)
    window.close()
    assert not window.worker_thread.thread.isRunning()
    notes = [r.note for r in read_log(path) if r.note]
    assert "disconnected from sim://coxiris?speed=100" in notes
    assert notes[-1] == "Motion Panel quit; the session log ends here"
    assert not any("turned off" in note for note in notes)
