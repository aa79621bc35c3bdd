"""motionctl across runs on the devices that cannot be asked where they are, against `motionsim`
in another process, checked by the simulator's own axes (`where`): the pi-frame's commanded
position is kept per port, so a relative move in a later run starts from it (its frames carry
absolute targets) and is refused where none is kept; a fresh Firmata board is never stepped
unconfigured: the run says what to type, and that works."""

from __future__ import annotations

import json
import re
from collections.abc import Iterator

import pytest

from tests.support.e2e import Run, motionctl
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.usefixtures("settings_file"), pytest.mark.timeout(120)]
TICKS_PER_MM = 100  # the pi-frame's default setting
STEPS_PER_MM = 80  # Firmata's


@pytest.fixture
def piframe() -> Iterator[SimProcess]:
    process = SimProcess("pi-frame", "--instant", control=True)
    yield process
    assert process.stop() == 0


@pytest.fixture
def firmata() -> Iterator[SimProcess]:
    process = SimProcess("firmata", "--reset-delay", "0.2", "--instant", control=True)
    yield process
    assert process.stop() == 0


def _where(sim: SimProcess, per_mm: float) -> list[float]:
    return [float(v) / per_mm for v in sim.fault("where").split()[2:]]


def _pi(sim: SimProcess, *args: str) -> Run:
    return motionctl("pi-frame", sim.path, *args, timeout=60)


def test_a_piframe_jog_in_a_new_run_goes_on_from_the_position_kept(piframe) -> None:
    assert _pi(piframe, "set-home").returncode == 0
    moved = _pi(piframe, "move", "2", "1", "0.5")
    assert moved.returncode == 0, moved.stderr
    assert _where(piframe, TICKS_PER_MM) == [2.0, 1.0, 0.5]

    jogged = _pi(piframe, "jog", "1", "0", "0")  # a new run: from (2, 1, 0.5), not the origin
    assert jogged.returncode == 0, jogged.stderr
    assert jogged.stdout.strip() == "3.00 1.00 0.50 (commanded, not measured)"
    assert _where(piframe, TICKS_PER_MM) == [3.0, 1.0, 0.5]
    here = _pi(piframe, "--json", "position")
    assert json.loads(here.stdout) == {
        "position": [3.0, 1.0, 0.5],
        "measured": False,
        "commanded": True,
    }


def test_a_piframe_relative_move_with_nothing_kept_is_refused_with_the_way_out(piframe) -> None:
    for args in (("jog", "1", "0", "0"), ("position",)):
        refused = _pi(piframe, *args)
        assert refused.returncode == 2, refused.stdout
        assert "position unknown" in refused.stderr, refused.stderr
        assert "motionctl set-home, home or move X Y Z" in refused.stderr
    assert _where(piframe, TICKS_PER_MM) == [0.0, 0.0, 0.0]  # nothing was sent
    assert _pi(piframe, "move", "1", "1", "0").returncode == 0  # absolute: the way out
    assert _pi(piframe, "jog", "1", "0", "0").returncode == 0
    assert _where(piframe, TICKS_PER_MM) == [2.0, 1.0, 0.0]


def test_a_fresh_firmata_board_is_not_stepped_unconfigured(firmata) -> None:
    assert motionctl("firmata", firmata.path, "set-home").returncode == 0
    refused = motionctl("firmata", firmata.path, "jog", "2")
    assert refused.returncode == 2, refused.stderr
    assert "not configured" in refused.stderr and "STEPPER Error" not in refused.stderr
    assert _where(firmata, STEPS_PER_MM) == [0.0]
    typed = re.search(r"run (motionctl .+?) with your motor", refused.stderr)
    assert typed is not None, refused.stderr
    words = typed.group(1).split()[1:]  # exactly what the refusal says to run
    assert words[:4] == ["--port", firmata.path, "--protocol", "firmata"]
    configured = motionctl("firmata", firmata.path, *words[4:])
    assert configured.returncode == 0, configured.stderr
    jogged = motionctl("firmata", firmata.path, "jog", "2")  # a new run: the board reset
    assert jogged.returncode == 0, jogged.stderr
    assert jogged.stdout.strip() == "2.00 0.00 0.00 (counted, not measured)"
    assert _where(firmata, STEPS_PER_MM) == [2.0]
    helped = motionctl("firmata", firmata.path, "config", "--help")
    assert helped.returncode == 0 and helped.stdout.startswith("usage: motionctl")
