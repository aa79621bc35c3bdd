"""Stuffed framer for the laser-robot link (drivers/protocols/README.md §3).

Frame: header `EB 90 82`, flag `F0`, data with every `90` doubled, tail `90 82`, then a checksum
byte: the sum of the unstuffed data bytes mod 256. The checksum comes after the tail, so it is not
stuffed: the receiver knows the byte after `90 82` is the checksum whatever its value.
"""

from __future__ import annotations

from drivers.framers.base import Framer, garbage_before
from drivers.messages import Message

HEADER = b"\xeb\x90\x82"
FLAG = 0xF0
ESCAPE = 0x90
TAIL_SECOND = 0x82


def checksum(data: bytes | bytearray) -> int:
    """Sum of the bytes mod 256."""
    return sum(data) & 0xFF


class StuffedFramer(Framer):
    """Byte-stuffed frames with a checksum; corrupt frames are dropped and `last_error` says why
    (a Message, made only for a corrupt frame)."""

    def __init__(self, max_length: int = 4096) -> None:
        self.max_length = max_length
        self.last_error: str | None = None

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """Take one frame's unstuffed data (command word onwards)."""
        garbage = garbage_before(buffer, HEADER)
        if garbage:
            return garbage, None
        index = len(HEADER)
        if len(buffer) <= index:
            return 0, None
        if buffer[index] != FLAG:
            self.last_error = Message("flag byte {byte:#04x}, expected 0xf0", byte=buffer[index])
            return 1, None
        index += 1
        data = bytearray()
        while index < len(buffer):
            byte = buffer[index]
            if byte != ESCAPE:
                data.append(byte)
                index += 1
            elif index + 1 >= len(buffer):
                return 0, None
            elif buffer[index + 1] == ESCAPE:
                data.append(ESCAPE)
                index += 2
            elif buffer[index + 1] == TAIL_SECOND:
                if index + 2 >= len(buffer):
                    return 0, None
                if buffer[index + 2] != checksum(data):
                    self.last_error = Message(
                        "checksum {got:#04x}, expected {expected:#04x}",
                        got=buffer[index + 2],
                        expected=checksum(data),
                    )
                    return index + 3, None
                self.last_error = None
                return index + 3, bytes(data)
            else:
                self.last_error = Message(
                    "0x90 followed by {byte:#04x} inside the data", byte=buffer[index + 1]
                )
                return index + 1, None
            if len(data) > self.max_length:
                self.last_error = Message("no tail within {most} bytes", most=self.max_length)
                return index, None
        return 0, None

    def encode(self, payload: bytes) -> bytes:
        """Header, flag, stuffed data, tail, checksum."""
        stuffed = payload.replace(bytes((ESCAPE,)), bytes((ESCAPE, ESCAPE)))
        return HEADER + bytes((FLAG,)) + stuffed + bytes((ESCAPE, TAIL_SECOND, checksum(payload)))
