"""Behaviour shared by the position views: a refresh timer that runs only while visible."""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QTimer
from PySide6.QtGui import QHideEvent, QShowEvent

from widgets.position_buffer import PositionBuffer

REFRESH_INTERVAL_MS = 33  # ~30 Hz


class BufferedViewMixin:
    """For a QWidget subclass with `buffer`, `timer` and `refresh()`: list it before the Qt base."""

    buffer: PositionBuffer
    _target: tuple[float, float, float] | None

    def start_refresh_timer(self) -> None:
        """Create the timer that calls `refresh` at ~30 Hz while the view is shown."""
        self._seen_version = -1
        self.timer = QTimer(self)  # type: ignore[arg-type]
        self.timer.setInterval(REFRESH_INTERVAL_MS)
        self.timer.timeout.connect(self.refresh)

    def changed_rows(self) -> np.ndarray | None:
        """The buffer's rows if it changed since the last call, else None."""
        if self.buffer.version == self._seen_version:
            return None
        self._seen_version = self.buffer.version
        return self.buffer.view()

    def refresh(self) -> None:  # pragma: no cover - provided by the view
        """Redraw from the buffer."""
        raise NotImplementedError

    def target(self) -> tuple[float, float, float] | None:
        """The target shown, or None."""
        return self._target

    def clear_trail(self) -> None:
        """Empty the shared buffer except the newest position, and redraw."""
        self.buffer.clear(keep_last=True)
        self.refresh()

    def showEvent(self, event: QShowEvent) -> None:
        """Refresh periodically while visible."""
        super().showEvent(event)  # type: ignore[misc]
        self.refresh()
        self.timer.start()

    def hideEvent(self, event: QHideEvent) -> None:
        """No redrawing while hidden."""
        self.timer.stop()
        super().hideEvent(event)  # type: ignore[misc]
