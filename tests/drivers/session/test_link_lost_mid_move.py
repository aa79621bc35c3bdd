"""A link lost during a move shows the estimate at the loss, marked, not the move's start; after
reconnecting, the device's own answer (issue 28, item 2). Real processes, a real pty."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from app.window.main_window import MainWindow
from tests.support.simproc import SimProcess

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


@pytest.fixture
def devices(tmp_path: Path):
    """The devices served on one link in turn (each killed at the end)."""
    served: list[SimProcess] = []
    yield served
    for sim in served:
        sim.kill()


def test_the_estimate_at_the_loss_then_the_devices_answer(
    qtbot, window: MainWindow, tmp_path: Path, devices: list[SimProcess]
) -> None:
    link = str(tmp_path / "stage")
    devices.append(SimProcess("coxiris", "--speed", "5", "--link", link, control=True))
    with qtbot.waitSignal(window.settled, timeout=DEADLINE_MS):
        window.connect_device(link, "coxiris", 115200)
    window.coordinates.set_values(-40, 0, 0)  # 8 s at 5 mm/s
    window.coordinates.go_button.click()
    qtbot.waitUntil(lambda: window.readout.status() == "estimated", timeout=DEADLINE_MS)
    qtbot.waitUntil(lambda: _x(window) < -5.0, timeout=DEADLINE_MS)
    devices[0].fault("vanish")
    qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=DEADLINE_MS)
    assert window.readout.status() == "lost-moving"
    assert "estimated when the link was lost" in window.readout.status_label.text()
    assert -40.0 < _x(window) < -5.0, _x(window)  # between the start and the target
    again = SimProcess("coxiris", "--instant", "--link", link, control=True)
    devices.append(again)
    qtbot.waitUntil(
        lambda: window.connection_bar.state() == "connected" and window.jog_panel.isEnabled(),
        timeout=DEADLINE_MS,
    )
    qtbot.waitUntil(lambda: window.readout.status() == "live", timeout=DEADLINE_MS)
    assert window.readout.position() == pytest.approx(_where(again), abs=0.01)
    window.disconnect_device()


def _x(window: MainWindow) -> float:
    shown = window.readout.position()
    return shown[0] if shown is not None else 0.0
