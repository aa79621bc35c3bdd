"""Where the device panels' docks go, for the window (which makes them empty before its first
paint, so that the saved layout places them) and the device docks (which fill them)."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QT_TRANSLATE_NOOP, Qt
from PySide6.QtWidgets import QDockWidget, QMainWindow

LEFT, BOTTOM = Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.BottomDockWidgetArea

DEVICE_DOCKS: dict[str, tuple[str, Qt.DockWidgetArea]] = {
    # object name: (title, area); in tab order, the bottom ones first. The titles are marked
    # here and translated where the docks are made, context "DockLayout".
    "firmataPanelDock": (QT_TRANSLATE_NOOP("DockLayout", "Stepper setup"), BOTTOM),
    "piFramePanelDock": (QT_TRANSLATE_NOOP("DockLayout", "Frame setup"), BOTTOM),
    "programPanelDock": (QT_TRANSLATE_NOOP("DockLayout", "Program"), BOTTOM),
    "arcEntryDock": (QT_TRANSLATE_NOOP("DockLayout", "Arc"), LEFT),
    "dwellEntryDock": (QT_TRANSLATE_NOOP("DockLayout", "Dwell"), LEFT),
    "travelLimitsDock": (QT_TRANSLATE_NOOP("DockLayout", "Travel limits"), BOTTOM),
}


def empty_dock(
    window: QMainWindow, name: str, make: Callable[[QMainWindow], QDockWidget]
) -> QDockWidget:
    """The window's empty dock `name` if it made one before its first paint (placed and
    restored already), else `make(window)`."""
    dock = window.findChild(QDockWidget, name, Qt.FindChildOption.FindDirectChildrenOnly)
    if dock is None or dock.widget() is not None:
        dock = make(window)
    return dock
