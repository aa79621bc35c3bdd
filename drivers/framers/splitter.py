"""The one place a byte stream is cut into frames: the client's reads, the traffic decoder's
records and the sniffer's guesses all go through a FrameSplitter over the protocol's framer."""

from __future__ import annotations

from drivers.framers.base import Framer
from drivers.framers.lines import LineFramer

__all__ = ["FrameSplitter", "wire_spans"]


class FrameSplitter:
    """One direction of a stream: the protocol's framer, the partial frame it waits to end, and
    when bytes last came (a frame the framer ends by the line's silence)."""

    def __init__(self, framer: Framer | None, now: float = 0.0) -> None:
        """`framer` None: every chunk of bytes is one frame (packets ended by their writes)."""
        self.framer = framer
        self.pending = b""
        """Bytes not yet a whole frame."""
        self.last_data = now
        """When bytes last came (the clock the caller passes)."""

    def feed(self, data: bytes, now: float = 0.0) -> list[bytes]:
        """The frames that `data`, after what was pending, completes."""
        if data:
            self.last_data = now
        if self.framer is None:
            return [data] if data else []
        if not data:
            return []
        buffer = self.pending + data if self.pending else data
        frames, self.pending = self.framer.split(buffer)
        return frames

    def feed_wired(self, data: bytes) -> tuple[list[bytes], list[bytes]]:
        """As `feed`, with each frame's bytes as they crossed (its line end, noise before it)."""
        framer = self.framer
        if framer is None:
            return [data], [data]
        buffer = self.pending + data if self.pending else data
        split = framer.split_wired(buffer) if isinstance(framer, LineFramer) else None
        if split is None:
            found, rest = framer.split(buffer)
            split = found, wire_spans(buffer[: len(buffer) - len(rest)], found), rest
        found, wires, self.pending = split
        return found, wires

    def idle(self, now: float) -> list[bytes]:
        """The pending frame, where the framer ends one after its idle timeout of silence and
        that much time has passed since bytes last came (else nothing)."""
        framer = self.framer
        timeout = framer.idle_timeout if framer is not None else None
        if framer is None or not self.pending or timeout is None or now - self.last_data < timeout:
            return []
        used, frame = framer.flush(self.pending)
        self.pending = self.pending[used:]
        return [frame] if frame is not None else []

    def end(self) -> list[bytes]:
        """A line the device was still printing when the stream ended, as a whole line (a line
        framer's); other formats' partial frames stay partial."""
        framer = self.framer
        if not self.pending or not isinstance(framer, LineFramer):
            return []
        frames = framer.split(self.pending + framer.terminator)[0]
        self.pending = b""
        return frames

    def whole(self, data: bytes) -> tuple[list[bytes], bytes]:
        """Every frame in `data` on its own (nothing pending before or kept after), and the rest
        that is no whole frame."""
        if self.framer is None:
            return [data], b""
        return self.framer.split(data)


def wire_spans(consumed: bytes, frames: list[bytes]) -> list[bytes]:
    """Each frame's bytes as they crossed (terminators, skipped noise before it); where a frame
    is not found verbatim in them (escaped or stuffed), its decoded bytes stand for it."""
    spans: list[bytes] = []
    position = 0
    starts = []
    for frame in frames:
        start = consumed.find(frame, position) if frame else -1
        if start < 0:
            return [b""] * len(frames)
        starts.append(start)
        position = start + len(frame)
    for index in range(len(frames)):
        end = starts[index + 1] if index + 1 < len(frames) else len(consumed)
        begin = starts[index]
        if index == 0 and consumed[:begin].strip(b"\r\n"):
            begin = 0  # noise before the frame crossed with it; a bare line end is the last one's
        spans.append(consumed[begin:end])
    return spans
