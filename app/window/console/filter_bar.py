"""The traffic console's filters and search bar: which lines are shown (direction, kind, a
regular expression) and which are highlighted (a search, stepped through with F3).

A filter or search typed is applied when typing pauses: a million lines are not filtered again
at every key. The strings are in the console's translation context (RawConsole).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QObject, Qt, QTimer, Signal
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import QCheckBox, QLineEdit, QMenu, QPushButton, QToolButton, QWidget

from app.common.messages import localized
from app.window.console.table import KIND_NAMES
from drivers.traffic.lines import KINDS
from drivers.traffic.search import FilterError, compile_filter

TYPING_PAUSE_MS = 250  # a filter or search is applied this long after the last key
HIDDEN_BY_DEFAULT = ("poll",)
_BAD = "color: #c62828;"


class TrafficFilterBar(QObject):
    """The filter and search widgets of a console (`parent`, which lays them out), and the
    filters they make: `directions`, `kinds`, `pattern` and the `search` pattern."""

    filters_changed = Signal()  # directions, kinds or pattern: the lines shown change
    search_changed = Signal()  # a new search pattern: the lines highlighted change
    find_requested = Signal(bool)  # go to the next match (True) or the previous one (False)

    def __init__(self, parent: QWidget) -> None:
        super().__init__(parent)
        self.pattern = None
        self.search = None
        self.pattern_text = self.search_text = ""
        self.kinds = {k for k in KINDS if k not in HIDDEN_BY_DEFAULT}
        self.directions = {"tx", "rx", ""}
        self.typing = QTimer(self)  # a million lines are not filtered again at every key
        self.typing.setObjectName("consoleTypingTimer")
        self.typing.setSingleShot(True)
        self.typing.setInterval(TYPING_PAUSE_MS)
        self.typing.timeout.connect(self.typed)
        self._build_filters()
        self._build_search(parent)

    def _check(self, text: str, name: str, tip: str) -> QCheckBox:
        box = QCheckBox(text)
        box.setObjectName(name)
        box.setChecked(True)
        box.setToolTip(tip)
        box.toggled.connect(self._filters_changed)
        return box

    def _build_filters(self) -> None:
        self.tx_check = self._check(
            QCoreApplication.translate("RawConsole", "TX"),
            "consoleShowTx",
            QCoreApplication.translate("RawConsole", "Show what was sent to the device"),
        )
        self.rx_check = self._check(
            QCoreApplication.translate("RawConsole", "RX"),
            "consoleShowRx",
            QCoreApplication.translate("RawConsole", "Show what the device sent"),
        )
        self.kind_button = QToolButton()
        self.kind_button.setObjectName("consoleKinds")
        self.kind_button.setText(QCoreApplication.translate("RawConsole", "Kinds"))
        self.kind_button.setToolTip(
            QCoreApplication.translate("RawConsole", "Which kinds of lines to show")
        )
        self.kind_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        menu = QMenu(self.kind_button)
        self.kind_actions = {}
        for kind in KINDS:
            name = KIND_NAMES.get(kind, kind)
            action = menu.addAction(QCoreApplication.translate("RawConsole", name))
            action.setCheckable(True)
            action.setChecked(kind in self.kinds)
            action.setObjectName(f"consoleKind_{kind}")
            action.toggled.connect(self._kinds_changed)
            self.kind_actions[kind] = action
        self.kind_button.setMenu(menu)
        self.poll_check = QCheckBox(QCoreApplication.translate("RawConsole", "Poll"))
        self.poll_check.setObjectName("consoleShowPoll")
        self.poll_check.setToolTip(
            QCoreApplication.translate(
                "RawConsole",
                "Show the idle position queries and their replies"
                " (hidden by default; counted below)",
            )
        )
        self.poll_check.toggled.connect(self.kind_actions["poll"].setChecked)
        self.filter_edit = QLineEdit()
        self.filter_edit.setObjectName("consoleFilter")
        self.filter_edit.setPlaceholderText(
            QCoreApplication.translate("RawConsole", "filter (regex)")
        )
        self.filter_edit.setClearButtonEnabled(True)
        self.filter_edit.setMinimumWidth(80)
        self.filter_edit.setToolTip(
            QCoreApplication.translate(
                "RawConsole",
                "Show only lines matching this regular expression (case-insensitive) in their "
                "direction, kind, hex, text or meaning, e.g. error|FA00",
            )
        )
        self.filter_edit.textChanged.connect(self.typing.start)  # applied when typing pauses

    def _build_search(self, shortcuts_on: QWidget) -> None:
        self.search_edit = QLineEdit()
        self.search_edit.setObjectName("consoleSearch")
        self.search_edit.setPlaceholderText(
            QCoreApplication.translate("RawConsole", "search (regex)")
        )
        self.search_edit.setClearButtonEnabled(True)
        self.search_edit.setMinimumWidth(80)
        self.search_edit.setToolTip(
            QCoreApplication.translate(
                "RawConsole", "Highlight matching lines; Enter or F3: next, Shift+F3: previous"
            )
        )
        self.search_edit.textChanged.connect(self.typing.start)
        self.search_edit.returnPressed.connect(lambda: self.find_requested.emit(True))
        self.previous_button = QPushButton("◀")
        self.previous_button.setObjectName("consoleSearchPrevious")
        self.previous_button.setToolTip(
            QCoreApplication.translate("RawConsole", "Previous match (Shift+F3)")
        )
        self.previous_button.clicked.connect(lambda: self.find_requested.emit(False))
        self.next_button = QPushButton("▶")
        self.next_button.setObjectName("consoleSearchNext")
        self.next_button.setToolTip(QCoreApplication.translate("RawConsole", "Next match (F3)"))
        self.next_button.clicked.connect(lambda: self.find_requested.emit(True))
        for button in (self.previous_button, self.next_button):
            button.setMaximumWidth(32)
        for keys, forward in (("F3", True), ("Shift+F3", False)):
            QShortcut(
                QKeySequence(keys),
                shortcuts_on,
                lambda forward=forward: self.find_requested.emit(forward),
                context=Qt.ShortcutContext.WidgetWithChildrenShortcut,
            )

    # -- filters -----------------------------------------------------------------------------

    def typed(self) -> None:
        """The filter or search text stopped changing: apply what changed."""
        self.typing.stop()
        if self.filter_edit.text() != self.pattern_text:
            self._filters_changed()
        if self.search_edit.text() != self.search_text:
            self._search_changed(self.search_edit.text())

    def apply_typing(self) -> None:
        """Apply a filter or search still being typed, now."""
        if self.typing.isActive():
            self.typed()

    def _kinds_changed(self) -> None:
        self.kinds = {kind for kind, action in self.kind_actions.items() if action.isChecked()}
        self.poll_check.blockSignals(True)
        self.poll_check.setChecked("poll" in self.kinds)
        self.poll_check.blockSignals(False)
        self.filters_changed.emit()

    def _filters_changed(self) -> None:
        self.pattern_text = self.filter_edit.text()
        try:
            self.pattern = compile_filter(self.pattern_text)
        except FilterError as exc:
            self.filter_edit.setStyleSheet(_BAD)
            self.filter_edit.setToolTip(localized(exc))
            return
        self.filter_edit.setStyleSheet("")
        self.directions = {
            d for d, box in (("tx", self.tx_check), ("rx", self.rx_check)) if box.isChecked()
        }
        self.directions.add("")
        self.filters_changed.emit()

    def set_filter(
        self,
        pattern: str | None = None,
        directions: set[str] | None = None,
        kinds: set[str] | None = None,
    ) -> None:
        """Set the filters (None: leave as is); raises FilterError for a bad expression."""
        if pattern is not None:
            compile_filter(pattern)
            self.filter_edit.setText(pattern)
            self.typed()
        if directions is not None:
            self.tx_check.setChecked("tx" in directions)
            self.rx_check.setChecked("rx" in directions)
        if kinds is not None:
            for kind, action in self.kind_actions.items():
                action.setChecked(kind in kinds)

    def show_kind(self, kind: str) -> None:
        """Show the lines of `kind` (a line of a hidden kind is to be shown)."""
        self.kind_actions[kind].setChecked(True)

    # -- search ------------------------------------------------------------------------------

    def _search_changed(self, text: str) -> None:
        self.search_text = text
        try:
            self.search = compile_filter(text)
        except FilterError as exc:
            self.search_edit.setStyleSheet(_BAD)
            self.search_edit.setToolTip(localized(exc))
            return
        self.search_edit.setStyleSheet("")
        self.search_changed.emit()

    def set_search(self, text: str) -> None:
        """Search for `text` (a regex) at once."""
        self.search_edit.setText(text)
        self.typed()
