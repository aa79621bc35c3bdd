"""SendLine on its own: modes, line endings, enabling, history reset after sending."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QEvent, Qt
from PySide6.QtGui import QAction, QKeyEvent, QKeySequence
from PySide6.QtWidgets import QLineEdit, QMainWindow

from widgets.send_line import WINDOW_SHORTCUTS, SendLine, pass_shortcuts_through


@pytest.fixture
def line(qtbot) -> SendLine:
    widget = SendLine()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def test_ending_follows_mode_and_enabling(line: SendLine) -> None:
    assert line.ending_combo.isEnabled()
    line.set_mode("hex")
    line.setEnabled(False)
    line.setEnabled(True)
    assert not line.ending_combo.isEnabled()  # no line ending in hex mode, even re-enabled
    line.set_mode("text")
    assert line.ending_combo.isEnabled()
    with pytest.raises(ValueError):
        line.set_mode("binary")
    with pytest.raises(ValueError):
        line.set_line_ending(b"\n\n")


def test_data_and_send(line: SendLine, qtbot, record) -> None:
    calls = record(line.send_requested)
    line.edit.setText("GET_ID")
    assert line.data() == b"GET_ID\n"
    qtbot.mouseClick(line.button, Qt.MouseButton.LeftButton)
    assert calls == [(b"GET_ID\n",)]
    assert line.edit.history() == ["GET_ID"]
    line.setEnabled(False)
    line.edit.setText("X")
    line.send()
    assert calls == [(b"GET_ID\n",)]


def test_ctrl_e_in_the_line_reaches_the_window_shortcut(qtbot) -> None:
    # Discriminating under X11 key bindings (xvfb-run: QLineEdit takes Ctrl+E as end of line);
    # on offscreen only End is end of line: see the next test for an edit that takes the key.
    window = QMainWindow()
    qtbot.addWidget(window)
    line = SendLine()
    window.setCentralWidget(line)
    export = QAction("Export traffic log", window)
    export.setShortcut(QKeySequence("Ctrl+E"))
    window.addAction(export)
    triggered: list[bool] = []
    export.triggered.connect(lambda: triggered.append(True))
    window.show()
    window.activateWindow()
    qtbot.waitActive(window)
    line.edit.setFocus()
    qtbot.waitUntil(line.edit.hasFocus, timeout=1000)
    line.edit.setText("GET_POSITION")
    line.edit.setCursorPosition(0)
    qtbot.keyClick(line.edit, Qt.Key.Key_E, Qt.KeyboardModifier.ControlModifier)
    assert triggered == [True]
    assert line.edit.cursorPosition() == 0  # not QLineEdit's "end of line"
    assert line.edit.text() == "GET_POSITION"
    qtbot.keyClick(line.edit, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)  # others as usual
    assert line.edit.selectedText() == "GET_POSITION"
    assert triggered == [True]


class _EmacsLineEdit(QLineEdit):
    """Takes Ctrl+E for itself as QLineEdit does with X11 key bindings (not on offscreen)."""

    def event(self, event: QEvent) -> bool:
        if (
            event.type() == QEvent.Type.ShortcutOverride
            and isinstance(event, QKeyEvent)
            and event.keyCombination() == QKeySequence("Ctrl+E")[0]
        ):
            event.accept()
            return True
        return super().event(event)


@pytest.mark.parametrize("passed", [False, True])
def test_pass_shortcuts_through_an_edit_that_takes_the_key(qtbot, passed: bool) -> None:
    window = QMainWindow()
    qtbot.addWidget(window)
    edit = _EmacsLineEdit()
    window.setCentralWidget(edit)
    if passed:
        pass_shortcuts_through(edit, WINDOW_SHORTCUTS)
    export = QAction("Export traffic log", window)
    export.setShortcut(QKeySequence("Ctrl+E"))
    window.addAction(export)
    triggered: list[bool] = []
    export.triggered.connect(lambda: triggered.append(True))
    window.show()
    window.activateWindow()
    qtbot.waitActive(window)
    edit.setFocus()
    qtbot.waitUntil(edit.hasFocus, timeout=1000)
    qtbot.keyClick(edit, Qt.Key.Key_E, Qt.KeyboardModifier.ControlModifier)
    assert triggered == ([True] if passed else [])  # without: the edit keeps the key
