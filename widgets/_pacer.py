"""At most one heavy piece of GUI-thread work a turn of the event loop, and a little apart.

The views' and the console's timers (a plot's data, the 3D render, a console decoding turn or
table update, the traffic timeline) each cost 1-5 ms, and after a late turn of the event loop
Qt fires every overdue timer in one go: together, and with the window's repaints that follow,
they made the window's longest stalls (30-50 ms in a flood). Each of them asks `take()` first:
only the first in a turn gets it, and only SPACING_S after the one before (the time its
window repaint takes); the others try again a moment later, so input and the window's own
events are handled between them.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QTimer
from shiboken6 import isValid

SPACING_S = 0.006  # a heavy job starts at least this long after the one before
RETRY_MS = 2  # a job refused in the same turn tries again this much later, at the least
_FREED = QEvent.Type(QEvent.registerEventType())


class Pacer(QObject):
    """Hands out one slot a turn of the event loop (a posted event frees it for the next),
    at most one every `spacing` seconds of `clock`."""

    def __init__(
        self,
        parent: QObject | None = None,
        spacing: float = SPACING_S,
        clock: Callable[[], float] = time.perf_counter,
    ) -> None:
        super().__init__(parent)
        self.spacing = spacing
        self.clock = clock
        self._taken = False
        self._last = -math.inf

    def take(self) -> bool:
        """Whether a heavy job may run now: the first to ask in a turn of the event loop,
        `spacing` after the last one that could."""
        now = self.clock()
        if self._taken or now - self._last < self.spacing:
            return False
        self._taken = True
        self._last = now
        QCoreApplication.postEvent(self, QEvent(_FREED))  # handled after this turn's timers
        return True

    def wait_ms(self) -> int:
        """How long a refused job should wait before it asks again."""
        left = self.spacing - (self.clock() - self._last)
        return max(RETRY_MS, math.ceil(left * 1000))

    def busy(self) -> bool:
        """Whether a heavy job has run in this turn already."""
        return self._taken

    def event(self, event: QEvent) -> bool:
        """The posted event: the turn is over, the slot is free."""
        if event.type() == _FREED:
            self._taken = False
            return True
        return super().event(event)


_pacer: Pacer | None = None


def pacer() -> Pacer:
    """The application's pacer (made at the first call, kept by the application)."""
    global _pacer
    if _pacer is None or not isValid(_pacer):  # (an application made again: a new one)
        _pacer = Pacer(QCoreApplication.instance())
    return _pacer


def run_paced(timer: QTimer) -> bool:
    """For a job that `timer` (single-shot) runs: True if it may run now; else `timer` is
    started again to ask again when it may (its interval is changed), and False."""
    paced = pacer()
    if paced.take():
        return True
    timer.start(paced.wait_ms())
    return False
