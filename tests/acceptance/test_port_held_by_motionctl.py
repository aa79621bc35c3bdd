"""Issue 19 item 7: a port the panel holds cannot be opened by another program."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, hold, motionctl


def test_motionctl_cannot_open_the_panels_port(x_server: XServer, rig: Rig, tmp_path: Path) -> None:
    """motionctl on the panel's device: exit 3 naming the port, and no byte of it at the device."""
    sim = rig.sim("coxiris", "--speed", "100")
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "coxiris")
    panel.wait_ready(b"DONE GET_SPEED")
    done = motionctl("--port", sim.path, "--protocol", "coxiris", "raw", "GET_MAX_SPEED")
    assert done.returncode == 3, (done.returncode, done.stdout, done.stderr)
    assert sim.path in done.stderr, done.stderr
    hold(0.5, every=sim.record.observe)
    asked = [line.text for line in sim.record.received_lines() if line.text == "GET_MAX_SPEED"]
    assert asked == ["GET_MAX_SPEED"], "only the panel's own GET_MAX_SPEED reached the device"
