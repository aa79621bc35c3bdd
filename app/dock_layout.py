"""Where the device panels' docks go, for the window (which makes them empty before its first
paint, so that the saved layout places them) and the device docks (which fill them)."""

from __future__ import annotations

from PySide6.QtCore import Qt

LEFT, BOTTOM = Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.BottomDockWidgetArea

DEVICE_DOCKS: dict[str, tuple[str, Qt.DockWidgetArea]] = {
    # object name: (title, area); in tab order, the bottom ones first
    "firmataPanelDock": ("Stepper setup", BOTTOM),
    "piFramePanelDock": ("Frame setup", BOTTOM),
    "programPanelDock": ("Program", BOTTOM),
    "arcEntryDock": ("Arc", LEFT),
    "dwellEntryDock": ("Dwell", LEFT),
}
