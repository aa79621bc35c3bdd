"""Issue 28 item 10: after a program ends, the arrow keys jog again (the issue saw the focus left
on the dock's tab bar, whose arrows switched tabs instead)."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, numbers, wait_for, write_program

PROGRAM = [(2.0, 1.0, 0.0, 50.0), (4.0, 1.0, 0.0, 50.0), (4.0, 3.0, 0.0, 50.0)]


def test_an_arrow_key_jogs_once_a_program_has_run_to_its_end(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """A three-point program loaded (Alt+L) and run (Alt+R) to its end, then → : the device
    receives a move of X by the jog step (1 mm) from the program's last point."""
    width, height = any_screen.size
    sim = rig.sim("coxiris", "--speed", "100")
    program = write_program(tmp_path / "three.csv", PROGRAM)
    panel = rig.panel(any_screen, "--port", sim.path, "--protocol", "coxiris")
    panel.wait_ready(b"DONE GET_SPEED")
    note = panel.load_program(program)
    assert note.endswith("ready"), note
    panel.key("alt+r")
    record = sim.record

    def moves() -> list[list[float]]:
        return [numbers(m) for m in record.commands("ABSOLUTE_MOVE")]

    wait_for(lambda: moves()[-1:] == [[4.0, 3.0, 0.0]], 30.0, "the program's last move")
    panel.wait_state("idle", 15.0)
    panel.screenshot(shots / f"program-ended-{width}x{height}.png")
    panel.key("Right")
    try:
        jogs = wait_for(lambda: record.commands("DELTA_MOVE"), 10.0, "a jog move after →")
    finally:
        panel.screenshot(shots / f"arrow-after-program-{width}x{height}.png")
    assert [numbers(m) for m in jogs] == [[1.0, 0.0, 0.0]], f"→ sent {[m.text for m in jogs]}"
    assert moves()[-1] == [4.0, 3.0, 0.0]  # the jog was the device's last move
