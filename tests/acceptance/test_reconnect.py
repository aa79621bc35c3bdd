"""Issue 19 item 11: the device vanishes and comes back under its name; the panel reconnects."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, wait_for, write_settings

RECONNECT_S = 20.0


def _vanish_and_return(rig: Rig, x: XServer, tmp_path: Path) -> None:
    link = tmp_path / "ttyStage"
    first = rig.sim("coxiris", "--speed", "5", link=link)
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=str(link), jog_step=10.0
    )
    panel = rig.panel(x, "--port", str(link), "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    panel.key("Right")  # 10 mm at 5 mm/s: 2 s under way
    wait_for(lambda: first.record.commands("DELTA_MOVE"), 10.0, "the jog at the first device")
    first.vanish()  # mid-move: killed, its link gone (as a pulled USB adapter's node)
    panel.wait_state("error", 15.0)
    second = rig.sim("coxiris", "--speed", "100", link=link)
    panel.wait_handshake(b"DONE GET_ID", RECONNECT_S, count=2)
    panel.wait_state("idle", 15.0)
    panel.key("Right")
    wait_for(
        lambda: [m.text for m in second.record.commands("DELTA_MOVE")],
        10.0,
        "the jog at the device that came back",
    )
    assert [m.text for m in second.record.commands("DELTA_MOVE")] == ["DELTA_MOVE 10 0 0"]


def test_device_back_under_its_name_is_reconnected(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """Killed mid-move, served again on the same link: a new handshake within 20 s, then a
    jog works."""
    _vanish_and_return(rig, x_server, tmp_path)


@pytest.mark.usefixtures("cpu_busy")
def test_device_back_under_its_name_is_reconnected_cpu_busy(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """The same with three `yes > /dev/null` running."""
    _vanish_and_return(rig, x_server, tmp_path)
