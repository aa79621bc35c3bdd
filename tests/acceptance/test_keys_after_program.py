"""Issue 28 item 10: after a program ends, the arrow keys jog again (the issue saw the focus left
on the dock's tab bar, whose arrows switched tabs instead).

As the issue did it: a look at the Traffic layout and back (Ctrl+3, Ctrl+1: the docks' tab bars
are made again, last in the focus chain, right after the Program dock's buttons), then Run
clicked with the mouse. The focus goes to Run, which goes off under it while the program runs,
and Qt moves the focus on to the next in the chain: Pause and Stop are off too, so a tab bar,
whose arrows switch tabs. The Run button is found on the screen from the panel's layout report
(MOTIONPANEL_LAYOUT_REPORT, app/window/layout/layout_report.py); the device's own record says what
the
keys sent.
"""

from __future__ import annotations

import contextlib
import json
from pathlib import Path

import pytest

from app.window.layout.layout_report import ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, XServer, numbers, wait_for, write_program

pytestmark = pytest.mark.timeout(150)

PROGRAM = [(2.0, 1.0, 0.0, 50.0), (4.0, 1.0, 0.0, 50.0), (4.0, 3.0, 0.0, 50.0)]


def _report(panel: Panel, report: Path, layout: str) -> dict | None:
    """The layout report once it is of `layout` at the window's present size, else None."""
    panel.alive()
    with contextlib.suppress(FileNotFoundError, json.JSONDecodeError):  # not written yet
        data = json.loads(report.read_text(encoding="utf-8"))
        same = data["layout"] == layout and data["window"] == list(panel.geometry()[2:])
        if same and data["views_ready"]:  # (the docks under the views settle after them)
            return data
    return None


def _run_button(panel: Panel, report: Path) -> tuple[int, int]:
    """The Run button's centre on the screen, once a report of Operate at the window's present
    size shows it whole (the Program dock in front, after the program was loaded)."""

    def found() -> list[int] | None:
        data = _report(panel, report, "operate")
        run = data["located"].get("programRun") if data else None
        return run["rect"] if run and run["whole"] else None

    x, y, w, h = wait_for(found, 20.0, "the Run button shown whole in a layout report", 0.1)
    left, top = panel.geometry()[:2]
    return left + x + w // 2, top + y + h // 2


def test_an_arrow_key_jogs_once_a_program_clicked_to_run_has_ended(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """A three-point program loaded (Alt+L), a look at Traffic and back (Ctrl+3, Ctrl+1), Run
    clicked with the mouse, the program run to its end, then → : the device receives a move of
    X by the jog step (1 mm) from the program's last point, and no other move."""
    width, height = any_screen.size
    sim = rig.sim("coxiris", "--speed", "100")
    program = write_program(tmp_path / "three.csv", PROGRAM)
    report = tmp_path / "layout.json"
    panel = rig.panel(
        any_screen, "--port", sim.path, "--protocol", "coxiris", env={ENVIRONMENT: str(report)}
    )
    panel.wait_ready(b"DONE GET_SPEED")
    note = panel.load_program(program)
    assert note.endswith("ready"), note
    panel.key("ctrl+3")
    wait_for(lambda: _report(panel, report, "traffic"), 20.0, "the Traffic layout", 0.1)
    panel.key("ctrl+1")
    x, y = _run_button(panel, report)
    panel.activate()
    any_screen.xdotool("mousemove", str(x), str(y), "click", "1")
    record = sim.record

    def moves() -> list[list[float]]:
        return [numbers(m) for m in record.commands("ABSOLUTE_MOVE")]

    wait_for(lambda: moves()[-1:] == [[4.0, 3.0, 0.0]], 30.0, "the program's last move")
    panel.wait_state("idle", 15.0)
    any_screen.xdotool("mousemove", "0", str(height - 1))  # the pointer off the Run button
    panel.screenshot(shots / f"program-ended-{width}x{height}.png")
    panel.key("Right")
    try:
        jogs = wait_for(lambda: record.commands("DELTA_MOVE"), 10.0, "a jog move after →")
    finally:
        panel.screenshot(shots / f"arrow-after-program-{width}x{height}.png")
    assert [numbers(m) for m in jogs] == [[1.0, 0.0, 0.0]], f"→ sent {[m.text for m in jogs]}"
    assert moves()[-1] == [4.0, 3.0, 0.0]  # the jog was the device's last move
