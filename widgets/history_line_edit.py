"""A line edit that recalls earlier entries with Up and Down, like a shell."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QLineEdit, QWidget

DEFAULT_HISTORY = 200


class HistoryLineEdit(QLineEdit):
    """Up recalls the previous entry, Down the next one and finally the unsent draft."""

    def __init__(self, parent: QWidget | None = None, max_history: int = DEFAULT_HISTORY) -> None:
        super().__init__(parent)
        self._max = max_history
        self._history: list[str] = []
        self._index = 0  # == len(_history): editing the draft
        self._draft = ""
        self.textEdited.connect(self._edited)

    def history(self) -> list[str]:
        """The entries, oldest first."""
        return list(self._history)

    def add_history(self, text: str) -> None:
        """Remember an entry (not empty, not twice in a row) and go back to an empty draft."""
        if text and (not self._history or self._history[-1] != text):
            self._history.append(text)
            del self._history[: -self._max]
        self._index = len(self._history)
        self._draft = ""

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Up/Down walk the history; other keys edit."""
        if event.key() == Qt.Key.Key_Up:
            self._recall(-1)
        elif event.key() == Qt.Key.Key_Down:
            self._recall(1)
        else:
            super().keyPressEvent(event)

    def _recall(self, step: int) -> None:
        index = min(max(self._index + step, 0), len(self._history))
        if index == self._index:
            return
        if self._index == len(self._history):
            self._draft = self.text()
        self._index = index
        self.setText(self._history[index] if index < len(self._history) else self._draft)

    def _edited(self, text: str) -> None:
        self._index = len(self._history)
        self._draft = text
