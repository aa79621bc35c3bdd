"""The window over a real pseudo-terminal to motionsim in another process."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from app.window.device import jobs
from app.window.main_window import MainWindow
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.timeout(40), pytest.mark.e2e]


@pytest.fixture
def sim(request: pytest.FixtureRequest) -> Iterator[SimProcess]:
    marker = request.node.get_closest_marker("sim_args")
    process = SimProcess("coxiris", *(marker.args if marker else ()))
    yield process
    if process.proc.poll() is None:
        assert process.stop() == 0


@pytest.mark.sim_args("--speed", "100")
def test_jog_over_a_real_pty(qtbot, window: MainWindow, sim: SimProcess) -> None:
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device(sim.path, "coxiris", 115200)
    window.jog_panel.jog_requested.emit("x", 5.0)
    qtbot.waitUntil(lambda: window.readout.position() == (5.0, 0.0, 0.0), timeout=5000)

    def console_shows_it() -> None:
        window.console.flush()
        assert "DONE DELTA_MOVE" in window.console.text()

    qtbot.waitUntil(console_shows_it, timeout=5000)


@pytest.mark.sim_args("--speed", "1")
def test_device_vanishing_mid_move(qtbot, window: MainWindow, sim: SimProcess) -> None:
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device(sim.path, "coxiris", 115200)
    received: list[bytes] = []
    window.worker.traffic.connect(
        lambda rs: received.extend(r.data for r in rs if r.direction == "rx")
    )
    window.worker.submit(jobs.MoveToJob(100, 0, 0))
    qtbot.waitUntil(lambda: b"ACK ABSOLUTE_MOVE" in b"".join(received), timeout=5000)
    sim.kill()
    qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=5000)
    assert not window.jog_panel.isEnabled()
    assert window.status_line.state() == "error"
    window.console.flush()
    text = window.console.text()
    assert "ACK ABSOLUTE_MOVE" in text
    assert "connection error: reading from" in text
    assert window.readout.status() == "lost-moving"  # the estimate at the loss, marked
