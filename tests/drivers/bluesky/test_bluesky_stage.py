"""The stage as a Bluesky device: a real RunEngine scans a simulated COXIRIS stage (motionsim in
another process, on a pseudo-terminal), each event's position checked against the simulator's
own axes; a scan that leaves the box is refused before the first move; a pause stops the stage."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

pytest.importorskip("ophyd_async")  # the `lab` extra; the test set-up installs it

import bluesky.plan_stubs as bps
from bluesky import RunEngine
from bluesky.plans import grid_scan, scan
from bluesky.run_engine import call_in_bluesky_event_loop
from bluesky.simulators import check_limits
from bluesky.utils import RunEngineInterrupted
from ophyd_async.core import init_devices

from drivers import BadInput
from drivers.bluesky import Stage
from tests.acceptance.xsession import wait_for
from tests.support.e2e import device_received, device_received_text
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(120)]

BOX = "-10:10,-10:10,0:5"


@pytest.fixture
def engine() -> RunEngine:
    """A RunEngine as a lab makes one (its own event loop in a thread of its own)."""
    return RunEngine({}, call_returns_result=True)


@pytest.fixture
def device(tmp_path: Path) -> Iterator[tuple[SimProcess, Path]]:
    record = tmp_path / "device.log"
    sim = SimProcess("coxiris", "--instant", "--record", str(record), control=True)
    yield sim, record
    assert sim.stop() == 0


def _stage(port: str, protocol: str = "coxiris", **settings) -> Stage:
    with init_devices():
        stage = Stage(port, protocol, travel=BOX, **settings)
    return stage


def _where(sim: SimProcess) -> list[float]:
    return [float(v) for v in sim.fault("where").split()[2:5]]


def test_a_grid_scan_reads_the_simulators_own_axes_at_every_point(engine, device) -> None:
    sim, _ = device
    stage = _stage(sim.path)
    assert stage.name == "stage" and [name for name, _ in stage.children()][:3] == ["x", "y", "z"]
    seen: list[tuple[dict, list[float]]] = []

    def on_event(name: str, doc: dict) -> None:
        if name == "event":
            seen.append((doc["data"], _where(sim)))  # the simulator asked at that moment

    try:
        engine(grid_scan([stage], stage.x, -4, 4, 5, stage.y, -2, 2, 5), on_event)
    finally:
        stage.close()
    assert len(seen) == 25
    for data, axes in seen:
        assert [data["stage-x"], data["stage-y"], data["stage-z"]] == pytest.approx(axes)
        assert data["stage-truth"] == "live"
    assert {(d["stage-x"], d["stage-y"]) for d, _ in seen} == {
        (x, y) for x in (-4, -2, 0, 2, 4) for y in (-2, -1, 0, 1, 2)
    }


def test_a_scan_locates_and_describes_each_axis(engine, device) -> None:
    sim, _ = device
    stage = _stage(sim.path)
    try:
        engine(scan([stage], stage.x, -5, 5, 3))
        location = call_in_bluesky_event_loop(stage.x.locate())
        described = call_in_bluesky_event_loop(stage.describe())
    finally:
        stage.close()
    assert location == {"setpoint": 5.0, "readback": 5.0}
    assert _where(sim) == [5.0, 0.0, 0.0]
    assert described["stage-x"]["units"] == "mm"


def test_a_scan_that_leaves_the_box_fails_before_the_first_move(engine, device) -> None:
    sim, record = device
    stage = _stage(sim.path)
    try:
        before = device_received_text(record)
        with pytest.raises(BadInput, match=r"X 12 mm refused: outside -10\.\.10 mm"):
            check_limits(scan([stage], stage.x, -4, 12, 5))
        with pytest.raises(BadInput, match="outside"):
            call_in_bluesky_event_loop(stage.y.check_value(-11))
        assert "MOVE" not in device_received_text(record)[len(before) :]  # nothing sent
        check_limits(scan([stage], stage.x, -4, 10, 5))  # within: no error
    finally:
        stage.close()
    assert _where(sim) == [0.0, 0.0, 0.0]


def _frames(record: Path) -> list[str]:
    """What the laser head received, frame by frame, as the protocol's decoder reads it."""
    from drivers.protocols.registry import create_protocol
    from drivers.traffic.decoding import StreamDecoder

    decoder = StreamDecoder(create_protocol("laser-frame"))
    return [str(f.meaning) for f in decoder.feed_bytes("tx", device_received(record), 0.0)]


def test_a_pause_stops_the_stage_and_abort_ends_the_run(engine, tmp_path: Path) -> None:
    """laser-frame has a stop: a RunEngine pause during a 20 mm move at 2 mm/s stops the
    stage on the way (the RunEngine stops what the plan moved); the device receives STOP."""
    record = tmp_path / "laser.log"
    sim = SimProcess("laser-frame", "--speed", "2", "--record", str(record), control=True)
    with init_devices():
        stage = Stage(sim.path, "laser-frame", travel="-25:25,-25:25,0:10")
    moving = threading.Event()

    def pause_once_moving() -> None:
        wait_for(lambda: _where(sim)[0] > 0.2, 20.0, "the stage on its way")
        moving.set()
        engine.request_pause(defer=False)

    pauser = threading.Thread(target=pause_once_moving, daemon=True)
    pauser.start()
    try:
        with pytest.raises(RunEngineInterrupted):
            engine(bps.mv(stage.x, 20))
        pauser.join(30)
        assert moving.is_set()
        engine.abort("the operator stopped it")
        wait_for(lambda: "STOP" in _frames(record), 10.0, "STOP at the device")
        x = _where(sim)[0]
        assert 0 < x < 15  # stopped on the way, not at the target
        frames = _frames(record)
        moves = [i for i, text in enumerate(frames) if "MOVE" in text.upper()]
        assert moves and "STOP" in frames[moves[-1] :], frames
    finally:
        stage.close()
        assert sim.stop() == 0
