"""The framer contract shared by every wire format."""

from __future__ import annotations

from abc import ABC, abstractmethod


class Framer(ABC):
    """Splits a byte stream into frames and builds frames from payloads.

    `decode(buffer)` returns `(bytes_used, frame)`: `frame` is None when no complete frame is in
    `buffer` yet; `bytes_used` counts bytes to drop from the front (a frame, or garbage skipped).
    Framers keep no state between calls, except where a wire format needs it (documented there).
    """

    #: Seconds of line silence that end a frame (None: frames end by their own bytes).
    idle_timeout: float | None = None

    @abstractmethod
    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """Take at most one frame from the front of `buffer`."""

    @abstractmethod
    def encode(self, payload: bytes) -> bytes:
        """Wrap `payload` into one frame as it goes on the wire."""

    def flush(self, buffer: bytes) -> tuple[int, bytes | None]:
        """After `idle_timeout` seconds of silence: end a pending frame, if the format does."""
        return 0, None

    def split(self, buffer: bytes) -> tuple[list[bytes], bytes]:
        """Decode every complete frame in `buffer`; return them and the unused rest."""
        frames: list[bytes] = []
        while buffer:
            used, frame = self.decode(buffer)
            if used == 0:
                break
            buffer = buffer[used:]
            if frame is not None:
                frames.append(frame)
        return frames, buffer


def garbage_before(buffer: bytes, header: bytes) -> int:
    """How many leading bytes cannot start a frame beginning with `header`.

    That is everything before the first header, or, with no header in `buffer`, everything but a
    tail that could be the start of one.
    """
    start = buffer.find(header)
    if start >= 0:
        return start
    for keep in range(min(len(header) - 1, len(buffer)), 0, -1):
        if header.startswith(buffer[-keep:]):
            return len(buffer) - keep
    return len(buffer)
