"""Every frame of a session, decoded, classified and paired, kept on disk with a small index.

A console over a million lines keeps no strings per line: each line's text goes to a spool file
(`DIR\\tKIND\\tHEX\\tTEXT\\tMEANING\\n`), and numpy arrays hold its offset, time, direction and
kind, its pair (request ↔ reply) with the latency, and the first copy of a retransmission:
about 30 bytes a line in memory. Lines are read back from the spool on demand; filters by
direction, kind and regular expression run over the arrays and the spool.

Kinds: `motion`, `query`, `poll` (the position query and its reply), `setting`, `error`,
`debug` (the device's own text) and `note`. A sent frame's kind is the protocol's
`sent_kind`; a reply takes its request's kind. Replies are paired with requests by the
protocol's own reply tracker (`raw_exchange`) where it has one, else the next reply answers
the oldest request still waiting (for `REPLY_WINDOW` seconds) that `expects_reply`.
"""

from __future__ import annotations

import logging
import math
import mmap
import os
import re
import tempfile
from array import array
from collections import deque
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from drivers.decoding import DecodedFrame, StreamDecoder
from drivers.errors import BadInput
from drivers.log_reader import LogRecord
from drivers.protocols.base import Exchange, Protocol

log = logging.getLogger(__name__)

KINDS = ("motion", "query", "poll", "setting", "error", "debug", "note")
DIRECTIONS = ("tx", "rx", "")  # "" for notes
REPLY_WINDOW = 10.0  # s a request waits for its reply before it counts as unanswered
_KIND_CODE = {kind: code for code, kind in enumerate(KINDS)}
_DIR_CODE = {direction: code for code, direction in enumerate(DIRECTIONS)}
_ESCAPES = {0x0D: "\\r", 0x0A: "\\n", 0x09: "\\t", 0x5C: "\\\\"}
_ESCAPE_TABLE = {
    b: _ESCAPES.get(b, chr(b) if 0x20 <= b < 0x7F else f"\\x{b:02x}") for b in range(256)
}
_CLEAN = str.maketrans({"\t": " ", "\n": " ", "\r": " "})
_CACHE_SIZE = 4096


class FilterError(BadInput):
    """A filter that cannot be used (a regular expression that does not compile)."""


def escape(data: bytes) -> str:
    """Printable ASCII as is; CR, LF, tab and backslash as \\r \\n \\t \\\\; others as \\xNN."""
    text = data.decode("latin-1")
    core = text.rstrip("\r\n")
    if core.isascii() and core.isprintable() and "\\" not in core:  # the common case, fast
        return core + text[len(core) :].replace("\r", "\\r").replace("\n", "\\n")
    return text.translate(_ESCAPE_TABLE)


def compile_filter(pattern: str) -> re.Pattern[bytes] | None:
    """A case-insensitive pattern over the spool's lines, `^` and `$` at each line's ends
    ("" → None); FilterError if invalid."""
    if not pattern:
        return None
    try:
        return re.compile(pattern.encode("utf-8"), re.IGNORECASE | re.MULTILINE)
    except re.error as exc:
        raise FilterError(f"{pattern!r} is not a regular expression: {exc}") from None
    except UnicodeEncodeError:  # a lone surrogate: no line of the spool can hold it
        raise FilterError(f"{pattern!r} is not valid text") from None
    except (OverflowError, RecursionError) as exc:  # a{4294967296}, thousands of nested groups
        raise FilterError(f"{pattern[:40]!r}… is too large a regular expression: {exc}") from None


@dataclass(frozen=True)
class TrafficLine:
    """One line of the session: a frame or a note, with its pairing."""

    number: int
    time: float  # seconds, on the clock of the records (monotonic or log time)
    direction: str  # "tx", "rx", or "" for a note
    kind: str
    data: bytes  # as they crossed, terminator included, where known
    meaning: str
    pair: int = -1  # the reply of a request, the request of a reply (-1: none)
    latency_ms: float = math.nan  # on a reply: time since its request
    first_copy: int = -1  # on a retransmission: the line of the frame's first copy


_CHUNK = 8 << 20  # bytes of the spool lowered at a time for a literal search
_REGEX_SYNTAX = frozenset(b".^$*+?{}[]\\|()#")


def _hit_spans(
    spool: mmap.mmap, begin: int, end: int, pattern: re.Pattern[bytes]
) -> tuple[np.ndarray, np.ndarray]:
    """Where the pattern matches in spool[begin:end] (starts, ends). A plain word (no regex
    syntax) is searched case-sensitively in lowered chunks: IGNORECASE makes the engine step
    byte by byte, a literal is found at memory-scan speed, about ten times faster."""
    text = pattern.pattern
    if any(byte in _REGEX_SYNTAX for byte in text):
        spans = [hit.span() for hit in pattern.finditer(spool, begin, end)]
        found = np.asarray(spans, dtype=np.int64).reshape(-1, 2)
        return found[:, 0], found[:, 1]
    literal = re.compile(re.escape(text.lower()))
    starts: list[np.ndarray] = []
    for start in range(begin, end, _CHUNK):
        chunk = spool[start : min(end, start + _CHUNK + len(text) - 1)].lower()
        hits = literal.finditer(chunk)
        starts.append(np.fromiter((start + hit.start() for hit in hits), dtype=np.int64))
    unique = np.unique(np.concatenate(starts)) if starts else np.zeros(0, dtype=np.int64)
    return unique, unique + len(text)


class _Columns:
    """One row a line, in typed arrays (appending is cheap); numpy reads them in place."""

    def __init__(self) -> None:
        self.offset = array("q", [0])  # offset[i + 1]: where line i ends in the spool
        self.time = array("d")
        self.code = array("B")  # direction << 4 | kind
        self.size_ = array("I")  # bytes of the frame
        self.pair = array("i")
        self.latency = array("f")
        self.first_copy = array("i")

    @property
    def size(self) -> int:
        return len(self.time)

    def view(self, name: str, dtype: type) -> np.ndarray:
        """A numpy view of a column: do not keep it (the column cannot grow while it lives)."""
        return np.frombuffer(getattr(self, name), dtype=dtype)


@dataclass
class _Waiting:
    line: int
    time: float
    data: bytes
    exchange: Exchange | None


class TrafficIndex:
    """The session's lines, decoded by `protocol` (None: each record one line, undecoded)."""

    def __init__(self, protocol: Protocol | None = None, spool_dir: str | Path | None = None):
        handle, name = tempfile.mkstemp(
            prefix="motionpanel-traffic-", suffix=".spool", dir=spool_dir
        )
        self._fd = handle
        self.spool_path = Path(name)
        os.unlink(name)  # the descriptor keeps it; nothing is left behind after a crash
        self._columns = _Columns()
        self._unwritten = bytearray()
        self._written = 0
        self._cache: dict[int, TrafficLine] = {}
        self.counts = dict.fromkeys(KINDS, 0)
        self.new_latencies: list[int] = []  # replies paired since the caller last took them
        self.wall_offset: float | None = None  # wall-clock time minus record time
        self.set_protocol(protocol)

    def set_protocol(self, protocol: Protocol | None) -> None:
        """Decode what comes next with `protocol` (a new connection)."""
        self.protocol = protocol
        self._decoder = StreamDecoder(protocol) if protocol is not None else None
        self._waiting: deque[_Waiting] = deque()
        self._last_sent: dict[bytes, int] = {}  # frame → line of its first copy, unanswered
        self._last_kind = "query"
        self._sent_kinds: dict[bytes, str] = {}

    def close(self) -> None:
        """Release the spool."""
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1

    def __len__(self) -> int:
        return self._columns.size

    # -- adding ------------------------------------------------------------------------------

    def add(self, direction: str, data: bytes, time: float, wall: float | None = None) -> int:
        """Take bytes that crossed; returns how many lines they completed."""
        if wall is not None and self.wall_offset is None:
            self.wall_offset = wall - time
        if self._decoder is None:
            frames = [DecodedFrame(time, direction, bytes(data), "", "frame")]
        else:
            frames = self._decoder.feed_bytes(direction, bytes(data), time)
        for frame in frames:
            self._add_frame(frame)
        return len(frames)

    def add_note(self, text: str, time: float, wall: float | None = None) -> None:
        """Take an information line (connected, a command not sent, …)."""
        if wall is not None and self.wall_offset is None:
            self.wall_offset = wall - time
        self._append(time, "", "note", b"", text)

    def add_records(self, records: list[LogRecord]) -> None:
        """Take a log's records, in order."""
        for record in records:
            if record.note:
                self._append(record.time, "", "note", b"", record.note)
            elif self._decoder is None:
                self._append(record.time, record.direction, "query", record.data, "")
            else:
                for frame in self._decoder.feed(record):
                    self._add_frame(frame)
            if len(self._unwritten) > 1 << 20:
                self._write()
        self._write()

    def _add_frame(self, frame: DecodedFrame) -> None:
        if frame.direction == "tx":
            self._add_sent(frame)
        else:
            self._add_received(frame)

    def _add_sent(self, frame: DecodedFrame) -> None:
        protocol = self.protocol
        kind = self._sent_kinds.get(frame.data)
        if kind is None:
            kind = protocol.sent_kind(frame.data) if protocol else "query"
            if len(self._sent_kinds) >= 4096:
                self._sent_kinds.clear()
            self._sent_kinds[frame.data] = kind
        line = self._append(frame.time, "tx", kind, frame.raw, frame.meaning)
        self._last_kind = kind
        self._expire(frame.time)
        first = self._last_sent.get(frame.data)
        if first is not None:
            self._columns.first_copy[line] = first
        else:
            self._last_sent[frame.data] = line
        if protocol is None or not protocol.expects_reply(frame.data):
            return
        exchange = None
        try:
            exchange = protocol.raw_exchange(frame.raw)
        except Exception:  # a tracker for a frame that makes no sense: pair by order instead
            log.debug("no reply tracker for %r", frame.data, exc_info=True)
        self._waiting.append(_Waiting(line, frame.time, frame.data, exchange))

    def _add_received(self, frame: DecodedFrame) -> None:
        kind = {"error": "error", "text": "debug"}.get(frame.kind, "")
        request = self._match(frame) if frame.kind != "text" else None
        if request is None and frame.kind == "text":
            request = self._match(frame, text_only=True)
        if not kind:
            kind = self._kind_of(request.line) if request else self._last_kind
        line = self._append(frame.time, "rx", kind, frame.raw, frame.meaning)
        if request is not None:
            columns = self._columns
            if columns.pair[request.line] < 0:  # the first reply line answers the request
                columns.pair[request.line] = line
                self._cache.pop(request.line, None)
                columns.latency[line] = (frame.time - request.time) * 1000.0
                self.new_latencies.append(line)
            columns.pair[line] = request.line
            if kind != "error":
                self._last_sent.pop(request.data, None)  # answered: a copy now is not a retry

    def _match(self, frame: DecodedFrame, text_only: bool = False) -> _Waiting | None:
        """The request this received frame belongs to (it stays waiting until finished).

        Trackers are offered the frame newest first: on a one-in-flight device the newest
        request is the one being answered, and a tracker takes what is not its own as garbled.
        """
        for waiting in reversed(self._waiting):
            exchange = waiting.exchange
            if exchange is None:
                continue
            try:
                taken = any(exchange.on_event(event) for event in frame.events)
            except Exception:  # a tracker confused by foreign traffic: not this request's
                log.debug("reply tracker failed on %r", frame.data, exc_info=True)
                taken = False
            if taken:
                if exchange.finished and not exchange.wants_more:
                    self._waiting.remove(waiting)
                return waiting
        if not text_only:
            for waiting in self._waiting:
                if waiting.exchange is None:
                    self._waiting.remove(waiting)
                    return waiting
        return None

    def _expire(self, now: float) -> None:
        while self._waiting and now - self._waiting[0].time > REPLY_WINDOW:
            self._waiting.popleft()

    def _kind_of(self, line: int) -> str:
        return KINDS[self._columns.code[line] & 0x0F]

    def _append(self, time: float, direction: str, kind: str, data: bytes, meaning: str) -> int:
        columns = self._columns
        line = columns.size
        text = "\t".join(
            (
                direction.upper() or "--",
                kind,
                data.hex(" ").upper(),
                escape(data),
                meaning.translate(_CLEAN) if not meaning.isprintable() else meaning,
            )
        )
        encoded = (text + "\n").encode("utf-8")
        self._unwritten += encoded
        columns.offset.append(columns.offset[line] + len(encoded))
        columns.time.append(time)
        columns.code.append(_DIR_CODE[direction] << 4 | _KIND_CODE[kind])
        columns.size_.append(len(data))
        columns.pair.append(-1)
        columns.latency.append(math.nan)
        columns.first_copy.append(-1)
        self.counts[kind] += 1
        return line

    def commit(self) -> None:
        """Hand the lines added so far to the spool (reads do it themselves when needed)."""
        self._write()

    def _write(self) -> None:
        if self._fd < 0:  # closed: a late line has nowhere to go
            self._unwritten = bytearray()
            return
        if self._unwritten:
            view = memoryview(self._unwritten)
            while view:
                written = os.write(self._fd, view)
                view = view[written:]
            self._written += len(self._unwritten)
            self._unwritten = bytearray()

    # -- reading -----------------------------------------------------------------------------

    def time(self, line: int) -> float:
        """A line's time (s)."""
        return float(self._columns.time[line])

    def times(self, start: int = 0, end: int | None = None) -> np.ndarray:
        """Times of lines start..end-1 (a copy)."""
        return np.array(self._columns.time[start:end], dtype=np.float64)

    def sizes(self, start: int, end: int) -> np.ndarray:
        """Bytes of lines start..end-1 (0 for notes)."""
        return np.array(self._columns.size_[start:end], dtype=np.uint32)

    def directions(self, start: int, end: int) -> list[str]:
        """Directions of lines start..end-1 ("" for notes)."""
        return [DIRECTIONS[code >> 4] for code in self._columns.code[start:end]]

    def take_latencies(self) -> list[tuple[int, float, float]]:
        """(reply line, its time, latency in ms) paired since the last call."""
        columns, taken = self._columns, self.new_latencies
        self.new_latencies = []
        return [(n, float(columns.time[n]), float(columns.latency[n])) for n in taken]

    def line(self, number: int) -> TrafficLine:
        """One line, read back from the spool."""
        cached = self._cache.get(number)
        if cached is not None:
            return cached
        columns = self._columns
        if not 0 <= number < columns.size:
            raise IndexError(f"line {number} of {columns.size}")
        start, end = int(columns.offset[number]), int(columns.offset[number + 1])
        if end > self._written:
            self._write()
        raw = os.pread(self._fd, end - start, start).decode("utf-8")
        _, kind, hexes, _, meaning = raw.rstrip("\n").split("\t", 4)
        code = int(columns.code[number])
        result = TrafficLine(
            number,
            float(columns.time[number]),
            DIRECTIONS[code >> 4],
            kind,
            bytes.fromhex(hexes),
            meaning,
            int(columns.pair[number]),
            float(columns.latency[number]),
            int(columns.first_copy[number]),
        )
        if len(self._cache) >= _CACHE_SIZE:
            self._cache.clear()
        self._cache[number] = result
        return result

    def select(
        self,
        directions: set[str] | None = None,
        kinds: set[str] | None = None,
        pattern: re.Pattern[bytes] | None = None,
        start: int = 0,
    ) -> np.ndarray:
        """Line numbers from `start` on that pass the filters (None: any), in order."""
        codes = self._columns.view("code", np.uint8)[start:]
        mask = np.ones(len(codes), dtype=bool)
        if directions is not None:
            wanted = [_DIR_CODE[d] for d in directions]
            mask &= np.isin(codes >> 4, wanted)
        if kinds is not None:
            mask &= np.isin(codes & 0x0F, [_KIND_CODE[k] for k in kinds])
        lines = np.flatnonzero(mask).astype(np.int64) + start
        if pattern is not None and len(lines):
            lines = self._matching(lines, pattern)
        return lines

    def _matching(self, lines: np.ndarray, pattern: re.Pattern[bytes]) -> np.ndarray:
        """Those of `lines` whose spool text the pattern finds (one native scan of the span)."""
        self._write()
        if self._written == 0:
            return lines[:0]
        if pattern.search(b"") is not None:  # it matches the empty string: every line
            return lines
        offsets = self._columns.view("offset", np.int64)
        first, last = int(lines[0]), int(lines[-1])
        begin, end = int(offsets[first]), int(offsets[last + 1])
        with mmap.mmap(self._fd, self._written, access=mmap.ACCESS_READ) as spool:
            if len(lines) * 64 < last - first:  # few candidates far apart: look at each
                keep = [
                    line
                    for line in lines.tolist()
                    if pattern.search(spool, int(offsets[line]), int(offsets[line + 1]) - 1)
                ]
                return np.asarray(keep, dtype=np.int64)
            starts, ends = _hit_spans(spool, begin, end, pattern)
            first_line = np.searchsorted(offsets, starts, side="right") - 1
            last_line = np.searchsorted(offsets, np.maximum(ends - 1, starts), side="right") - 1
            inside = first_line == last_line  # a match across a line end belongs to neither:
            doubtful = np.unique(np.concatenate((first_line[~inside], last_line[~inside])))
            checked = [  # those lines are looked at alone (a match inside may have been eaten)
                line
                for line in doubtful.tolist()
                if pattern.search(spool, int(offsets[line]), int(offsets[line + 1]) - 1)
            ]
        hits = np.unique(np.concatenate((first_line[inside], np.asarray(checked, np.int64))))
        return hits[np.isin(hits, lines, assume_unique=True)]
