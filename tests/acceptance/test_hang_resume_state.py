"""Issue 19 item 12: the state follows the device as soon as it answers again."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, wait_for


def test_state_is_idle_soon_after_the_device_resumes(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """`hang`, a jog, then `resume`: Idle within 8 s (the issue saw Busy for about 60 s)."""
    sim = rig.sim("coxiris", "--speed", "100", control=True)
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "coxiris")
    panel.wait_ready(b"DONE GET_SPEED")
    sim.fault("hang")
    panel.key("Right")
    wait_for(lambda: panel.state() in ("busy", "error", "moving"), 15.0, "the hung device seen")
    sim.fault("resume")
    panel.wait_state("idle", 8.0)
