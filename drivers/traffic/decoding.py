"""Traffic decoded by the protocols' own decoders: each frame with its meaning beside its bytes.

The same decoders serve the driver, the log reader and `motionctl log decode`: replies through
the protocol's framer and `decode`, what was sent through its TX framer and `describe_sent`.
A log that changed device is decoded part by part: each part by the protocol its connection
note names (`PartProtocols`), the part before any note by the protocol chosen.
"""

from __future__ import annotations

import logging
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from drivers.errors import FrameError, MotionError
from drivers.framers.lines import LineFramer
from drivers.framers.splitter import FrameSplitter
from drivers.messages import Message, message_of
from drivers.protocols.base import Protocol
from drivers.protocols.events import ErrorReport, Event, TextLine, Undecodable
from drivers.protocols.registry import create_protocol, protocol_names
from drivers.traffic.log_reader import LogRecord

log = logging.getLogger(__name__)

CACHE_SIZE = 4096  # distinct frames remembered per direction, with their meaning
RECORD_FRAMES = 4  # a record of at most this many frames, each known, is remembered whole
# The session log's `connected to URL (protocol [variant], N baud)`, the bridge's `bridge A <-> B
# (protocol)`: the protocol and variant that the traffic after the note speaks.
_CONNECTION = re.compile(r"(?:connected to|bridge) .*\(([\w-]+)(?: ([\w-]+))?[,)]")


@dataclass(slots=True)
class DecodedFrame:
    """One frame (or note) of the traffic and what it means; `kind`: frame, error, text, note.

    `meaning` is for people: a Message (drivers/messages.py) where the decoder's words are to
    be translated, else the protocol's own words.
    """

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
        # The error's Message, not the error: a kept frame must not keep its traceback alive.
        return Message("unreadable: {error}", error=message_of(exc) or str(exc)), "error", ()
    if len(events) == 1:  # the common case (one line, one event), without generators
        event = events[0]
        if isinstance(event, (ErrorReport, Undecodable)):
            return str(event), "error", (event,)
        return str(event), "text" if isinstance(event, TextLine) else "frame", (event,)
    kind = "frame"
    if any(isinstance(e, (ErrorReport, Undecodable)) for e in events):
        kind = "error"
    elif events and all(isinstance(e, TextLine) for e in events):
        kind = "text"
    return "; ".join(str(e) for e in events), kind, tuple(events)


class Frame:
    """One decoded frame, shared by every time its bytes cross again (do not change it).

    `raw` is what crossed (its `wire`, else its `data`); `memo` is free for the traffic index to
    keep what it derives from the frame: (its code, the raw size, its spool line).
    """

    __slots__ = ("data", "events", "kind", "meaning", "memo", "raw", "wire")

    def __init__(
        self, data: bytes, wire: bytes, meaning: str, kind: str, events: tuple[Event, ...]
    ) -> None:
        self.data = data
        self.wire = wire
        self.raw = wire or data
        self.meaning = meaning
        self.kind = kind
        self.events = events
        self.memo: tuple[int, int, bytes] | None = None

    def __repr__(self) -> str:
        return f"Frame({self.raw!r}, {self.kind}, {self.meaning!r})"


class StreamDecoder:
    """Decodes traffic as it comes, record by record, keeping each direction's partial frame.

    Traffic repeats itself (polls, acks): each distinct frame that crosses more than once is
    decoded once (a cache per direction, CACHE_SIZE frames), and a short record that split into
    the same frames before is not split again (a line framer's records: it keeps no state).
    """

    def __init__(self, protocol: Protocol) -> None:
        self.protocol = protocol
        self._splitters = {
            "rx": FrameSplitter(protocol.new_framer()),
            "tx": FrameSplitter(protocol.new_tx_framer()),
        }
        self._cache: dict[str, dict[bytes, Frame]] = {"rx": {}, "tx": {}}
        # Frames seen once, as bytes: a frame is kept (with its events) when it crosses again,
        # so a flood of lines that never repeat leaves no objects for the garbage collector.
        self._seen: dict[str, dict[bytes, None]] = {"rx": {}, "tx": {}}
        self._records: dict[str, dict[bytes, tuple[tuple[Frame, ...], bytes]]] = {
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
        return [
            DecodedFrame(time, direction, f.data, f.meaning, f.kind, f.wire, f.events)
            for f in self.frames(direction, data)
        ]

    def frames(self, direction: str, data: bytes) -> Sequence[Frame]:
        """As `feed_bytes`, as shared Frame objects (no time): the traffic index's fast path."""
        splitter = self._splitters[direction]
        pending = splitter.pending
        records = self._records[direction]
        if not pending:
            recorded = records.get(data)
            if recorded is not None:
                frames, splitter.pending = recorded
                return frames
        found, wires = splitter.feed_wired(data)
        rest = splitter.pending
        cache, seen = self._cache[direction], self._seen[direction]
        out = []
        repeated = True  # every frame of the record crossed before
        for frame, wire in zip(found, wires, strict=True):
            known = cache.get(frame)
            if known is None or known.wire != wire:
                if known is not None:
                    meaning, kind, events = known.meaning, known.kind, known.events
                elif direction == "rx":
                    meaning, kind, events = _received(self.protocol, frame)
                else:
                    meaning, kind, events = self.protocol.describe_sent(frame), "frame", ()
                kept = known is not None or frame in seen
                known = Frame(frame, wire, meaning, kind, events)
                if kept:  # it crosses again: kept, with its meaning
                    if len(cache) >= CACHE_SIZE:
                        cache.clear()
                    cache[frame] = known
                else:  # maybe never again (a counter in debug output): remembered as bytes only
                    repeated = False
                    if len(seen) >= CACHE_SIZE:
                        seen.clear()
                    seen[frame] = None
            out.append(known)
        framer = splitter.framer
        stateless = framer is None or isinstance(framer, LineFramer)  # the same split again
        if stateless and repeated and not pending and len(out) <= RECORD_FRAMES:
            if len(records) >= CACHE_SIZE:
                records.clear()
            records[data] = (tuple(out), rest)
        return out

    def pending(self, direction: str) -> bytes:
        """Bytes of `direction` not yet a whole frame."""
        return self._splitters[direction].pending


def connection_protocol(note: str) -> tuple[str, str] | None:
    """(protocol, variant) that a connection note names, e.g. `connected to … (coxiris, …)`;
    None for another note or an unknown protocol."""
    hit = _CONNECTION.search(note)
    if hit is None or hit.group(1) not in protocol_names():
        return None
    return hit.group(1), hit.group(2) or ""


def _name_of(protocol: Protocol) -> tuple[str, str]:
    return protocol.name, protocol.variant.name if protocol.variant else ""


class PartProtocols:
    """The protocol each part of a log is decoded with: the one chosen (or None: undecoded)
    until a connection note names one, then that one until the next such note."""

    def __init__(self, chosen: Protocol | None) -> None:
        self.chosen = chosen
        self.current = chosen
        self.used: list[tuple[str, str]] = [_name_of(chosen)] if chosen is not None else []

    def follow(self, record: LogRecord) -> bool:
        """Whether `record` is a connection note that changes the protocol (then `current`)."""
        if not record.note:
            return False
        named = connection_protocol(record.note)
        if named is None:
            return False
        try:
            protocol = create_protocol(named[0], named[1] or None)  # ("": the first variant)
        except MotionError as exc:  # a variant this version does not know
            log.warning("log note %r: %s; the protocol so far goes on", record.note, exc)
            return False
        key = _name_of(protocol)
        current, chosen = self.current, self.chosen
        if current is not None and _name_of(current) == key:
            return False
        if chosen is not None and _name_of(chosen) == key:
            protocol = chosen  # the one chosen, with its settings (ticks/mm, …)
        self.current = protocol
        if key not in self.used:
            self.used.append(key)
        return True


def decode_records(protocol: Protocol, records: Iterable[LogRecord]) -> list[DecodedFrame]:
    """Every frame of the records, in order, with its meaning: by `protocol` until a connection
    note names another protocol, then by that one (a log of a session that changed device)."""
    parts = PartProtocols(protocol)
    decoder = StreamDecoder(protocol)
    frames: list[DecodedFrame] = []
    for record in records:
        if parts.follow(record) and parts.current is not None:
            decoder = StreamDecoder(parts.current)
        frames.extend(decoder.feed(record))
    return frames
