"""Line framer: frames end at CR or LF (COXIRIS replies, Visiomex feedback lines)."""

from __future__ import annotations

from drivers.framers.base import Framer


class LineFramer(Framer):
    """Lines ended by `\\r\\n`, `\\n` or `\\r`; the terminator is not part of the frame.

    Empty lines are skipped. `max_length` bounds a line without a terminator: past it the bytes
    are returned as a frame of their own so a device that never ends its line cannot grow memory.
    A lone `\\r` at the end of the buffer waits, since a `\\n` may follow it.
    """

    def __init__(self, terminator: bytes = b"\n", max_length: int = 4096) -> None:
        self.terminator = terminator
        self.max_length = max_length

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """Take one line from the front of `buffer`."""
        skipped = 0
        while skipped < len(buffer) and buffer[skipped] in b"\r\n":
            skipped += 1
        if skipped:
            if skipped == len(buffer) and buffer.endswith(b"\r"):
                # Keep a trailing CR: it may be the first half of CRLF, then is skipped next time.
                return (skipped - 1, None) if skipped > 1 else (0, None)
            return skipped, None
        for index, byte in enumerate(buffer):
            if byte in b"\r\n":
                return index, buffer[:index]
            if index + 1 >= self.max_length:
                return index + 1, buffer[: index + 1]
        return 0, None

    def encode(self, payload: bytes) -> bytes:
        """Append the terminator."""
        return payload + self.terminator
