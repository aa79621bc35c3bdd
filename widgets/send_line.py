"""The console's send line: text (with escapes and a line ending) or hex, with history."""

from __future__ import annotations

import logging
from collections.abc import Iterable

from PySide6.QtCore import QT_TRANSLATE_NOOP, QEvent, QObject, Signal
from PySide6.QtGui import QKeyEvent, QKeySequence
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QPushButton, QVBoxLayout, QWidget

from widgets import traffic_format as fmt
from widgets.history_line_edit import HistoryLineEdit

log = logging.getLogger(__name__)

TEXT, HEX = "text", "hex"
MODE_NAMES = {  # shown translated; the keys are what mode() returns
    TEXT: QT_TRANSLATE_NOOP("SendLine", "text"),
    HEX: QT_TRANSLATE_NOOP("SendLine", "hex"),
}
LINE_ENDINGS = {"LF (\\n)": b"\n", "CR (\\r)": b"\r", "CR+LF": b"\r\n", "none": b""}
ENDING_NAMES = {"none": QT_TRANSLATE_NOOP("SendLine", "none")}  # the others are not words
WINDOW_SHORTCUTS = ("Ctrl+E",)  # the window's "Export traffic log", not the edit's end of line


class ShortcutPassThrough(QObject):
    """Event filter: keys a line edit would keep for itself (e.g. emacs Ctrl+E) reach shortcuts.

    Qt first offers a key that matches a shortcut to the focus widget as a ShortcutOverride
    event; QLineEdit accepts Ctrl+E there (with X11 key bindings) and the shortcut never fires.
    Filtering that event out, unaccepted, lets Qt's shortcut map trigger the shortcut.
    """

    def __init__(self, keys: Iterable[str], parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._keys = [QKeySequence(key) for key in keys]

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Hide a ShortcutOverride for one of the keys from the widget (without accepting it)."""
        if event.type() == QEvent.Type.ShortcutOverride and isinstance(event, QKeyEvent):
            pressed = QKeySequence(event.keyCombination())
            if any(
                pressed.matches(key) == QKeySequence.SequenceMatch.ExactMatch for key in self._keys
            ):
                return True
        return False


def pass_shortcuts_through(widget: QWidget, keys: Iterable[str]) -> ShortcutPassThrough:
    """Let `keys` (like "Ctrl+E") reach the window's shortcuts while `widget` has focus."""
    passer = ShortcutPassThrough(keys, widget)
    widget.installEventFilter(passer)
    return passer


class SendLine(QWidget):
    """Type bytes to send; `send_requested(bytes)` on Enter or Send, or an error shown inline."""

    send_requested = Signal(object)  # bytes

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("consoleSendBar")
        self.edit = HistoryLineEdit()
        self.edit.setObjectName("consoleSendLine")
        self.edit.returnPressed.connect(self.send)
        self.edit.textEdited.connect(lambda _: self.show_error(""))
        pass_shortcuts_through(self.edit, WINDOW_SHORTCUTS)
        self.mode_combo = QComboBox()
        self.mode_combo.setObjectName("consoleSendMode")
        for mode, name in MODE_NAMES.items():
            self.mode_combo.addItem(self.tr(name), mode)
        self.mode_combo.setToolTip(
            self.tr(
                "text: UTF-8 with \\r \\n \\t \\0 \\\\ \\xNN escapes, plus the line ending;\n"
                "hex: bytes like 48 45 4C 4C 4F, sent as they are"
            )
        )
        self.mode_combo.currentIndexChanged.connect(self._mode_index_changed)
        self.ending_combo = QComboBox()
        self.ending_combo.setObjectName("consoleLineEnding")
        for ending in LINE_ENDINGS:
            self.ending_combo.addItem(
                self.tr(ENDING_NAMES[ending]) if ending in ENDING_NAMES else ending, ending
            )
        self.ending_combo.setToolTip(self.tr("Appended to every line sent in text mode"))
        self.button = QPushButton(self.tr("Send"))
        self.button.setObjectName("consoleSend")
        self.button.setToolTip(self.tr("Send the line to the device (Enter)"))
        self.button.clicked.connect(self.send)
        self.error_label = QLabel()
        self.error_label.setObjectName("consoleError")
        self.error_label.setStyleSheet("color: #c62828;")
        self.error_label.setVisible(False)

        row = QHBoxLayout()
        row.setContentsMargins(0, 0, 0, 0)
        label = QLabel(self.tr("Sen&d:"))  # Alt+D: the keyboard's way into the line
        label.setBuddy(self.edit)
        row.addWidget(label)
        row.addWidget(self.edit, 1)
        row.addWidget(self.mode_combo)
        row.addWidget(self.ending_combo)
        row.addWidget(self.button)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addLayout(row)
        layout.addWidget(self.error_label)
        self._mode_changed(TEXT)

    def mode(self) -> str:
        """How the line is read: `"text"` or `"hex"`."""
        return str(self.mode_combo.currentData())

    def set_mode(self, mode: str) -> None:
        """Read the line as text (with escapes and the line ending) or as hex bytes."""
        if mode not in (TEXT, HEX):
            raise ValueError(f"send mode must be 'text' or 'hex', not {mode!r}")
        self.mode_combo.setCurrentIndex(self.mode_combo.findData(mode))

    def set_line_ending(self, ending: bytes) -> None:
        """The bytes appended to a text line: b"\\n", b"\\r", b"\\r\\n" or b""."""
        names = {value: name for name, value in LINE_ENDINGS.items()}
        if ending not in names:
            raise ValueError(f"unsupported line ending {ending!r}")
        self.ending_combo.setCurrentIndex(self.ending_combo.findData(names[ending]))

    def _mode_index_changed(self, _index: int) -> None:
        self._mode_changed(self.mode())

    def _mode_changed(self, mode: str) -> None:
        self.ending_combo.setEnabled(mode == TEXT)
        if mode == HEX:
            hint = self.tr("hex bytes, e.g. 48 45 4C 4C 4F (Up/Down: history)")
        else:
            hint = self.tr("text to send (Up/Down: history)")
        self.edit.setPlaceholderText(hint)
        self.show_error("")

    def data(self) -> bytes:
        """The bytes the line stands for; raises ValueError saying what is wrong."""
        text = self.edit.text()
        if self.mode() == HEX:
            data = fmt.parse_hex(text)
        else:
            data = fmt.unescape(text) + LINE_ENDINGS[str(self.ending_combo.currentData())]
        if not data:
            raise ValueError(self.tr("nothing to send"))
        return data

    def send(self) -> None:
        """Emit `send_requested` with the line's bytes, or show what is wrong with it."""
        if not self.isEnabled():
            return
        try:
            data = self.data()
        except ValueError as exc:
            self.show_error(str(exc))
            return
        self.show_error("")
        self.edit.add_history(self.edit.text())
        self.edit.clear()
        log.debug("send requested: %r", data)
        self.send_requested.emit(data)

    def show_error(self, message: str) -> None:
        """Show a problem under the line ("" hides it)."""
        self.error_label.setText(message)
        self.error_label.setVisible(bool(message))
