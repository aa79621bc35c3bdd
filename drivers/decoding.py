"""Traffic decoded by the protocols' own decoders: each frame with its meaning beside its bytes.

The same decoders serve the driver, the log reader and `motionctl log decode`: replies through
the protocol's framer and `decode`, what was sent through its TX framer and `describe_sent`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from drivers.errors import FrameError
from drivers.events import ErrorReport, Event, TextLine, Undecodable
from drivers.framers.base import Framer
from drivers.log_reader import LogRecord
from drivers.protocols.base import Protocol

CACHE_SIZE = 4096  # distinct frames remembered per direction, with their meaning


@dataclass(slots=True)
class DecodedFrame:
    """One frame (or note) of the traffic and what it means; `kind`: frame, error, text, note."""

    time: float
    direction: str
    data: bytes
    meaning: str
    kind: str
    wire: bytes = b""  # the exact bytes that crossed, terminator and all, where known
    events: tuple[Event, ...] = field(default=(), compare=False, repr=False)  # received only

    def as_dict(self) -> dict[str, object]:
        """The frame as JSON-ready fields: time, direction, hex, meaning, kind."""
        return {
            "time": round(self.time, 6),
            "direction": self.direction,
            "hex": self.data.hex(" ").upper(),
            "meaning": self.meaning,
            "kind": self.kind,
        }

    @property
    def raw(self) -> bytes:
        """The bytes as they crossed (`wire`), else the frame as the framer gave it."""
        return self.wire or self.data

    def line(self) -> str:
        """E.g. `000001.039 TX  EB 90 82 F0 10 90 82 10  GET_POSITION`."""
        if self.kind == "note":
            return f"{self.time:010.3f} #   {self.meaning}"
        shown = self.data.hex(" ").upper()
        return f"{self.time:010.3f} {self.direction.upper()}  {shown}  {self.meaning}"


def _received(protocol: Protocol, frame: bytes) -> tuple[str, str, tuple[Event, ...]]:
    try:
        events = protocol.decode(frame)
    except FrameError as exc:
        return f"unreadable: {exc}", "error", ()
    kind = "frame"
    if any(isinstance(e, (ErrorReport, Undecodable)) for e in events):
        kind = "error"
    elif events and all(isinstance(e, TextLine) for e in events):
        kind = "text"
    return "; ".join(str(e) for e in events), kind, tuple(events)


def _wire_spans(consumed: bytes, frames: list[bytes]) -> list[bytes]:
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


class StreamDecoder:
    """Decodes traffic as it comes, record by record, keeping each direction's partial frame."""

    def __init__(self, protocol: Protocol) -> None:
        self.protocol = protocol
        self._framers: dict[str, Framer | None] = {
            "rx": protocol.new_framer(),
            "tx": protocol.new_tx_framer(),
        }
        self._pending = {"rx": b"", "tx": b""}
        self._cache: dict[str, dict[bytes, tuple[str, str, tuple[Event, ...]]]] = {
            "rx": {},
            "tx": {},
        }

    def feed(self, record: LogRecord) -> list[DecodedFrame]:
        """The frames a record completes (a note is one DecodedFrame of kind `note`)."""
        if record.note:
            return [DecodedFrame(record.time, "", b"", record.note, "note")]
        return self.feed_bytes(record.direction, record.data, record.time)

    def feed_bytes(self, direction: str, data: bytes, time: float) -> list[DecodedFrame]:
        """The frames that bytes crossing in `direction` at `time` complete."""
        framer = self._framers[direction]
        if framer is None:  # the record is the frame (packets ended by silence)
            frames, self._pending[direction] = [data], b""
            spans = [data]
        else:
            buffer = self._pending[direction] + data
            frames, rest = framer.split(buffer)
            self._pending[direction] = rest
            spans = _wire_spans(buffer[: len(buffer) - len(rest)], frames)
        out = []
        cache = self._cache[direction]
        for frame, wire in zip(frames, spans, strict=True):
            known = cache.get(frame)
            if known is None:  # traffic repeats itself (polls, acks): each frame decoded once
                if direction == "rx":
                    known = _received(self.protocol, frame)
                else:
                    known = (self.protocol.describe_sent(frame), "frame", ())
                if len(cache) >= CACHE_SIZE:
                    cache.clear()
                cache[frame] = known
            meaning, kind, events = known
            out.append(DecodedFrame(time, direction, frame, meaning, kind, wire, events))
        return out

    def pending(self, direction: str) -> bytes:
        """Bytes of `direction` not yet a whole frame."""
        return self._pending[direction]


def decode_records(protocol: Protocol, records: list[LogRecord]) -> list[DecodedFrame]:
    """Every frame of the records, in order, with its meaning."""
    decoder = StreamDecoder(protocol)
    return [frame for record in records for frame in decoder.feed(record)]
