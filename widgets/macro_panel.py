"""The macros of the connected protocol as buttons, with New, Edit, Import and Export."""

from __future__ import annotations

from PySide6.QtCore import Signal
from PySide6.QtWidgets import (
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QMenu,
    QPushButton,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from widgets._i18n import fill

COLUMNS = 2


class MacroPanel(QWidget):
    """A button per macro (click: run it); `run_requested(name)`, `edit_requested(name)`,
    `new_requested()`, `import_requested()`, `export_requested()`."""

    run_requested = Signal(str)
    edit_requested = Signal(str)
    new_requested = Signal()
    import_requested = Signal()
    export_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("macroPanel")
        self.buttons: dict[str, QPushButton] = {}
        self._runnable = False
        self.empty = QLabel(self.tr("No macros yet: New… writes one, Import… reads a file."))
        self.empty.setObjectName("macroEmpty")
        self.empty.setWordWrap(True)
        self.blocked = QLabel()  # why the macros cannot run now, while motion is off for a job
        self.blocked.setObjectName("macroBlocked")
        self.blocked.setWordWrap(True)
        self.blocked.setStyleSheet("color: #616161;")
        self.blocked.setVisible(False)
        self.grid = QGridLayout()
        self.new_button = self._tool(self.tr("New…"), "macroNew", self.tr("Write a new macro"))
        self.new_button.clicked.connect(self.new_requested)
        self.edit_button = self._tool(
            self.tr("Edit"), "macroEdit", self.tr("Change or delete a macro")
        )
        self.edit_menu = QMenu(self.edit_button)
        self.edit_menu.setObjectName("macroEditMenu")
        self.edit_button.setMenu(self.edit_menu)
        self.edit_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        self.import_button = self._tool(
            self.tr("Import…"),
            "macroImport",
            self.tr("Add the macros of a file (JSON; data only, checked before any is kept)"),
        )
        self.import_button.clicked.connect(self.import_requested)
        self.export_button = self._tool(
            self.tr("Export…"), "macroExport", self.tr("Write this protocol's macros to a file")
        )
        self.export_button.clicked.connect(self.export_requested)
        tools = QHBoxLayout()
        for button in (self.new_button, self.edit_button, self.import_button, self.export_button):
            tools.addWidget(button)
        tools.addStretch(1)
        layout = QVBoxLayout(self)
        layout.addWidget(self.empty)
        layout.addWidget(self.blocked)
        layout.addLayout(self.grid)
        layout.addLayout(tools)
        layout.addStretch(1)
        self.set_macros([])

    def _tool(self, text: str, name: str, tip: str) -> QToolButton:
        button = QToolButton()
        button.setText(text)
        button.setObjectName(name)
        button.setToolTip(tip)
        return button

    def set_macros(self, macros: list[tuple[str, tuple[str, ...]]]) -> None:
        """Show these macros (name, steps) as buttons, in order."""
        for button in self.buttons.values():
            self.grid.removeWidget(button)
            button.deleteLater()
        self.buttons.clear()
        self.edit_menu.clear()
        for index, (name, steps) in enumerate(macros):
            button = QPushButton(name)
            button.setObjectName("macroButton")
            button.setProperty("macro", name)
            shown = "\n".join(steps[:12]) + ("\n…" if len(steps) > 12 else "")
            button.setToolTip(fill(self.tr("Run %1:\n%2"), name, shown))
            button.clicked.connect(self._run_clicked)
            button.setEnabled(self._runnable)
            self.grid.addWidget(button, index // COLUMNS, index % COLUMNS)
            self.buttons[name] = button
            action = self.edit_menu.addAction(name)
            action.setData(name)
            action.triggered.connect(self._edit_triggered)
        self.empty.setVisible(not macros)
        self.edit_button.setEnabled(bool(macros))
        self.export_button.setEnabled(bool(macros))

    def set_runnable(self, runnable: bool, reason: str = "") -> None:
        """Enable the run buttons (connected, motion allowed) or not; `reason`, shown while
        they are off, says why (e.g. a program is running)."""
        self._runnable = runnable
        for button in self.buttons.values():
            button.setEnabled(runnable)
        shown = reason if not runnable else ""
        self.blocked.setText(fill(self.tr("Macros off: %1"), shown) if shown else "")
        self.blocked.setVisible(bool(shown))

    def _run_clicked(self) -> None:
        button = self.sender()
        if isinstance(button, QPushButton) and button.isEnabled():
            self.run_requested.emit(str(button.property("macro")))

    def _edit_triggered(self) -> None:
        action = self.sender()
        if action is not None:
            self.edit_requested.emit(str(action.data()))  # type: ignore[attr-defined]
