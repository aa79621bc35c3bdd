"""Behaviour shared by the position views: a refresh timer that runs only while visible."""

from __future__ import annotations

from PySide6.QtGui import QHideEvent, QShowEvent

from widgets.position_buffer import PositionBuffer


class BufferedViewMixin:
    """For a QWidget subclass with `buffer`, `timer` and `refresh()`: list it before the Qt base."""

    buffer: PositionBuffer
    _target: tuple[float, float, float] | None

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
        self.timer.start()  # type: ignore[attr-defined]

    def hideEvent(self, event: QHideEvent) -> None:
        """No redrawing while hidden."""
        self.timer.stop()  # type: ignore[attr-defined]
        super().hideEvent(event)  # type: ignore[misc]
