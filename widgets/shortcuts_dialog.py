"""Help → Keyboard shortcuts: a searchable table of the (keys, what they do) pairs it is given."""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

from PySide6.QtCore import QSortFilterProxyModel, Qt
from PySide6.QtGui import QAction, QKeySequence, QStandardItem, QStandardItemModel
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDialog,
    QDialogButtonBox,
    QHeaderView,
    QLabel,
    QLineEdit,
    QTableView,
    QVBoxLayout,
    QWidget,
)

Keys = str | QKeySequence | QKeySequence.StandardKey | Sequence[QKeySequence]
KEYS_COLUMN = 0
ACTION_COLUMN = 1
_MNEMONIC = re.compile(r"&(&?)")


def keys_text(keys: Keys) -> str:
    """`keys` as shown: a string as it is (e.g. "←/→" or "Shift+arrows"), key sequences in the
    platform's native text, several joined with ", "."""
    if isinstance(keys, str):
        return keys
    if isinstance(keys, QKeySequence.StandardKey):
        keys = QKeySequence.keyBindings(keys)
    if isinstance(keys, QKeySequence):
        keys = [keys]
    return ", ".join(
        sequence.toString(QKeySequence.SequenceFormat.NativeText)
        for sequence in keys
        if not sequence.isEmpty()
    )


def plain_action_text(text: str) -> str:
    """A menu text without its mnemonic ("&Home" → "Home", "&&" → "&") and trailing "…"."""
    text = _MNEMONIC.sub(lambda match: match.group(1), text)
    return text.removesuffix("…").removesuffix("...").strip()


def shortcuts_from_actions(actions: Iterable[QAction]) -> list[tuple[Keys, str]]:
    """(shortcuts, plain text) of each action that has a shortcut, once each, in order."""
    found: list[tuple[Keys, str]] = []
    seen: set[tuple[str, str]] = set()
    for action in actions:
        sequences = [s for s in action.shortcuts() if not s.isEmpty()]
        if not sequences:
            continue
        what = plain_action_text(action.text())
        key = (keys_text(sequences), what)
        if key not in seen:
            seen.add(key)
            found.append((sequences, what))
    return found


class ShortcutsDialog(QDialog):
    """The shortcuts given, in their order, in a table that the search field filters (on the
    keys and the description, ignoring case)."""

    def __init__(
        self, shortcuts: Iterable[tuple[Keys, str]] = (), parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("shortcutsDialog")
        self.setWindowTitle(self.tr("Keyboard Shortcuts"))

        self.filter_edit = QLineEdit(self)
        self.filter_edit.setObjectName("shortcutsFilter")
        self.filter_edit.setPlaceholderText(self.tr("Search shortcuts…"))
        self.filter_edit.setClearButtonEnabled(True)
        self.filter_edit.setAccessibleName(self.tr("Search shortcuts"))

        self.model = QStandardItemModel(0, 2, self)
        self.model.setHorizontalHeaderLabels([self.tr("Keys"), self.tr("Action")])
        self.proxy = QSortFilterProxyModel(self)
        self.proxy.setSourceModel(self.model)
        self.proxy.setFilterKeyColumn(-1)  # any column
        self.proxy.setFilterCaseSensitivity(Qt.CaseSensitivity.CaseInsensitive)

        self.table = QTableView(self)
        self.table.setObjectName("shortcutsTable")
        self.table.setModel(self.proxy)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setAlternatingRowColors(True)
        self.table.setShowGrid(False)
        self.table.setWordWrap(False)
        self.table.verticalHeader().setVisible(False)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(KEYS_COLUMN, QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(ACTION_COLUMN, QHeaderView.ResizeMode.Stretch)

        self.empty_label = QLabel(self)
        self.empty_label.setObjectName("shortcutsEmpty")
        self.empty_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.empty_label.setVisible(False)

        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close, self)
        buttons.rejected.connect(self.reject)

        layout = QVBoxLayout(self)
        layout.addWidget(self.filter_edit)
        layout.addWidget(self.table, 1)
        layout.addWidget(self.empty_label)
        layout.addWidget(buttons)
        self.resize(520, 420)

        self.filter_edit.textChanged.connect(self.set_filter)
        self.set_shortcuts(shortcuts)

    def set_shortcuts(self, shortcuts: Iterable[tuple[Keys, str]]) -> None:
        """Show `shortcuts` ((keys, what they do) pairs, in that order) instead of the current."""
        self.model.removeRows(0, self.model.rowCount())
        for keys, what in shortcuts:
            keys_item = QStandardItem(keys_text(keys))
            what_item = QStandardItem(what)
            for item in (keys_item, what_item):
                item.setEditable(False)
            self.model.appendRow([keys_item, what_item])
        self._update_empty()

    def shortcuts(self) -> list[tuple[str, str]]:
        """Every (keys, what) row as shown, filtered out or not."""
        return [self._row(self.model, row) for row in range(self.model.rowCount())]

    def visible_shortcuts(self) -> list[tuple[str, str]]:
        """The (keys, what) rows the search leaves in the table."""
        return [self._row(self.proxy, row) for row in range(self.proxy.rowCount())]

    def set_filter(self, text: str) -> None:
        """Show only the rows whose keys or description contain `text` (any case)."""
        if self.filter_edit.text() != text:
            self.filter_edit.setText(text)  # comes back here through textChanged
            return
        self.proxy.setFilterFixedString(text.strip())
        self._update_empty()

    def _row(self, model: QStandardItemModel | QSortFilterProxyModel, row: int) -> tuple[str, str]:
        return (
            str(model.index(row, KEYS_COLUMN).data()),
            str(model.index(row, ACTION_COLUMN).data()),
        )

    def _update_empty(self) -> None:
        empty = self.proxy.rowCount() == 0
        if not empty:
            self.empty_label.setVisible(False)
            return
        text = self.filter_edit.text().strip()
        if text and self.model.rowCount():
            message = self.tr("No shortcut matches “%1”.").replace("%1", text)
        else:
            message = self.tr("No keyboard shortcuts.")
        self.empty_label.setText(message)
        self.empty_label.setVisible(True)
