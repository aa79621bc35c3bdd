"""The built-in arrangement of each layout (Operate, Set up, Traffic): which docks it shows,
which corner belongs to which area and where each dock goes, with the layouts' names."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtWidgets import QDockWidget

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"

OPERATE, SETUP, TRAFFIC = "operate", "setup", "traffic"
NAMES = (OPERATE, SETUP, TRAFFIC)

LEFT = Qt.DockWidgetArea.LeftDockWidgetArea
RIGHT = Qt.DockWidgetArea.RightDockWidgetArea
TOP = Qt.DockWidgetArea.TopDockWidgetArea
BOTTOM = Qt.DockWidgetArea.BottomDockWidgetArea
VERTICAL, HORIZONTAL = Qt.Orientation.Vertical, Qt.Orientation.Horizontal

READOUT, JOG, GOTO, SPEED = (
    "positionReadoutDock",
    "jogPanelDock",
    "coordinateEntryDock",
    ("speedControlDock"),
)
CONSOLE, TIMELINE, MACROS = "rawConsoleDock", "trafficTimelineDock", "macroPanelDock"
PARAMETERS, FIRMATA, PIFRAME = "parameterEditor", "firmataPanelDock", "piFramePanelDock"
PROGRAM, ARC, DWELL = "programPanelDock", "arcEntryDock", "dwellEntryDock"
TRAVEL = "travelLimitsDock"
# Shown only when the connected device calls for them (DeviceDocks says which).
DEVICE = (PARAMETERS, FIRMATA, PIFRAME, PROGRAM, ARC, DWELL)
SETUP_PANELS = (PARAMETERS, FIRMATA, PIFRAME)  # a device with one of these is offered Set up

# The docks each layout shows (of the device's, those it calls for).
MEMBERS: dict[str, frozenset[str]] = {
    OPERATE: frozenset({READOUT, JOG, GOTO, SPEED, PROGRAM, ARC, DWELL}),
    SETUP: frozenset({READOUT, JOG, PARAMETERS, FIRMATA, PIFRAME, MACROS, TRAVEL}),
    TRAFFIC: frozenset({CONSOLE, TIMELINE}),  # and the position on one line (`compact`)
}
CENTRAL = {OPERATE: True, SETUP: False, TRAFFIC: False}  # whether the views are shown
CORNERS: dict[str, dict[Qt.Corner, Qt.DockWidgetArea]] = {
    OPERATE: {
        Qt.Corner.TopLeftCorner: LEFT,
        Qt.Corner.BottomLeftCorner: LEFT,
        Qt.Corner.TopRightCorner: RIGHT,
        Qt.Corner.BottomRightCorner: BOTTOM,
    },
    SETUP: {
        Qt.Corner.TopLeftCorner: LEFT,
        Qt.Corner.BottomLeftCorner: LEFT,
        Qt.Corner.TopRightCorner: RIGHT,
        Qt.Corner.BottomRightCorner: RIGHT,
    },
    TRAFFIC: {
        Qt.Corner.TopLeftCorner: TOP,
        Qt.Corner.BottomLeftCorner: BOTTOM,
        Qt.Corner.TopRightCorner: TOP,
        Qt.Corner.BottomRightCorner: BOTTOM,
    },
}
# Where each dock goes, in order: (area, docks stacked top to bottom (left to right in the top and
# bottom areas), each a tab group whose first dock is shown).
PLACES: dict[str, list[tuple[Qt.DockWidgetArea, list[tuple[str, ...]]]]] = {
    OPERATE: [
        # The controls in one column, Go to and the program's docks under the views.
        (LEFT, [(READOUT,), (JOG,), (SPEED, MACROS)]),
        (BOTTOM, [(GOTO, ARC, DWELL, PROGRAM)]),
        (RIGHT, [(CONSOLE, TIMELINE, PARAMETERS, FIRMATA, PIFRAME, TRAVEL)]),
    ],
    SETUP: [
        (LEFT, [(READOUT,), (JOG,), (GOTO, SPEED, ARC, DWELL)]),
        (RIGHT, [(PARAMETERS, FIRMATA, PIFRAME, MACROS, TRAVEL, PROGRAM, CONSOLE, TIMELINE)]),
    ],
    TRAFFIC: [  # each full width: the readout is a line in the status bar
        (TOP, [(TIMELINE,)]),
        (BOTTOM, [(CONSOLE, PARAMETERS, FIRMATA, PIFRAME, PROGRAM, TRAVEL)]),
        (LEFT, [(READOUT, JOG, GOTO, SPEED, MACROS, ARC, DWELL)]),
    ],
}
SIDE_TITLES = (GOTO, ARC, DWELL, PROGRAM)  # Operate's docks under the views
SIDE_TITLE = QDockWidget.DockWidgetFeature.DockWidgetVerticalTitleBar
OBJECT_NAMES = {OPERATE: "layoutOperate", SETUP: "layoutSetup", TRAFFIC: "layoutTraffic"}
SWITCH_NAMES = {
    OPERATE: "layoutSwitchOperate",
    SETUP: "layoutSwitchSetup",
    TRAFFIC: "layoutSwitchTraffic",
}


def titles() -> dict[str, str]:
    """Each layout's menu and switch title, translated."""
    return {
        OPERATE: translate("MainWindow", "&Operate"),
        SETUP: translate("MainWindow", "&Set up"),
        TRAFFIC: translate("MainWindow", "&Traffic"),
    }


def tips() -> dict[str, str]:
    """Each layout's switch tooltip, translated."""
    return {
        OPERATE: translate("MainWindow", "Jog, go to and watch the stage: the views large"),
        SETUP: translate("MainWindow", "The device's parameters and setup panels, and macros"),
        TRAFFIC: translate("MainWindow", "The traffic console and its timeline, full width"),
    }
