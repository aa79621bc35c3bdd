"""The estimated position of a move the device cannot be asked about while it runs."""

from __future__ import annotations

import time

from PySide6.QtCore import QObject, QTimer, Signal

from drivers.device.motion import MoveStart

ESTIMATE_INTERVAL_MS = 33  # ~30 Hz, as the views redraw


class MoveEstimate(QObject):
    """From a MoveStart, emits `estimated(x, y, z)` at ~30 Hz until stopped or at the target."""

    estimated = Signal(float, float, float)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._move: MoveStart | None = None
        self._timer = QTimer(self)
        self._timer.setInterval(ESTIMATE_INTERVAL_MS)
        self._timer.timeout.connect(self._tick)

    def start(self, move: MoveStart) -> None:
        """Estimate this move from now on."""
        self._move = move
        self._timer.start()

    def stop(self) -> None:
        """A measured position has come, or the move ended: no more estimates."""
        self._move = None
        self._timer.stop()

    def now(self) -> tuple[float, float, float] | None:
        """Where the move under way should be now (None: no move is being estimated)."""
        move = self._move
        return move.estimate(time.monotonic()) if move is not None else None

    def active(self) -> bool:
        """Whether a move is being estimated."""
        return self._move is not None

    def _tick(self) -> None:
        move = self._move
        if move is None:
            return
        now = time.monotonic()
        x, y, z = move.estimate(now)
        self.estimated.emit(x, y, z)
        if now >= move.started + move.duration:
            self._timer.stop()  # at the target: stay there until the device confirms it
