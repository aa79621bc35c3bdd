"""The list of a program's lines (G-code lines, DXF entities, SVG elements, points) for the
Program panel: made as they are shown, so that a 100,000-line file lists at once."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from PySide6.QtCore import QAbstractListModel, QModelIndex, QObject, QPersistentModelIndex, Qt

from widgets._i18n import fill


class SourceLine(Protocol):
    """What the program list shows of a line (drivers.toolpath.Source)."""

    @property
    def kind(self) -> str:
        """ "line", "entity", "element" or "point"."""

    @property
    def number(self) -> int:
        """Its number in the file, from 1."""

    @property
    def text(self) -> str:
        """What it says."""


class ProgramLines(QAbstractListModel):
    """The program's lines ("line 12  G1 X10"), made as they are shown: a 100,000-line file
    lists at once."""

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._sources: Sequence[SourceLine] = ()
        self._labels: dict[str, str] = {}

    def set_sources(self, sources: Sequence[SourceLine], labels: dict[str, str]) -> None:
        """Show these lines; `labels`: per kind, its template ("line %1")."""
        self.beginResetModel()
        self._sources = sources
        self._labels = labels
        self.endResetModel()

    def rowCount(self, parent: QModelIndex | QPersistentModelIndex = QModelIndex()) -> int:  # noqa: B008
        """The lines (a list: no children)."""
        return 0 if parent.isValid() else len(self._sources)

    def columnCount(self, parent: QModelIndex | QPersistentModelIndex = QModelIndex()) -> int:  # noqa: B008
        """One column."""
        return 0 if parent.isValid() else 1

    def data(
        self, index: QModelIndex | QPersistentModelIndex, role: int = Qt.ItemDataRole.DisplayRole
    ) -> object:
        """A line's text."""
        if role != Qt.ItemDataRole.DisplayRole or not index.isValid():
            return None
        source = self._sources[index.row()]
        label = fill(self._labels.get(source.kind, "%1"), source.number)
        return f"{label}  {source.text}"
