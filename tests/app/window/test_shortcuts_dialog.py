"""Help → Keyboard shortcuts: the table shows what it is given, and the search filters it."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QLabel, QLineEdit, QTableView

from widgets.shortcuts_dialog import (
    ShortcutsDialog,
    keys_text,
    plain_action_text,
    shortcuts_from_actions,
)

pytestmark = pytest.mark.timeout(30)

SHORTCUTS = [
    ("←/→", "Jog X"),
    ("↑/↓", "Jog Y"),
    ("PgUp/PgDn", "Jog Z"),
    ("Shift+arrows", "Jog ten times the step"),
    (QKeySequence("Ctrl+H"), "Home"),
    (QKeySequence("F1"), "Keyboard shortcuts"),
]


def _dialog(qtbot, shortcuts=SHORTCUTS) -> ShortcutsDialog:
    dialog = ShortcutsDialog(shortcuts)
    qtbot.addWidget(dialog)
    return dialog


def test_lists_what_it_is_given_in_order(qtbot) -> None:
    dialog = _dialog(qtbot)
    assert dialog.objectName() == "shortcutsDialog"
    assert dialog.shortcuts() == [
        ("←/→", "Jog X"),
        ("↑/↓", "Jog Y"),
        ("PgUp/PgDn", "Jog Z"),
        ("Shift+arrows", "Jog ten times the step"),
        (QKeySequence("Ctrl+H").toString(QKeySequence.SequenceFormat.NativeText), "Home"),
        ("F1", "Keyboard shortcuts"),
    ]
    table = dialog.findChild(QTableView, "shortcutsTable")
    assert table.model().rowCount() == len(SHORTCUTS)
    assert table.model().index(0, 1).data() == "Jog X"


def test_search_filters_keys_and_descriptions_ignoring_case(qtbot) -> None:
    dialog = _dialog(qtbot)
    search = dialog.findChild(QLineEdit, "shortcutsFilter")
    qtbot.keyClicks(search, "JOG")
    assert [what for _, what in dialog.visible_shortcuts()] == [
        "Jog X",
        "Jog Y",
        "Jog Z",
        "Jog ten times the step",
    ]
    dialog.set_filter("pgup")
    assert dialog.visible_shortcuts() == [("PgUp/PgDn", "Jog Z")]
    assert search.text() == "pgup"
    dialog.set_filter("")
    assert len(dialog.visible_shortcuts()) == len(SHORTCUTS)


def test_no_match_says_so(qtbot) -> None:
    dialog = _dialog(qtbot)
    dialog.show()
    qtbot.waitExposed(dialog)
    empty = dialog.findChild(QLabel, "shortcutsEmpty")
    assert not empty.isVisible()
    dialog.set_filter("zzz")
    assert dialog.visible_shortcuts() == []
    assert empty.isVisible()
    assert "zzz" in empty.text()
    dialog.set_filter("")
    assert not empty.isVisible()


def test_replaced_and_empty(qtbot) -> None:
    dialog = _dialog(qtbot)
    dialog.set_shortcuts([("Esc", "Close")])
    assert dialog.shortcuts() == [("Esc", "Close")]
    dialog.set_shortcuts([])
    assert dialog.shortcuts() == []
    assert dialog.findChild(QLabel, "shortcutsEmpty").text()


def test_not_editable(qtbot) -> None:
    dialog = _dialog(qtbot)
    index = dialog.proxy.index(0, 1)
    assert not dialog.proxy.flags(index) & Qt.ItemFlag.ItemIsEditable


def test_keys_text() -> None:
    assert keys_text("Shift+←") == "Shift+←"
    assert keys_text(QKeySequence("F1")) == "F1"
    assert keys_text([QKeySequence("F5"), QKeySequence()]) == "F5"
    several = keys_text([QKeySequence("Ctrl+Q"), QKeySequence("F10")])
    assert several.endswith(", F10")
    assert keys_text(QKeySequence.StandardKey.HelpContents)  # F1 on most platforms


def test_plain_action_text() -> None:
    assert plain_action_text("&Home") == "Home"
    assert plain_action_text("Travel &limits…") == "Travel limits"
    assert plain_action_text("Save && quit...") == "Save & quit"


def test_shortcuts_from_actions(qtbot) -> None:
    dialog = _dialog(qtbot, [])
    home = QAction("&Home", dialog)
    home.setShortcut(QKeySequence("Ctrl+H"))
    plain = QAction("No shortcut", dialog)
    help_ = QAction("&Keyboard shortcuts…", dialog)
    help_.setShortcuts([QKeySequence("F1"), QKeySequence("Ctrl+?")])
    found = shortcuts_from_actions([home, plain, help_, home])
    assert [what for _, what in found] == ["Home", "Keyboard shortcuts"]
    dialog.set_shortcuts(found)
    assert dialog.shortcuts()[1][0].startswith("F1, ")
