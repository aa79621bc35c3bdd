"""Every frame of a session, decoded, classified and paired, kept on disk with a small index.

A console over a million lines keeps no strings per line: each line's text goes to a spool file
(`DIR\\tKIND\\tHEX\\tTEXT\\tMEANING\\n`), and typed arrays (read by numpy in place) hold its
offset, time, direction and kind, its pair (request ↔ reply) with the latency, and the first
copy of a retransmission: 33 bytes a line in memory. Lines are read back from the spool on
demand; filters by direction, kind and regular expression run over the arrays and the spool.

Taking lines in is made cheap for a flood (`add_many`): traffic repeats itself, so a frame's
decoding and its spool line are made once and kept on the decoder's shared Frame; lines join
the arrays and the spool a batch at a time; and what a request's reply tracker does with each
reply frame is learnt once and replayed for the next copy of the request (see _Waiting).

A console with a line limit drops its oldest lines (`drop_oldest`): lines keep their numbers
(`first` is the oldest kept, `len()` the number the next line gets), the arrays lose their
first rows (a memory move) and, on Linux, the spool's dropped bytes are given back to the file
system (a hole punched; offsets in the spool stay as they were).

Kinds: `motion`, `query`, `poll` (the position query and its reply), `setting`, `error`,
`debug` (the device's own text) and `note`. A sent frame's kind is the protocol's
`sent_kind`; a reply takes its request's kind. Replies are paired with requests by the
protocol's own reply tracker (`raw_exchange`) where it has one, else the next reply answers
the oldest request still waiting (for `REPLY_WINDOW` seconds) that `expects_reply`.
"""

from __future__ import annotations

import ctypes
import functools
import logging
import math
import mmap
import os
import re
import sys
import tempfile
import time as time_module
from array import array
from collections import deque
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from itertools import accumulate
from pathlib import Path

import numpy as np

from drivers.decoding import Frame, StreamDecoder
from drivers.errors import BadInput
from drivers.log_reader import LogRecord
from drivers.messages import Message
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
_TAILS = {"\r\n": "\\r\\n", "\n": "\\n", "\r": "\\r"}
_CLEAN = str.maketrans({"\t": " ", "\n": " ", "\r": " "})
_CACHE_SIZE = 4096
_TX, _RX = _DIR_CODE["tx"] << 4, _DIR_CODE["rx"] << 4
_ERROR = _KIND_CODE["error"]
_RECEIVED_KIND = {"error": _ERROR, "text": _KIND_CODE["debug"]}  # else the request's kind


class FilterError(BadInput):
    """A filter that cannot be used (a regular expression that does not compile)."""


def escape(data: bytes) -> str:
    """Printable ASCII as is; CR, LF, tab and backslash as \\r \\n \\t \\\\; others as \\xNN."""
    text = data.decode("latin-1")
    if text.isascii():  # the common cases, fast: printable text, then a line end
        if text.isprintable():
            return text.replace("\\", "\\\\") if "\\" in text else text
        core = text.rstrip("\r\n")
        if core.isprintable() and "\\" not in core:
            tail = text[len(core) :]
            return core + (_TAILS.get(tail) or tail.replace("\r", "\\r").replace("\n", "\\n"))
    return text.translate(_ESCAPE_TABLE)


def compile_filter(pattern: str) -> re.Pattern[bytes] | None:
    """A case-insensitive pattern over the spool's lines, `^` and `$` at each line's ends
    ("" → None); FilterError if invalid."""
    if not pattern:
        return None
    try:
        return re.compile(pattern.encode("utf-8"), re.IGNORECASE | re.MULTILINE)
    except re.error as exc:
        raise FilterError(
            Message(
                "{pattern!r} is not a regular expression: {error}", pattern=pattern, error=str(exc)
            )
        ) from None
    except UnicodeEncodeError:  # a lone surrogate: no line of the spool can hold it
        raise FilterError(Message("{pattern!r} is not valid text", pattern=pattern)) from None
    except (OverflowError, RecursionError) as exc:  # a{4294967296}, thousands of nested groups
        raise FilterError(
            Message(
                "{pattern!r}… is too large a regular expression: {error}",
                pattern=pattern[:40],
                error=str(exc),
            )
        ) from None


@functools.lru_cache(maxsize=64)
def _wanted_codes(directions: frozenset[str], kinds: frozenset[str]) -> np.ndarray:
    """Which line codes (direction << 4 | kind) pass a direction and kind filter."""
    wanted = np.zeros(256, dtype=bool)
    for direction in directions:
        for kind in kinds:
            wanted[_DIR_CODE[direction] << 4 | _KIND_CODE[kind]] = True
    return wanted


def _record_direction(record: LogRecord) -> str:
    return "" if record.note else record.direction


def _record_data(record: LogRecord) -> bytes:
    return record.note.encode("utf-8") if record.note else record.data


def _spool_line(direction: str, kind: str, data: bytes, meaning: str) -> bytes:
    """A line of the spool: `DIR\tKIND\tHEX\tTEXT\tMEANING\n`, UTF-8."""
    if not meaning.isprintable():
        meaning = meaning.translate(_CLEAN)
    text = (
        f"{direction.upper() or '--'}\t{kind}\t{data.hex(' ').upper()}\t{escape(data)}\t{meaning}\n"
    )
    return text.encode("utf-8")


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
    """One row a line, in typed arrays; numpy reads them in place.

    New lines wait in `new` (a tuple each) and join the arrays a batch at a time. The pairing
    columns, written while a batch is under way, are allocated ahead (their defaults filled in)
    and are longer than `size`. Row 0 is the oldest line kept (the index's `first`): the index
    subtracts it from a line's number; `offset` holds absolute positions in the spool.
    """

    def __init__(self) -> None:
        self.offset = array("q", [0])  # offset[i + 1]: where line i ends in the spool
        self.time = array("d")
        self.code = array("B")  # direction << 4 | kind
        self.size_ = array("I")  # bytes of the frame
        self.pair = array("i")
        self.latency = array("f")
        self.first_copy = array("i")
        self.new: list[tuple[float, tuple[int, int, bytes]]] = []  # time, (code, size, line)

    @property
    def size(self) -> int:
        return len(self.time)

    def reserve(self, lines: int) -> int:
        """Room in the pairing columns for lines 0..lines-1 at least; returns how many."""
        have = len(self.pair)
        if lines > have:
            more = max(lines - have, 4096, have // 8)
            self.pair.extend(_MINUS_ONE * more)
            self.first_copy.extend(_MINUS_ONE * more)
            self.latency.extend(_NAN * more)
        return len(self.pair)

    def take_new(self) -> list[bytes]:
        """Put the waiting lines in the arrays; returns their spool lines."""
        if not self.new:
            return []
        times, memos = zip(*self.new, strict=True)
        self.new.clear()
        codes, sizes, lines = zip(*memos, strict=True)
        self.time.extend(times)
        self.code.extend(codes)
        self.size_.extend(sizes)
        ends = accumulate(map(len, lines), initial=self.offset[-1])
        next(ends)  # where the first starts
        self.offset.extend(ends)
        return list(lines)

    def drop(self, count: int) -> None:
        """Forget the first `count` rows (count <= size, nothing waiting in `new`)."""
        for column in (self.time, self.code, self.size_, self.pair, self.latency):
            del column[:count]
        del self.first_copy[:count]
        del self.offset[:count]  # offset[0]: where the first row kept starts

    def view(self, name: str, dtype: type) -> np.ndarray:
        """A numpy view of a column: do not keep it (the column cannot grow while it lives)."""
        column = getattr(self, name)
        return np.frombuffer(column, dtype=dtype)[: self.size + (column is self.offset)]


_MINUS_ONE = array("i", [-1])
_NAN = array("f", [math.nan])
_HOLE_BLOCK = 1 << 20  # bytes: the spool's dropped bytes are given back a megabyte at a time


@functools.cache
def _fallocate() -> Callable[[int, int, int, int], int] | None:
    """libc's fallocate (Linux), to punch holes in the spool; None where there is none."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        function = ctypes.CDLL(None, use_errno=True).fallocate
    except (OSError, AttributeError):
        return None
    function.argtypes = (ctypes.c_int, ctypes.c_int, ctypes.c_int64, ctypes.c_int64)
    function.restype = ctypes.c_int
    return function


def _punch_hole(fd: int, start: int, end: int) -> bool:
    """Give bytes start..end-1 of a file back to the file system, the file's size and the
    other bytes' offsets unchanged (FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE); False where
    the platform or the file system cannot."""
    function = _fallocate()
    if function is None or end <= start:
        return False
    return function(fd, 0x02 | 0x01, start, end - start) == 0


@dataclass(slots=True)
class _Waiting:
    """A request waiting for its reply, and where its reply tracker is.

    The tracker is the protocol's (`raw_exchange`): `exchange` once built. Trackers are state
    machines fed events, so what one did with each frame, in order, is the same for every copy
    of a request: the index remembers it (a script: `_Scripts`) and replays it without building
    the tracker, until a frame comes that the script has not seen; then the tracker is built and
    fed the frames so far (`offered`), and goes on live, adding to the script.
    """

    line: int
    time: float
    data: bytes
    raw: bytes
    kind: int  # its kind's code, which its replies take
    tracked: bool  # the protocol has a tracker for it (else it is answered by order)
    exchange: Exchange | None = None
    state: int = -1  # the script's state it is in (-1: off the script)
    offered: list[Frame] | None = None  # frames replayed so far, while `exchange` is None


class _Scripts:
    """What reply trackers did with the frames offered them (see _Waiting), by request frame."""

    MAX_STEPS = 20_000  # then forgotten, and learnt again
    MAX_DEPTH = 64  # frames a script follows a request for; the tracker then goes on live

    def __init__(self) -> None:
        self.starts: dict[bytes, int | None] = {}  # request (raw) → first state (None: none)
        self.steps: dict[tuple[int, bytes], tuple[bool, bool, int]] = {}  # → taken, done, next
        self.depth: dict[int, int] = {}  # state → frames since its start
        self.states = 0

    def start(self, data: bytes, tracked: bool) -> int | None:
        """A request's first state (None: it has no tracker)."""
        if len(self.steps) + len(self.starts) >= self.MAX_STEPS:
            self.starts.clear()
            self.steps.clear()
            self.depth.clear()
        state = self.starts[data] = self.states if tracked else None
        if tracked:
            self.depth[self.states] = 0
            self.states += 1
        return state

    def learn(self, state: int, frame: bytes, taken: bool, done: bool) -> int:
        """The tracker in `state` did this with `frame`; returns the next state (-1: no more)."""
        known = self.steps.get((state, frame))
        if known is not None:  # (another copy of the request learnt it first)
            return known[2]
        depth = self.depth.get(state, self.MAX_DEPTH)
        if depth >= self.MAX_DEPTH or len(self.steps) + len(self.starts) >= self.MAX_STEPS:
            return -1
        following = self.states
        self.states += 1
        self.depth[following] = depth + 1
        self.steps[state, frame] = (taken, done, following)
        return following


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
        self._size = 0  # lines, those waiting in the columns' `new` included
        self._base = 0  # the oldest line kept (row 0 of the columns); lines before it dropped
        self._reserved = 0  # lines the pairing columns have room for (up to this line number)
        self._punched = 0  # spool bytes before this were given back (see drop_oldest)
        self._new = self._columns.new.append
        self._unwritten: list[bytes] = []  # spool lines not yet written (one write a batch)
        self._written = 0
        self._cache: dict[int, TrafficLine] = {}
        self._counts = dict.fromkeys(KINDS, 0)
        self._counted = 0  # lines before this one have had their kinds added up in `counts`
        self.new_latencies = array("i")  # replies paired since the caller last took them
        self.wall_offset: float | None = None  # wall-clock time minus record time
        self.meaning_text: Callable[[str], str] = str
        """What a decoded frame's meaning reads as in the index (the window: its language)."""
        self.set_protocol(protocol)

    def set_protocol(self, protocol: Protocol | None) -> None:
        """Decode what comes next with `protocol` (a new connection)."""
        self.protocol = protocol
        self._decoder = StreamDecoder(protocol) if protocol is not None else None
        self._waiting: deque[_Waiting] = deque()
        self._last_sent: dict[bytes, int] = {}  # frame → line of its first copy, unanswered
        self._last_kind = _KIND_CODE["query"]  # of the last frame sent, for a reply unpaired
        self._sent: dict[bytes, tuple[int, bool]] = {}  # frame → kind code, expects a reply
        self._scripts = _Scripts()

    def close(self) -> None:
        """Release the spool."""
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1

    def __len__(self) -> int:
        """The number the next line gets: every line ever added, dropped ones included
        (`kept` is how many are here)."""
        return self._size

    @property
    def first(self) -> int:
        """The oldest line kept (0 until lines are dropped: see drop_oldest)."""
        return self._base

    @property
    def kept(self) -> int:
        """Lines kept: first..len()-1."""
        return self._size - self._base

    @property
    def counts(self) -> dict[str, int]:
        """Lines kept of each kind (the kind codes of the lines new since last time added up)."""
        columns = self._columns
        end = self._base + columns.size
        if self._counted < end:
            codes = columns.view("code", np.uint8)[self._counted - self._base :]
            self._count_kinds(codes, 1)
            self._counted = end
        return self._counts

    def _count_kinds(self, codes: np.ndarray, sign: int) -> None:
        added = np.bincount(codes & 0x0F, minlength=len(KINDS)).tolist()
        for kind, count in zip(KINDS, added, strict=False):
            self._counts[kind] += sign * count

    def drop_oldest(self, count: int) -> int:
        """Forget the oldest `count` lines (at most every line); returns how many went.

        The lines after keep their numbers, and their pairs and first copies still name the
        lines dropped (`first` says which are gone). Costs a memory move of the columns (about
        33 bytes a line kept) and, on Linux, a hole punched in the spool for the bytes dropped,
        a megabyte at a time (elsewhere the spool file keeps them until the index is closed).
        """
        self._write()  # every line in the columns and the spool
        columns = self._columns
        count = min(max(0, int(count)), columns.size)
        if not count:
            return 0
        base = self._base
        counted = min(count, self._counted - base)
        if counted > 0:
            self._count_kinds(columns.view("code", np.uint8)[:counted], -1)
        end = columns.offset[count]  # where the first line kept starts in the spool
        columns.drop(count)
        self._base = base + count
        self._counted = max(self._counted, self._base)
        if self._cache:
            self._cache = {n: line for n, line in self._cache.items() if n >= self._base}
        latencies = self.new_latencies  # (in order: the replies dropped are the first ones)
        if latencies and latencies[0] < self._base:
            del latencies[: int(np.searchsorted(np.frombuffer(latencies, np.int32), self._base))]
        hole_end = end - end % _HOLE_BLOCK
        if (
            hole_end - self._punched >= _HOLE_BLOCK
            and self._fd >= 0
            and _punch_hole(self._fd, self._punched, hole_end)
        ):
            self._punched = hole_end
        return count

    # -- adding ------------------------------------------------------------------------------

    def add(self, direction: str, data: bytes, time: float, wall: float | None = None) -> int:
        """Take bytes that crossed; returns how many lines they completed."""
        before = len(self)
        self.add_many([(time, direction, bytes(data), wall)])
        return len(self) - before

    def add_note(self, text: str, time: float, wall: float | None = None) -> None:
        """Take an information line (connected, a command not sent, …)."""
        if wall is not None and self.wall_offset is None:
            self.wall_offset = wall - time
        self._append(time, "", "note", b"", text)
        self._unwritten += self._columns.take_new()

    def add_many(
        self,
        items: Sequence[tuple[float, str, bytes, float | None]],
        deadline: float | None = None,
    ) -> int:
        """Take records in order: (time, direction, data, wall clock or None), a direction of ""
        a note (data its UTF-8 text). With a `deadline` (perf_counter), stops once it has passed
        and returns how many were taken (all, else)."""
        decoder = self._decoder
        frames_of = decoder.frames if decoder is not None else None
        sent, received = self._add_sent, self._add_received
        clock = time_module.perf_counter
        no_wall = self.wall_offset is None
        taken = 0
        for when, direction, data, wall in items:
            taken += 1
            if no_wall and wall is not None:
                self.wall_offset = wall - when
                no_wall = False
            if not direction:
                self._append(when, "", "note", b"", data.decode("utf-8"))
                continue
            if frames_of is None:
                frames: Sequence[Frame] = (Frame(bytes(data), b"", "", "frame", ()),)
            else:
                frames = frames_of(direction, data)
            add = sent if direction == "tx" else received
            for frame in frames:
                add(frame, when)
            if deadline is not None and clock() > deadline:
                break
        self._unwritten += self._columns.take_new()
        if len(self._unwritten) > 4096:
            self._write()
        return taken

    def add_records(self, records: list[LogRecord]) -> None:
        """Take a log's records, in order (without a protocol, each record is a line)."""
        for start in range(0, len(records), 4096):
            chunk = records[start : start + 4096]
            if self._decoder is None:
                for r in chunk:
                    kind = "note" if r.note else "query"
                    self._append(r.time, "" if r.note else r.direction, kind, r.data, r.note)
                self._unwritten += self._columns.take_new()
            else:
                self.add_many(
                    [(r.time, _record_direction(r), _record_data(r), None) for r in chunk]
                )
            self._write()

    def _add_sent(self, frame: Frame, time: float) -> None:
        protocol = self.protocol
        data = frame.data
        known = self._sent.get(data)
        if known is None:
            kind = protocol.sent_kind(data) if protocol else "query"
            expects = protocol is not None and protocol.expects_reply(data)
            if len(self._sent) >= 4096:
                self._sent.clear()
            known = self._sent[data] = (_KIND_CODE[kind], expects)
        code, expects = known
        line = self._append_frame(frame, time, _TX | code)
        self._last_kind = code
        waiting = self._waiting
        while waiting and time - waiting[0].time > REPLY_WINDOW:
            waiting.popleft()
        first = self._last_sent.get(data)
        if first is not None:
            self._columns.first_copy[line - self._base] = first
        else:
            self._last_sent[data] = line
        if not expects:
            return
        scripts = self._scripts
        # Scripts are keyed by the frame's bytes as sent, ends included: two frames with the
        # same text can end differently, and a tracker is built from the whole frame.
        if frame.raw in scripts.starts:  # followed before: replayed (see _Waiting)
            state = scripts.starts[frame.raw]
            if state is None:
                waiting.append(_Waiting(line, time, data, frame.raw, code, False))
            else:
                waiting.append(_Waiting(line, time, data, frame.raw, code, True, None, state, []))
            return
        exchange = self._tracker(frame.raw)
        state = scripts.start(frame.raw, exchange is not None)
        tracked = exchange is not None
        waiting.append(
            _Waiting(
                line, time, data, frame.raw, code, tracked, exchange, -1 if state is None else state
            )
        )

    def _tracker(self, raw: bytes) -> Exchange | None:
        """The protocol's reply tracker for a request (None: it pairs by order)."""
        if self.protocol is None:  # (no request waits without one: see _add_sent)
            return None
        try:
            return self.protocol.raw_exchange(raw)
        except Exception:  # a tracker for a frame that makes no sense: pair by order instead
            log.debug("no reply tracker for %r", raw, exc_info=True)
            return None

    def _add_received(self, frame: Frame, time: float) -> None:
        request = self._match(frame, frame.kind == "text") if self._waiting else None
        kind = _RECEIVED_KIND.get(frame.kind)
        if kind is None:
            kind = request.kind if request is not None else self._last_kind
        line = self._append_frame(frame, time, _RX | kind)
        if request is not None:
            asked, base = request.line, self._base
            pair = self._columns.pair  # (rows: line numbers less `first`)
            pair[line - base] = asked
            # (a request dropped meanwhile: its reply names it, with no latency)
            if asked >= base and pair[asked - base] < 0:  # the first reply line answers it
                pair[asked - base] = line
                self._cache.pop(asked, None)
                self._columns.latency[line - base] = (time - request.time) * 1000.0
                self.new_latencies.append(line)
            if kind != _ERROR:
                self._last_sent.pop(request.data, None)  # answered: a copy now is not a retry

    def _match(self, frame: Frame, text_only: bool = False) -> _Waiting | None:
        """The request this received frame belongs to (it stays waiting until finished).

        Trackers are offered the frame newest first: on a one-in-flight device the newest
        request is the one being answered, and a tracker takes what is not its own as garbled.
        """
        steps = self._scripts.steps
        for waiting in reversed(self._waiting):
            if not waiting.tracked:
                continue
            if waiting.exchange is None:  # replaying its script
                step = steps.get((waiting.state, frame.raw))
                if step is not None:
                    taken, done, waiting.state = step
                    assert waiting.offered is not None  # kept while replaying
                    waiting.offered.append(frame)
                    if taken:
                        if done:
                            self._waiting.remove(waiting)
                        return waiting
                    continue
                self._go_live(waiting)
                if waiting.exchange is None:
                    continue
            taken, done = self._offer(waiting, waiting.exchange, frame)
            if taken:
                if done:
                    self._waiting.remove(waiting)
                return waiting
        if not text_only:
            for waiting in self._waiting:
                if not waiting.tracked:
                    self._waiting.remove(waiting)
                    return waiting
        return None

    def _go_live(self, waiting: _Waiting) -> None:
        """Build a replayed request's tracker and feed it the frames replayed so far."""
        offered, waiting.offered = waiting.offered or [], None
        exchange = waiting.exchange = self._tracker(waiting.raw)
        if exchange is None:  # (the protocol changed its mind: pair it by order)
            waiting.tracked = False
            return
        state, waiting.state = waiting.state, -1
        for frame in offered:
            self._offer(waiting, exchange, frame)
        waiting.state = state

    def _offer(self, waiting: _Waiting, exchange: Exchange, frame: Frame) -> tuple[bool, bool]:
        """Feed a frame's events to a request's live tracker (`exchange`, the waiting one's):
        (taken, the reply is complete), learnt by the script where it follows."""
        events = frame.events
        try:
            if len(events) == 1:
                taken = exchange.on_event(events[0])
            else:
                taken = any(exchange.on_event(event) for event in events)
        except Exception:  # a tracker confused by foreign traffic: not this request's
            log.debug("reply tracker failed on %r", frame.data, exc_info=True)
            taken = False
        done = taken and exchange.finished and not exchange.wants_more
        if waiting.state >= 0:
            waiting.state = self._scripts.learn(waiting.state, frame.raw, taken, done)
        return taken, done

    def _append_frame(self, frame: Frame, time: float, code: int) -> int:
        """A frame's line (its spool line kept on the frame for the next time it crosses)."""
        memo = frame.memo
        if memo is None or memo[0] != code:
            raw = frame.raw
            direction, kind = DIRECTIONS[code >> 4], KINDS[code & 0x0F]
            meaning = self.meaning_text(frame.meaning)
            memo = frame.memo = (code, len(raw), _spool_line(direction, kind, raw, meaning))
        line = self._size
        self._size = line + 1
        self._new((time, memo))
        if line >= self._reserved:
            self._reserved = self._base + self._columns.reserve(line + 1 - self._base)
        return line

    def _append(self, time: float, direction: str, kind: str, data: bytes, meaning: str) -> int:
        code = _DIR_CODE[direction] << 4 | _KIND_CODE[kind]
        line = self._size
        self._size = line + 1
        self._new((time, (code, len(data), _spool_line(direction, kind, data, meaning))))
        if line >= self._reserved:
            self._reserved = self._base + self._columns.reserve(line + 1 - self._base)
        return line

    def commit(self) -> None:
        """Hand the lines added so far to the spool (reads do it themselves when needed)."""
        self._write()

    def _write(self) -> None:
        self._unwritten += self._columns.take_new()
        if self._fd < 0:  # closed: a late line has nowhere to go
            self._unwritten = []
            return
        if self._unwritten:
            view = memoryview(b"".join(self._unwritten))
            self._unwritten = []
            self._written += len(view)
            while view:
                written = os.write(self._fd, view)
                view = view[written:]

    # -- reading -----------------------------------------------------------------------------

    def _rows(self, start: int, end: int | None) -> slice:
        """The columns' rows of lines start..end-1 (lines dropped left out: from `first` on)."""
        base = self._base
        return slice(max(start - base, 0), None if end is None else max(end - base, 0))

    def time(self, line: int) -> float:
        """A line's time (s)."""
        if line < self._base:
            raise IndexError(f"line {line} was dropped (the oldest kept is {self._base})")
        return float(self._columns.time[line - self._base])

    def times(self, start: int = 0, end: int | None = None) -> np.ndarray:
        """Times of lines start..end-1 (a copy; lines dropped left out: see `first`)."""
        return np.array(self._columns.time[self._rows(start, end)], dtype=np.float64)

    def sizes(self, start: int, end: int) -> np.ndarray:
        """Bytes of lines start..end-1 (0 for notes; lines dropped left out)."""
        return np.array(self._columns.size_[self._rows(start, end)], dtype=np.uint32)

    def directions(self, start: int, end: int) -> list[str]:
        """Directions of lines start..end-1 ("" for notes; lines dropped left out)."""
        return [DIRECTIONS[code >> 4] for code in self._columns.code[self._rows(start, end)]]

    def direction_codes(self, start: int, end: int) -> np.ndarray:
        """Directions of lines start..end-1 as indexes into DIRECTIONS (a copy; lines dropped
        left out)."""
        return self._columns.view("code", np.uint8)[self._rows(start, end)] >> 4

    def take_latencies(self) -> list[tuple[int, float, float]]:
        """(reply line, its time, latency in ms) paired since the last call (and not dropped)."""
        columns, taken, base = self._columns, self.new_latencies, self._base
        self.new_latencies = array("i")
        return [
            (n, float(columns.time[n - base]), float(columns.latency[n - base]))
            for n in taken
            if n >= base
        ]

    def line(self, number: int) -> TrafficLine:
        """One line, read back from the spool (the latest few thousand are kept)."""
        cached = self._cache.get(number)
        if cached is not None:
            return cached
        result = TrafficLine(*self.read(number))
        if len(self._cache) >= _CACHE_SIZE:
            self._cache.clear()
        self._cache[number] = result
        return result

    def read(self, number: int) -> tuple[int, float, str, str, bytes, str, int, float, int]:
        """A line's fields as TrafficLine has them, in a tuple, read from the spool each time
        (what the console's table keeps: plain tuples, which the garbage collector skips)."""
        columns, base = self._columns, self._base
        if not base <= number < self._size:
            raise IndexError(f"line {number} of {base}..{self._size - 1}")
        row = number - base
        start, end = columns.offset[row], columns.offset[row + 1]
        if end > self._written:
            self._write()
        raw = os.pread(self._fd, end - start, start).decode("utf-8")
        _, kind, hexes, _, meaning = raw.rstrip("\n").split("\t", 4)
        direction, pair, latency, first_copy = self.pairing(number)
        data = bytes.fromhex(hexes)
        return (
            number,
            columns.time[row],
            direction,
            kind,
            data,
            meaning,
            pair,
            latency,
            first_copy,
        )

    def pairing(self, number: int) -> tuple[str, int, float, int]:
        """A line's direction, pair, latency (ms) and first copy (see TrafficLine)."""
        columns, row = self._columns, number - self._base
        if row < 0:
            raise IndexError(f"line {number} was dropped (the oldest kept is {self._base})")
        return (
            DIRECTIONS[columns.code[row] >> 4],
            columns.pair[row],
            columns.latency[row],
            columns.first_copy[row],
        )

    def select(
        self,
        directions: set[str] | None = None,
        kinds: set[str] | None = None,
        pattern: re.Pattern[bytes] | None = None,
        start: int = 0,
    ) -> np.ndarray:
        """Line numbers from `start` on that pass the filters (None: any), in order (lines
        dropped left out: from `first` on)."""
        start = max(start, self._base)
        codes = self._columns.view("code", np.uint8)[start - self._base :]
        if directions is None and kinds is None:
            lines = np.arange(start, start + len(codes), dtype=np.int64)
        else:
            wanted = _wanted_codes(
                frozenset(DIRECTIONS if directions is None else directions),
                frozenset(KINDS if kinds is None else kinds),
            )
            lines = wanted[codes].nonzero()[0]
            lines += start
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
        base = self._base
        offsets = self._columns.view("offset", np.int64)
        lines = lines - base  # rows of the columns; numbers again at the end
        first, last = int(lines[0]), int(lines[-1])
        begin, end = int(offsets[first]), int(offsets[last + 1])
        with mmap.mmap(self._fd, self._written, access=mmap.ACCESS_READ) as spool:
            if len(lines) * 64 < last - first:  # few candidates far apart: look at each
                keep = [
                    line
                    for line in lines.tolist()
                    if pattern.search(spool, int(offsets[line]), int(offsets[line + 1]) - 1)
                ]
                return np.asarray(keep, dtype=np.int64) + base
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
        return hits[np.isin(hits, lines, assume_unique=True)] + base
