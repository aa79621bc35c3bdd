"""The Settings dialog: its fields, live validation, Restore defaults, OK/Apply and its size."""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import pytest
from PySide6.QtCore import Qt, QTranslator
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import (
    QAbstractButton,
    QAbstractSpinBox,
    QComboBox,
    QDialog,
    QDoubleSpinBox,
    QGroupBox,
    QKeySequenceEdit,
    QLabel,
    QLineEdit,
    QPushButton,
    QSpinBox,
    QTabWidget,
    QWidget,
)

from app.window.preferences import DEFAULTS, Preferences
from widgets.settings_dialog import OBJECT_NAMES, SettingsDialog

pytestmark = pytest.mark.timeout(30)

NAMES = (
    "pollMovingHz",
    "pollIdleS",
    "consoleLines",
    "sessionLog",
    "logFolder",
    "unitsShown",
    "decimalsShown",
    "clampToLimits",
    "jogKeyXMinus",
    "jogKeyXPlus",
    "jogKeyYMinus",
    "jogKeyYPlus",
    "jogKeyZMinus",
    "jogKeyZPlus",
    "jogKeyStepSmaller",
    "jogKeyStepLarger",
    "theme",
    "language",
)
KEY_EDITS = {name for name in NAMES if name.startswith("jogKey")} | {""}
OTHERS = "pollMovingHz pollIdleS consoleLines decimalsShown"
CHANGED = dataclasses.replace(
    DEFAULTS,
    poll_moving_hz=15.0,
    poll_idle_s=2.5,
    console_max_lines=200_000,
    session_log=False,
    units="in",
    decimals=4,
    clamp_to_limits=True,
    jog_key_x_minus="A",
    jog_key_step_larger="",
    theme="dark",
    language="fr",
)


@pytest.fixture
def dialog(qtbot) -> SettingsDialog:
    """A dialog on the default preferences."""
    widget = SettingsDialog(DEFAULTS, default_log_folder="/var/log/motionpanel")
    qtbot.addWidget(widget)
    return widget


def _child(dialog: QDialog, name: str) -> QWidget:
    found = dialog.findChild(QWidget, name)
    assert found is not None, name
    return found


def _ok(dialog: QDialog) -> QPushButton:
    button = _child(dialog, "settingsOk")
    assert isinstance(button, QPushButton)
    return button


def _problem(dialog: QDialog) -> str:
    label = _child(dialog, "settingsProblem")
    assert isinstance(label, QLabel)
    return label.text()


def test_every_field_has_its_name_a_tooltip_and_its_unit(dialog: SettingsDialog) -> None:
    assert dialog.objectName() == "settingsDialog"
    assert set(OBJECT_NAMES.values()) == set(NAMES)
    assert set(OBJECT_NAMES) == {f.name for f in dataclasses.fields(Preferences)}
    for name in (*NAMES, "logFolderBrowse", "settingsDefaults", "settingsApply", "settingsOk"):
        assert _child(dialog, name).toolTip(), name
    suffixes = {name: _child(dialog, name) for name in OTHERS.split()}
    assert suffixes["pollMovingHz"].suffix() == " Hz"  # type: ignore[attr-defined]
    assert suffixes["pollIdleS"].suffix() == " s"  # type: ignore[attr-defined]
    assert suffixes["consoleLines"].suffix() == " lines"  # type: ignore[attr-defined]
    assert "5 to 20 Hz" in _child(dialog, "pollMovingHz").toolTip()
    assert "0.2 to 10 s" in _child(dialog, "pollIdleS").toolTip()
    for name in NAMES:
        if name.startswith("jogKey"):
            assert isinstance(_child(dialog, name), QKeySequenceEdit)


def test_the_fields_show_the_preferences_given(qtbot) -> None:
    dialog = SettingsDialog(CHANGED)
    qtbot.addWidget(dialog)
    assert dialog.preferences() == CHANGED
    assert _ok(dialog).isEnabled() and _problem(dialog) == ""
    lines = _child(dialog, "consoleLines")
    assert isinstance(lines, QSpinBox) and lines.value() == 200_000
    decimals = _child(dialog, "decimalsShown")
    assert isinstance(decimals, QSpinBox) and decimals.value() == 4
    key = _child(dialog, "jogKeyXMinus")
    assert isinstance(key, QKeySequenceEdit) and key.keySequence().toString() == "A"


def test_special_values_are_words(dialog: SettingsDialog) -> None:
    lines, decimals = _child(dialog, "consoleLines"), _child(dialog, "decimalsShown")
    assert isinstance(lines, QSpinBox) and isinstance(decimals, QSpinBox)
    assert lines.text() == "Keep every line"
    assert decimals.text() == "As the device resolves"


def test_a_duplicate_key_disables_ok_and_says_why(dialog: SettingsDialog) -> None:
    key = _child(dialog, "jogKeyXPlus")
    assert isinstance(key, QKeySequenceEdit)
    key.setKeySequence(QKeySequence("Left"))
    assert not _ok(dialog).isEnabled()
    assert not _child(dialog, "settingsApply").isEnabled()
    assert _problem(dialog) == "Jog key X+: Left is already Jog key X-"
    assert key.styleSheet()  # marked
    key.setKeySequence(QKeySequence("D"))
    assert _ok(dialog).isEnabled() and _problem(dialog) == ""
    assert not key.styleSheet()
    assert dialog.preferences().jog_key_x_plus == "D"


def test_a_reserved_key_disables_ok(dialog: SettingsDialog) -> None:
    key = _child(dialog, "jogKeyZPlus")
    assert isinstance(key, QKeySequenceEdit)
    key.setKeySequence(QKeySequence(Qt.Key.Key_Escape))
    assert not _ok(dialog).isEnabled()
    assert "Stop" in _problem(dialog)


def test_console_lines_between_zero_and_the_minimum_are_refused(dialog: SettingsDialog) -> None:
    lines = _child(dialog, "consoleLines")
    assert isinstance(lines, QSpinBox)
    lines.setValue(5_000)
    assert not _ok(dialog).isEnabled()
    assert "Console lines kept: 5,000 lines is out of range" in _problem(dialog)
    lines.setValue(50_000)
    assert _ok(dialog).isEnabled()
    assert "1.6 MB" in _child(dialog, "consoleMemory").text()  # type: ignore[attr-defined]


def test_a_log_folder_that_is_not_a_folder_disables_ok(
    dialog: SettingsDialog, tmp_path: Path
) -> None:
    folder = _child(dialog, "logFolder")
    assert isinstance(folder, QLineEdit)
    assert "/var/log/motionpanel" in folder.placeholderText()
    a_file = tmp_path / "notes.txt"
    a_file.write_text("x")
    folder.setText(str(a_file))
    assert not _ok(dialog).isEnabled()
    assert "it is not a folder" in _problem(dialog)
    folder.setText(str(tmp_path))
    assert _ok(dialog).isEnabled()
    assert dialog.preferences().log_folder == str(tmp_path)


def test_browse_puts_the_chosen_folder_in_the_field(
    qtbot, dialog: SettingsDialog, tmp_path: Path
) -> None:
    asked: list[str] = []
    dialog.ask_folder = lambda start: asked.append(start) or str(tmp_path)
    qtbot.mouseClick(_child(dialog, "logFolderBrowse"), Qt.MouseButton.LeftButton)
    assert asked == [""]
    assert dialog.preferences().log_folder == str(tmp_path)
    dialog.ask_folder = lambda start: ""  # cancelled: unchanged
    qtbot.mouseClick(_child(dialog, "logFolderBrowse"), Qt.MouseButton.LeftButton)
    assert dialog.preferences().log_folder == str(tmp_path)


def test_a_number_being_typed_out_of_range_disables_ok(qtbot, dialog: SettingsDialog) -> None:
    spin = _child(dialog, "pollMovingHz")
    assert isinstance(spin, QDoubleSpinBox)
    spin.setFocus()
    spin.selectAll()
    qtbot.keyClicks(spin, "3")
    assert spin.text() == "3 Hz" and not spin.hasAcceptableInput()
    assert not _ok(dialog).isEnabled()
    assert _problem(dialog) == "Poll while moving: 3 is not a number from 5 to 20 Hz"
    qtbot.keyClicks(spin, "2")  # 32: still out of range
    assert not _ok(dialog).isEnabled()
    spin.selectAll()
    qtbot.keyClicks(spin, "12")
    assert _ok(dialog).isEnabled()
    assert dialog.preferences().poll_moving_hz == 12.0


def test_spin_boxes_keep_to_the_ranges(dialog: SettingsDialog) -> None:
    for name, low, high in (("pollMovingHz", 5, 20), ("pollIdleS", 0.2, 10)):
        spin = _child(dialog, name)
        assert isinstance(spin, QAbstractSpinBox)
        assert (spin.minimum(), spin.maximum()) == (low, high)  # type: ignore[attr-defined]


def test_restore_defaults_resets_the_fields_without_applying(qtbot, record) -> None:
    dialog = SettingsDialog(CHANGED)
    qtbot.addWidget(dialog)
    applied = record(dialog.applied)
    qtbot.mouseClick(_child(dialog, "settingsDefaults"), Qt.MouseButton.LeftButton)
    assert dialog.preferences() == DEFAULTS
    assert applied == []
    assert dialog.result() == QDialog.DialogCode.Rejected  # still open, nothing accepted


def test_apply_and_ok_emit_the_new_preferences(qtbot, dialog: SettingsDialog, record) -> None:
    applied = record(dialog.applied)
    dialog.set_preferences(CHANGED)
    qtbot.mouseClick(_child(dialog, "settingsApply"), Qt.MouseButton.LeftButton)
    assert applied == [(CHANGED,)]
    assert isinstance(applied[0][0], Preferences)
    theme = _child(dialog, "theme")
    theme.setCurrentIndex(theme.findData("light"))  # type: ignore[attr-defined]
    qtbot.mouseClick(_ok(dialog), Qt.MouseButton.LeftButton)
    assert applied[-1] == (dataclasses.replace(CHANGED, theme="light"),)
    assert dialog.result() == QDialog.DialogCode.Accepted


def test_cancel_emits_nothing(qtbot, dialog: SettingsDialog, record) -> None:
    applied = record(dialog.applied)
    qtbot.mouseClick(_child(dialog, "settingsCancel"), Qt.MouseButton.LeftButton)
    assert applied == []
    assert dialog.result() == QDialog.DialogCode.Rejected


def test_ok_does_nothing_while_invalid(dialog: SettingsDialog, record) -> None:
    applied = record(dialog.applied)
    key = _child(dialog, "jogKeyYPlus")
    assert isinstance(key, QKeySequenceEdit)
    key.setKeySequence(QKeySequence("Down"))
    _ok(dialog).click()  # disabled: no click
    assert applied == []


def test_choices_offer_every_value(dialog: SettingsDialog) -> None:
    for name, values in (
        ("unitsShown", ["mm", "in"]),
        ("theme", ["system", "light", "dark"]),
        ("language", ["system", "en", "es", "fr", "zh_CN"]),
    ):
        combo = _child(dialog, name)
        got = [combo.itemData(i) for i in range(combo.count())]  # type: ignore[attr-defined]
        assert got == values


def test_it_fits_a_1024_by_640_screen(qtbot, dialog: SettingsDialog) -> None:
    for hint in (dialog.minimumSizeHint(), dialog.sizeHint()):
        assert hint.width() <= 1024 and hint.height() <= 640, hint
    dialog.show()
    qtbot.waitExposed(dialog)
    for index in range(dialog.tabs.count()):
        dialog.tabs.setCurrentIndex(index)
        assert dialog.tabs.currentWidget().isVisible()
    assert dialog.width() <= 1024 and dialog.height() <= 640


class Bracketing(QTranslator):
    """Translates every string into [[string]], so what was not translated shows."""

    def translate(
        self, context: str, source: str, disambiguation: str | None = None, n: int = -1
    ) -> str:
        return f"[[{source}]]" if source else ""

    def isEmpty(self) -> bool:
        return False


def _outside_brackets(text: str) -> str:
    """`text` without its [[translated]] parts (innermost first: messages nest them)."""
    while True:
        shorter = re.sub(r"\[\[[^\[\]]*\]\]", " ", text)
        if shorter == text:
            return text
        text = shorter


def _shown(root: QWidget) -> list[tuple[str, str]]:
    found = []
    for widget in [root, *root.findChildren(QWidget)]:
        texts = [widget.toolTip()]
        if isinstance(widget, QLabel | QAbstractButton):
            texts.append(widget.text())
        if isinstance(widget, QGroupBox):
            texts.append(widget.title())
        if isinstance(widget, QLineEdit):
            texts.append(widget.placeholderText())
        if isinstance(widget, QComboBox):
            texts += [widget.itemText(i) for i in range(widget.count())]
        if isinstance(widget, QSpinBox | QDoubleSpinBox):
            texts += [widget.suffix(), widget.specialValueText()]
        if isinstance(widget, QTabWidget):
            texts += [widget.tabText(i) for i in range(widget.count())]
        found += [(widget.objectName(), text) for text in texts if text]
    return found


def test_every_word_shown_goes_through_translation(qtbot, qapp) -> None:
    translator = Bracketing()
    qapp.installTranslator(translator)
    try:
        dialog = SettingsDialog(DEFAULTS)
        qtbot.addWidget(dialog)
        key = _child(dialog, "jogKeyXPlus")
        key.setKeySequence(QKeySequence("Left"))  # type: ignore[attr-defined]
        lines = _child(dialog, "consoleLines")
        lines.setValue(5_000)  # type: ignore[attr-defined]
        shown = _shown(dialog)
        assert dialog.windowTitle() == "[[Settings]]"
        left = [
            (where, text)
            for where, text in shown
            if re.search(r"[A-Za-z]{2,}", _outside_brackets(text))
            and where not in KEY_EDITS  # the keys themselves: Left, PgUp...
        ]
        assert left == []
        assert "[[Jog key %1]]" not in _problem(dialog)
        assert "[[%1: %2 is already %3]]" not in _problem(dialog)  # filled, then shown
        assert _problem(dialog).startswith("[[")
    finally:
        qapp.removeTranslator(translator)
