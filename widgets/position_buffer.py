"""A fixed-capacity ring buffer of (t, x, y, z) rows for the position views."""

from __future__ import annotations

import numpy as np

DEFAULT_CAPACITY = 20_000


class PositionBuffer:
    """Bounded history of positions; `view()` is always a contiguous slice, never a copy.

    Every row is stored twice, at `i` and `i + capacity` of an array of `2 * capacity` rows, so
    the last `len` rows in order are one slice of it whatever the wrap-around. Memory is fixed at
    `2 * capacity * 4` float64 values (1.3 MB for the default capacity).
    """

    def __init__(self, capacity: int = DEFAULT_CAPACITY) -> None:
        if capacity < 1:
            raise ValueError(f"capacity must be at least 1, not {capacity}")
        self._capacity = int(capacity)
        self._data = np.zeros((2 * self._capacity, 4), dtype=np.float64)
        self._next = 0  # where the next row goes, 0 <= _next < capacity
        self._len = 0
        self._version = 0

    @property
    def capacity(self) -> int:
        """The most rows kept; older ones are dropped."""
        return self._capacity

    @property
    def version(self) -> int:
        """A counter that changes on every append, clear and shift (cheap change detection)."""
        return self._version

    def __len__(self) -> int:
        """The number of rows kept."""
        return self._len

    def append(self, t: float, x: float, y: float, z: float) -> None:
        """Add a row, dropping the oldest one when full."""
        row = (t, x, y, z)
        self._data[self._next] = row
        self._data[self._next + self._capacity] = row
        self._next = (self._next + 1) % self._capacity
        self._len = min(self._len + 1, self._capacity)
        self._version += 1

    def view(self) -> np.ndarray:
        """The rows, oldest first, as a read-only (n, 4) view: valid until the next append."""
        start = (self._next - self._len) % self._capacity
        rows = self._data[start : start + self._len]
        rows.flags.writeable = False
        return rows

    def last(self) -> tuple[float, float, float, float] | None:
        """The newest row (t, x, y, z), or None when empty."""
        if not self._len:
            return None
        t, x, y, z = self._data[(self._next - 1) % self._capacity]
        return float(t), float(x), float(y), float(z)

    def shift(self, dx: float, dy: float, dz: float) -> None:
        """Add (dx, dy, dz) to every kept row's x, y and z, as when the home is moved.

        Both copies of each row are shifted, so `view()` stays consistent whatever the wrap-around
        and whatever rows are appended later. Dropped rows (outside the kept window) are left as
        they were: they are never shown again.
        """
        offset = np.array([dx, dy, dz], dtype=np.float64)
        if self._len:
            start = (self._next - self._len) % self._capacity
            first = np.arange(start, start + self._len) % self._capacity  # primary copies
            self._data[first, 1:4] += offset
            self._data[first + self._capacity, 1:4] += offset
        self._version += 1

    def clear(self, keep_last: bool = False) -> None:
        """Drop all rows (all but the newest with `keep_last`, so a marker can stay)."""
        last = self.last() if keep_last else None
        self._next = 0
        self._len = 0
        self._version += 1
        if last is not None:
            self.append(*last)
