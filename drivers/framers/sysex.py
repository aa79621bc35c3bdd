"""Firmata framer (drivers/protocols/README.md §5): SysEx `F0 ... F7` and the base protocol's short
messages."""

from __future__ import annotations

from drivers.errors import FrameError
from drivers.framers.base import Framer
from drivers.messages import Message

START_SYSEX = 0xF0
END_SYSEX = 0xF7
REPORT_VERSION = 0xF9


def _message_length(status: int) -> int | None:
    """Length of a fixed-size message starting with `status` (None: not a fixed-size status)."""
    if status == REPORT_VERSION:
        return 3
    if 0xC0 <= status <= 0xDF:
        return 2
    if 0x80 <= status <= 0xEF:
        return 3
    return None


class SysexFramer(Framer):
    """Whole Firmata messages: SysEx with its F0/F7, version reports, channel messages."""

    def __init__(self, max_length: int = 4096) -> None:
        self.max_length = max_length

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """Take one message; data bytes where a status byte is due are skipped as garbage."""
        skipped = 0
        while skipped < len(buffer) and buffer[skipped] < 0x80:
            skipped += 1
        if skipped:
            return skipped, None
        if not buffer:
            return 0, None
        status = buffer[0]
        if status == START_SYSEX:
            for index in range(1, len(buffer)):
                byte = buffer[index]
                if byte == END_SYSEX:
                    return index + 1, buffer[: index + 1]
                if byte >= 0x80:
                    return index, None  # interrupted by another status byte: resync there
                if index >= self.max_length:
                    return index, None
            return 0, None
        length = _message_length(status)
        if length is None:
            return 1, None  # a status byte with no meaning here (stray F7, real-time bytes)
        if len(buffer) < length:
            return 0, None
        body = buffer[1:length]
        if any(b >= 0x80 for b in body):
            return 1, None
        return length, buffer[:length]

    def encode(self, payload: bytes) -> bytes:
        """`F0 payload F7`; every payload byte must be 7-bit."""
        if not payload:
            raise FrameError(Message("a SysEx message needs at least a command byte"))
        bad = [b for b in payload if b > 0x7F]
        if bad:
            raise FrameError(Message("SysEx data must be 7-bit; got {byte:#04x}", byte=bad[0]))
        return bytes((START_SYSEX,)) + payload + bytes((END_SYSEX,))
