"""The Macros dock: the selected protocol's macros, edited in the window, saved with the settings,
imported and exported as data, and run as one job through the worker."""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, Qt
from PySide6.QtWidgets import QDockWidget, QFileDialog, QMainWindow

from app.common import macros
from app.common.messages import localized
from app.window.device import jobs
from app.window.layout.dock_layout import empty_dock
from drivers.errors import BadInput
from drivers.protocols.base import Protocol
from drivers.protocols.registry import create_protocol
from widgets._i18n import fill
from widgets.macro_editor import MacroEditor
from widgets.macro_panel import MacroPanel
from widgets.panel_scroll_area import PanelScrollArea

if TYPE_CHECKING:
    from app.window.services import WindowServices

log = logging.getLogger(__name__)

DOCK_NAME = "macroPanelDock"
FILE_FILTER = QT_TRANSLATE_NOOP(
    "MacroDock", "Motion Panel macros (*.json);;All files (*)"
)  # translated at use


def make_dock(window: QMainWindow) -> QDockWidget:
    """The macros' dock, empty, on the left of `window`."""
    dock = QDockWidget(QCoreApplication.translate("MacroDock", "Macros"), window)
    dock.setObjectName(DOCK_NAME)
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, dock)
    return dock


def vocabulary() -> str:
    """What a step may be, for the editor's help."""
    return QCoreApplication.translate(
        "MacroDock",
        "Steps (one per line, each waits for the device): home · set-home · position · "
        "move X Y [Z] (mm) · jog DX DY [DZ] (mm) · speed V (mm/s) · raw TEXT (sent as typed, "
        "its reply awaited) · wait S (s, the panel pauses) · check · id · limits; and where the "
        "device has them: dwell MS (ms) · arc CX CY R START END --cw|--ccw · step RPM STEPS · "
        "status · stop · version.",
        "the command words (home, move, --cw …) are typed as they are: keep them in English",
    )


class MacroDock(QObject):
    """Keeps the protocol's macros, shows them as buttons, runs one as a MacroJob."""

    def __init__(self, window: QMainWindow, services: WindowServices) -> None:
        super().__init__(window)
        self.window = window  # the docks' and dialogs' parent
        self.services = services
        self.panel = MacroPanel(window)
        self.dock = empty_dock(window, DOCK_NAME, make_dock)
        self.dock.setWidget(PanelScrollArea(self.panel, self.dock))
        self.protocol: Protocol | None = None
        self.macros: list[macros.Macro] = []
        self.editor: MacroEditor | None = None
        self.panel.run_requested.connect(self.run)
        self.panel.new_requested.connect(self.new)
        self.panel.edit_requested.connect(self.edit)
        self.panel.import_requested.connect(self._ask_import)
        self.panel.export_requested.connect(self._ask_export)
        services.worker.macro_step.connect(self._on_step)

    # -- which protocol ------------------------------------------------------------------------
    def set_protocol(self, name: str, variant: str = "") -> None:
        """Show the macros kept for this protocol (the one chosen, connected or not)."""
        if self.protocol is not None and self.protocol.name == name:
            return
        try:
            self.protocol = create_protocol(name, variant or None)
        except LookupError:
            self.protocol = None
            self.macros = []
        else:
            self.macros = macros.read_saved(self.services.settings, name)
        self.dock.setWindowTitle(fill(self.tr("Macros (%1)"), name))
        self._show()

    def set_runnable(self, runnable: bool, reason: str = "") -> None:
        """Run buttons on (connected, motion allowed) or off, and why (shown in the panel)."""
        self.panel.set_runnable(runnable, reason)

    def _show(self) -> None:
        self.panel.set_macros([(m.name, m.steps) for m in self.macros])

    def macro(self, name: str) -> macros.Macro | None:
        """The macro of that name for the current protocol."""
        return next((m for m in self.macros if m.name == name), None)

    # -- running -------------------------------------------------------------------------------
    def run(self, name: str) -> bool:
        """Check the macro whole, then queue it; False (and why) when refused."""
        macro = self.macro(name)
        if macro is None or self.protocol is None:
            return False
        try:
            macros.check_macro(macro, self.protocol)
        except BadInput as exc:
            self.services.say(fill(self.tr("%1; nothing sent"), localized(exc)))
            return False
        return self.services.submit_job(jobs.MacroJob(macro))

    def _on_step(self, name: str, number: int, count: int, step: str) -> None:
        self.services.say(fill(self.tr("macro %1: step %2/%3: %4"), name, number, count, step))

    # -- editing -------------------------------------------------------------------------------
    def problem(self, name: str, steps: tuple[str, ...], original: str = "") -> str:
        """Why a macro of this name and steps cannot be kept ("" when it can)."""
        if self.protocol is None:
            return self.tr("choose a protocol first")
        try:
            stripped = macros.check_name(name)
            if stripped != original and self.macro(stripped) is not None:
                return fill(self.tr("a macro named %1 exists already"), repr(stripped))
            macros.check_macro(macros.Macro(stripped, self.protocol.name, steps), self.protocol)
        except BadInput as exc:
            return localized(exc)
        return ""

    def new(self) -> MacroEditor | None:
        """Open the editor for a new macro."""
        return self._open_editor("", ())

    def edit(self, name: str) -> MacroEditor | None:
        """Open the editor on an existing macro."""
        macro = self.macro(name)
        return None if macro is None else self._open_editor(macro.name, macro.steps)

    def _open_editor(self, name: str, steps: tuple[str, ...]) -> MacroEditor | None:
        if self.protocol is None:
            return None
        if self.editor is not None:
            self.editor.close()
        editor = MacroEditor(
            lambda n, s: self.problem(n, s, name), vocabulary(), name, steps, self.window
        )
        editor.accepted_macro.connect(self._keep)
        editor.delete_requested.connect(self.delete)
        editor.finished.connect(editor.deleteLater)
        self.editor = editor
        editor.open()
        return editor

    def _keep(self, name: str, steps: tuple[str, ...]) -> None:
        editor = self.sender()
        original = editor.original if isinstance(editor, MacroEditor) else ""
        assert self.protocol is not None
        kept = macros.Macro(name, self.protocol.name, steps)
        index = next((i for i, m in enumerate(self.macros) if m.name == original), None)
        if index is None:
            self.macros.append(kept)
        else:
            self.macros[index] = kept
        self._save()
        self.services.say(fill(self.tr("macro %1 kept (%2 steps)"), name, len(steps)))

    def delete(self, name: str) -> None:
        """Forget a macro."""
        self.macros = [m for m in self.macros if m.name != name]
        self._save()
        self.services.say(fill(self.tr("macro %1 deleted"), name))

    def _save(self) -> None:
        assert self.protocol is not None
        macros.save(self.services.settings, self.protocol.name, self.macros)
        self._show()

    # -- files -----------------------------------------------------------------------------------
    def import_file(self, path: str) -> bool:
        """Add this protocol's macros from a file; all refused (nothing kept) if one is bad."""
        if self.protocol is None:
            return False
        try:
            read = macros.read_macro_file(path)
            incoming = [m for m in read if m.protocol == self.protocol.name]
            for macro in incoming:
                macros.check_macro(macro, self.protocol)
            merged = macros.merge(self.macros, incoming)
            if len(merged) > macros.MAX_MACROS:
                too_many = self.tr("%1 macros; at most %2")
                raise macros.BadMacro(fill(too_many, len(merged), macros.MAX_MACROS))
        except BadInput as exc:
            self.services.say(fill(self.tr("macros not imported: %1"), localized(exc)))
            return False
        self.macros = merged
        self._save()
        others = len(read) - len(incoming)
        left = fill(self.tr("; %1 for other protocols left out"), others) if others else ""
        imported = self.tr("imported %1 macro(s) from %2%3")
        self.services.say(fill(imported, len(incoming), path, left))
        return True

    def export_file(self, path: str) -> bool:
        """Write this protocol's macros to a file."""
        try:
            macros.write_macro_file(path, self.macros)
        except OSError as exc:
            why = self.tr("macros not exported: cannot write %1: %2")
            self.services.say(fill(why, path, exc.strerror or exc))
            return False
        self.services.say(fill(self.tr("exported %1 macro(s) to %2"), len(self.macros), path))
        return True

    def _ask_import(self) -> None:
        path, _ = QFileDialog.getOpenFileName(
            self.window, self.tr("Import macros"), "", self.tr(FILE_FILTER)
        )
        if path:
            self.import_file(path)

    def _ask_export(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self.window, self.tr("Export macros"), "macros.json", self.tr(FILE_FILTER)
        )
        if path:
            self.export_file(path)
