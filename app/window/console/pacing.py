"""The traffic console's feed: records arriving in a flood are decoded in turns of at most
FLUSH_BUDGET and shown at most every FLUSH_INTERVAL_MS, each in a turn of its own."""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable

from PySide6.QtCore import QObject, QTimer

from widgets._pacer import run_paced

FLUSH_INTERVAL_MS = 100  # 10 Hz: a flood costs a repaint of the table per flush
FLUSH_BUDGET = 0.002  # s of decoding per turn of the event loop; the rest waits its turn
RECENT_RECORDS = 20_000  # raw records kept for `records()`; the index keeps every line

Incoming = tuple[float, str, bytes, float | None]  # (timestamp, direction or "", data, wall)


def _when(item: Incoming) -> float:
    return item[0]


class FeedPacer(QObject):
    """Records waiting to be decoded (`take`: into the index, up to a deadline; returns how
    many it took) and shown (`show`: the table updated and painted), on a timer of their own."""

    def __init__(
        self,
        parent: QObject,
        take: Callable[[list[Incoming], float | None], int],
        show: Callable[[], None],
    ) -> None:
        super().__init__(parent)
        self._take = take
        self._show = show
        # arrived and not yet looked at; taken and waiting for their turn (in time order);
        # the latest taken
        self.incoming: list[Incoming] = []
        self.pending: list[Incoming] = []
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

    def _schedule(self) -> None:
        if not self.timer.isActive():
            self.timer.start(FLUSH_INTERVAL_MS)

    def take_pending(self, deadline: float | None = None) -> None:
        """Into the index, in time order (a note is stamped when added, traffic comes batched);
        with a `deadline` (perf_counter), what is left when it passes waits for the next turn."""
        if self.incoming:
            incoming, self.incoming = self.incoming, []
            self.recent.extend(incoming)
            self.pending.extend(incoming)
            self.pending.sort(key=_when)  # stable: ties keep their order
        if not self.pending:
            return
        pending = self.pending
        taken = self._take(pending, deadline)
        self.pending = pending[taken:] if taken < len(pending) else []

    def backlog(self) -> int:
        """Records received but not yet decoded and shown (a flood beyond the budget)."""
        return len(self.pending) + len(self.incoming)

    def records(self) -> list[Incoming]:
        """The latest records (at most RECENT_RECORDS), those not yet looked at included."""
        return [*self.recent, *self.incoming][-RECENT_RECORDS:]

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
            self.take_pending(now + FLUSH_BUDGET)
            if not self.pending or now - self.shown_at >= FLUSH_INTERVAL_MS / 1000:
                self.show_due = True
        if self.pending or self.show_due:
            self.timer.start(0)  # the rest after the events waiting now
        elif self.incoming:  # arrived since the decoding turn: the next batch, in its time
            self.timer.start(FLUSH_INTERVAL_MS)
