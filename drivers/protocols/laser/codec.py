"""The laser-robot link's data (drivers/protocols/README.md §3): instructions of a command word and
typed fields.

Field = marker + count + values, little-endian: `F0` float32, `F1` int16, `F2` uint8, `F3` char.
An instruction is a command word (0x01..0x7F) followed by its fields; a frame's data holds one or
more instructions (the framing, stuffing and checksum are `drivers/framers/stuffed.py`'s).
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass

from drivers.errors import BadInput, FrameError
from drivers.messages import Message

FLOAT, INT16, UINT8, CHAR = 0xF0, 0xF1, 0xF2, 0xF3
_FORMATS = {FLOAT: ("<f", 4), INT16: ("<h", 2), UINT8: ("<B", 1), CHAR: ("<c", 1)}
_RANGES = {INT16: (-32768, 32767), UINT8: (0, 255)}
_NAMES = {FLOAT: "float32", INT16: "int16", UINT8: "uint8", CHAR: "char"}
FLOAT32_MAX = 3.4028234663852886e38


@dataclass(frozen=True)
class Field:
    """Typed values: `kind` is the marker (FLOAT, INT16, UINT8, CHAR)."""

    kind: int
    values: tuple[float | int | str, ...]

    def encode(self) -> bytes:
        """Marker, count, the values; BadInput where a value does not fit its type."""
        if not 0 < len(self.values) <= 255:
            raise BadInput(
                Message("a field holds 1 to 255 values, not {count}", count=len(self.values))
            )
        fmt, _ = _FORMATS[self.kind]
        out = bytearray((self.kind, len(self.values)))
        for value in self.values:
            if self.kind == CHAR:
                text = str(value)
                if len(text) != 1 or not text.isascii():
                    raise BadInput(Message("{value!r} is not one ASCII character", value=value))
                out += text.encode("ascii")
                continue
            if self.kind == FLOAT:
                number = float(value)
                if not math.isfinite(number) or abs(number) > FLOAT32_MAX:
                    raise BadInput(Message("{value} does not fit a float32", value=value))
                out += struct.pack(fmt, number)
                continue
            low, high = _RANGES[self.kind]
            if not isinstance(value, int) or not low <= value <= high:
                raise BadInput(
                    Message(
                        "{value} does not fit a {kind} ({low} to {high})",
                        value=value,
                        kind=_NAMES[self.kind],
                        low=low,
                        high=high,
                    )
                )
            out += struct.pack(fmt, value)
        return bytes(out)


@dataclass(frozen=True)
class Instruction:
    """A command word and its fields."""

    word: int
    fields: tuple[Field, ...] = ()

    def encode(self) -> bytes:
        """The instruction's bytes."""
        if not 0x01 <= self.word <= 0x7F:
            raise BadInput(
                Message("command word {word:#04x} is outside 0x01..0x7F", word=self.word)
            )
        return bytes((self.word,)) + b"".join(f.encode() for f in self.fields)

    def values(self, kind: int) -> tuple[float | int | str, ...]:
        """The values of its first field of `kind` (empty if none)."""
        return next((f.values for f in self.fields if f.kind == kind), ())


def decode_instructions(data: bytes) -> list[Instruction]:
    """A frame's data as instructions; FrameError for data that is not instructions."""
    instructions: list[Instruction] = []
    index = 0
    while index < len(data):
        word = data[index]
        if not 0x01 <= word <= 0x7F:
            raise FrameError(
                Message(
                    "byte {index}: {byte:#04x} where a command word was expected",
                    index=index,
                    byte=word,
                )
            )
        index += 1
        fields: list[Field] = []
        while index < len(data) and data[index] in _FORMATS:
            kind = data[index]
            if index + 1 >= len(data):
                raise FrameError(
                    Message(
                        "byte {index}: a {kind} field without its count",
                        index=index,
                        kind=_NAMES[kind],
                    )
                )
            count = data[index + 1]
            fmt, size = _FORMATS[kind]
            end = index + 2 + count * size
            if end > len(data):
                raise FrameError(
                    Message(
                        "byte {index}: {count} {kind} values run past the data",
                        index=index,
                        count=count,
                        kind=_NAMES[kind],
                    )
                )
            raw = data[index + 2 : end]
            if kind == CHAR:
                values: tuple[float | int | str, ...] = tuple(raw.decode("latin-1"))
            else:
                values = tuple(struct.unpack(f"<{count}{fmt[1]}", raw))
            fields.append(Field(kind, values))
            index = end
        instructions.append(Instruction(word, tuple(fields)))
    return instructions


def crc16(data: bytes) -> int:
    """CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF) of `data`."""
    crc = 0xFFFF
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) & 0xFFFF if crc & 0x8000 else (crc << 1) & 0xFFFF
    return crc


def as_int16(value: int) -> int:
    """A 16-bit pattern as the int16 that carries it."""
    return value - 0x10000 if value >= 0x8000 else value
