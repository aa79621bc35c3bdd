"""motionctl on Firmata, which cannot be asked where the stage is: `move` is absolute from the
position counted for the port across runs (after a Set Home), refused where none is counted,
never reckoned from an assumed origin. Against `motionsim firmata` in another process."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.support.e2e import Run, device_received, motionctl
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.usefixtures("settings_file"), pytest.mark.timeout(90)]
STEP = bytes.fromhex("F07201")  # STEPPER_DATA, STEPPER_STEP


def firmata(port: str, *args: str) -> Run:
    return motionctl("firmata", port, "--steps-per-mm", "80", *args, timeout=60)


@pytest.fixture
def board(tmp_path: Path) -> Iterator[tuple[SimProcess, Path]]:
    record = tmp_path / "device.log"
    process = SimProcess("firmata", "--reset-delay", "0.2", "--instant", "--record", str(record))
    yield process, record
    assert process.stop() == 0


def _steps(record: Path) -> list[int]:
    """The signed step counts of the STEPPER_STEP messages the board received."""
    data = device_received(record)
    found = []
    start = data.find(STEP)
    while start >= 0:
        message = data[start : data.index(b"\xf7", start) + 1]
        steps = message[6] | message[7] << 7
        found.append(steps if message[8] == 1 else -steps)
        start = data.find(STEP, start + 1)
    return found


def test_move_is_absolute_from_the_count_kept_across_runs(board) -> None:
    sim, record = board
    assert firmata(sim.path, "config", "--steps-per-rev", "200", "--pins", "8", "9").returncode == 0
    refused = firmata(sim.path, "move", "10")
    assert refused.returncode == 2
    assert "position unknown" in refused.stderr and "Set Home" in refused.stderr
    assert _steps(record) == []  # nothing was sent
    assert firmata(sim.path, "position").returncode == 2

    assert firmata(sim.path, "set-home").returncode == 0
    first = firmata(sim.path, "move", "10")
    second = firmata(sim.path, "move", "10")  # already there: not 10 mm further
    jogged = firmata(sim.path, "jog", "2.5")
    assert (first.returncode, second.returncode, jogged.returncode) == (0, 0, 0), second.stderr
    assert "10.00 0.00 0.00 (counted, not measured)" in second.stdout
    here = json.loads(firmata(sim.path, "--json", "position").stdout)
    assert here == {"position": [12.5, 0.0, 0.0], "measured": False, "counted": True}
    assert firmata(sim.path, "home").returncode == 0  # back by the count: -12.5 mm
    assert sum(_steps(record)) == 0
    assert _steps(record)[0] == 800  # the first move: 10 mm at 80 steps/mm
    assert -1000 in _steps(record)  # home: 12.5 mm back
