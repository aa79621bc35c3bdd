"""The traffic timeline's data: bytes in one-second bins each way, and latency points."""

from __future__ import annotations

import logging
import math

import numpy as np

log = logging.getLogger("widgets.traffic_timeline")  # the timeline's logger, as before the split

DIRECTIONS = ("tx", "rx")
_DIRECTION_INDEX = {direction: index for index, direction in enumerate(DIRECTIONS)}
INITIAL_CAPACITY = 1024
MAX_BINS = 7 * 24 * 3600  # a week of one-second bins (10 MB); later times are dropped


def dropped(store: ByteBins | Latencies, what: str) -> None:
    """Log a rejected sample: a warning for a store's first, debug messages after it."""
    store.dropped += 1
    level = logging.WARNING if store.dropped == 1 else logging.DEBUG
    log.log(level, "traffic timeline: dropped %s (further drops are logged at debug)", what)


# The stores are plain classes, not QObjects: an attribute of a PySide widget costs 4-15 times
# as much to read or write, and `add_*` may be called for every record of a busy link.
class ByteBins:
    """Bytes per one-second bin each way, and each bin's first console line."""

    __slots__ = ("bytes", "count", "dropped", "first_line", "latest", "version")

    def __init__(self) -> None:
        self.bytes = np.zeros((2, INITIAL_CAPACITY))  # [direction, second]
        self.first_line = np.full((2, INITIAL_CAPACITY), -1, dtype=np.int64)
        self.count = 0  # bins in use: seconds 0 .. the latest
        self.latest = 0.0  # the latest time added, s
        self.version = 0
        self.dropped = 0

    def add(self, time_s: float, direction: str, count: int, line: int) -> None:
        """Add `count` bytes to the bin of `time_s`; see TrafficTimeline.add_bytes."""
        d = _DIRECTION_INDEX.get(direction)
        if d is None:
            raise ValueError(f"direction must be 'tx' or 'rx', not {direction!r}")
        if count <= 0:
            if count < 0:
                raise ValueError(f"a byte count cannot be negative: {count}")
            return  # nothing crossed: no rate, no line to jump to
        if not 0.0 <= time_s < MAX_BINS:  # also false for NaN
            dropped(self, f"{count} {direction} bytes at {time_s!r} s")
            return
        second = int(time_s)
        if second >= self.bytes.shape[1]:
            self._grow(second + 1)
        self.bytes[d, second] += count
        first = self.first_line[d, second]
        if first < 0 or line < first:
            self.first_line[d, second] = line
        if second >= self.count:
            self.count = second + 1
        if time_s > self.latest:
            self.latest = time_s
        self.version += 1

    def _grow(self, needed: int) -> None:
        """Make room for `needed` bins, at least doubling."""
        capacity = min(max(needed, 2 * self.bytes.shape[1]), MAX_BINS)
        grown = np.zeros((2, capacity))
        grown[:, : self.count] = self.bytes[:, : self.count]
        lines = np.full((2, capacity), -1, dtype=np.int64)
        lines[:, : self.count] = self.first_line[:, : self.count]
        self.bytes, self.first_line = grown, lines


class Latencies:
    """Latency points (time s, ms, console line), kept in time order for drawing and lookup."""

    __slots__ = ("dropped", "lines", "max_t", "ms", "n", "t", "unsorted_from", "version")

    def __init__(self) -> None:
        self.t = np.empty(INITIAL_CAPACITY)
        self.ms = np.empty(INITIAL_CAPACITY)
        self.lines = np.empty(INITIAL_CAPACITY, dtype=np.int64)
        self.n = 0
        self.max_t = -math.inf
        self.unsorted_from: int | None = None  # the first index appended out of time order
        self.version = 0
        self.dropped = 0

    def add(self, time_s: float, ms: float, line: int) -> None:
        """Append one point; see TrafficTimeline.add_latency."""
        if not (math.isfinite(time_s) and math.isfinite(ms)):
            dropped(self, f"latency {ms!r} ms at {time_s!r} s")
            return
        n = self.n
        if n == len(self.t):
            self._grow(n + 1)
        self.t[n] = time_s
        self.ms[n] = ms
        self.lines[n] = line
        if time_s >= self.max_t:
            self.max_t = time_s
        elif self.unsorted_from is None:
            self.unsorted_from = n
        self.n = n + 1
        self.version += 1

    def add_many(self, times_s: np.ndarray, ms: np.ndarray, lines: np.ndarray) -> None:
        """Append many points; see TrafficTimeline.add_latencies."""
        t = np.asarray(times_s, dtype=float)
        values = np.asarray(ms, dtype=float)
        numbers = np.asarray(lines, dtype=np.int64)
        if not t.shape == values.shape == numbers.shape or t.ndim != 1:
            raise ValueError("times, latencies and lines must be 1-D arrays of one length")
        keep = np.isfinite(t) & np.isfinite(values)
        if not keep.all():
            dropped(self, f"{int((~keep).sum())} latencies without a finite time or value")
            t, values, numbers = t[keep], values[keep], numbers[keep]
        if not len(t):
            return
        n, end = self.n, self.n + len(t)
        if end > len(self.t):
            self._grow(end)
        self.t[n:end] = t
        self.ms[n:end] = values
        self.lines[n:end] = numbers
        in_order = t[0] >= self.max_t and bool(np.all(t[1:] >= t[:-1]))
        if not in_order and self.unsorted_from is None:
            self.unsorted_from = n
        self.max_t = max(self.max_t, float(t.max()))
        self.n = end
        self.version += 1

    def _grow(self, needed: int) -> None:
        """Make room for `needed` points, at least doubling."""
        capacity = max(needed, 2 * len(self.t))
        n = self.n
        for name in ("t", "ms", "lines"):
            old = getattr(self, name)
            new = np.empty(capacity, dtype=old.dtype)
            new[:n] = old[:n]
            setattr(self, name, new)

    def sort(self) -> None:
        """Put late-arriving points in time order; only the tail from the earliest one moves."""
        start = self.unsorted_from
        if start is None:
            return
        n = self.n
        earliest = self.t[start:n].min()
        begin = int(np.searchsorted(self.t[:start], earliest, side="right"))
        order = np.argsort(self.t[begin:n], kind="stable")
        for values in (self.t, self.ms, self.lines):
            values[begin:n] = values[begin:n][order]
        self.unsorted_from = None
        self.version += 1  # the drawn arrays were rearranged in place: redraw

    def between(self, low: float, high: float) -> tuple[int, int]:
        """The index range [start, end) of the points with low <= time <= high."""
        self.sort()
        times = self.t[: self.n]
        start = int(np.searchsorted(times, low, side="left"))
        end = int(np.searchsorted(times, high, side="right"))
        return start, max(start, end)
