"""A bench of two devices (motionsim processes on pseudo-terminals): `drivers.open_bench` and
`motionctl --bench FILE --device NAME` drive each one, checked on the simulators' own axes."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

import drivers
from tests.support.e2e import device_received_text, motionctl_as_typed
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(90)]


@pytest.fixture
def bench(tmp_path: Path) -> Iterator[tuple[Path, dict[str, SimProcess], Path]]:
    """A COXIRIS stage and a laser-frame head, each its own motionsim; the bench file naming
    them; the stage's record."""
    record = tmp_path / "stage.log"
    stage = SimProcess("coxiris", "--instant", "--record", str(record), control=True)
    head = SimProcess("laser-frame", "--instant", control=True)
    path = tmp_path / "bench.toml"
    path.write_text(
        f'[devices.stage]\nport = "{stage.path}"\nprotocol = "coxiris"\nspeed = 12.5\n'
        "travel = { x = [-50, 50], y = [-50, 50], z = [0, 20] }\n\n"
        f'[devices.head]\nport = "{head.path}"\nprotocol = "laser-frame"\n'
        'travel = "-25:25,-25:25,0:10"\n',
        encoding="utf-8",
    )
    sims = {"stage": stage, "head": head}
    yield path, sims, record
    for sim in sims.values():
        if sim.proc.poll() is None:
            assert sim.stop() == 0


def _where(sim: SimProcess) -> list[float]:
    return [float(v) for v in sim.fault("where").split()[2:5]]


def test_open_bench_drives_each_device_and_closes_them_all(bench) -> None:
    path, sims, record = bench
    with drivers.open_bench(path) as opened:
        assert list(opened) == ["stage", "head"]
        opened["stage"].move_to(10, -5, 2)
        opened["head"].move_to(3, 4, 0)
        assert _where(sims["stage"]) == [10.0, -5.0, 2.0]
        assert _where(sims["head"]) == pytest.approx([3.0, 4.0, 0.0], abs=0.01)
        with pytest.raises(drivers.BadInput, match="outside"):
            opened["head"].move_to(30, 0, 0)  # its own box, not the stage's
        assert opened.devices["stage"].speed == 12.5
    assert all(session.closed for session in opened.values())
    assert "SET_SPEED 12.5" in device_received_text(record)  # the bench's speed, once open


def test_a_device_that_cannot_open_closes_those_opened_and_is_named(bench, tmp_path: Path) -> None:
    path, sims, _ = bench
    sims["head"].kill()  # its pty is gone
    with pytest.raises(drivers.PortError) as caught:
        drivers.open_bench(path)
    assert "bench device 'head'" in caught.value.__notes__
    # the stage was opened first and closed again: it can be opened at once
    with drivers.open_bench(path, names=["stage"]) as opened:
        assert list(opened) == ["stage"]


def test_motionctl_drives_the_device_the_bench_names(bench) -> None:
    path, sims, record = bench
    run = motionctl_as_typed("--bench", str(path), "--device", "stage", "move", "7", "8", "1")
    assert run.returncode == 0, run.stderr
    assert _where(sims["stage"]) == [7.0, 8.0, 1.0]
    assert "SET_SPEED 12.5" in device_received_text(record)
    run = motionctl_as_typed("--bench", str(path), "--device", "stage", "move", "70", "0", "0")
    assert run.returncode == 2 and "outside -50..50 mm" in run.stderr  # the bench's box
    assert _where(sims["stage"]) == [7.0, 8.0, 1.0]


@pytest.mark.parametrize(
    ("args", "why"),
    [
        (("move", "1", "1", "0"), "has 2 devices: choose one with --device (stage, head)"),
        (("--device", "arm", "id"), "has no device 'arm' (it has stage, head)"),
        (("--device", "stage", "--port", "/dev/null", "id"), "--port and --bench"),
        (("--device", "stage", "--protocol", "firmata", "id"), "disagrees with the bench"),
    ],
)
def test_motionctl_refuses_a_bench_use_before_sending(bench, args, why) -> None:
    path, _, record = bench
    before = device_received_text(record)
    run = motionctl_as_typed("--bench", str(path), *args)
    assert run.returncode == 2, run.stderr
    assert why in run.stderr
    assert device_received_text(record) == before  # nothing sent


def test_motionctl_device_without_a_bench_is_refused() -> None:
    run = motionctl_as_typed("--device", "stage", "id")
    assert run.returncode == 2 and "give --bench FILE" in run.stderr
