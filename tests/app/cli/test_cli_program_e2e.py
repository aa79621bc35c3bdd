"""`motionctl run` with programs from the tools people draw with, on every simulator in another
process: a DXF written by ezdxf (standing in for a CAD program), an SVG as an illustration
program writes it (nested transforms, a viewBox in mm) and G-code as a CAM program writes it
(preamble, tool change, spindle, line numbers). Each runs to its last point, which is checked
where the device keeps it: the simulator's own axes (`motionsim --control`, `where`)."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.support.e2e import motionctl
from tests.support.program_files import Drawings, write_drawings
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.usefixtures("settings_file"), pytest.mark.timeout(120)]


@pytest.fixture
def drawings(tmp_path: Path) -> Drawings:
    return write_drawings(tmp_path)


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
    pytest.param(("visiomex",), id="visiomex"),
]
# pi-frame: a program starts from the position kept (Set Home); its moves are waited for by
# estimate: the panel's speed for what has no feed rate (its
# Circular frames hold at most 655.35 °/s: 25 mm/s on the 2.5 mm bulge arc is 573 °/s).
SETUP = {"visiomex": (("set-home",),), "pi-frame": (("set-home",), ("speed", "25"))}
OPTIONS = {"visiomex": ("--tolerance", "1")}  # each of its moves is a packet and 1 s of silence
UNITS = {"pi-frame": 100.0}  # ticks per mm (the default setting)
# The Visiomex firmware truncates each relative move to whole motor steps (38.9 a mm at its
# power-on parameters, drivers/protocols/README.md §2b): its axes end within a step of the counted
# point.
WITHIN = {"visiomex": 0.026}
# Each Visiomex move is a packet and 1 s of silence: its drawings are the short ones along X
# (the G-code, in X and Y, has an arc).
FILES = {"visiomex": ("part.nc", "line.dxf", "line.svg")}


@pytest.mark.parametrize("device", DEVICES, indirect=True)
def test_drawings_run_to_their_last_point_on_each_device(device, drawings) -> None:
    sim = device
    protocol = sim.proc.args[3]  # [python, -m, app.simcli, PROTOCOL, ...]
    for command in SETUP.get(protocol, ()):
        assert motionctl(protocol, sim.path, *command).returncode == 0
    for name in FILES.get(protocol, ("part.nc", "drawing.dxf", "art.svg")):
        path, (x, y) = drawings[name]
        layer = ("--layer", "CUT") if name.endswith(".dxf") else ()
        run = motionctl(
            protocol, sim.path, "--json", "run", str(path), *layer, *OPTIONS.get(protocol, ())
        )
        assert run.returncode == 0, (name, run.stderr)
        result = json.loads(run.stdout)
        assert result["finished"] is True and result["executed"] == result["instructions"]
        if protocol == "visiomex":  # its firmware's Y loop makes no step at power-on (issue 28)
            y = 0.0
        within = WITHIN.get(protocol, 0.011)
        assert result["position"] == pytest.approx([x, y, 0.0], abs=within), name
        scale = UNITS.get(protocol, 1.0)
        where = [v / scale for v in _where(sim)]
        assert where[:2] == pytest.approx([x, y], abs=within), (name, where)
        assert result["position"][:2] == pytest.approx(where[:2], abs=1e-6), name
        notices = " ".join(result.get("notices", []))
        if name == "part.nc":  # told once what was skipped, then run
            assert "T1, M6, S10000, M3, M5, M30" in notices, notices
        elif name == "art.svg":
            assert "art.svg: skipped 1 fill-only shape" in notices, notices


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
