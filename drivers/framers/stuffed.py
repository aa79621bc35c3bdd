"""Stuffed framer for the laser-robot link (PROTOCOLS.md §3).

Frame: header `EB 90 82`, flag `F0`, data with every `90` doubled, tail `90 82`, then a checksum
byte: the sum of the unstuffed data bytes mod 256. The checksum comes after the tail, so it is not
stuffed: the receiver knows the byte after `90 82` is the checksum whatever its value.
"""

from __future__ import annotations

from drivers.framers.base import Framer, garbage_before

HEADER = b"\xeb\x90\x82"
FLAG = 0xF0
ESCAPE = 0x90
TAIL_SECOND = 0x82


def checksum(data: bytes) -> int:
    """Sum of the bytes mod 256."""
    return sum(data) & 0xFF


class StuffedFramer(Framer):
    """Byte-stuffed frames with a checksum; corrupt frames are dropped and `last_error` says why."""

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
            self.last_error = f"flag byte {buffer[index]:#04x}, expected 0xf0"
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
                    self.last_error = (
                        f"checksum {buffer[index + 2]:#04x}, expected {checksum(data):#04x}"
                    )
                    return index + 3, None
                self.last_error = None
                return index + 3, bytes(data)
            else:
                self.last_error = f"0x90 followed by {buffer[index + 1]:#04x} inside the data"
                return index + 1, None
            if len(data) > self.max_length:
                self.last_error = f"no tail within {self.max_length} bytes"
                return index, None
        return 0, None

    def encode(self, payload: bytes) -> bytes:
        """Header, flag, stuffed data, tail, checksum."""
        stuffed = payload.replace(bytes((ESCAPE,)), bytes((ESCAPE, ESCAPE)))
        return HEADER + bytes((FLAG,)) + stuffed + bytes((ESCAPE, TAIL_SECOND, checksum(payload)))
