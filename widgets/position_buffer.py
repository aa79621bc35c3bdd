"""The trail of (t, x, y, z) rows behind the position views, and its decimated form for drawing.

`PositionBuffer(capacity=None)` keeps every row (the panel's trail: nothing is forgotten until
Clear trail); with a capacity it is a ring that drops the oldest rows. `TrailLOD` (`buffer.lod`)
is what the views draw: the older rows decimated per block to their first, last and extreme
points, the recent ones all, so a frame costs about the same for a million points as for ten
thousand, and the drawn trail keeps its shape, its bounding box and its newest point.

A row of NaN positions is a break: the trail is drawn in segments, none joining the rows on
either side of it (a new connection: the stage was not watched meanwhile). Breaks are never
decimated away.
"""

from __future__ import annotations

import numpy as np

DEFAULT_CAPACITY = 20_000  # a ring's size when none is given; the panel keeps every row (None)
INITIAL_ROWS = 1024  # an unbounded buffer's first allocation; it doubles when full

DECIMATED_MAX_ROWS = 6144  # the decimated older part stays below this many rows
RECENT_ROWS = 2048  # the newest rows are always drawn, all of them
FIRST_BLOCK = 16  # rows per block at first; the block doubles when the decimated part is full


class PositionBuffer:
    """History of positions; `view()` is always a contiguous slice, never a copy.

    With `capacity=None` every row is kept, in an array that doubles when full (32 bytes a row;
    32 MB for a million). With a capacity, the oldest rows are dropped: every row is stored
    twice, at `i` and `i + capacity` of an array of `2 * capacity` rows, so the last `len` rows in
    order are one slice of it whatever the wrap-around, and memory is fixed at
    `2 * capacity * 4` float64 values (1.3 MB for the default capacity).
    """

    def __init__(self, capacity: int | None = DEFAULT_CAPACITY) -> None:
        if capacity is not None and capacity < 1:
            raise ValueError(f"capacity must be at least 1, not {capacity}")
        self._capacity = None if capacity is None else int(capacity)
        rows = INITIAL_ROWS if capacity is None else 2 * int(capacity)
        self._data = np.zeros((rows, 4), dtype=np.float64)
        self._next = 0  # where the next row goes, 0 <= _next < capacity (rings only)
        self._len = 0
        self._version = 0
        self._generation = 0  # changes when kept rows change or go (clear, shift, a ring's drop)
        self._lod: TrailLOD | None = None
        self._break = False  # the next row starts a new segment (a NaN row goes before it)
        self._appended = 0  # rows appended so far (breaks included), less those dropped
        self._provisional: tuple[int, bool] | None = None  # _appended and _break at its start

    @property
    def capacity(self) -> int | None:
        """The most rows kept (older ones are dropped), or None: every row is kept."""
        return self._capacity

    @property
    def version(self) -> int:
        """A counter that changes on every append, clear and shift (cheap change detection)."""
        return self._version

    @property
    def generation(self) -> int:
        """A counter that changes when rows already kept change or are dropped, not on appends."""
        return self._generation

    @property
    def lod(self) -> TrailLOD:
        """The decimated trail the views draw (shared by them; see `TrailLOD.update`)."""
        if self._lod is None:
            self._lod = TrailLOD(self)
        return self._lod

    def __len__(self) -> int:
        """The number of rows kept."""
        return self._len

    def break_trail(self) -> None:
        """The next row starts a new segment: no line joins it to the rows before (a NaN row
        goes between them when it comes; nothing when the trail is empty)."""
        self._break = self._len > 0

    def begin_provisional(self) -> None:
        """The rows from now on are an estimate: `drop_provisional` takes them back."""
        self._provisional = (self._appended, self._break)

    def keep_provisional(self) -> None:
        """The rows since `begin_provisional` are kept (the estimate came true)."""
        self._provisional = None

    def drop_provisional(self) -> None:
        """Take back the rows appended since `begin_provisional` (the estimate did not come
        true: the move failed); a ring's oldest rows dropped meanwhile do not come back."""
        if self._provisional is None:
            return
        mark, pending = self._provisional
        self._provisional = None
        count = min(self._appended - mark, self._len)
        self._appended = mark
        self._break = self._break or pending
        if count <= 0:
            return
        self._len -= count
        if self._capacity is not None:
            self._next = (self._next - count) % self._capacity
        self._version += 1
        self._generation += 1

    def append(self, t: float, x: float, y: float, z: float) -> None:
        """Add a row (a ring drops the oldest one when full); after `break_trail`, a NaN row
        first."""
        if self._break:
            self._break = False
            self._append_row((t, np.nan, np.nan, np.nan))
        self._append_row((t, x, y, z))
        self._version += 1

    def _append_row(self, row: tuple[float, float, float, float]) -> None:
        if self._capacity is None:
            if self._len == len(self._data):
                self._grow(self._len + 1)
            self._data[self._len] = row
            self._len += 1
        else:
            self._data[self._next] = row
            self._data[self._next + self._capacity] = row
            self._next = (self._next + 1) % self._capacity
            if self._len == self._capacity:
                self._generation += 1  # the oldest row went
            self._len = min(self._len + 1, self._capacity)
        self._appended += 1

    def extend(self, rows: np.ndarray) -> None:
        """Add many (t, x, y, z) rows at once, oldest first (as `append` for each)."""
        rows = np.asarray(rows, dtype=np.float64).reshape(-1, 4)
        if self._break and len(rows):
            self._break = False
            gap = np.array([[rows[0, 0], np.nan, np.nan, np.nan]])
            rows = np.concatenate([gap, rows])
        if self._capacity is not None:
            for row in rows[-self._capacity :]:
                self.append(*row)
            return
        end = self._len + len(rows)
        if end > len(self._data):
            self._grow(end)
        self._data[self._len : end] = rows
        self._len = end
        self._appended += len(rows)
        self._version += 1

    def _grow(self, needed: int) -> None:
        """Make room for `needed` rows, at least doubling (unbounded buffers)."""
        rows = max(2 * len(self._data), 1 << (needed - 1).bit_length())  # a power of two
        grown = np.zeros((rows, 4), dtype=np.float64)
        grown[: self._len] = self._data[: self._len]
        self._data = grown

    def _start(self) -> int:
        """Where the oldest kept row is in `_data`."""
        if self._capacity is None:
            return 0
        return (self._next - self._len) % self._capacity

    def view(self) -> np.ndarray:
        """The rows, oldest first, as a read-only (n, 4) view: valid until the next append."""
        start = self._start()
        rows = self._data[start : start + self._len]
        rows.flags.writeable = False
        return rows

    def row(self, index: int) -> tuple[float, float, float, float]:
        """Row `index` (0 the oldest kept, -1 the newest) as (t, x, y, z)."""
        if not -self._len <= index < self._len:
            raise IndexError(f"row {index} of {self._len}")
        t, x, y, z = self._data[self._start() + index % self._len]
        return float(t), float(x), float(y), float(z)

    def last(self) -> tuple[float, float, float, float] | None:
        """The newest row (t, x, y, z), or None when empty."""
        return self.row(-1) if self._len else None

    def shift(self, dx: float, dy: float, dz: float) -> None:
        """Add (dx, dy, dz) to every kept row's x, y and z, as when the home is moved.

        In a ring both copies of each row are shifted, so `view()` stays consistent whatever the
        wrap-around and whatever rows are appended later. Dropped rows (outside the kept window)
        are left as they were: they are never shown again.
        """
        offset = np.array([dx, dy, dz], dtype=np.float64)
        if self._len:
            if self._capacity is None:
                self._data[: self._len, 1:4] += offset
            else:
                start = self._start()
                first = np.arange(start, start + self._len) % self._capacity  # primary copies
                self._data[first, 1:4] += offset
                self._data[first + self._capacity, 1:4] += offset
        self._version += 1
        self._generation += 1

    def clear(self, keep_last: bool = False) -> None:
        """Drop all rows (all but the newest with `keep_last`, so a marker can stay); a break
        asked for still applies to the next row."""
        last = self.last() if keep_last else None
        pending, self._break = self._break, False
        self._next = 0
        self._len = 0
        if self._capacity is None and len(self._data) > INITIAL_ROWS:
            self._data = np.zeros((INITIAL_ROWS, 4), dtype=np.float64)  # give the memory back
        self._version += 1
        self._generation += 1
        if last is not None:
            self.append(*last)
        self._break = pending and self._len > 0
        if self._provisional is not None:
            self._provisional = (self._appended, self._break)  # what is kept stays


def _block_picks(xyz: np.ndarray) -> np.ndarray:
    """For (blocks, size, 3) points: the offsets (blocks, 8) of each block's first and last
    point and of its lowest and highest x, y and z (among its finite values; breaks, the NaN
    rows, are kept apart: see `TrailLOD`)."""
    blocks, size, _ = xyz.shape
    missing = np.isnan(xyz)
    picks = np.empty((blocks, 8), dtype=np.int64)
    picks[:, 0] = 0
    picks[:, 1] = size - 1
    picks[:, 2:5] = np.argmin(np.where(missing, np.inf, xyz), axis=1)
    picks[:, 5:8] = np.argmax(np.where(missing, -np.inf, xyz), axis=1)
    return picks


class TrailLOD:
    """A buffer's trail as drawn: older rows min/max-decimated per block, the recent ones all.

    Rows older than the newest `recent` are decimated in blocks: each block keeps its first and
    last row, its rows of lowest and highest x, y and z, and every break (NaN row), in order, so
    every extreme of the whole is kept and no segment joins what a break separates. Blocks
    start at `first_block` rows (longer when many rows come at once, as after a restart);
    whenever the decimated part would exceed `max_rows` rows, neighbouring
    blocks are merged (the extremes of two blocks are among their kept rows, so nothing is read
    twice) and new blocks are twice as long. Updating costs only the rows appended since the
    last update; a clear, a shift or a ring's dropped row makes it start again from the buffer.

    `rows` (after `update()`) is what to draw: (n, 4) rows, the decimated part first
    (`decimated_count` rows), then every recent row, the newest last. The drawn rows have the
    same bounding box as the whole trail (`bounds`).
    """

    def __init__(
        self,
        buffer: PositionBuffer,
        max_rows: int = DECIMATED_MAX_ROWS,
        recent: int = RECENT_ROWS,
        first_block: int = FIRST_BLOCK,
    ) -> None:
        if max_rows < 16 or recent < 1 or first_block < 2:
            raise ValueError("a TrailLOD needs max_rows >= 16, recent >= 1, first_block >= 2")
        self.buffer = buffer
        self.max_rows = max_rows
        self.recent = recent
        self.first_block = first_block
        self.epoch = 0  # changes whenever rows already drawn change (see `unchanged_prefix`)
        self._reset()
        self._generation = buffer.generation

    def _reset(self) -> None:
        self.block = self.first_block
        self._kept = np.zeros(0, dtype=np.int64)  # buffer indices of the decimated rows
        self._groups = np.zeros(0, dtype=np.int64)  # the block each decimated row came from
        self._done = 0  # rows [0, _done) are decimated; [_done, len) are drawn as they are
        self._decimated = np.zeros((0, 4))
        self.rows = np.zeros((0, 4))
        self._version = -1
        self.epoch += 1

    @property
    def decimated_count(self) -> int:
        """How many of `rows` are the decimated older part (the rest are every recent row)."""
        return len(self._decimated)

    @property
    def block_rows(self) -> int:
        """The rows of trail each new decimated block stands for."""
        return self.block

    def update(self) -> np.ndarray:
        """Catch up with the buffer; returns `rows`, the trail to draw."""
        buffer = self.buffer
        if buffer.version == self._version:
            return self.rows
        if buffer.generation != self._generation:
            self._generation = buffer.generation
            self._reset()
        self._version = buffer.version
        data = buffer.view()
        n = len(data)
        ready = n - self.recent - self._done  # rows old enough to be decimated
        while not len(self._kept) and (ready // self.block) * 4 > self.max_rows:
            self.block *= 2  # a long trail at once: blocks about as long as merging would make
        if ready >= self.block:
            self._add_blocks(data, ready // self.block)
        self.rows = np.concatenate([self._decimated, data[self._done :]])
        return self.rows

    def _add_blocks(self, data: np.ndarray, count: int) -> None:
        """Decimate `count` whole blocks after `_done`, then merge blocks while there are too many
        decimated rows."""
        block, start = self.block, self._done
        xyz = data[start : start + count * block, 1:4].reshape(count, block, 3)
        picks = _block_picks(xyz) + (np.arange(count, dtype=np.int64)[:, None] * block + start)
        first_group = int(self._groups[-1]) + 1 if len(self._groups) else 0
        groups = np.repeat(np.arange(first_group, first_group + count, dtype=np.int64), 8)
        picks = picks.ravel()
        breaks = np.flatnonzero(np.isnan(xyz[:, :, 0]).ravel())  # every one is kept
        if len(breaks):
            picks = np.concatenate([picks, breaks + start])
            groups = np.concatenate([groups, first_group + breaks // block])
        order = np.argsort(picks, kind="stable")
        picks, groups = picks[order], groups[order]
        new = np.ones(len(picks), dtype=bool)
        new[1:] = picks[1:] != picks[:-1]
        added = picks[new]
        self._kept = np.concatenate([self._kept, added])
        self._groups = np.concatenate([self._groups, groups[new]])
        self._done = start + count * block
        merged = False
        while len(self._kept) > self.max_rows:
            before = len(self._kept)
            self._merge_pairs(data)
            merged = True
            if len(self._kept) >= before:
                break  # nothing left to merge (only breaks, ends and extremes)
        if merged:
            self._decimated = data[self._kept]
            self.epoch += 1  # rows already drawn changed
        else:
            self._decimated = np.concatenate([self._decimated, data[added]])

    def _merge_pairs(self, data: np.ndarray) -> None:
        """Merge neighbouring blocks two by two, keeping each merged block's first, last and
        extreme rows; new blocks are twice as long."""
        kept, groups = self._kept, self._groups // 2
        chosen = np.zeros(len(kept), dtype=bool)
        edges = np.flatnonzero(np.diff(groups)) + 1
        chosen[0] = chosen[-1] = True
        chosen[edges] = chosen[edges - 1] = True  # the first and last row of each block
        xyz = data[kept, 1:4]
        missing = np.isnan(xyz)
        chosen |= missing[:, 0]  # the breaks
        for axis in range(3):
            values = xyz[:, axis]
            lowest = np.lexsort((np.where(missing[:, axis], np.inf, values), groups))
            highest = np.lexsort((np.where(missing[:, axis], -np.inf, values), groups))
            sorted_groups = groups[lowest]  # by block, then by value: the same blocks in order
            starts = np.flatnonzero(np.r_[True, sorted_groups[1:] != sorted_groups[:-1]])
            ends = np.r_[starts[1:], len(lowest)] - 1
            chosen[lowest[starts]] = True
            chosen[highest[ends]] = True
        self._kept, self._groups = kept[chosen], groups[chosen]
        self.block *= 2

    @property
    def recent_start(self) -> int:
        """The buffer row from which on every row is drawn (the decimated ones come before)."""
        return self._done

    def rows_since(self, index: int) -> np.ndarray:
        """`rows`, but with every buffer row from row `index` on: (n, 4) rows, oldest first."""
        rows = self.update()
        if index >= self._done:
            return rows
        index = max(index, 0)
        before = int(np.searchsorted(self._kept, index))  # the decimated rows before `index`
        return np.concatenate([self._decimated[:before], self.buffer.view()[index:]])

    def bounds(self) -> tuple[np.ndarray, np.ndarray] | None:
        """The lowest and highest (x, y, z) of every row in the buffer (NaN ignored), or None."""
        rows = self.update()
        if not len(rows):
            return None
        xyz = rows[:, 1:4]
        return np.fmin.reduce(xyz, axis=0), np.fmax.reduce(xyz, axis=0)

    def token(self) -> tuple[int, int, int]:
        """What identifies `rows` as drawn now, for `unchanged_prefix` later."""
        return self.epoch, self.decimated_count, len(self.rows)

    def unchanged_prefix(self, token: tuple[int, int, int] | None) -> int:
        """How many leading `rows` are the same as when `token` was taken (0: none, or unknown).

        Rows only change by appending, except that a finished block replaces recent rows by its
        decimated ones (from the old decimated count on), and a merge or a restart changes all.
        """
        if token is None:
            return 0
        epoch, decimated, count = token
        if epoch != self.epoch:
            return 0
        if decimated != self.decimated_count:
            return decimated
        return min(count, len(self.rows))
