"""The laser robot's frame data as its firmware reads it (drivers/protocols/README.md §3):
instructions, checked.

Data = instructions; instruction = command word (0x01..0x7F) + typed fields; field = marker +
count + little-endian values (`F0` float32, `F1` int16, `F2` uint8, `F3` char).
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass

from drivers.protocols.laser.codec import crc16

MOVE_LINEAR, DWELL, GO_HOME = 0x01, 0x02, 0x03
GET_POSITION, GET_STATUS, SET_HOME, STOP, GET_ID = 0x10, 0x11, 0x12, 0x13, 0x14
SEQUENCE, ERROR = 0x20, 0x7F
FLOAT, INT16, UINT8, CHAR = 0xF0, 0xF1, 0xF2, 0xF3
QUEUED = frozenset((MOVE_LINEAR, DWELL, GO_HOME))
IMMEDIATE = frozenset((GET_POSITION, GET_STATUS, SET_HOME, STOP, GET_ID))
GROUP = 7  # queued instructions a frame may carry (the article)
FRAMING, CHECKSUM, UNKNOWN, BAD_ARGUMENTS, QUEUE_FULL = 1, 2, 3, 4, 5

_SIZES = {FLOAT: 4, INT16: 2, UINT8: 1, CHAR: 1}
_FORMATS = {FLOAT: "f", INT16: "h", UINT8: "B"}
# The fields each known word must carry, exactly: (marker, count) pairs.
SIGNATURES: dict[int, tuple[tuple[int, int], ...]] = {
    MOVE_LINEAR: ((FLOAT, 4),),
    DWELL: ((INT16, 1),),
    GO_HOME: (),
    GET_POSITION: (),
    GET_STATUS: (),
    SET_HOME: (),
    STOP: (),
    GET_ID: (),
    SEQUENCE: ((INT16, 1),),
}

Values = tuple[float | int | str, ...]


class Refused(Exception):
    """A frame the firmware answers with an error reply: the failed word and the code."""

    def __init__(self, word: int, code: int, reason: str) -> None:
        super().__init__(reason)
        self.word = word
        self.code = code


@dataclass(frozen=True)
class Parsed:
    """A frame's instructions as the firmware runs them."""

    sequence: int | None  # the SEQUENCE number (0..65535), if the frame had one
    instructions: tuple[tuple[int, Values], ...]  # (word, values), SEQUENCE excluded

    @property
    def immediate(self) -> bool:
        """Whether it is one immediate instruction."""
        return self.sequence is None and self.instructions[0][0] in IMMEDIATE


def split_instructions(data: bytes) -> list[tuple[int, list[tuple[int, bytes]]]]:
    """(word, [(marker, raw field bytes)]) per instruction; Refused for bytes that do not parse."""
    if not data:
        raise Refused(0, UNKNOWN, "a frame without data")
    result: list[tuple[int, list[tuple[int, bytes]]]] = []
    index = 0
    while index < len(data):
        word = data[index]
        if not 0x01 <= word <= 0x7F:
            failed = result[-1][0] if result else word
            code = BAD_ARGUMENTS if result else UNKNOWN
            raise Refused(failed, code, f"byte {index}: {word:#04x} is no command word")
        index += 1
        fields: list[tuple[int, bytes]] = []
        while index < len(data) and data[index] in _SIZES:
            marker = data[index]
            if index + 1 >= len(data):
                raise Refused(word, BAD_ARGUMENTS, f"byte {index}: a field without its count")
            end = index + 2 + data[index + 1] * _SIZES[marker]
            if end > len(data):
                raise Refused(word, BAD_ARGUMENTS, f"byte {index}: field values run past the data")
            fields.append((marker, bytes(data[index:end])))
            index = end
        result.append((word, fields))
    return result


def _values(word: int, fields: list[tuple[int, bytes]]) -> Values:
    signature = SIGNATURES.get(word)
    if signature is None:
        raise Refused(word, UNKNOWN, f"unknown command word {word:#04x}")
    shape = tuple((marker, raw[1]) for marker, raw in fields)
    if word == SEQUENCE and shape == ((INT16, 2),):
        signature = shape  # the frame number and the queued instructions' CRC-16
    if shape != signature:
        raise Refused(word, BAD_ARGUMENTS, f"fields of {word:#04x} do not match {signature}")
    if not fields:
        return ()
    marker, raw = fields[0]
    if marker == CHAR:
        return tuple(raw[2:].decode("latin-1"))
    return struct.unpack(f"<{raw[1]}{_FORMATS[marker]}", raw[2:])


def parse(data: bytes) -> Parsed:
    """Check a frame's data as the firmware does; Refused (word, code) when it is not accepted."""
    # The CRC first: a damaged frame whose one-byte sum still matches may not even parse.
    numbered = data[:3] == bytes((SEQUENCE, INT16, 2)) and len(data) >= 7
    if numbered and struct.unpack("<H", data[5:7])[0] != crc16(data[7:]):
        raise Refused(SEQUENCE, CHECKSUM, "the queued instructions' CRC-16 differs")
    raw = split_instructions(data)
    instructions = [(word, _values(word, fields)) for word, fields in raw]
    first = instructions[0][0]
    sequence: int | None = None
    if first == SEQUENCE:
        values = instructions[0][1]
        sequence = int(values[0]) & 0xFFFF  # an int16 field read as 16 bits
        instructions = instructions[1:]
        if not instructions:
            raise Refused(SEQUENCE, BAD_ARGUMENTS, "SEQUENCE without queued instructions")
    for word, values in instructions:
        if word == SEQUENCE:
            raise Refused(word, BAD_ARGUMENTS, "SEQUENCE is not first in its frame")
        if word in IMMEDIATE and len(raw) > 1:
            raise Refused(word, BAD_ARGUMENTS, f"immediate {word:#04x} grouped with others")
        if word == MOVE_LINEAR:
            if not all(math.isfinite(float(v)) for v in values):
                raise Refused(word, BAD_ARGUMENTS, "MOVE_LINEAR with a NaN or infinite value")
            if float(values[3]) <= 0:
                raise Refused(word, BAD_ARGUMENTS, f"MOVE_LINEAR speed {values[3]} <= 0")
        if word == DWELL and int(values[0]) < 0:
            raise Refused(word, BAD_ARGUMENTS, f"DWELL of {values[0]} ms")
    if len(instructions) > GROUP:
        raise Refused(first, BAD_ARGUMENTS, f"{len(instructions)} queued instructions in a frame")
    return Parsed(sequence, tuple(instructions))


def field(marker: int, values: Values) -> bytes:
    """Marker, count, values, as the firmware writes them in a reply."""
    out = bytearray((marker, len(values)))
    for value in values:
        if marker == CHAR:
            out += str(value).encode("latin-1")
        else:
            out += struct.pack(f"<{_FORMATS[marker]}", value)
    return bytes(out)


def error_reply(word: int, code: int) -> bytes:
    """`7F F2 02 <failed word> <code>`."""
    return bytes((ERROR,)) + field(UINT8, (word & 0xFF, code))
