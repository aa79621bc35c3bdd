"""What motionctl tells of the Visiomex firmware (issue 20), against `motionsim visiomex` in
another process through a real pseudo-terminal: a rotational or steps jog in its own unit and
what the firmware really moves (µm, whatever the type letter: drivers/protocols/README.md §2b);
`move X Y` absolute from the position counted for the port across runs, refused where none is
counted; `id` saying there is no identity query."""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from app.common.settings import open_settings, read_counted_position, write_counted_position
from tests.support import e2e as e2e_support
from tests.support.e2e import Run, device_received, sent, stream
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.usefixtures("settings_file")]


def motionctl(port: str, *args: str, log: Path | None = None) -> Run:
    """Run `motionctl --port PORT --protocol visiomex ARGS`."""
    return e2e_support.motionctl("visiomex", port, *args, log=log, timeout=90)


@pytest.fixture
def sim(tmp_path: Path) -> Iterator[tuple[SimProcess, Path]]:
    """`motionsim visiomex --instant --record FILE --control` (moves without their stepping
    time; `where` answers the simulator's own axes)."""
    record = tmp_path / "device.log"
    process = SimProcess("visiomex", "--instant", "--record", str(record), control=True)
    yield process, record
    assert process.stop() == 0


@pytest.fixture
def logs(tmp_path: Path) -> Callable[[], Path]:
    """A new host log file at each call."""
    made: list[Path] = []

    def new() -> Path:
        made.append(tmp_path / f"host{len(made)}.log")
        return made[-1]

    return new


def _where(process: SimProcess) -> tuple[float, ...]:
    """The simulator's own axes, in mm (its `where` answers them)."""
    return tuple(float(value) for value in process.fault("where").split()[2:4])  # ok where X Y


def _debug_value(log: Path, label: str) -> str:
    """A value the firmware printed before FP0001, e.g. `Distance x (mm)`."""
    text = stream(log, "RX").decode("ascii")
    found = re.search(re.escape(label) + r": (\S+)\r", text)
    assert found is not None, text
    return found.group(1)


# -- --kind rotational / steps ---------------------------------------------------------------------
@pytest.mark.timeout(40)
def test_rotational_and_steps_jogs_report_their_unit_and_the_firmware_reading(
    sim: tuple[SimProcess, Path], logs: Callable[[], Path]
) -> None:
    process, _ = sim
    assert motionctl(process.path, "set-home").returncode == 0
    log = logs()
    turned = motionctl(process.path, "--kind", "rotational", "jog", "90", "0", log=log)
    assert turned.returncode == 0, turned.stderr
    assert [r.data for r in sent(log)] == [b"MRP0000090P0000000"]
    lines = turned.stdout.strip().splitlines()
    assert lines[0] == "jog X 90 Y 0 degrees, packet MRP0000090P0000000"
    assert "reads the digits as µm whatever the type letter" in lines[1]
    # 90 µm is 3.6 steps of 0.025 mm at power-on: the firmware makes 3 (not 2.5 mm for 90°).
    assert "X 0.075 mm, Y 0.000 mm" in lines[1]
    assert lines[2] == "0.08 0.00 0.00 (counted, not measured)"  # 0.075 mm to 2 decimals
    assert "mm" not in lines[0]
    # The device itself read 90 µm (its debug line says so) and made whole steps of it.
    assert _debug_value(log, "Distance x (mm)") == "0.09"
    assert _where(process) == pytest.approx((0.075, 0.0))

    log = logs()
    stepped = motionctl(process.path, "--json", "--kind", "steps", "jog", "400", "-20", log=log)
    assert stepped.returncode == 0, stepped.stderr
    assert [r.data for r in sent(log)] == [b"MSP0000400N0000020"]
    result = json.loads(stepped.stdout)
    assert result["jog"] == {
        "x": 400.0,
        "y": -20.0,
        "unit": "steps",
        "kind": "steps",
        "packet": "MSP0000400N0000020",
    }
    # 0.4 mm is 16 whole steps; Y's 0.02 mm is not made: the Y loop runs its ramp count, 0.
    assert result["firmware_mm"] == pytest.approx([0.4, 0.0, 0.0])
    assert "whatever the type letter" in result["firmware_note"]
    assert result["position"] == pytest.approx([0.475, 0.0, 0.0])
    assert _where(process) == pytest.approx((0.475, 0.0))
    assert result["counted"] is True and result["measured"] is False
    assert _debug_value(log, "Distance x (mm)") == "0.40"
    assert _debug_value(log, "Distance y (mm)") == "0.02"

    # --kind is for jog only: refused before anything is sent.
    refused = motionctl(process.path, "--kind", "steps", "move", "1", "0")
    assert refused.returncode == 2 and "--kind is for jog only" in refused.stderr


# -- move X Y across runs ---------------------------------------------------------------------
@pytest.mark.timeout(60)
def test_move_across_runs_is_absolute_from_the_counted_position(
    sim: tuple[SimProcess, Path], logs: Callable[[], Path]
) -> None:
    process, record = sim
    for command in (("move", "10", "0"), ("position",), ("home",)):
        refused = motionctl(process.path, *command)
        assert refused.returncode == 2, refused.stderr
        assert "no position is counted for this port" in refused.stderr
        assert "Set Home" in refused.stderr and "Home" in refused.stderr.replace("Set Home", "")
        assert refused.stdout == ""
    jogged = motionctl(process.path, "jog", "1", "0")  # relative: it goes, the count stays unknown
    assert jogged.returncode == 0, jogged.stderr
    assert jogged.stdout.startswith("position unknown:")
    assert device_received(record) == b"MLP0001000P0000000"

    homed = motionctl(process.path, "set-home")
    assert homed.returncode == 0, homed.stderr
    assert homed.stdout.strip() == "0.00 0.00 0.00 (counted, not measured)"
    assert device_received(record) == b"MLP0001000P0000000"  # Set Home sends nothing

    first, second = logs(), logs()
    assert motionctl(process.path, "move", "10", "0", log=first).returncode == 0
    moved = motionctl(process.path, "move", "15", "-2", log=second)
    assert moved.returncode == 0, moved.stderr
    assert [r.data for r in sent(first)] == [b"MLP0010000P0000000"]
    assert [r.data for r in sent(second)] == [b"MLP0005000N0002000"]  # from 10, not from 0
    # At power-on the firmware's Y loop makes no step (issue 28): the count says so, and
    # motionctl said it before sending.
    assert moved.stdout.strip() == "15.00 0.00 0.00 (counted, not measured)"
    assert "Y will not move" in moved.stderr
    shown = motionctl(process.path, "--json", "position")
    assert json.loads(shown.stdout) == {
        "position": [15.0, 0.0, 0.0],
        "measured": False,
        "counted": True,
    }
    back = logs()
    assert motionctl(process.path, "home", log=back).returncode == 0
    assert [r.data for r in sent(back)] == [b"MLN0015000P0000000"]


@pytest.mark.timeout(30)
def test_move_goes_on_from_the_count_the_panel_kept(
    sim: tuple[SimProcess, Path], logs: Callable[[], Path]
) -> None:
    """The panel keeps its count where it keeps the last written parameters, per port."""
    process, _ = sim
    settings = open_settings()
    write_counted_position(settings, "visiomex", process.path, (2.5, 1.0, 0.0))
    assert read_counted_position(settings, "visiomex", "/dev/other") is None  # per port
    log = logs()
    moved = motionctl(process.path, "move", "0", "3", log=log)
    assert moved.returncode == 0, moved.stderr
    assert [r.data for r in sent(log)] == [b"MLN0002500P0002000"]
    settings.sync()
    # X goes back 2.5 mm (100 whole steps); Y does not move at power-on (issue 28).
    assert read_counted_position(settings, "visiomex", process.path) == (0.0, 1.0, 0.0)


# -- id --------------------------------------------------------------------------------------
@pytest.mark.timeout(30)
def test_id_says_there_is_no_identity_query(
    sim: tuple[SimProcess, Path], logs: Callable[[], Path]
) -> None:
    process, record = sim
    log = logs()
    result = motionctl(process.path, "id", log=log)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == (
        "visiomex has no identity query: the device cannot be asked what it is"
    )
    as_json = motionctl(process.path, "--json", "id")
    assert json.loads(as_json.stdout) == {
        "id": None,
        "identity": "visiomex has no identity query: the device cannot be asked what it is",
    }
    assert sent(log) == [] and device_received(record) == b""
