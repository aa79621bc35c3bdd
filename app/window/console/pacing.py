"""The traffic console's feed: records arriving in a flood are decoded in turns of at most
FLUSH_BUDGET (BACKLOG_BUDGET while a backlog waits) and shown at most every FLUSH_INTERVAL_MS,
each in a turn of its own; what arrives joins what waits in time order, in time linear in what
arrived, however long the backlog."""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable
from itertools import islice

from PySide6.QtCore import QObject, QTimer

from drivers.link.records import Record
from widgets._pacer import run_paced

FLUSH_INTERVAL_MS = 100  # 10 Hz: a flood costs a repaint of the table per flush
FLUSH_BUDGET = 0.002  # s of decoding per turn of the event loop; the rest waits its turn
BACKLOG_BUDGET = 0.005  # s a turn while a backlog waits (a burst, a busy moment): drained fast
BACKLOG = 20_000  # records waiting from which a turn takes BACKLOG_BUDGET
ARRIVALS_A_TURN = 5_000  # records a turn puts in order among those waiting (bounded work)
RECENT_RECORDS = 20_000  # raw records kept for `records()`; the index keeps every line

Incoming = Record  # as the tap (or the panel, for a note) made it


def _when(item: Incoming) -> float:
    return item.time


class FeedPacer(QObject):
    """Records waiting to be decoded (`take`: into the index, up to a deadline; returns how
    many it took) and shown (`show`: the table updated and painted), on a timer of their own."""

    def __init__(
        self,
        parent: QObject,
        take: Callable[[deque[Incoming], float | None], int],
        show: Callable[[], None],
    ) -> None:
        super().__init__(parent)
        self._take = take
        self._show = show
        # arrived and not yet looked at; taken and waiting for their turn (in time order);
        # the latest taken
        self.incoming: deque[Incoming] = deque()
        self.pending: deque[Incoming] = deque()
        self.recent: deque[Incoming] = deque(maxlen=RECENT_RECORDS)
        self.shown_at = 0.0  # perf_counter of the last update of the table
        self.show_due = False  # the table's update waits for the next turn (see timed_flush)
        self.timer = QTimer(self)
        self.timer.setObjectName("consoleFlushTimer")
        self.timer.setSingleShot(True)
        self.timer.setInterval(FLUSH_INTERVAL_MS)
        self.timer.timeout.connect(self.timed_flush)

    def add(self, item: Incoming) -> None:
        """Take a record; it is decoded and shown in the turns to come."""
        if not self.incoming:  # the timer runs while anything is waiting (see take_pending)
            self._schedule()
        self.incoming.append(item)

    def extend(self, items: list[Incoming]) -> None:
        """Take records (a worker's batch); decoded and shown in the turns to come."""
        if items:
            if not self.incoming:
                self._schedule()
            self.incoming.extend(items)

    def _schedule(self) -> None:
        if not self.timer.isActive():
            self.timer.start(FLUSH_INTERVAL_MS)

    def take_pending(self, budget: float | None = None) -> None:
        """Into the index, in time order (a note is stamped when added, traffic comes batched);
        with a `budget` (s of decoding, counted once the new records are in order), at most
        ARRIVALS_A_TURN of what arrived is put in order and what is left when the budget is
        spent waits for the next turn: a turn's work is bounded, however long the backlog."""
        if self.incoming:
            self._arrive(None if budget is None else ARRIVALS_A_TURN)
        if not self.pending:
            return
        deadline = None if budget is None else time.perf_counter() + budget
        pending = self.pending
        taken = self._take(pending, deadline)
        if taken >= len(pending):
            pending.clear()
        else:
            for _ in range(taken):
                pending.popleft()

    def _arrive(self, limit: int | None) -> None:
        """Put what arrived (at most `limit` records: None, all) among what waits."""
        incoming = self.incoming
        if limit is None or len(incoming) <= limit:
            arrived = list(incoming)
            incoming.clear()
        else:
            arrived = [incoming.popleft() for _ in range(limit)]
        self.recent.extend(arrived)
        self._merge(arrived)

    def _merge(self, incoming: list[Incoming]) -> None:
        """Put records among what waits, in time order; ties keep their order (what waited
        first). Only the waiting records later than the earliest new one are moved."""
        incoming.sort(key=_when)  # stable; a worker's batch is in order already
        pending, first = self.pending, incoming[0].time
        displaced: list[Incoming] = []
        while pending and pending[-1].time > first:
            displaced.append(pending.pop())
        if displaced:
            displaced.reverse()
            incoming = sorted(displaced + incoming, key=_when)
        pending.extend(incoming)

    def backlog(self) -> int:
        """Records received but not yet decoded and shown (a flood beyond the budget)."""
        return len(self.pending) + len(self.incoming)

    def records(self) -> list[Incoming]:
        """The latest records (at most RECENT_RECORDS), those not yet looked at included."""
        waiting = self.incoming
        if len(waiting) >= RECENT_RECORDS:
            return list(islice(waiting, len(waiting) - RECENT_RECORDS, None))
        return [*self.recent, *waiting][-RECENT_RECORDS:]

    def clear(self) -> None:
        """Forget every record (another index is shown)."""
        self.recent.clear()
        self.pending.clear()
        self.incoming.clear()

    def flush(self) -> None:
        """Take every record waiting now, whatever the time it takes (the caller shows them)."""
        self.timer.stop()
        self.take_pending(None)

    def showing(self) -> float:
        """The table is being updated: no update is due until the next interval; returns now
        (perf_counter)."""
        self.show_due = False
        self.timer.setInterval(FLUSH_INTERVAL_MS)
        self.shown_at = time.perf_counter()
        return self.shown_at

    def timed_flush(self) -> None:
        """The timer's turn: at most FLUSH_BUDGET of decoding, or the table's update, so a flood
        never stalls the window. The table is updated at most every FLUSH_INTERVAL_MS (its
        repaint is dear), in a turn after the decoding's: the two together, and the window's
        repaint that follows, made one of the window's longest stalls. Each turn is paced: not
        in the same turn of the event loop as the views' heavy work."""
        if not run_paced(self.timer):
            return
        if self.show_due:
            self.show_due = False
            self._show()
        else:
            now = time.perf_counter()
            behind = len(self.pending) + len(self.incoming) > BACKLOG
            self.take_pending(BACKLOG_BUDGET if behind else FLUSH_BUDGET)
            if not self.pending or now - self.shown_at >= FLUSH_INTERVAL_MS / 1000:
                self.show_due = True
        if self.pending or self.show_due:
            self.timer.start(0)  # the rest after the events waiting now
        elif self.incoming:  # arrived since the decoding turn: the next batch, in its time
            self.timer.start(FLUSH_INTERVAL_MS)
