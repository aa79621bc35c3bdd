"""motionctl counts a Visiomex move as the firmware makes it (issue 28, item 1), checked against
`motionsim visiomex --control` in another process through a real pseudo-terminal: `where` after a
Y jog at power-on (the firmware's Y loop makes no step), after a profile write (22 = 6000, 24 = 1:
the Y loop runs its ramp count, 14 steps) and after an X jog truncated to whole steps; and what
will really happen said on stderr before the move is sent."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.common.settings import open_settings, read_counted_position
from tests.support import e2e as e2e_support
from tests.support.e2e import Run
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.usefixtures("settings_file")]
STEP = 0.025  # mm: 10 mm a turn, 400 full steps, ×1 at power-on


def motionctl(port: str, *args: str) -> Run:
    """Run `motionctl --port PORT --protocol visiomex ARGS`."""
    return e2e_support.motionctl("visiomex", port, *args, timeout=90)


def where(sim: SimProcess) -> tuple[float, float]:
    """Where the simulated stage physically is (mm from power-on)."""
    x, y = (float(v) for v in sim.fault("where").split()[2:4])
    return x, y


@pytest.fixture
def sim() -> Iterator[SimProcess]:
    """`motionsim visiomex --instant --control`: moves without their stepping time."""
    process = SimProcess("visiomex", "--instant", control=True)
    yield process
    assert process.stop() == 0


def jog(sim: SimProcess, dx: str, dy: str) -> tuple[list[float], str]:
    """`motionctl --json jog DX DY`: the position it reports, and its stderr."""
    run = motionctl(sim.path, "--json", "jog", dx, dy)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)["position"], run.stderr


@pytest.mark.timeout(80)
def test_count_follows_the_firmware_y_loop_and_whole_steps(sim: SimProcess, tmp_path: Path) -> None:
    assert motionctl(sim.path, "set-home").returncode == 0
    assert where(sim) == (0.0, 0.0)

    position, said = jog(sim, "0", "1")  # power-on: R_y = 0, the Y loop makes no step
    assert where(sim) == (0.0, 0.0)
    assert position[:2] == [0.0, 0.0]
    assert "Y will not move: at these parameters the firmware's Y loop makes no step" in said

    position, said = jog(sim, "1", "1")
    assert where(sim) == (1.0, 0.0)
    assert position[:2] == pytest.approx([1.0, 0.0])

    profile = tmp_path / "y.toml"
    profile.write_text(
        'protocol = "visiomex"\n[parameters]\ninput_speed_steady_y = 6000\n'
        "input_acceleration_y = 1\n",
        encoding="utf-8",
    )
    written = motionctl(sim.path, "param", "write", str(profile))
    assert written.returncode == 0, written.stderr
    position, said = jog(sim, "0", "1")  # the Y loop runs its ramp count: 14 of 40 steps
    assert where(sim) == pytest.approx((1.0, 14 * STEP))
    assert position[:2] == pytest.approx([1.0, 0.35])
    assert "Y moves 0.350 mm, not 1.000: the firmware's Y loop runs the ramp count" in said

    position, said = jog(sim, "0.99", "0")  # 39.6 steps, truncated to 39
    assert where(sim) == pytest.approx((1.0 + 39 * STEP, 0.35))
    assert position[:2] == pytest.approx([1.975, 0.35])
    assert "X moves 0.975 mm, not 0.990: whole steps (39)" in said

    kept = read_counted_position(open_settings(), "visiomex", sim.path)
    assert kept is not None and kept[:2] == pytest.approx((1.975, 0.35))
    # A new run goes on from the count kept; Home's Y half comes back only as far as the Y
    # loop goes (its ramp count, at most half the steps), and the count says where.
    run = motionctl(sim.path, "--json", "home")
    assert run.returncode == 0, run.stderr
    assert "Y moves" in run.stderr
    x, y = where(sim)
    assert json.loads(run.stdout)["position"][:2] == pytest.approx([x, y], abs=1e-9)
    assert y > 0.0  # not back at 0: the count must not say it is
