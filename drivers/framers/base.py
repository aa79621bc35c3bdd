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
