"""Every frame of a session, decoded, classified and paired, kept on disk with a small index.

A console over a million lines keeps no strings per line: each line's text goes to a spool file
(`DIR\\tKIND\\tHEX\\tTEXT\\tMEANING\\n`), and typed arrays (read by numpy in place) hold its
offset, time, direction and kind, its pair (request ↔ reply) with the latency, and the first
copy of a retransmission: 33 bytes a line in memory (drivers/traffic/spool.py). Lines are read
back from the spool on demand; filters by direction, kind and regular expression run over the
arrays and the spool (drivers/traffic/search.py).

Taking lines in is made cheap for a flood (`add_many`): traffic repeats itself, so a frame's
decoding and its spool line are made once and kept on the decoder's shared Frame; lines join
the arrays and the spool a batch at a time; and replies are paired with their requests by
replaying what a reply tracker did for the request's last copy (drivers/traffic/pairing.py).

A console with a line limit drops its oldest lines (`drop_oldest`): lines keep their numbers
(`first` is the oldest kept, `len()` the number the next line gets), the arrays lose their
first rows (a memory move) and, on Linux, the spool's dropped bytes are given back to the file
system (a hole punched; offsets in the spool stay as they were).

Kinds and the line's fields: drivers/traffic/lines.py.
"""

from __future__ import annotations

import re
import time as time_module
from array import array
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path

import numpy as np

from drivers.link.records import DIRECTIONS, Note, Record, Traffic
from drivers.protocols.base import Protocol
from drivers.traffic.decoding import Frame, StreamDecoder
from drivers.traffic.lines import DIRECTION_CODE, KIND_CODE, KINDS, TrafficLine
from drivers.traffic.log_reader import LogRecord
from drivers.traffic.pairing import Pairing
from drivers.traffic.search import matching_rows, wanted_codes
from drivers.traffic.spool import Columns, Spool, spool_line

_CACHE_SIZE = 4096
_TX, _RX = DIRECTION_CODE["tx"] << 4, DIRECTION_CODE["rx"] << 4


def _record(record: LogRecord) -> Record:
    """A log's record as the tap makes one (its wall-clock time not known)."""
    if record.note:
        return Note(record.note, record.time, None)
    return Traffic(record.direction, record.data, record.time, None)


class TrafficIndex:
    """The session's lines, decoded by `protocol` (None: each record one line, undecoded)."""

    def __init__(self, protocol: Protocol | None = None, spool_dir: str | Path | None = None):
        self._spool = Spool(spool_dir)
        self.spool_path = self._spool.path
        self._columns = Columns()
        self._size = 0  # lines, those waiting in the columns' `new` included
        self._base = 0  # the oldest line kept (row 0 of the columns); lines before it dropped
        self._reserved = 0  # lines the pairing columns have room for (up to this line number)
        self._new = self._columns.new.append
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
        self._pairing = Pairing(protocol)

    def close(self) -> None:
        """Release the spool."""
        self._spool.close()

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
        self._spool.give_back(end)
        return count

    # -- adding ------------------------------------------------------------------------------

    def add(self, direction: str, data: bytes, time: float, wall: float | None = None) -> int:
        """Take bytes that crossed; returns how many lines they completed."""
        before = len(self)
        self.add_many([Traffic(direction, bytes(data), time, wall)])
        return len(self) - before

    def typed(self, data: bytes, time: float) -> None:
        """Bytes the operator typed, about to be sent at about `time` (the records' clock):
        their frames are queries, never hidden as polling."""
        self._pairing.typed(data, time)

    def add_note(self, text: str, time: float, wall: float | None = None) -> None:
        """Take an information line (connected, a command not sent, …)."""
        if wall is not None and self.wall_offset is None:
            self.wall_offset = wall - time
        self._append(time, "", "note", b"", text)
        self._spool.unwritten += self._columns.take_new()

    def add_many(self, items: Iterable[Record], deadline: float | None = None) -> int:
        """Take records in order, as the tap made them (Traffic, Note). With a `deadline`
        (perf_counter), stops once it has passed and returns how many were taken (all, else)."""
        decoder = self._decoder
        frames_of = decoder.frames if decoder is not None else None
        sent, received = self._add_sent, self._add_received
        clock = time_module.perf_counter
        no_wall = self.wall_offset is None
        taken = 0
        for item in items:
            taken += 1
            when, direction = item.time, item.direction
            if no_wall and item.wall is not None:
                self.wall_offset = item.wall - when
                no_wall = False
            if isinstance(item, Note):
                self._append(when, "", "note", b"", item.text)
                continue
            data = item.data
            if frames_of is None:
                frames: Sequence[Frame] = (Frame(bytes(data), b"", "", "frame", ()),)
            else:
                frames = frames_of(direction, data)
            add = sent if direction == "tx" else received
            for frame in frames:
                add(frame, when)
            if deadline is not None and clock() > deadline:
                break
        self._spool.unwritten += self._columns.take_new()
        if len(self._spool.unwritten) > 4096:
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
                self._spool.unwritten += self._columns.take_new()
            else:
                self.add_many([_record(r) for r in chunk])
            self._write()

    # The two below append a frame's line inline (its spool line kept on the frame for the next
    # time it crosses): a call less a frame, in a flood's hot path.

    def _add_sent(self, frame: Frame, time: float) -> None:
        line = self._size
        code, first = self._pairing.sent(frame, time, line)
        memo = frame.memo
        if memo is None or memo[0] != _TX | code:
            memo = self._memo(frame, _TX | code)
        self._size = line + 1
        self._new((time, memo))
        if line >= self._reserved:
            self._reserve(line)
        if first >= 0:
            self._columns.first_copy[line - self._base] = first

    def _add_received(self, frame: Frame, time: float) -> None:
        request, kind = self._pairing.received(frame)
        memo = frame.memo
        if memo is None or memo[0] != _RX | kind:
            memo = self._memo(frame, _RX | kind)
        line = self._size
        self._size = line + 1
        self._new((time, memo))
        if line >= self._reserved:
            self._reserve(line)
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

    def _memo(self, frame: Frame, code: int) -> tuple[int, int, bytes]:
        """A frame's line as the columns take it (code, size, spool line), kept on the frame."""
        raw = frame.raw
        direction, kind = DIRECTIONS[code >> 4], KINDS[code & 0x0F]
        meaning = self.meaning_text(frame.meaning)
        memo = frame.memo = (code, len(raw), spool_line(direction, kind, raw, meaning))
        return memo

    def _reserve(self, line: int) -> None:
        """Room in the pairing columns for `line` (and more)."""
        self._reserved = self._base + self._columns.reserve(line + 1 - self._base)

    def _append(self, time: float, direction: str, kind: str, data: bytes, meaning: str) -> int:
        code = DIRECTION_CODE[direction] << 4 | KIND_CODE[kind]
        line = self._size
        self._size = line + 1
        self._new((time, (code, len(data), spool_line(direction, kind, data, meaning))))
        if line >= self._reserved:
            self._reserve(line)
        return line

    def commit(self) -> None:
        """Hand the lines added so far to the spool (reads do it themselves when needed)."""
        self._write()

    def _write(self) -> None:
        spool = self._spool
        spool.unwritten += self._columns.take_new()
        spool.write()

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
        if end > self._spool.written:
            self._write()
        raw = self._spool.read(start, end)
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
            wanted = wanted_codes(
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
        spool = self._spool
        if spool.written == 0:
            return lines[:0]
        offsets = self._columns.view("offset", np.int64)
        rows = matching_rows(spool.fd, spool.written, offsets, lines - self._base, pattern)
        return rows + self._base
