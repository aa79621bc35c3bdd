"""`motionctl run` with programs from the tools people draw with, on every simulator in another
process: a DXF written by ezdxf (standing in for a CAD program), an SVG as an illustration
program writes it (nested transforms, a viewBox in mm) and G-code as a CAM program writes it
(preamble, tool change, spindle, line numbers). Each runs to its last point, which is checked
where the device keeps it: the simulator's own axes (`motionsim --control`, `where`)."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import ezdxf
import pytest

from tests.e2e_support import motionctl
from tests.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.usefixtures("settings_file"), pytest.mark.timeout(120)]

CAM_GCODE = """%
(part.nc - as a CAM program writes it)
(T1 D=3 FLAT)
N10 G90 G94 G17 G21
N20 G54
N30 T1 M6
N40 S10000 M3
N50 G0 X5 Y5
N60 G1 X15 Y5 F600
N70 G1 X15 Y10
N80 G3 X10 Y15 I-5 J0
N90 G4 P0.1
N100 G0 X2 Y3
N110 M5
N120 M30
%
"""
ILLUSTRATION_SVG = """<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="30mm" viewBox="0 0 40 30">
  <g transform="translate(5 5)">
    <path d="M 0 0 L 10 0 A 5 5 0 0 1 15 5" stroke="#000" fill="none"/>
    <g transform="scale(0.5)"><circle cx="40" cy="20" r="6" stroke="#000" fill="none"/></g>
  </g>
  <rect x="1" y="1" width="4" height="4" fill="#f00" stroke="none"/>
  <line x1="20" y1="20" x2="30" y2="24" stroke="#000"/>
</svg>
"""
# Firmata turns one motor: the same three kinds of file, along X only.
CAM_GCODE_X = """(one axis)
G21 G90 G17
G1 X10 F300
G0 X2
G4 P0.1
G1 X6 F300
M30
"""
ILLUSTRATION_SVG_X = """<svg xmlns="http://www.w3.org/2000/svg"
     width="30mm" height="10mm" viewBox="0 0 30 10">
  <path d="M 2 10 H 12 M 15 10 H 8" stroke="black" fill="none"/>
</svg>
"""


def _cad_dxf(path: Path, one_axis: bool = False) -> Path:
    """A drawing as a CAD program saves it (ezdxf's own writer), in mm, on three layers."""
    doc = ezdxf.new("R2010", units=4)
    space = doc.modelspace()
    if one_axis:
        space.add_line((0, 0), (10, 0), dxfattribs={"layer": "CUT"})
        space.add_line((12, 0), (4, 0), dxfattribs={"layer": "CUT"})
    else:
        space.add_line((5, 5), (15, 5), dxfattribs={"layer": "CUT"})
        space.add_arc((15, 10), 5, -90, 90, dxfattribs={"layer": "CUT"})
        space.add_circle((25, 10), 3, dxfattribs={"layer": "CUT"})
        space.add_lwpolyline([(30, 2, 0.5), (34, 2)], format="xyb", dxfattribs={"layer": "CUT"})
        space.add_line((20, 2), (28, 4), dxfattribs={"layer": "CUT"})
    space.add_line((0, 20), (5, 20), dxfattribs={"layer": "ENGRAVE"})
    space.add_text("part 7", dxfattribs={"layer": "NOTES"})
    doc.saveas(path)
    return path


@pytest.fixture
def drawings(tmp_path: Path) -> dict[str, tuple[Path, tuple[float, float]]]:
    """Each file and its last point (x, y) in mm."""
    files = {
        "part.nc": (CAM_GCODE, (2.0, 3.0)),
        "art.svg": (ILLUSTRATION_SVG, (30.0, 6.0)),
        "line.nc": (CAM_GCODE_X, (6.0, 0.0)),
        "line.svg": (ILLUSTRATION_SVG_X, (8.0, 0.0)),
    }
    made = {}
    for name, (text, last) in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
        made[name] = (tmp_path / name, last)
    made["drawing.dxf"] = (_cad_dxf(tmp_path / "drawing.dxf"), (28.0, 4.0))
    made["line.dxf"] = (_cad_dxf(tmp_path / "line.dxf", one_axis=True), (4.0, 0.0))
    return made


@pytest.fixture
def device(request) -> Iterator[SimProcess]:
    protocol, *options = request.param
    process = SimProcess(protocol, "--instant", *options, control=True)
    yield process
    assert process.stop() == 0


def _where(sim: SimProcess) -> list[float]:
    return [float(v) for v in sim.fault("where").split()[2:]]


DEVICES = [
    pytest.param(("coxiris",), id="coxiris"),
    pytest.param(("laser-frame",), id="laser-frame"),
    pytest.param(("pi-frame",), id="pi-frame"),
    # The documented firmware: at its power-on parameters the real one never moves Y.
    pytest.param(("visiomex", "--no-bugs"), id="visiomex"),
]
# pi-frame's moves are waited for by estimate: the panel's speed for what has no feed rate (its
# Circular frames hold at most 655.35 °/s: 25 mm/s on the 2.5 mm bulge arc is 573 °/s).
SETUP = {"visiomex": (("set-home",),), "pi-frame": (("speed", "25"),)}
OPTIONS = {"visiomex": ("--tolerance", "1")}  # each of its moves is a packet and 1 s of silence
UNITS = {"pi-frame": 100.0}  # ticks per mm (the default setting)
# The Visiomex firmware truncates each relative move to whole motor steps (38.9 a mm at its
# power-on parameters, PROTOCOLS.md §2b): its axes end within a step of the counted point.
WITHIN = {"visiomex": 0.026}


@pytest.mark.parametrize("device", DEVICES, indirect=True)
def test_drawings_run_to_their_last_point_on_each_device(device, drawings) -> None:
    sim = device
    protocol = sim.proc.args[3]  # [python, -m, app.simcli, PROTOCOL, ...]
    for command in SETUP.get(protocol, ()):
        assert motionctl(protocol, sim.path, *command).returncode == 0
    for name in ("part.nc", "drawing.dxf", "art.svg"):
        path, (x, y) = drawings[name]
        layer = ("--layer", "CUT") if name.endswith(".dxf") else ()
        run = motionctl(
            protocol, sim.path, "--json", "run", str(path), *layer, *OPTIONS.get(protocol, ())
        )
        assert run.returncode == 0, (name, run.stderr)
        result = json.loads(run.stdout)
        assert result["finished"] is True and result["executed"] == result["instructions"]
        assert result["position"] == pytest.approx([x, y, 0.0], abs=0.011), name
        scale = UNITS.get(protocol, 1.0)
        where = [v / scale for v in _where(sim)]
        assert where[:2] == pytest.approx([x, y], abs=WITHIN.get(protocol, 0.011)), (name, where)
    notices = json.loads(run.stdout).get("notices", [])
    assert notices == ["art.svg: skipped 1 fill-only shape"] or notices, notices


def test_drawings_along_x_run_on_the_firmata_board(drawings) -> None:
    sim = SimProcess("firmata", "--instant", "--reset-delay", "0.2", control=True)
    try:
        options = ("--steps-per-mm", "80")
        config = ("config", "--steps-per-rev", "200", "--pins", "8", "9")
        assert motionctl("firmata", sim.path, *options, *config).returncode == 0
        assert motionctl("firmata", sim.path, *options, "set-home").returncode == 0
        for name in ("line.nc", "line.dxf", "line.svg"):
            path, (x, _) = drawings[name]
            layer = ("--layer", "CUT") if name.endswith(".dxf") else ()
            run = motionctl("firmata", sim.path, *options, "--json", "run", str(path), *layer)
            assert run.returncode == 0, (name, run.stderr)
            assert json.loads(run.stdout)["position"] == pytest.approx([x, 0.0, 0.0], abs=0.013)
            [steps] = _where(sim)
            assert steps / 80 == pytest.approx(x, abs=0.013), name
        refused = motionctl("firmata", sim.path, *options, "run", str(drawings["part.nc"][0]))
        assert refused.returncode == 2
        assert "part.nc line 8: the program moves Y to 5 mm" in refused.stderr
        assert "it has X" in refused.stderr
    finally:
        assert sim.stop() == 0


def test_a_program_leaving_the_box_is_refused_before_the_port_opens(drawings) -> None:
    sim = SimProcess("coxiris", "--instant", control=True)
    try:
        path, _ = drawings["drawing.dxf"]
        run = motionctl(
            "coxiris", sim.path, "run", str(path), "--layer", "CUT", "--travel", "0:30,0:30,0:1"
        )
        assert run.returncode == 2
        # The fourth CUT entity, the bulged polyline, goes on to X 34 mm.
        assert "drawing.dxf entity 4 (LWPOLYLINE on layer CUT)" in run.stderr, run.stderr
        assert "would leave the travel box at (30." in run.stderr
        assert "(X 0..30, Y 0..30, Z 0..1 mm); nothing was sent" in run.stderr
        assert _where(sim) == [0.0, 0.0, 0.0]
    finally:
        assert sim.stop() == 0
