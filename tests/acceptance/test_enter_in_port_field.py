"""Issue 19 item 17: Enter in the Port field connects, with a real keyboard."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, wait_for


def test_enter_in_the_port_field_connects(x_server: XServer, rig: Rig, tmp_path: Path) -> None:
    """Started on a port that is not there; the operator types the device's path and presses
    Return: the device is asked who it is."""
    sim = rig.sim("coxiris", "--speed", "100")
    panel = rig.panel(x_server, "--port", str(tmp_path / "no-such-port"), "--protocol", "coxiris")
    wait_for(lambda: panel.state() in ("error", "disconnected"), 20.0, "the failed connection")
    panel.key("alt+p")  # the Port field (its label's mnemonic)
    panel.key("ctrl+a")
    panel.type(sim.path)
    panel.key("Return")
    wait_for(lambda: sim.record.commands("GET_ID"), 15.0, "GET_ID at the device")
    panel.wait_handshake(b"DONE GET_ID")
