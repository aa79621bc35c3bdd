"""Silence framer: a packet ends after a time without bytes (Visiomex, drivers/protocols/README.md
§2).

The firmware reads packets with `Serial.readString()`, which returns after 1 s of silence; there
is no terminator and no length check. Content never ends a frame: the I/O layer calls `flush`
once the line has been idle for `idle_timeout` seconds.
"""

from __future__ import annotations

from drivers.framers.base import Framer


class SilenceFramer(Framer):
    """Frames ended by `idle_timeout` seconds of silence; `max_length` bounds a frame's size."""

    def __init__(self, idle_timeout: float = 1.0, max_length: int = 4096) -> None:
        self.idle_timeout = idle_timeout
        self.max_length = max_length

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """No frame by content; only an over-long buffer is cut, so memory stays bounded."""
        if len(buffer) >= self.max_length:
            return self.max_length, buffer[: self.max_length]
        return 0, None

    def flush(self, buffer: bytes) -> tuple[int, bytes | None]:
        """After the silence: everything pending is one frame."""
        if not buffer:
            return 0, None
        return len(buffer), buffer

    def encode(self, payload: bytes) -> bytes:
        """The packet as it is: the silence after it is what ends it."""
        return payload
