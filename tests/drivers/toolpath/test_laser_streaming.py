"""Streaming programs over the laser link to its simulator, faults included: once each, in order."""

from __future__ import annotations

import math

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.link.transport import open_link
from drivers.protocols import commands as cmd
from drivers.protocols.laser.protocol import LaserProtocol
from drivers.toolpath.point_program import ProgramPoint
from drivers.toolpath.streaming import Streamer

pytestmark = pytest.mark.timeout(60)


def _circle(count: int) -> list[ProgramPoint]:
    return [
        ProgramPoint(
            round(10 * math.cos(i / count * 2 * math.pi), 3),
            round(10 * math.sin(i / count * 2 * math.pi), 3),
            round(i / count, 3),
            1000.0,
        )
        for i in range(count)
    ]


def _stream(url: str, points: list[ProgramPoint], group: int = 7):
    link = open_link(url, 115200)
    try:
        client = Client(link, LaserProtocol())
        state = Streamer(client, points, group=group).run()
        return state, link.port.device  # type: ignore[attr-defined]
    finally:
        link.close()


def _executed_points(device: object) -> list[tuple[float, float, float, float]]:
    moves = [values for word, values, *_ in device.executed if word == 0x01]  # type: ignore[attr-defined]
    return [tuple(round(v, 3) for v in values) for values in moves]


@pytest.mark.parametrize(
    "faults",
    [
        "corrupt=0.01",
        "drop_reply=0.05",
        "drop=0.05",
        "delay_reply=0.05",
        "garbage=0.2",
        "corrupt=0.01&drop_reply=0.005",
    ],
)
def test_every_point_executed_once_in_order_under_faults(faults: str) -> None:
    points = _circle(300)
    state, device = _stream(f"sim://laser-frame?instant=1&seed=11&{faults}", points)
    assert state.finished and state.executed == 300
    expected = [(p.x, p.y, p.z, p.speed) for p in points]
    assert _executed_points(device) == expected  # float32 on the wire, rounded back to 1 µm


def test_a_clean_line_groups_seven_a_frame() -> None:
    state, _ = _stream("sim://laser-frame?instant=1", _circle(70))
    assert (state.frames, state.retransmissions) == (10, 0)
    single, _ = _stream("sim://laser-frame?instant=1", _circle(70), group=1)
    assert single.frames == 70


def test_a_small_queue_is_back_pressure_not_loss() -> None:
    points = [ProgramPoint(p.x, p.y, p.z, 100.0) for p in _circle(60)]  # 0.6 s of moves
    link = open_link("sim://laser-frame?queue=8", 115200)  # sent faster than run: it fills
    try:
        client = Client(link, LaserProtocol())
        state = Streamer(client, points).run()
        assert client.backpressure_waits > 0
        assert state.executed == 60
        assert len(_executed_points(link.port.device)) == 60  # type: ignore[attr-defined]
    finally:
        link.close()


def test_motion_on_the_laser_simulator() -> None:
    link = open_link("sim://laser-frame?instant=1", 115200)
    try:
        motion = Motion(Client(link, LaserProtocol()))
        assert motion.identify() == "LZR-SIM-01"
        report = motion.move_to(10, -5, 2)
        assert (report.x, report.y, report.z, report.measured) == (10, -5, 2, True)
        assert motion.move_by(1, 1, 0).x == pytest.approx(11)
        motion.set_home()
        assert (motion.position().x, motion.position().y) == (0, 0)
        motion.client.execute(cmd.Stop())
    finally:
        link.close()
