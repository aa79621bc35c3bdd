"""The laser link's codec and protocol: frames, typed fields, replies, and what fails how."""

from __future__ import annotations

import contextlib
import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from drivers.errors import BadInput, DeviceError, FrameError, QueueFull, Retransmit
from drivers.framers.stuffed import StuffedFramer
from drivers.protocols import commands as cmd
from drivers.protocols.events import PositionReport, Undecodable
from drivers.protocols.laser.codec import (
    CHAR,
    FLOAT,
    INT16,
    UINT8,
    Field,
    Instruction,
    crc16,
    decode_instructions,
)
from drivers.protocols.laser.protocol import (
    GetStatus,
    LaserProtocol,
    LaserReply,
    QueuedGroup,
    move_instruction,
)
from drivers.toolpath.point_program import ProgramError, parse_csv, parse_json


def _reply(data: bytes) -> LaserReply:
    event = LaserProtocol().decode(data)[0]
    assert isinstance(event, LaserReply)
    return event


def test_position_query_is_exactly_the_reference_frame() -> None:
    assert LaserProtocol().encode(cmd.GetPosition()) == bytes.fromhex("EB 90 82 F0 10 90 82 10")


def test_typed_fields_round_trip() -> None:
    instructions = [
        Instruction(0x01, (Field(FLOAT, (1.5, -2.25, 0.0, 10.0)),)),
        Instruction(0x02, (Field(INT16, (-300,)),)),
        Instruction(0x11, (Field(UINT8, (3, 1)),)),
        Instruction(0x14, (Field(CHAR, tuple("LZR")),)),
    ]
    data = b"".join(i.encode() for i in instructions)
    assert decode_instructions(data) == instructions


@pytest.mark.parametrize(
    ("field", "why"),
    [
        (Field(INT16, (40000,)), "int16"),
        (Field(UINT8, (-1,)), "uint8"),
        (Field(FLOAT, (float("nan"),)), "float32"),
        (Field(CHAR, ("ab",)), "one ASCII character"),
        (Field(FLOAT, ()), "1 to 255 values"),
    ],
)
def test_values_that_do_not_fit_are_refused(field: Field, why: str) -> None:
    with pytest.raises(BadInput, match=why):
        field.encode()


def test_a_0x90_inside_the_data_is_stuffed_and_survives() -> None:
    value = struct.unpack("<f", b"\x90\x90\x10\x41")[0]  # a float whose bytes hold 0x90 twice
    frame = LaserProtocol().encode(cmd.MoveTo(value, 0, 0, 10))
    assert b"\x90\x90\x90\x90" in frame
    frames, rest = StuffedFramer().split(frame)
    assert rest == b""
    decoded = decode_instructions(frames[0])
    assert decoded[1].values(FLOAT)[0] == pytest.approx(value)


def test_queued_frames_carry_a_sequence_that_advances_only_when_sent() -> None:
    protocol = LaserProtocol()
    assert 1 <= protocol.sequence <= 32767  # a session starts at a random number
    protocol.configure({"next_sequence": 1})  # or where the last one left off
    move = cmd.MoveTo(1, 2, 3, 10)
    first = protocol.instructions(move)
    check = crc16(first[1].encode())  # the frame's CRC-16 of the queued instructions
    assert first[0] == Instruction(0x20, (Field(INT16, (1, check - 0x10000 * (check >= 0x8000))),))
    assert protocol.instructions(move)[0] == first[0]  # encoding alone takes no number
    protocol.on_sent(move)
    assert protocol.instructions(move)[0].values(INT16)[0] == 2
    protocol.on_sent(cmd.GetPosition())  # immediate frames take none
    assert protocol.sequence == 2
    protocol.sequence = 32767
    protocol.on_sent(move)
    assert protocol.sequence == 1  # wraps within a positive int16


def test_grouping_is_seven_queued_at_most_and_immediate_alone() -> None:
    protocol = LaserProtocol()
    moves = tuple(move_instruction(i, 0, 0, 10) for i in range(7))
    assert len(protocol.instructions(QueuedGroup(moves))) == 8  # SEQUENCE + 7
    with pytest.raises(BadInput, match="1 to 7"):
        protocol.encode(QueuedGroup((*moves, move_instruction(8, 0, 0, 10))))
    with pytest.raises(BadInput, match="1 to 7"):
        protocol.encode(QueuedGroup((Instruction(0x10),)))
    with pytest.raises(BadInput, match="speed 0"):
        move_instruction(0, 0, 0, 0)
    with pytest.raises(BadInput, match="int16"):
        protocol.encode(cmd.Dwell(40000))


def _exchange_result(command: cmd.Command, reply: bytes) -> object:
    protocol = LaserProtocol()
    exchange = protocol.exchange(command)
    for event in protocol.decode(reply):
        exchange.on_event(event)
    assert exchange.finished
    return exchange.result().value


def test_replies_become_values() -> None:
    position = bytes((0x10, FLOAT, 3)) + struct.pack("<3f", 1.5, -2, 0.25)
    assert _exchange_result(cmd.GetPosition(), position) == PositionReport(1.5, -2, 0.25)
    assert _exchange_result(cmd.GetId(), b"\x14\xf3\x03LZR") == "LZR"
    assert _exchange_result(GetStatus(), b"\x11\xf2\x02\x05\x01") == {"queue": 5, "moving": True}


@pytest.mark.parametrize(
    ("code", "error"),
    [(1, Retransmit), (2, Retransmit), (3, DeviceError), (4, DeviceError), (5, QueueFull)],
)
def test_error_replies_fail_as_they_should(code: int, error: type[Exception]) -> None:
    with pytest.raises(error, match=f"error {code}"):
        _exchange_result(cmd.GetPosition(), bytes((0x7F, UINT8, 2, 0x10, code)))


def test_late_replies_to_other_frames_are_ignored() -> None:
    protocol = LaserProtocol()
    protocol.sequence = 5
    exchange = protocol.exchange(cmd.MoveTo(1, 0, 0, 10))
    assert not exchange.on_event(_reply(b"\x20\xf1\x01\x04\x00"))  # frame 4's acknowledgement
    assert not exchange.on_event(_reply(b"\x10\xf0\x03" + bytes(12)))  # a late position reply
    assert not exchange.on_event(_reply(bytes((0x7F, UINT8, 2, 0x11, 2))))  # another's error
    assert exchange.on_event(_reply(b"\x20\xf1\x01\x05\x00"))
    assert exchange.finished


def test_unreadable_reply_data_is_named_not_raised() -> None:
    assert isinstance(LaserProtocol().decode(b"\x10\xf0\x09\x00")[0], Undecodable)


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=64))
def test_decoding_arbitrary_bytes_never_raises_anything_else(data: bytes) -> None:
    with contextlib.suppress(FrameError):
        decode_instructions(data)
    LaserProtocol().decode(data)


def test_programs_from_csv_and_json_and_their_errors() -> None:
    points = parse_csv("# a square\nx, y, z, speed\n0,0,0,10\n10,0,0,10\n\n10,10,0,5\n")
    assert [(p.x, p.y, p.speed) for p in points] == [(0, 0, 10), (10, 0, 10), (10, 10, 5)]
    assert parse_csv("speed,z,y,x\n5,3,2,1\n")[0].x == 1  # columns by name
    assert parse_json('{"points": [[1, 2, 3, 4]]}')[0].z == 3
    for text, why in [
        ("x,y,z\n1,2,3\n", "header"),
        ("x,y,z,speed\n1,2,3\n", "line 2: 3 values"),
        ("x,y,z,speed\n1,2,a,3\n", "line 2: z 'a'"),
        ("x,y,z,speed\n1,2,3,0\n", "line 2: speed 0"),
        ("x,y,z,speed\n1,nan,3,1\n", "finite"),
        ("x,y,z,speed\n", "no points"),
    ]:
        with pytest.raises(ProgramError, match=why):
            parse_csv(text)
    with pytest.raises(ProgramError, match="line 1"):
        parse_json("{nope")
    with pytest.raises(ProgramError, match="point 1"):
        parse_json('{"points": [[1, 2]]}')


def test_crc16_is_ccitt_false() -> None:
    assert crc16(b"123456789") == 0x29B1


def test_the_simulator_refuses_queued_instructions_whose_crc_differs() -> None:
    from drivers.sim.clock import ManualClock
    from drivers.sim.laser_device import LaserDevice

    clock = ManualClock()
    device = LaserDevice(clock, instant=True)
    protocol = LaserProtocol()
    good = protocol.instructions(cmd.MoveTo(1, 2, 3, 10))
    damaged = Instruction(0x01, (Field(FLOAT, (1.0, 2.0, 3.5, 10.0)),))  # a changed z
    data = good[0].encode() + damaged.encode()
    device.receive(StuffedFramer().encode(data))
    clock.advance(0.1)
    frames, _ = StuffedFramer().split(device.read_output())
    assert decode_instructions(frames[0]) == [Instruction(0x7F, (Field(UINT8, (0x20, 2)),))]
    assert device.executed == []
    device.receive(protocol.encode(cmd.MoveTo(1, 2, 3, 10)))
    clock.advance(0.1)
    assert [word for word, *_ in device.executed] == [0x01]


@pytest.mark.parametrize("code", [3, 4])
def test_a_queued_frame_refused_as_malformed_is_sent_again(code: int) -> None:
    with pytest.raises(Retransmit, match=f"error {code}"):
        _exchange_result(cmd.MoveTo(1, 2, 3, 10), bytes((0x7F, UINT8, 2, 0x20, code)))
