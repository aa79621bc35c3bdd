"""Fixed-length framer: header, fixed body, trailer (the 25-byte pi-frame,
drivers/protocols/README.md §4)."""

from __future__ import annotations

from drivers.errors import FrameError
from drivers.framers.base import Framer, garbage_before
from drivers.messages import Message


class FixedFramer(Framer):
    """`header + body_length bytes + trailer`; a frame whose trailer is wrong is resynced past."""

    def __init__(
        self, header: bytes = b"\x7b\x7d", body_length: int = 22, trailer: bytes = b"\x2a"
    ) -> None:
        self.header = header
        self.body_length = body_length
        self.trailer = trailer
        self.length = len(header) + body_length + len(trailer)

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """Find a header, wait for the whole frame, check the trailer."""
        garbage = garbage_before(buffer, self.header)
        if garbage:
            return garbage, None
        if len(buffer) < self.length:
            return 0, None
        if buffer[self.length - len(self.trailer) : self.length] != self.trailer:
            return 1, None  # not a frame after all: resync one byte further
        return self.length, buffer[: self.length]

    def encode(self, payload: bytes) -> bytes:
        """Header, the body, trailer; the body must be exactly `body_length` bytes."""
        if len(payload) != self.body_length:
            raise FrameError(
                Message(
                    "a frame body is {expected} bytes, not {length}",
                    expected=self.body_length,
                    length=len(payload),
                )
            )
        return self.header + payload + self.trailer
