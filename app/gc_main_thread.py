"""Python's cyclic garbage collected in the GUI thread only.

A collection runs in whichever thread happens to allocate: in the serial worker's, it can free
the last reference to a Qt object, and PySide then destroys it while that thread emits a signal.
Seen in the tests: the GUI thread deleting a QAction waited on a Qt lock the worker held while
it waited for the interpreter lock, and neither moved again. So automatic collection is off and
a timer in the GUI thread collects, a generation at a time, as Python itself would.
"""

from __future__ import annotations

import gc

from PySide6.QtCore import QObject, QTimer, Slot

INTERVAL_MS = 500


class MainThreadCollector(QObject):
    """Turns automatic collection off and collects on a GUI-thread timer instead."""

    def __init__(self, parent: QObject | None = None, interval_ms: int = INTERVAL_MS) -> None:
        super().__init__(parent)
        gc.disable()
        self._timer = QTimer(self)
        self._timer.setInterval(interval_ms)
        self._timer.timeout.connect(self.collect)
        self._timer.start()

    @Slot()
    def collect(self) -> int:
        """Collect the oldest generation whose count is past its threshold; objects freed."""
        counts, thresholds = gc.get_count(), gc.get_threshold()
        generation = -1
        for level in range(3):
            if counts[level] > thresholds[level]:
                generation = level
        return gc.collect(generation) if generation >= 0 else 0
