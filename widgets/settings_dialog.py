"""The Settings dialog: polling, console and session log, display, jog keys, theme and language.

It edits a frozen preferences dataclass (app.window.preferences.Preferences; widgets import no
app, so it is used by its shape): each field's metadata `spec` gives its range or choices,
`field_problems()` checks it, the class called with no arguments gives the defaults. Problems
are shown as you type and OK stays disabled while there are any; OK and Apply emit `applied`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import Any

from PySide6.QtCore import QCoreApplication, Qt, Signal
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import (
    QAbstractSpinBox,
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDoubleSpinBox,
    QFileDialog,
    QFormLayout,
    QGroupBox,
    QHBoxLayout,
    QKeySequenceEdit,
    QLabel,
    QLineEdit,
    QPushButton,
    QScrollArea,
    QSpinBox,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from widgets._i18n import fill
from widgets._number_field import NumberSpinBox, TypedNumber, WholeSpinBox, mark_invalid

CONSOLE_BYTES_PER_LINE = 33  # the console's memory per line (drivers/traffic/index.py)
PORTABLE = QKeySequence.SequenceFormat.PortableText
INVALID_STYLE = "border: 1px solid #c62828;"
# field -> objectName of its control
OBJECT_NAMES = {
    "poll_moving_hz": "pollMovingHz",
    "poll_idle_s": "pollIdleS",
    "console_max_lines": "consoleLines",
    "session_log": "sessionLog",
    "log_folder": "logFolder",
    "units": "unitsShown",
    "decimals": "decimalsShown",
    "clamp_to_limits": "clampToLimits",
    "jog_key_x_minus": "jogKeyXMinus",
    "jog_key_x_plus": "jogKeyXPlus",
    "jog_key_y_minus": "jogKeyYMinus",
    "jog_key_y_plus": "jogKeyYPlus",
    "jog_key_z_minus": "jogKeyZMinus",
    "jog_key_z_plus": "jogKeyZPlus",
    "jog_key_step_smaller": "jogKeyStepSmaller",
    "jog_key_step_larger": "jogKeyStepLarger",
    "theme": "theme",
    "language": "language",
}


class SettingsDialog(QDialog):
    """Edit the preferences; `preferences()` is what the fields say, `applied` the accepted."""

    applied = Signal(object)  # the new preferences (same class as given), on OK or Apply

    def __init__(
        self, prefs: Any, parent: QWidget | None = None, *, default_log_folder: str = ""
    ) -> None:
        super().__init__(parent)
        self.setObjectName("settingsDialog")
        self.setWindowTitle(self.tr("Settings"))
        self._initial = prefs
        self._defaults = type(prefs)()
        self._specs = {f.name: f.metadata.get("spec") for f in dataclasses.fields(prefs)}
        self._default_log_folder = default_log_folder
        self.ask_folder: Callable[[str], str] = self._ask_folder  # tests replace it
        self.fields: dict[str, QWidget] = {}
        self._loading = False

        self.tabs = QTabWidget(self)
        self.tabs.setObjectName("settingsTabs")
        self.tabs.addTab(self._page(self._polling_group()), self.tr("Connection"))
        self.tabs.addTab(
            self._page(self._console_group(), self._log_group()), self.tr("Console && log")
        )
        self.tabs.addTab(
            self._page(self._display_group(), self._limits_group()), self.tr("Display")
        )
        self.tabs.addTab(self._page(self._keys_group()), self.tr("Keyboard jog"))
        self.tabs.addTab(self._page(self._looks_group()), self.tr("Appearance && language"))
        # Every tab's title whole, in any language: the dialog is as wide as the tabs need.
        self.tabs.setElideMode(Qt.TextElideMode.ElideNone)
        self.tabs.setUsesScrollButtons(False)

        self.problem_label = QLabel()
        self.problem_label.setObjectName("settingsProblem")
        self.problem_label.setWordWrap(True)
        self.problem_label.setStyleSheet("color: #c62828;")
        buttons = QDialogButtonBox.StandardButton
        self.buttons = QDialogButtonBox(
            buttons.RestoreDefaults | buttons.Ok | buttons.Cancel | buttons.Apply, self
        )
        self.ok_button = self._named_button(buttons.Ok, "settingsOk", self.tr("Use and save"))
        self.apply_button = self._named_button(
            buttons.Apply, "settingsApply", self.tr("Use and save, and keep this open")
        )
        self.defaults_button = self._named_button(
            buttons.RestoreDefaults,
            "settingsDefaults",
            self.tr("Put every field back to its default (saved only with OK or Apply)"),
        )
        self._named_button(buttons.Cancel, "settingsCancel", self.tr("Close without saving"))
        self.ok_button.clicked.connect(self._ok)
        self.apply_button.clicked.connect(self._apply)
        self.defaults_button.clicked.connect(self.restore_defaults)
        self.buttons.rejected.connect(self.reject)

        layout = QVBoxLayout(self)
        layout.addWidget(self.tabs, 1)
        layout.addWidget(self.problem_label)
        layout.addWidget(self.buttons)
        self.set_preferences(prefs)
        self.resize(620, 460)

    # -- building ------------------------------------------------------------------------------
    def _page(self, *groups: QWidget) -> QScrollArea:
        """A tab's page: its groups, scrolled when the screen is small."""
        inner = QWidget()
        column = QVBoxLayout(inner)
        for group in groups:
            column.addWidget(group)
        column.addStretch(1)
        scroll = QScrollArea()
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QScrollArea.Shape.NoFrame)
        scroll.setWidget(inner)
        return scroll

    def _group(self, title: str, name: str) -> tuple[QGroupBox, QFormLayout]:
        group = QGroupBox(title)
        group.setObjectName(name)
        form = QFormLayout(group)
        form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.ExpandingFieldsGrow)
        return group, form

    def _register(self, name: str, widget: QWidget, tip: str) -> QWidget:
        widget.setObjectName(OBJECT_NAMES[name])
        widget.setToolTip(tip)
        self.fields[name] = widget
        if isinstance(widget, QAbstractSpinBox):
            widget.textChanged.connect(self._changed)  # type: ignore[attr-defined]
            widget.lineEdit().textChanged.connect(self._changed)  # also what is half typed
        elif isinstance(widget, QCheckBox):
            widget.toggled.connect(self._changed)
        elif isinstance(widget, QLineEdit):
            widget.textChanged.connect(self._changed)
        elif isinstance(widget, QComboBox):
            widget.currentIndexChanged.connect(self._changed)
        elif isinstance(widget, QKeySequenceEdit):
            widget.keySequenceChanged.connect(self._changed)
        return widget

    def _label(self, name: str) -> str:
        """The field's label as the preferences' messages name it (their translation)."""
        return QCoreApplication.translate("Preferences", self._specs[name].label)

    def _unit(self, name: str) -> str:
        return QCoreApplication.translate("Preferences", self._specs[name].unit)

    def _range(self, name: str) -> tuple[float, float]:
        spec = self._specs[name]
        low, high = spec.low, spec.high
        if spec.special is not None:
            low = min(low, spec.special)
        return low, high

    def _double(self, name: str, suffix: str, tip: str) -> QDoubleSpinBox:
        spin = NumberSpinBox()
        spin.set_what(self._label(name))
        spin.setDecimals(2)
        spin.setRange(*self._range(name))
        spin.setSingleStep(1.0 if self._specs[name].high > 10 else 0.1)
        spin.setSuffix(suffix)
        spin.setAccelerated(True)
        self._register(name, spin, tip)
        return spin

    def _integer(self, name: str, suffix: str, special: str, step: int, tip: str) -> QSpinBox:
        spin = WholeSpinBox()
        spin.set_what(self._label(name))
        low, high = self._range(name)
        spin.setRange(int(low), int(high))
        spin.setSingleStep(step)
        spin.setSuffix(suffix)
        spin.setSpecialValueText(special)
        spin.setGroupSeparatorShown(True)
        spin.setAccelerated(True)
        self._register(name, spin, tip)
        return spin

    def _combo(self, name: str, labels: dict[str, str], tip: str) -> QComboBox:
        combo = QComboBox()
        for value in self._specs[name].choices:
            combo.addItem(labels.get(value, value), value)
        self._register(name, combo, tip)
        return combo

    def _note(self, text: str) -> QLabel:
        note = QLabel(text)
        note.setWordWrap(True)
        note.setStyleSheet("color: palette(placeholder-text);")
        return note

    def _polling_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Position polling"), "pollingGroup")
        low, high = self._range("poll_moving_hz")
        moving = self._double(
            "poll_moving_hz",
            self.tr(" Hz"),
            fill(
                self.tr(
                    "How often the position is read while a move is being confirmed, in hertz "
                    "(%1 to %2 Hz). Faster confirms the end of each jog step sooner; above 20 Hz "
                    "nothing is seen sooner."
                ),
                f"{low:g}",
                f"{high:g}",
            ),
        )
        form.addRow(self.tr("Poll while moving:"), moving)
        low, high = self._range("poll_idle_s")
        idle = self._double(
            "poll_idle_s",
            self.tr(" s"),
            fill(
                self.tr(
                    "Seconds between position reads while nothing moves (%1 to %2 s). This is also "
                    "how a device that restarted or stopped answering is noticed."
                ),
                f"{low:g}",
                f"{high:g}",
            ),
        )
        form.addRow(self.tr("Poll when idle:"), idle)
        return group

    def _console_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Console"), "consoleGroup")
        high = self._range("console_max_lines")[1]
        spec = self._specs["console_max_lines"]
        lines = self._integer(
            "console_max_lines",
            self.tr(" lines"),
            self.tr("Keep every line"),
            spec.low,
            fill(
                self.tr(
                    "The most lines the console keeps: 0 keeps every line (a spool file on disk "
                    "and about 33 bytes a line in memory), else %1 to %2 lines, the oldest "
                    "dropped as new ones come. The session log keeps every byte either way."
                ),
                f"{spec.low:,}",
                f"{int(high):,}",
            ),
        )
        form.addRow(self.tr("Console lines kept:"), lines)
        self.memory_label = self._note("")
        self.memory_label.setObjectName("consoleMemory")
        form.addRow("", self.memory_label)
        return group

    def _log_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Session log"), "sessionLogGroup")
        check = QCheckBox(self.tr("Write every byte of every session to a file"))
        self._register(
            "session_log",
            check,
            self.tr("One file a session in the log folder; the oldest go beyond 200 MiB"),
        )
        form.addRow(check)
        folder = QLineEdit()
        folder.setClearButtonEnabled(True)
        shown = self._default_log_folder or self.tr("the app-data folder")
        folder.setPlaceholderText(fill(self.tr("Default: %1"), shown))
        self._register(
            "log_folder",
            folder,
            self.tr("An absolute path to a folder you can write to; empty: the default folder"),
        )
        browse = QPushButton(self.tr("Browse…"))
        browse.setObjectName("logFolderBrowse")
        browse.setToolTip(self.tr("Choose the session log folder"))
        browse.clicked.connect(self._browse)
        row = QHBoxLayout()
        row.addWidget(folder, 1)
        row.addWidget(browse)
        form.addRow(self.tr("Session log folder:"), row)
        return group

    def _display_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Positions"), "displayGroup")
        units = self._combo(
            "units",
            {"mm": self.tr("Millimetres (mm)"), "in": self.tr("Inches (in)")},
            self.tr("The unit positions are shown in; the device is always sent millimetres"),
        )
        form.addRow(self.tr("Units shown:"), units)
        spec = self._specs["decimals"]
        decimals = self._integer(
            "decimals",
            self.tr(" decimals"),
            self.tr("As the device resolves"),
            1,
            fill(
                self.tr(
                    "Decimals of the positions shown (%1 to %2), or as many as the device "
                    "resolves (0.01 mm: 2)"
                ),
                f"{spec.low:g}",
                f"{spec.high:g}",
            ),
        )
        form.addRow(self.tr("Decimals shown:"), decimals)
        return group

    def _limits_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Travel limits"), "limitsGroup")
        clamp = QCheckBox(self.tr("Clamp a move to the limits instead of refusing it"))
        self._register(
            "clamp_to_limits",
            clamp,
            self.tr("What a device starts with until its own limits are saved"),
        )
        form.addRow(clamp)
        form.addRow(self._note(self.tr("Each device's box is set in Motion → Travel limits…")))
        return group

    def _keys_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Jog keys"), "jogKeysGroup")
        rows = (
            ("jog_key_x_minus", self.tr("X-:"), self.tr("Jog X down by one step")),
            ("jog_key_x_plus", self.tr("X+:"), self.tr("Jog X up by one step")),
            ("jog_key_y_minus", self.tr("Y-:"), self.tr("Jog Y down by one step")),
            ("jog_key_y_plus", self.tr("Y+:"), self.tr("Jog Y up by one step")),
            ("jog_key_z_minus", self.tr("Z-:"), self.tr("Jog Z down by one step")),
            ("jog_key_z_plus", self.tr("Z+:"), self.tr("Jog Z up by one step")),
            ("jog_key_step_smaller", self.tr("Smaller step:"), self.tr("The next smaller step")),
            ("jog_key_step_larger", self.tr("Larger step:"), self.tr("The next larger step")),
        )
        hint = self.tr("Click, then press one key (no Shift, Ctrl, Alt or Meta)")
        for name, text, tip in rows:
            edit = QKeySequenceEdit()
            edit.setMaximumSequenceLength(1)
            edit.setClearButtonEnabled(True)
            self._register(name, edit, f"{tip}. {hint}")
            form.addRow(text, edit)
        form.addRow(
            self._note(
                self.tr(
                    "Shift with a jog key makes the step ten times bigger. Esc (Stop), Tab, "
                    "Enter, Space and F3 are the window's own."
                )
            )
        )
        return group

    def _looks_group(self) -> QGroupBox:
        group, form = self._group(self.tr("Appearance and language"), "appearanceGroup")
        theme = self._combo(
            "theme",
            {
                "system": self.tr("As the system"),
                "light": self.tr("Light"),
                "dark": self.tr("Dark"),
            },
            self.tr("Light or dark colours, or those of the desktop"),
        )
        form.addRow(self.tr("Theme:"), theme)
        language = self._combo(
            "language",
            {
                "system": self.tr("As the system"),
                "en": self.tr("English"),
                "es": self.tr("Español"),
                "fr": self.tr("Français"),
                "zh_CN": self.tr("简体中文"),
            },
            self.tr("The interface's language; --lang and $MOTIONPANEL_LANG come first"),
        )
        form.addRow(self.tr("Language:"), language)
        form.addRow(self._note(self.tr("A new language shows when the panel next starts.")))
        return group

    def _named_button(
        self, which: QDialogButtonBox.StandardButton, name: str, tip: str
    ) -> QPushButton:
        button = self.buttons.button(which)
        button.setObjectName(name)
        button.setToolTip(tip)
        return button

    # -- values --------------------------------------------------------------------------------
    def set_preferences(self, prefs: Any) -> None:
        """Show `prefs` in the fields (saved only with OK or Apply)."""
        self._loading = True
        try:
            for name, widget in self.fields.items():
                value = getattr(prefs, name)
                if isinstance(widget, QDoubleSpinBox | QSpinBox):
                    widget.setValue(value)
                elif isinstance(widget, QCheckBox):
                    widget.setChecked(bool(value))
                elif isinstance(widget, QLineEdit):
                    widget.setText(value)
                elif isinstance(widget, QComboBox):
                    index = widget.findData(value)
                    widget.setCurrentIndex(max(index, 0))
                elif isinstance(widget, QKeySequenceEdit):
                    widget.setKeySequence(QKeySequence(value))
        finally:
            self._loading = False
        self._changed()

    def preferences(self) -> Any:
        """The preferences the fields say (same class as given; may be invalid)."""
        values: dict[str, Any] = {}
        for name, widget in self.fields.items():
            if isinstance(widget, QDoubleSpinBox):
                values[name] = float(widget.value())
            elif isinstance(widget, QSpinBox):
                values[name] = int(widget.value())
            elif isinstance(widget, QCheckBox):
                values[name] = widget.isChecked()
            elif isinstance(widget, QLineEdit):
                values[name] = widget.text().strip()
            elif isinstance(widget, QComboBox):
                values[name] = widget.currentData()
            elif isinstance(widget, QKeySequenceEdit):
                values[name] = widget.keySequence().toString(PORTABLE)
        return dataclasses.replace(self._initial, **values)

    def problems(self) -> list[str]:
        """What stops OK now, one message each ([] when the fields can be used)."""
        return [message for _, message in self._field_problems()]

    def _field_problems(self) -> list[tuple[str, str]]:
        typing: list[tuple[str, str]] = []
        for name, widget in self.fields.items():
            if isinstance(widget, QSpinBox | QDoubleSpinBox) and not widget.hasAcceptableInput():
                low, high = self._range(name)
                message = self.tr("%1: %2 is not a number from %3 to %4 %5")
                shown = (self._label(name), widget.cleanText(), f"{low:g}", f"{high:g}")
                typing.append((name, fill(message, *shown, self._unit(name)).rstrip()))
        return typing + self.preferences().field_problems()

    def restore_defaults(self) -> None:
        """Put every field back to its default (nothing is saved until OK or Apply)."""
        self.set_preferences(self._defaults)

    def _changed(self, *_args: object) -> None:
        if self._loading:
            return
        problems = self._field_problems()
        bad = {name for name, _ in problems}
        for name, widget in self.fields.items():
            if isinstance(widget, TypedNumber):
                mark_invalid(widget.lineEdit(), name in bad)  # its own mark, and a range error
            else:
                widget.setStyleSheet(INVALID_STYLE if name in bad else "")
        self.problem_label.setText("\n".join(message for _, message in problems))
        self.problem_label.setVisible(bool(problems))
        self.ok_button.setEnabled(not problems)
        self.apply_button.setEnabled(not problems)
        lines = self.fields["console_max_lines"]
        assert isinstance(lines, QSpinBox)
        self._show_memory(lines.value())

    def _show_memory(self, lines: int) -> None:
        if lines == 0:
            text = self.tr("Memory grows with the session: about 33 MB a million lines.")
        else:
            megabytes = lines * CONSOLE_BYTES_PER_LINE / 1e6
            text = fill(self.tr("About %1 MB of memory at most."), f"{megabytes:,.1f}")
        self.memory_label.setText(text)

    # -- actions -------------------------------------------------------------------------------
    def _ask_folder(self, start: str) -> str:
        return QFileDialog.getExistingDirectory(
            self, self.tr("Session log folder"), start or self._default_log_folder
        )

    def _browse(self) -> None:
        folder = self.fields["log_folder"]
        assert isinstance(folder, QLineEdit)
        chosen = self.ask_folder(folder.text())
        if chosen:
            folder.setText(chosen)

    def _apply(self) -> bool:
        """Emit `applied` with the fields' preferences if they can be used."""
        if self._field_problems():
            return False
        self.applied.emit(self.preferences())
        return True

    def _ok(self) -> None:
        if self._apply():
            self.accept()
