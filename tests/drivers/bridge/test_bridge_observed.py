"""Bridge mode's readout follows what the bridged traffic says: the window bridging motionsim (in
another process), motionctl (another process) moving the stage through the bridge and asking
its position; the readout shows it, marked as observed, never "not connected"."""

from __future__ import annotations

import pytest

from app.window.main_window import MainWindow
from tests.support.motionctl_run import run_motionctl
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.timeout(90)


def _motionctl(qtbot, port: str, protocol: str, *args: str) -> None:
    """Run the other program to its end; it must succeed."""
    done = run_motionctl(qtbot, "--port", port, "--protocol", protocol, *args)
    assert done.returncode == 0, (args, done.stdout, done.stderr)


@pytest.mark.parametrize("protocol", ["coxiris", "laser-frame"])
def test_the_readout_follows_the_bridged_traffic(qtbot, window: MainWindow, protocol) -> None:
    sim = SimProcess(protocol, "--instant")
    try:
        # The panel knew the stage at (28, 4), then let another program have it.
        _motionctl(qtbot, sim.path, protocol, "move", "28", "4", "0")
        with qtbot.waitSignal(window.settled, timeout=10_000):
            window.connect_device(sim.path, protocol, 115200)
        readout = window.readout
        qtbot.waitUntil(lambda: readout.text("x") == "28.00 mm", timeout=5000)
        window.disconnect_device()
        qtbot.waitUntil(lambda: window.connection_bar.state() == "disconnected", timeout=5000)
        assert readout.status() == "stale"

        window.connection_bar.set_bridge_mode(True)
        path = window.connection.start_bridge(sim.path, protocol, 115200)
        assert path, window.status_line.message()
        assert readout.status() == "bridged"  # not "last known position: not connected"
        assert readout.text("x") == "— mm"  # the other program may move it: not shown as known

        _motionctl(qtbot, path, protocol, "move", "5", "5", "0")
        qtbot.waitUntil(lambda: readout.text("x") == "5.00 mm", timeout=5000)
        assert readout.text("y") == "5.00 mm"
        _motionctl(qtbot, path, protocol, "position")
        qtbot.waitUntil(lambda: readout.status() == "observed", timeout=5000)
        assert (readout.text("x"), readout.text("y")) == ("5.00 mm", "5.00 mm")
        badge = readout.status_label.text()
        assert badge.startswith("observed in the bridged traffic"), badge
        assert not readout.measured_label.isVisibleTo(readout)  # nothing measured by the panel
        for shown in (badge, window.status_line.message(), window.status_line.state()):
            assert "not connected" not in shown.lower(), shown
        assert window.connection_bar.state() == "connected"
        assert window.buffer.last()[1:] == pytest.approx((5.0, 5.0, 0.0))  # the views follow

        window.connection.stop_bridge()
        qtbot.waitUntil(lambda: window.connection.bridge is None, timeout=5000)
        assert readout.status() == "stale"  # the last observed, now no longer followed
        assert readout.text("x") == "5.00 mm"
    finally:
        sim.kill()
