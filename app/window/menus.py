"""The main window's menus: File, Motion and View (the tools add Settings, Theme and Help)."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QAction, QKeySequence

if TYPE_CHECKING:
    from PySide6.QtWidgets import QDockWidget, QMainWindow, QMenu

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"


def build_menus(
    window: QMainWindow,
    docks: list[QDockWidget],
    actions: dict[str, Callable[[], object]],
) -> tuple[QMenu, QMenu, dict[str, QAction]]:
    """File, Motion and View in `window`'s menu bar; `actions` names what the items do (export,
    open_log, log_folder, stop, travel, reset_views, clear_trail). Returns the File and View
    menus, and the actions changed later by name (stop, travel, quit)."""
    bar = window.menuBar()
    file_menu = bar.addMenu(translate("MainWindow", "&File"))
    export = file_menu.addAction(translate("MainWindow", "&Export traffic log…"), actions["export"])
    export.setShortcut(QKeySequence("Ctrl+E"))
    export.setToolTip(
        translate(
            "MainWindow", "Save every byte sent and received, with timestamps, to a text file"
        )
    )
    opener = file_menu.addAction(translate("MainWindow", "&Open log…"), actions["open_log"])
    opener.setShortcut(QKeySequence.StandardKey.Open)
    opener.setToolTip(
        translate("MainWindow", "Browse a traffic log (ours or a pyserial spy:// capture) decoded")
    )
    folder = file_menu.addAction(
        translate("MainWindow", "Open the session &log folder"), actions["log_folder"]
    )
    folder.setToolTip(
        translate("MainWindow", "Every byte of every session is kept there, one file a session")
    )
    file_menu.addSeparator()
    quit_action = file_menu.addAction(
        translate("MainWindow", "&Quit"), QKeySequence.StandardKey.Quit, window.close
    )
    motion_menu = bar.addMenu(translate("MainWindow", "&Motion"))
    stop = motion_menu.addAction(translate("MainWindow", "&Stop"), actions["stop"])
    stop.setShortcut(QKeySequence(Qt.Key.Key_Escape))
    stop.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
    motion_menu.addSeparator()
    travel = motion_menu.addAction(translate("MainWindow", "&Travel limits…"), actions["travel"])
    travel.setToolTip(translate("MainWindow", "The box the stage may move in, for this device"))
    travel.setEnabled(False)
    view_menu = bar.addMenu(translate("MainWindow", "&View"))
    reset = view_menu.addAction(translate("MainWindow", "&Reset views"), actions["reset_views"])
    reset.setShortcut(QKeySequence("Ctrl+R"))
    view_menu.addAction(translate("MainWindow", "&Clear trail"), actions["clear_trail"])
    view_menu.addSeparator()
    for dock in docks:
        view_menu.addAction(dock.toggleViewAction())
    view_menu.addSeparator()
    return file_menu, view_menu, {"stop": stop, "travel": travel, "quit": quit_action}
