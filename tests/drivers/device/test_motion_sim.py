"""Client and Motion against the in-process simulated COXIRIS device (sim://)."""

from __future__ import annotations

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.errors import BadInput, DeviceError, DeviceTimeout
from drivers.link.transport import Link
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.protocols.events import PositionReport, TextLine
from drivers.sim.coxiris_device import HELP_LINES
from tests.conftest import Recorder

pytestmark = pytest.mark.timeout(20)


def test_identify_and_position(motion: Motion) -> None:
    assert motion.identify() == "CX25F7TK9P"
    assert motion.position() == PositionReport(0.0, 0.0, 0.0)


def test_move_then_position(motion: Motion) -> None:
    assert motion.move_to(10, -5, 2.5) == PositionReport(10.0, -5.0, 2.5)
    assert motion.position() == PositionReport(10.0, -5.0, 2.5)


def test_relative_move_home_and_set_home(motion: Motion) -> None:
    motion.move_to(1, 1, 1)
    assert motion.move_by(0.5, 1, -2) == PositionReport(1.5, 2.0, -1.0)
    assert motion.home() == PositionReport(0.0, 0.0, 0.0)
    motion.move_to(3, 4, 0)
    motion.set_home()
    assert motion.position() == PositionReport(0.0, 0.0, 0.0)


@pytest.mark.sim_url("sim://coxiris?speed=100&blocking=0")
def test_non_blocking_move_waits_until_the_target_is_reached(motion: Motion) -> None:
    assert motion.move_to(20, 0, 0) == PositionReport(20.0, 0.0, 0.0)


@pytest.mark.sim_url("sim://coxiris?speed=100&blocking=0")
def test_non_blocking_device_reports_positions_along_the_way(
    sim_link: tuple[Link, Recorder],
) -> None:
    link, _ = sim_link
    client = Client(link, CoxirisProtocol())
    client.execute(cmd.MoveTo(300, 0, 0))  # 3 s at 100 mm/s
    mid = client.execute(cmd.GetPosition()).value
    assert isinstance(mid, PositionReport)
    assert 0.0 <= mid.x < 300.0


def test_speed_comes_back_rounded(motion: Motion) -> None:
    assert motion.set_speed(12.5) == 13.0
    assert motion.speed() == 13.0
    assert motion.speed_limits() == (1.0, 100.0)


def test_speed_out_of_range_is_refused_without_set_speed(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    with pytest.raises(BadInput, match="1 to 100"):
        motion.set_speed(500)
    assert b"SET_SPEED" not in recorder.sent()


def test_bad_coordinates_are_refused_before_anything_is_sent(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    with pytest.raises(BadInput):
        motion.move_to(float("nan"), 0, 0)
    with pytest.raises(BadInput):
        motion.move_by(1e10, 0, 0)
    assert recorder.sent() == b""


def test_unknown_command_is_an_error_at_once_and_the_help_is_drained(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    with pytest.raises(DeviceError, match="FOO"):
        motion.raw(b"foo 1")
    # the last help line was read (its LF may still be on the way: the line ends at its CR)
    assert HELP_LINES[-1].encode() + b"\r" in recorder.received()
    assert motion.identify() == "CX25F7TK9P"


def test_help_returns_the_twelve_lines(motion: Motion) -> None:
    reply = motion.client.execute(cmd.Help())
    assert reply.value == ["Available commands:", *HELP_LINES]


@pytest.mark.sim_url("sim://coxiris?fault=Motor+X+stalled&fault=Endstop+Y")
def test_check_errors_reports_every_fault(motion: Motion) -> None:
    with pytest.raises(DeviceError, match="Motor X stalled; Endstop Y"):
        motion.check()


def test_check_without_faults(motion: Motion) -> None:
    motion.check()


@pytest.mark.sim_url("sim://coxiris?mute=1")
def test_silent_device_times_out(sim_link: tuple[Link, Recorder]) -> None:
    link, recorder = sim_link
    client = Client(link, CoxirisProtocol(), timeout=0.2)
    with pytest.raises(DeviceTimeout, match="did not answer to GET_ID") as raised:
        client.execute(cmd.GetId())
    assert "it may still be moving" in str(raised.value)
    assert recorder.sent() == b"GET_ID\n"


def test_raw_console_line_is_followed_to_its_error(sim_link: tuple[Link, Recorder]) -> None:
    link, _ = sim_link
    client = Client(link, CoxirisProtocol(), timeout=1.0)
    with pytest.raises(DeviceError, match="does not know the command 'FOO'"):
        client.send_raw(b"foo 1\r\n")
    reply = client.send_raw(b"get_id\n")
    assert reply is not None and reply.value == "CX25F7TK9P"
    assert client.send_raw(b"GET_") is None  # an unfinished line: nothing to wait for


def test_unsolicited_lines_reach_listeners(sim_link: tuple[Link, Recorder]) -> None:
    link, _ = sim_link
    client = Client(link, CoxirisProtocol())
    seen: list[tuple[object, bool]] = []
    client.listeners.append(lambda event, solicited: seen.append((event, solicited)))
    link.write(b"FOO\n")  # behind the client's back: the reply is unsolicited
    client.execute(cmd.GetId())
    assert (TextLine("Available commands:"), False) in seen
