"""Issue 23: G-code and DXF programs loaded through the file dialog, checked against the travel
box and run to their last point, on COXIRIS (a device without a queue: move by move), at each
screen size; observed through the session log's notes, the device's record and screenshots."""

from __future__ import annotations

from pathlib import Path

import ezdxf

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, numbers, wait_for, write_settings

CAM_GCODE = """%
(part.nc - as a CAM program writes it)
N10 G90 G94 G17 G21
N20 T1 M6
N30 S10000 M3
N40 G0 X5 Y5
N50 G1 X15 Y5 F1200
N60 G1 X15 Y10
N70 G3 X10 Y15 I-5 J0
N80 G0 X2 Y3
N90 M30
%
"""


def _wide_drawing(path: Path) -> Path:
    """A CAD drawing (ezdxf's writer) one of whose lines goes to X 80 mm."""
    doc = ezdxf.new("R2010", units=4)
    space = doc.modelspace()
    space.add_line((0, 0), (10, 0))
    space.add_line((10, 0), (80, 5))
    doc.saveas(path)
    return path


def test_gcode_runs_to_its_last_point_and_a_drawing_outside_the_box_is_refused(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """part.nc loaded with Alt+L and run with Alt+R: the device's record ends with the move to
    its last point (2, 3, 0); wide.dxf, which leaves the 50 mm box, is read and refused, and
    Run sends nothing."""
    sim = rig.sim("coxiris", "--speed", "100")
    settings = write_settings(
        tmp_path / "settings.ini",
        protocol="coxiris",
        port=sim.path,
        travel=((-50.0, 50.0), (-50.0, 50.0), (-10.0, 10.0)),
    )
    gcode = tmp_path / "part.nc"
    gcode.write_text(CAM_GCODE, encoding="utf-8")
    wide = _wide_drawing(tmp_path / "wide.dxf")
    panel = rig.panel(any_screen, "--port", sim.path, "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    panel.activate()
    width, height = any_screen.size
    record = sim.record

    note = panel.load_program(wide)
    assert note.endswith(", refused"), note
    panel.screenshot(shots / f"program-refused-{width}x{height}.png")
    panel.key("alt+r")
    note = panel.load_program(gcode)
    assert note == "program loaded: part.nc, 59 segments, ready" or note.endswith("ready"), note
    assert record.commands("ABSOLUTE_MOVE") == []  # nothing moved while loading or refused
    panel.screenshot(shots / f"program-loaded-{width}x{height}.png")
    panel.key("alt+r")

    def last_move() -> list[float] | None:
        moves = record.commands("ABSOLUTE_MOVE")
        return numbers(moves[-1]) if moves else None

    wait_for(lambda: last_move() == [2.0, 3.0, 0.0], 60.0, "the move to the program's last point")
    moves = record.commands("ABSOLUTE_MOVE")
    assert numbers(moves[0]) == [5.0, 5.0, 0.0]
    assert all(abs(v) <= 50 for move in moves for v in numbers(move))
    panel.screenshot(shots / f"program-done-{width}x{height}.png")
