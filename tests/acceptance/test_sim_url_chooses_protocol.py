"""Issue 19 items 14 and 16: a sim:// port names its protocol; a log that changed device is
decoded part by part."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, motionctl


def test_sim_url_sets_the_protocol_and_the_log_decodes_each_part(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """Connected to a COXIRIS device, which goes away; the operator types `sim://visiomex` in
    Port (Protocol still says coxiris) and presses Return: it connects as Visiomex, and
    `motionctl log decode` reads each part of the session log by its own protocol."""
    sim = rig.sim("coxiris", "--speed", "100")
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "coxiris")
    panel.wait_ready(b"DONE GET_SPEED")
    sim.kill()
    panel.wait_state("error", 15.0)
    panel.type_port("sim://visiomex")
    note = next(n for n in panel.logs.notes() if n.startswith("connected to sim://"))
    assert "(visiomex" in note, note
    panel.wait_state("idle", 20.0)
    logs = sorted(panel.logs.folder.glob("session-*.log"))
    decoded = motionctl("--port", "none", "--protocol", "coxiris", "log", "decode", str(logs[-1]))
    assert decoded.returncode == 0, decoded.stderr
    before, after = decoded.stdout.split("connected to sim://", 1)
    assert "GET_ID" in before, before[:2000]
    assert "unreadable" not in after.lower() and "GET_" not in after, after[:2000]
    assert "Checkpoint 2" in after, after[:2000]  # the Visiomex banner, read as Visiomex reads it
