"""A link lost during a move shows the estimate at the loss, marked, not the move's start; after
reconnecting, the device's own answer (issue 28, item 2). Real processes, a real pty."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from app.window.main_window import MainWindow
from tests.simproc import SimProcess

pytestmark = [
    pytest.mark.e2e,
    pytest.mark.timeout(90),
    pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX"),
]

DEADLINE_MS = 20_000


def _where(sim: SimProcess) -> tuple[float, float, float]:
    """The simulator's own axes (`where`), in mm (COXIRIS's units)."""
    answer = sim.fault("where").removeprefix("ok ").split()
    values = [float(v) for v in answer[-3:]]
    return values[0], values[1], values[2]


def test_the_estimate_at_the_loss_then_the_devices_answer(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    link = str(tmp_path / "stage")
    sim = SimProcess("coxiris", "--speed", "5", "--link", link, control=True)
    again: SimProcess | None = None
    try:
        with qtbot.waitSignal(window.settled, timeout=DEADLINE_MS):
            window.connect_device(link, "coxiris", 115200)
        window.coordinates.set_values(-40, 0, 0)  # 8 s at 5 mm/s
        window.coordinates.go_button.click()
        qtbot.waitUntil(lambda: window.readout.status() == "estimated", timeout=DEADLINE_MS)
        qtbot.waitUntil(lambda: window.readout.position()[0] < -5.0, timeout=DEADLINE_MS)  # type: ignore[index]
        sim.fault("vanish")
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=DEADLINE_MS)
        assert window.readout.status() == "lost-moving"
        assert "estimated when the link was lost" in window.readout.status_label.text()
        x = window.readout.position()[0]  # type: ignore[index]
        assert -40.0 < x < -5.0, x  # between the start and the target, not the start
        again = SimProcess("coxiris", "--instant", "--link", link, control=True)
        qtbot.waitUntil(
            lambda: window.connection_bar.state() == "connected" and window.jog_panel.isEnabled(),
            timeout=DEADLINE_MS,
        )
        qtbot.waitUntil(lambda: window.readout.status() == "live", timeout=DEADLINE_MS)
        assert window.readout.position() == pytest.approx(_where(again), abs=0.01)
    finally:
        window.disconnect_device()
        sim.kill()
        if again is not None:
            again.kill()
