"""Where the traffic index keeps its lines: their text in a spool file, a few numbers each in
typed arrays (the columns) that numpy reads in place.

The spool holds a line a frame, `DIR\\tKIND\\tHEX\\tTEXT\\tMEANING\\n` (UTF-8), in a temporary
file unlinked at once; lines dropped give their bytes back to the file system (on Linux, a hole
punched; offsets in the spool stay as they were).
"""

from __future__ import annotations

import ctypes
import functools
import math
import os
import sys
import tempfile
from array import array
from collections.abc import Callable
from itertools import accumulate
from pathlib import Path

import numpy as np

from drivers.traffic.lines import escape

_CLEAN = str.maketrans({"\t": " ", "\n": " ", "\r": " "})
_MINUS_ONE = array("i", [-1])
_NAN = array("f", [math.nan])
_HOLE_BLOCK = 1 << 20  # bytes: the spool's dropped bytes are given back a megabyte at a time


def spool_line(direction: str, kind: str, data: bytes, meaning: str) -> bytes:
    """A line of the spool: `DIR\tKIND\tHEX\tTEXT\tMEANING\n`, UTF-8."""
    if not meaning.isprintable():
        meaning = meaning.translate(_CLEAN)
    text = (
        f"{direction.upper() or '--'}\t{kind}\t{data.hex(' ').upper()}\t{escape(data)}\t{meaning}\n"
    )
    return text.encode("utf-8")


class Columns:
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
        """Rows in the arrays (lines waiting in `new` not counted)."""
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


class Spool:
    """The lines' text in a temporary file, unlinked at once (the descriptor keeps it; nothing
    is left behind after a crash), written a batch at a time."""

    def __init__(self, spool_dir: str | Path | None = None) -> None:
        handle, name = tempfile.mkstemp(
            prefix="motionpanel-traffic-", suffix=".spool", dir=spool_dir
        )
        self.fd = handle
        self.path = Path(name)
        os.unlink(name)
        self.unwritten: list[bytes] = []  # spool lines not yet written (one write a batch)
        self.written = 0  # bytes written
        self.punched = 0  # bytes before this were given back (see give_back)

    def write(self) -> None:
        """Write the lines waiting in `unwritten` (dropped once the spool is closed)."""
        if self.fd < 0:  # closed: a late line has nowhere to go
            self.unwritten = []
            return
        if self.unwritten:
            view = memoryview(b"".join(self.unwritten))
            self.unwritten = []
            self.written += len(view)
            while view:
                written = os.write(self.fd, view)
                view = view[written:]

    def read(self, start: int, end: int) -> str:
        """Bytes start..end-1 as text (written already)."""
        return os.pread(self.fd, end - start, start).decode("utf-8")

    def give_back(self, end: int) -> None:
        """The bytes before `end` are no longer read: give them back to the file system, a
        megabyte at a time, where it can (on Linux)."""
        hole_end = end - end % _HOLE_BLOCK
        if (
            hole_end - self.punched >= _HOLE_BLOCK
            and self.fd >= 0
            and _punch_hole(self.fd, self.punched, hole_end)
        ):
            self.punched = hole_end

    def close(self) -> None:
        """Release the file."""
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1
