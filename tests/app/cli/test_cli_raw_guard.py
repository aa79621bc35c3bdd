"""`motionctl raw` through the motion guard, against motionsim in another process: a raw move
outside the box and bytes that cannot be read are refused (exit 2, nothing sent) unless forced;
a slow raw move is followed to its end."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.e2e import device_received_text
from tests.support.simproc import ROOT, SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60)]

TRAVEL = ("--travel", "-50:50,-50:50,0:10")


def motionctl(port: str, *args: str, timeout: float = 2.0) -> subprocess.CompletedProcess[str]:
    """Run motionctl on a COXIRIS device and return the completed process."""
    options = ["--port", port, "--protocol", "coxiris", "--timeout", str(timeout)]
    return subprocess.run(
        [sys.executable, "-m", "app.cli", *options, *args],
        capture_output=True,
        text=True,
        timeout=40,
        cwd=ROOT,
    )


@pytest.fixture(autouse=True)
def _own_settings(settings_file: Path) -> None:
    """motionctl reads the panel's settings: a file of the test's own."""


def test_a_raw_move_outside_the_box_is_refused(sim: SimProcess, record: Path) -> None:
    result = motionctl(sim.path, *TRAVEL, "raw", "ABSOLUTE_MOVE 100 0 0")
    assert result.returncode == 2, result.stderr
    assert "X 100 mm is outside -50..50 mm (travel limits)" in result.stderr
    assert device_received_text(record) == ""


def test_a_raw_jog_outside_the_box_is_refused_once_the_position_is_known(
    sim: SimProcess, record: Path
) -> None:
    assert motionctl(sim.path, *TRAVEL, "move", "45", "0", "0").returncode == 0
    result = motionctl(sim.path, *TRAVEL, "raw", "DELTA_MOVE 10 0 0")
    assert result.returncode == 2, result.stderr
    assert "X 55 mm is outside" in result.stderr
    assert "DELTA_MOVE" not in device_received_text(record)


def test_unreadable_bytes_need_force_while_a_box_is_set(sim: SimProcess, record: Path) -> None:
    unreadable = "DELTA_MOVE 1 0 0 9"  # four numbers: not as the protocol documents a move
    refused = motionctl(sim.path, *TRAVEL, "raw", unreadable)
    assert refused.returncode == 2, refused.stderr
    assert "cannot read them" in refused.stderr
    assert "X -50..50, Y -50..50, Z 0..10 mm" in refused.stderr
    assert "force" in refused.stderr
    assert device_received_text(record) == ""
    forced = motionctl(sim.path, *TRAVEL, "--force", "raw", unreadable)
    assert forced.returncode == 0, forced.stderr
    assert unreadable in device_received_text(record)
    assert motionctl(sim.path, "--travel", "none", "raw", unreadable).returncode == 0


def test_force_is_for_raw_only(sim: SimProcess, record: Path) -> None:
    result = motionctl(sim.path, "--force", "move", "1", "0", "0")
    assert result.returncode == 2 and "--force is for raw only" in result.stderr
    assert device_received_text(record) == ""


@pytest.mark.sim_args("--speed", "2")
def test_a_slow_raw_move_completes_without_a_timeout(sim: SimProcess) -> None:
    """8 mm at 2 mm/s: 4 s, four times the reply timeout."""
    result = motionctl(sim.path, *TRAVEL, "raw", "ABSOLUTE_MOVE 8 0 0", timeout=1.0)
    assert result.returncode == 0, result.stderr
    assert "DONE ABSOLUTE_MOVE" in result.stdout
    assert motionctl(sim.path, "position").stdout.strip() == "8.00 0.00 0.00"
