"""Python's cyclic garbage collected in the GUI thread only.

A collection runs wherever an allocation happens to cross the threshold: inside a Qt call that
holds one of Qt's locks, it can free the last reference to a Qt object, whose destructor then
waits for that same lock for ever. Seen twice in the tests (stacks under gdb): pyqtgraph
disconnecting a signal (Qt holds its connection lock and asks Python for an override; that
allocation ran a collection, which destroyed a QObject waiting on the lock held by the same
thread), and a collection in the serial worker's thread destroying a QAction. So automatic
collection is off, and a timer in the GUI thread collects from the event loop, where no Qt lock
is held, a generation at a time, as Python itself would.
"""

from __future__ import annotations

import gc
import time
from collections.abc import Callable

from PySide6.QtCore import QObject, QTimer, SignalInstance, Slot

INTERVAL_MS = 500
FULL_DEFERRED_S = 10.0  # the longest a full collection waits while the window is behind
BURST_OBJECTS = 100_000  # young objects in one interval, while behind: a burst being taken in


class MainThreadCollector(QObject):
    """Turns automatic collection off and collects on a GUI-thread timer instead."""

    def __init__(self, parent: QObject | None = None, interval_ms: int = INTERVAL_MS) -> None:
        super().__init__(parent)
        self.behind: Callable[[], bool] = lambda: False
        """Whether the window is catching up (a traffic backlog): a full collection, which
        walks every live object (tens of ms with the backlog's), waits meanwhile."""
        self._deferred_since: float | None = None
        self.bursts_set_aside = 0
        """How many times the young objects of a burst were set aside instead of walked."""
        gc.disable()
        self._timer = QTimer(self)
        self._timer.setInterval(interval_ms)
        self._timer.timeout.connect(self.collect)
        self._timer.start()

    @Slot()
    def settle(self) -> None:
        """Once the window is built: what exists now lives as long as the program, so it is
        set aside (`gc.freeze`) and a full collection no longer walks it (tens of ms each)."""
        gc.collect()
        gc.freeze()

    @Slot()
    def collect(self) -> int:
        """Collect the oldest generation whose count is past its threshold; objects freed.

        While the window catches up a burst (hundreds of thousands of traffic records, kept by
        the console), walking its young objects would hold the GUI for tens of ms: they are
        set aside as `settle` sets aside the window's (`gc.freeze`, which moves lists and walks
        nothing). A record freed later leaves by its reference count; only a cycle among what
        was young at that moment is never collected."""
        counts, thresholds = gc.get_count(), gc.get_threshold()
        if counts[0] >= BURST_OBJECTS and self.behind():
            gc.freeze()
            self.bursts_set_aside += 1
            return 0
        generation = -1
        for level in range(3):
            if counts[level] > thresholds[level]:
                generation = level
        if generation == 2:
            now = time.monotonic()
            if self._deferred_since is None:
                self._deferred_since = now
            if self.behind() and now - self._deferred_since < FULL_DEFERRED_S:
                generation = 1  # the young objects only, until the window has caught up
            else:
                self._deferred_since = None
        return gc.collect(generation) if generation >= 0 else 0


def collect_for(
    app: QObject, ready: SignalInstance, behind: Callable[[], bool] | None = None
) -> MainThreadCollector:
    """The application's collector (kept by `app`), settled when `ready` (the window's views
    are built) is emitted; `behind` (asked from then on): whether the window is catching up."""
    collector = MainThreadCollector(app)
    ready.connect(collector.settle)
    if behind is not None:
        ready.connect(lambda: setattr(collector, "behind", behind))
    return collector
