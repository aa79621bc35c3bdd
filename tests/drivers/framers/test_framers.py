"""Framers for every wire format: whole, byte by byte, split anywhere, behind garbage; fuzzed."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from drivers.errors import FrameError
from drivers.framers.base import Framer
from drivers.framers.fixed import FixedFramer
from drivers.framers.lines import LineFramer
from drivers.framers.silence import SilenceFramer
from drivers.framers.stuffed import StuffedFramer, checksum
from drivers.framers.sysex import SysexFramer

pytestmark = pytest.mark.timeout(60)

PI_LINEAR = bytes.fromhex("7b7d01" + "0064" + "0032" + "0000" * 8 + "00" + "2a")
FIRMATA = [
    bytes.fromhex("F0 72 00 48 01 08 09 F7"),  # stepper_config(200, [8, 9])
    bytes.fromhex("F0 72 00 00 20 08 09 0A 0B F7"),  # stepper_config(4096, [8, 9, 10, 11])
    bytes.fromhex("F0 72 01 2C 02 00 74 03 01 F7"),  # stepper_step(300, 500)
    bytes.fromhex("F0 72 01 7F 7F 7F 7F 7F 00 F7"),  # stepper_step(2097151, -16383)
    bytes.fromhex("F0 72 02 F7"),  # stepper_request_library_version()
    bytes.fromhex("F0 72 05 00 F7"),  # reply: version 5
    bytes.fromhex("F9 02 05"),  # version report
]


def feed(framer: Framer, chunks: list[bytes]) -> list[bytes]:
    """Feed chunks as a port delivers them; return the frames in order."""
    frames: list[bytes] = []
    buffer = b""
    for chunk in chunks:
        got, buffer = framer.split(buffer + chunk)
        frames.extend(got)
    return frames


def deliveries(wire: bytes) -> list[list[bytes]]:
    """Whole, byte by byte, and split in two at every position."""
    ways = [[wire], [bytes((b,)) for b in wire]]
    ways += [[wire[:i], wire[i:]] for i in range(1, len(wire))]
    return ways


# -- lines ------------------------------------------------------------------------------------
def test_lines_every_ending() -> None:
    assert feed(LineFramer(), [b"ACK A\r\nDONE A\nX\rY\r\n"]) == [b"ACK A", b"DONE A", b"X", b"Y"]


def test_lines_delivery_independent() -> None:
    wire = b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"
    for chunks in deliveries(wire):
        assert feed(LineFramer(), chunks) == [b"ACK GET_ID", b"DONE GET_ID: CX25F7TK9P"]


def test_lines_bounded() -> None:
    frames = feed(LineFramer(max_length=10), [b"A" * 25])
    assert frames == [b"A" * 10, b"A" * 10]


# -- silence ----------------------------------------------------------------------------------
def test_silence_only_flush_ends_a_packet() -> None:
    framer = SilenceFramer()
    assert framer.decode(b"S03000382NNNNNNNNN") == (0, None)
    assert framer.flush(b"S03000382NNNNNNNNN") == (18, b"S03000382NNNNNNNNN")
    assert framer.flush(b"") == (0, None)
    assert framer.encode(b"MLP0010000P0010000") == b"MLP0010000P0010000"
    assert framer.idle_timeout == 1.0


def test_silence_bounded() -> None:
    assert SilenceFramer(max_length=4).decode(b"ABCDEF") == (4, b"ABCD")


# -- stuffed ----------------------------------------------------------------------------------
def test_stuffed_doubles_0x90_and_appends_the_checksum() -> None:
    data = bytes([0x01, 0x90, 0x82, 0x05])
    wire = StuffedFramer().encode(data)
    assert wire == bytes.fromhex("EB 90 82 F0 01 90 90 82 05 90 82") + bytes([checksum(data)])
    for chunks in deliveries(wire):
        assert feed(StuffedFramer(), chunks) == [data]


def test_stuffed_behind_garbage_and_back_to_back() -> None:
    a, b = bytes([0x10]), bytes([0x11, 0x90])
    framer = StuffedFramer()
    wire = b"\x00\xeb\x90" + framer.encode(a) + b"\xff" + framer.encode(b)
    assert feed(StuffedFramer(), [wire]) == [a, b]


def test_stuffed_corrupt_checksum_is_dropped_with_a_reason() -> None:
    framer = StuffedFramer()
    wire = bytearray(framer.encode(b"\x10"))
    wire[-1] ^= 0xFF
    assert feed(framer, [bytes(wire)]) == []
    assert framer.last_error is not None and "checksum" in framer.last_error
    assert feed(framer, [framer.encode(b"\x14")]) == [b"\x14"]


def test_stuffed_lone_0x90_inside_the_data_is_dropped() -> None:
    framer = StuffedFramer()
    assert feed(framer, [bytes.fromhex("EB 90 82 F0 01 90 05 90 82 96")]) == []
    assert framer.last_error is not None and "0x90" in framer.last_error


# -- fixed (pi-frame) -------------------------------------------------------------------------
def test_pi_frame_example_from_the_seed() -> None:
    assert len(PI_LINEAR) == 25
    assert FixedFramer().encode(PI_LINEAR[2:-1]) == PI_LINEAR
    for chunks in deliveries(PI_LINEAR):
        assert feed(FixedFramer(), chunks) == [PI_LINEAR]


def test_pi_frame_resyncs_after_garbage_and_a_bad_trailer() -> None:
    broken = PI_LINEAR[:-1] + b"\x00"
    assert feed(FixedFramer(), [b"\x7b\x01" + broken + PI_LINEAR]) == [PI_LINEAR]


def test_pi_frame_body_length_is_checked() -> None:
    with pytest.raises(FrameError):
        FixedFramer().encode(b"\x00" * 21)


# -- Firmata ----------------------------------------------------------------------------------
@pytest.mark.parametrize("message", FIRMATA)
def test_firmata_messages(message: bytes) -> None:
    for chunks in deliveries(message):
        assert feed(SysexFramer(), chunks) == [message]


def test_firmata_encode_matches_pymata() -> None:
    assert SysexFramer().encode(bytes.fromhex("72 01 2C 02 00 74 03 01")) == FIRMATA[2]
    with pytest.raises(FrameError):
        SysexFramer().encode(bytes([0x72, 0x80]))


def test_firmata_garbage_and_interrupted_sysex() -> None:
    wire = b"\x01\x02" + b"\xf0\x72\x01" + FIRMATA[6] + b"\xf7" + FIRMATA[5]
    assert feed(SysexFramer(), [wire]) == [FIRMATA[6], FIRMATA[5]]


# -- every framer -----------------------------------------------------------------------------
FRAMERS = [LineFramer, SilenceFramer, StuffedFramer, FixedFramer, SysexFramer]


@pytest.mark.parametrize("make", FRAMERS)
@settings(max_examples=300, deadline=None)
@given(data=st.binary(max_size=300))
def test_any_bytes_never_raise(make, data: bytes) -> None:
    framer = make()
    buffer = data
    for _ in range(len(data) + 2):
        try:
            used, _frame = framer.decode(buffer)
        except FrameError:
            return
        assert 0 <= used <= len(buffer)
        if used == 0:
            break
        buffer = buffer[used:]
    used, _ = framer.flush(buffer)
    assert 0 <= used <= len(buffer)


ROUND_TRIPS = [
    (StuffedFramer, st.binary(min_size=1, max_size=60)),
    (SysexFramer, st.binary(min_size=1, max_size=60).map(lambda b: bytes(x & 0x7F for x in b))),
    (FixedFramer, st.binary(min_size=22, max_size=22)),
]


@pytest.mark.parametrize(("make", "payloads"), ROUND_TRIPS)
@settings(max_examples=200, deadline=None)
@given(data=st.data())
def test_round_trip_split_anywhere_and_behind_garbage(make, payloads, data) -> None:
    payload = data.draw(payloads)
    wire = make().encode(payload)
    cut = data.draw(st.integers(0, len(wire)))
    if make is SysexFramer:  # Firmata garbage: data bytes where a status byte is due
        junk = data.draw(st.binary(max_size=8).map(lambda j: bytes(b & 0x7F for b in j)))
    else:  # anything that cannot begin a header
        junk = data.draw(st.binary(max_size=8).filter(lambda j: wire[0] not in j))
    frames = feed(make(), [junk + wire[:cut], wire[cut:]])
    expected = wire if make in (SysexFramer, FixedFramer) else payload
    assert frames == [expected]
