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
        skipped = len(buffer) - len(buffer.lstrip(b"\r\n"))
        if skipped:
            if skipped == len(buffer) and buffer.endswith(b"\r"):
                # Keep a trailing CR: it may be the first half of CRLF, then is skipped next time.
                return (skipped - 1, None) if skipped > 1 else (0, None)
            return skipped, None
        cr, lf = buffer.find(b"\r", 0, self.max_length), buffer.find(b"\n", 0, self.max_length)
        end = cr if lf < 0 else lf if cr < 0 else min(cr, lf)
        if end >= 0:
            return end, buffer[:end]
        if len(buffer) >= self.max_length:
            return self.max_length, buffer[: self.max_length]
        return 0, None

    def encode(self, payload: bytes) -> bytes:
        """Append the terminator."""
        return payload + self.terminator
