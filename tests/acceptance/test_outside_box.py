"""Issue 19 item 3: outside its box, the stage may be jogged back towards it, never further."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import (
    XServer,
    colour_count,
    motionctl,
    numbers,
    wait_for,
    write_settings,
)

BOX = ((-50.0, 50.0), (-50.0, 50.0), (-50.0, 50.0))
OUTSIDE_NOTICE = 0xFFF3E0  # the readout's "outside its travel limits" notice (background)


def test_jog_back_towards_the_box_is_allowed(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Stage at X 100, box ±50, step 10: Left jogs to 90 (the readout says the stage is
    outside, at the top of the Position panel, seen at every screen size), Right is refused,
    Left again goes on to 80."""
    x_server = any_screen
    sim = rig.sim("coxiris", "--speed", "100")
    placed = motionctl("--port", sim.path, "--protocol", "coxiris", "move", "100", "0", "0")
    assert placed.returncode == 0, placed.stderr
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=sim.path, travel=BOX, jog_step=10.0
    )
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    record = sim.record
    start = len(record.commands("DELTA_MOVE"))

    def jogs() -> list[list[float]]:
        return [numbers(m) for m in record.commands("DELTA_MOVE")[start:]]

    panel.key("Left")
    wait_for(lambda: jogs() == [[-10.0, 0.0, 0.0]], 10.0, "DELTA_MOVE -10 0 0 at the device")
    shot = shots / "outside-{}x{}.png".format(*x_server.size)
    wait_for(
        lambda: colour_count(x_server.grab(shot), OUTSIDE_NOTICE) > 200,
        10.0,
        "the readout's notice that the stage is outside its box",
        interval=0.2,
    )
    panel.wait_state("idle", 10.0)
    panel.key("Right")  # away from the box: refused
    # As an operator: Left once the refusal is shown (a press while the refused step is still
    # under way starts nothing, and the refusal comes back from the worker).
    panel.wait_state("error", 10.0)  # the status bar's badge: the refusal shown
    panel.key("Left")
    wait_for(lambda: len(jogs()) >= 2, 10.0, "the second jog towards the box")
    panel.wait_state("idle", 10.0)
    assert jogs() == [[-10.0, 0.0, 0.0], [-10.0, 0.0, 0.0]], jogs()
