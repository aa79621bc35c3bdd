"""Travel limits and resolution: refused or clamped before the move is sent."""

from __future__ import annotations

import pytest

from drivers.device.motion import Motion, MoveStart
from drivers.device.travel import TravelLimits, check_resolution, parse_travel
from drivers.errors import BadInput
from drivers.link.transport import Link
from tests.conftest import Recorder

pytestmark = pytest.mark.timeout(20)

BOX = ((-50.0, 50.0), (-20.0, 20.0), (0.0, 10.0))


def test_parse_travel() -> None:
    limits = parse_travel("-50:50, -20:20, 0:10")
    assert limits is not None and limits.box == BOX
    assert parse_travel("none") is None
    for bad in ("1:2", "a:b,1:2,3:4", "5:1,0:1,0:1", "1,2,3", "nan:1,0:1,0:1"):
        with pytest.raises(BadInput):
            parse_travel(bad)


def test_apply_refuses_or_clamps_with_a_message() -> None:
    limits = TravelLimits(BOX)
    assert limits.apply((10.0, 0.0, 5.0)) == ((10.0, 0.0, 5.0), None)
    with pytest.raises(BadInput, match=r"X 1000 mm is outside -50\.\.50 mm"):
        limits.apply((1000.0, 0.0, 0.0), "move to (1000, 0, 0) mm")
    clamped, note = TravelLimits(BOX, clamp=True).apply((1000.0, -30.0, 5.0))
    assert clamped == (50.0, -20.0, 5.0)
    assert note is not None and "clamped" in note and "Y -30 mm" in note


def test_resolution() -> None:
    check_resolution((0.01, -12.34, 100.0), ("x", "y", "z"), 0.01)
    with pytest.raises(BadInput, match=r"x 0\.001 mm refused: the device works to 0\.01 mm"):
        check_resolution((0.001, 0.0, 0.0), ("x", "y", "z"), 0.01)
    check_resolution((0.001, 0.0, 0.0), ("x", "y", "z"), None)


def test_out_of_limits_move_is_never_sent(motion: Motion, sim_link: tuple[Link, Recorder]) -> None:
    _, recorder = sim_link
    motion.travel = TravelLimits(BOX)
    with pytest.raises(BadInput, match="travel limits"):
        motion.move_to(100000, 0, 0)
    with pytest.raises(BadInput, match="travel limits"):
        motion.move_by(0, 25, 0)
    assert b"MOVE" not in recorder.sent()


def test_clamped_jog_goes_to_the_edge_and_says_so(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    notes: list[str] = []
    motion.notice_listeners.append(notes.append)
    motion.travel = TravelLimits(BOX, clamp=True)
    motion.move_to(49.99, 0, 0)
    report = motion.move_by(5, 0, 0)
    assert (report.x, report.y, report.z) == (50.0, 0.0, 0.0)
    assert b"DELTA_MOVE 0.01 0 0\n" in recorder.sent()
    assert len(notes) == 1 and "clamped" in notes[0]


def test_too_fine_a_move_is_refused_before_sending(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    with pytest.raises(BadInput, match=r"0\.01 mm"):
        motion.move_to(0.001, 0, 0)
    with pytest.raises(BadInput, match=r"0\.01 mm"):
        motion.move_by(0, 0.005, 0)
    assert recorder.sent() == b""


def test_move_listeners_hear_start_target_speed_and_duration(motion: Motion) -> None:
    starts: list[MoveStart] = []
    motion.move_listeners.append(starts.append)
    motion.move_to(10, 0, 0)
    (start,) = starts
    assert start.start == (0.0, 0.0, 0.0) and start.target == (10.0, 0.0, 0.0)
    assert start.duration == pytest.approx(10.0 / start.speed)
    assert start.estimate(start.started) == (0.0, 0.0, 0.0)
    halfway = start.estimate(start.started + start.duration / 2)
    assert halfway == pytest.approx((5.0, 0.0, 0.0))
    assert start.estimate(start.started + 2 * start.duration) == (10.0, 0.0, 0.0)
