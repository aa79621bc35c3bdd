"""A dialog to write or change one macro: its name and its steps, checked as they are typed."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QFontDatabase
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

Check = Callable[[str, tuple[str, ...]], str]
"""Given a name and steps, why the macro cannot be kept ("" when it can)."""


def steps_of(text: str) -> tuple[str, ...]:
    """The steps typed, one per line; blank lines left out."""
    return tuple(line.strip() for line in text.splitlines() if line.strip())


class MacroEditor(QDialog):
    """Name and steps of a macro; OK only once the device would take every step.

    `accepted_macro(name, steps)` when kept, `delete_requested(name)` for Delete (an existing one).
    """

    accepted_macro = Signal(str, tuple)
    delete_requested = Signal(str)

    def __init__(
        self,
        check: Check,
        vocabulary: str,
        name: str = "",
        steps: tuple[str, ...] = (),
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("macroEditor")
        self.original = name
        self._check = check
        self.setWindowTitle(self.tr("Edit macro") if name else self.tr("New macro"))
        self.name_edit = QLineEdit(name)
        self.name_edit.setObjectName("macroName")
        self.name_edit.setMaxLength(40)
        self.name_edit.setToolTip(self.tr("The button's label: 1 to 40 characters"))
        self.steps_edit = QPlainTextEdit("\n".join(steps))
        self.steps_edit.setObjectName("macroSteps")
        self.steps_edit.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.steps_edit.setPlaceholderText("home\nmove 10 5 0\njog 0 0 -2\nwait 0.5\nposition")
        self.steps_edit.setToolTip(
            self.tr(
                "One step per line, as motionctl takes it: distances in mm, speeds in mm/s, "
                "waits in s. Each step waits for the device's reply before the next."
            )
        )
        self.steps_edit.setMinimumSize(360, 180)
        help_label = QLabel(vocabulary)
        help_label.setObjectName("macroHelp")
        help_label.setWordWrap(True)
        help_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.problem = QLabel()
        self.problem.setObjectName("macroProblem")
        self.problem.setWordWrap(True)
        self.problem.setStyleSheet("color: #c62828;")
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self.buttons.accepted.connect(self._keep)
        self.buttons.rejected.connect(self.reject)
        self.delete_button: QPushButton | None = None
        if name:
            self.delete_button = self.buttons.addButton(
                self.tr("Delete"), QDialogButtonBox.ButtonRole.DestructiveRole
            )
            self.delete_button.setObjectName("macroDelete")
            self.delete_button.setToolTip(self.tr("Remove this macro"))
            self.delete_button.clicked.connect(self._delete)
        form = QFormLayout()
        form.addRow(self.tr("&Name:"), self.name_edit)
        form.addRow(self.tr("&Steps:"), self.steps_edit)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(help_label)
        layout.addWidget(self.problem)
        layout.addWidget(self.buttons)
        self.name_edit.textChanged.connect(self._recheck)
        self.steps_edit.textChanged.connect(self._recheck)
        self._recheck()

    def name(self) -> str:
        """The name typed, stripped."""
        return self.name_edit.text().strip()

    def steps(self) -> tuple[str, ...]:
        """The steps typed."""
        return steps_of(self.steps_edit.toPlainText())

    def _recheck(self) -> None:
        why = self._check(self.name(), self.steps())
        self.problem.setText(why)
        self.buttons.button(QDialogButtonBox.StandardButton.Ok).setEnabled(not why)

    def _keep(self) -> None:
        if self._check(self.name(), self.steps()):
            return
        self.accepted_macro.emit(self.name(), self.steps())
        self.accept()

    def _delete(self) -> None:
        self.delete_requested.emit(self.original)
        self.reject()
