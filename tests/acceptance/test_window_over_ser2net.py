"""Issue 21: the panel drives a device on another machine through ser2net, by its plain
`rfc2217://HOST:PORT` URL, as an operator types it."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, numbers, wait_for, write_settings
from tests.support.ser2net_proc import SER2NET, Ser2netProcess

pytestmark = pytest.mark.skipif(SER2NET is None, reason="ser2net is not installed")


def test_jog_over_ser2net_reaches_the_device(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """`motionsim coxiris` served by ser2net; the panel opens rfc2217://127.0.0.1:PORT and the
    Right key moves the stage: the device's own record shows the DELTA_MOVE, and the session
    log notes that the server left the control lines unconfirmed."""
    sim = rig.sim("coxiris", "--speed", "100")
    server = Ser2netProcess(sim.path, tmp_path)
    try:
        settings = write_settings(
            tmp_path / "settings.ini", protocol="coxiris", port=server.url, jog_step=1.0
        )
        panel = rig.panel(
            any_screen, "--port", server.url, "--protocol", "coxiris", settings=settings
        )
        panel.wait_ready(b"DONE GET_SPEED")
        panel.activate()
        panel.key("Right")
        record = sim.record
        move = wait_for(
            lambda: record.commands("DELTA_MOVE"), 15.0, "the jog's DELTA_MOVE at the device"
        )
        assert numbers(move[0]) == [1.0, 0.0, 0.0], move[0].text
        wait_for(
            lambda: [n for n in panel.logs.notes() if "did not confirm the control lines" in n],
            10.0,
            "the session log's note on the unconfirmed control lines",
        )
        width, height = any_screen.size
        panel.screenshot(shots / f"ser2net-{width}x{height}.png")
    finally:
        server.stop()
