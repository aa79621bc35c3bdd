"""COXIRIS encoding, decoding and reply tracking, without any I/O."""

from __future__ import annotations

import pytest

from drivers.errors import BadInput, DeviceError, GarbledReply
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.protocols.events import Ack, Done, ErrorReport, PositionReport, TextLine

P = CoxirisProtocol()


def _feed(command: cmd.Command, text: bytes):
    exchange = P.exchange(command)
    framer = P.new_framer()
    frames, _rest = framer.split(text)
    for frame in frames:
        for event in P.decode(frame):
            exchange.on_event(event)
    return exchange


@pytest.mark.parametrize(
    ("command", "wire"),
    [
        (cmd.Help(), b"HELP\n"),
        (cmd.SetHome(), b"SET_HOME\n"),
        (cmd.Home(), b"GO_HOME\n"),
        (cmd.MoveTo(1.5, -2, 0.5), b"ABSOLUTE_MOVE 1.5 -2 0.5\n"),
        (cmd.MoveBy(0.5, 1, -2), b"DELTA_MOVE 0.5 1 -2\n"),
        (cmd.MoveTo(1e-7, 0, -0.0), b"ABSOLUTE_MOVE 0.0000001 0 0\n"),
        (cmd.GetPosition(), b"GET_POSITION\n"),
        (cmd.SetSpeed(12.5), b"SET_SPEED 12.5\n"),
        (cmd.GetSpeed(), b"GET_SPEED\n"),
        (cmd.GetMinSpeed(), b"GET_MIN_SPEED\n"),
        (cmd.GetMaxSpeed(), b"GET_MAX_SPEED\n"),
        (cmd.GetId(), b"GET_ID\n"),
        (cmd.CheckErrors(), b"CHECK_ERRORS\n"),
        (cmd.Raw(b"get_id"), b"get_id\n"),
    ],
)
def test_encode_every_command(command: cmd.Command, wire: bytes) -> None:
    assert P.encode(command) == wire


@pytest.mark.parametrize(
    ("command", "why"),
    [
        (cmd.MoveTo(float("nan"), 0, 0), "finite"),
        (cmd.MoveTo(float("inf"), 0, 0), "finite"),
        (cmd.MoveBy(5e9, 0, 0), "out of range"),
        (cmd.SetSpeed(0), "positive"),
        (cmd.SetSpeed(-5), "positive"),
        (cmd.Raw(b"X" * 64), "at most 63"),
        (cmd.Raw(b"   "), "empty"),
        (cmd.Raw(b"GET_ID\nHELP"), "line break"),
        (cmd.Raw("GET_ÏD".encode()), "ASCII"),
        (cmd.MoveTo(-123456789.12345, -123456789.12345, -123456789.12345), "at most 63"),
        (cmd.Stop(), "no command"),
    ],
)
def test_refused_before_sending(command: cmd.Command, why: str) -> None:
    with pytest.raises(BadInput, match=why):
        P.encode(command)


def test_63_characters_is_the_longest_accepted() -> None:
    assert len(P.encode(cmd.Raw(b"X" * 63))) == 64


def test_decode_lines() -> None:
    assert P.decode(b"ACK GET_ID") == [Ack("GET_ID")]
    assert P.decode(b"DONE GET_ID: CX25F7TK9P") == [Done("GET_ID", "CX25F7TK9P")]
    assert P.decode(b"DONE SET_HOME") == [Done("SET_HOME", None)]
    assert P.decode(b"ERROR: Speed must be positive") == [ErrorReport("Speed must be positive")]
    assert P.decode(b"Available commands:") == [TextLine("Available commands:")]


def test_position_reply() -> None:
    ex = _feed(cmd.GetPosition(), b"ACK GET_POSITION\r\nDONE GET_POSITION: 1.50 -2.00 0.50\r\n")
    assert ex.finished
    assert ex.result().value == PositionReport(1.5, -2.0, 0.5)


def test_rounded_speed_reply() -> None:
    ex = _feed(cmd.GetSpeed(), b"ACK GET_SPEED\r\nDONE GET_SPEED: 13\r\n")
    assert ex.result().value == 13.0


def test_error_between_ack_and_done_is_a_device_error() -> None:
    ex = _feed(
        cmd.SetSpeed(5),
        b"ACK SET_SPEED\r\nERROR: Speed must be positive - Usage: SET_SPEED speed "
        b"(where speed > 0)\r\nDONE SET_SPEED\r\n",
    )
    with pytest.raises(DeviceError, match="Speed must be positive"):
        ex.result()


def test_unknown_command_fails_at_the_first_line_then_swallows_the_help() -> None:
    ex = _feed(cmd.Raw(b"FOO 1"), b"ERROR: Unknown command - \r\nFOO\r\n")
    assert ex.finished and ex.wants_more
    with pytest.raises(DeviceError, match="FOO"):
        ex.result()
    tail = b"Available commands:\r\n" + b"".join(b"X - y\r\n" for _ in range(12))
    frames, _ = P.new_framer().split(tail)
    for frame in frames:
        assert ex.on_event(P.decode(frame)[0])
    assert not ex.wants_more


def test_unknown_command_reply_of_an_earlier_command_is_not_ours() -> None:
    stale = b"ERROR: Unknown command - \r\nFOO\r\nAvailable commands:\r\nHELP - x\r\n"
    ex = _feed(cmd.GetId(), stale + b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n")
    assert ex.result().value == "CX25F7TK9P"


def test_too_long_reply_fails_at_once() -> None:
    ex = _feed(cmd.Raw(b"GET_ID"), b"ERROR: Command too long\r\n")
    with pytest.raises(DeviceError, match="too long"):
        ex.result()


def test_leftover_lines_before_ack_are_not_taken() -> None:
    ex = _feed(cmd.GetId(), b"CHECK_ERRORS - old help\r\nACK GET_ID\r\nDONE GET_ID: X\r\n")
    assert ex.result().value == "X"
    assert ex.events[0] == Ack("GET_ID")


@pytest.mark.parametrize("data", ["ovf 0.00 0.00", "nan 1 2", "1 2", "a b c"])
def test_unreadable_position_is_a_garbled_reply(data: str) -> None:
    ex = _feed(cmd.GetPosition(), f"ACK GET_POSITION\r\nDONE GET_POSITION: {data}\r\n".encode())
    with pytest.raises(GarbledReply):
        ex.result()


def test_done_for_another_command_is_garbled() -> None:
    ex = _feed(cmd.GetId(), b"ACK GET_ID\r\nDONE GET_SPEED: 1\r\n")
    with pytest.raises(GarbledReply):
        ex.result()


def test_events_read_as_the_wire_says_them() -> None:
    assert str(Ack("GET_ID")) == "ACK GET_ID"
    assert str(Done("GET_ID", "CX1")) == "DONE GET_ID: CX1"
    assert str(ErrorReport("Speed must be positive")) == "error: Speed must be positive"
    assert str(TextLine("Checkpoint 2")) == "the line 'Checkpoint 2'"


def test_command_names_are_the_wire_names() -> None:
    protocol = CoxirisProtocol()
    assert protocol.command_name(cmd.GetPosition()) == "GET_POSITION"
    assert protocol.command_name(cmd.MoveTo(1, 2, 3)) == "ABSOLUTE_MOVE"
    assert protocol.command_name(cmd.Raw(b"get_id")) == "GET_ID"


def test_raw_exchange_follows_one_whole_line_only() -> None:
    protocol = CoxirisProtocol()
    exchange = protocol.raw_exchange(b"foo 1\r\n")
    assert exchange is not None and exchange.name == "FOO"
    assert protocol.raw_exchange(b"GET_ID") is None  # not ended: nothing to follow yet
    assert protocol.raw_exchange(b"GET_ID\nGET_ID\n") is None
    assert protocol.raw_exchange(b"  \n") is None
