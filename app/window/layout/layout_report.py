"""What Qt shows of the current layout, for the real-input acceptance tier: with the environment
variable MOTIONPANEL_LAYOUT_REPORT=PATH, PATH gets a JSON report after each layout switch and
each resize (once things have been still for a moment): the layout, the window's size, and for
each control of the layout's list whether it is shown, where, and whether Qt shows all of it;
for each plot whether it lies inside the window. Without the variable nothing is watched."""

from __future__ import annotations

import json
import logging
import os
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, QObject, QPoint, QRect, Qt, QTimer
from PySide6.QtGui import QRegion
from PySide6.QtWidgets import (
    QDockWidget,
    QMainWindow,
    QTabBar,
    QTableView,
    QToolBar,
    QWidget,
)

from app.window.layout.dock_balance import need
from app.window.layout.layout_details import columns, details, shown_region, tab_bars, whole

if TYPE_CHECKING:
    from PySide6.QtCore import SignalInstance

    from app.window.layout.layouts import Layouts
    from widgets.lazy_view import DeferredViews

    class MainWindow(QMainWindow):
        """What the report reads of the panel's window (app/window/main_window.py, which
        imports this module: not imported back)."""

        layouts: Layouts
        views: DeferredViews
        settled: SignalInstance
        connected: bool


log = logging.getLogger(__name__)

ENVIRONMENT = "MOTIONPANEL_LAYOUT_REPORT"
DEBOUNCE_MS = 300
SAMPLES = (9, 5)  # points across and down a control where Qt is asked which widget is on top

# Each layout's controls (objectNames), as the issue lists them; those of a device's setup
# panels are there only when the device calls for them.
CONTROLS: dict[str, tuple[str, ...]] = {
    "operate": (
        "positionReadout",
        "jogPanel",
        "coordinateEntry",
        "goButton",
        "homeButton",
        "setHomeButton",
        "stopButton",
        "speedControl",
        "machineState",
        "layoutSwitcher",
    ),
    "setup": (
        "positionReadout",
        "jogPanel",
        "parameterEditorPanel",
        "firmataPanel",
        "piFramePanel",
        "travelLimits",
        "macroPanel",
        "machineState",
        "layoutSwitcher",
    ),
    "traffic": (
        "compactReadout",  # the position on one line, beside the layout switcher
        "consoleView",
        "consoleSendBar",
        "trafficTimeline",
        "machineState",
        "layoutSwitcher",
    ),
}
# Widgets a scenario clicks that are no layout's control (the Program dock's Run): their place.
LOCATED = ("programRun",)
PLOTS = ("positionView3d", "positionXYPlot", "positionTimePlot", "trafficTimelinePlots")
WATCHED = (QEvent.Type.Resize, QEvent.Type.Show, QEvent.Type.Hide)


def watch(window: MainWindow) -> LayoutReport | None:
    """Report the window's layout to the file MOTIONPANEL_LAYOUT_REPORT names (None: unset)."""
    path = os.environ.get(ENVIRONMENT)
    if not path:
        return None
    return LayoutReport(window, Path(path))


def _rect(widget: QWidget, window: QWidget) -> QRect:
    """The widget's rectangle in the window's coordinates."""
    return QRect(widget.mapTo(window, QPoint(0, 0)), widget.size())


def _name(widget: QWidget) -> str:
    return widget.objectName() or type(widget).__name__


def _covered_by(widget: QWidget, window: QWidget) -> list[str]:
    """The widgets Qt finds on top of `widget` at points spread over it (not its own children,
    nor its ancestors where it lets clicks through)."""
    if not widget.isVisible() or widget.width() <= 2 or widget.height() <= 2:
        return []
    found: set[str] = set()
    columns, rows = SAMPLES
    origin = widget.mapTo(window, QPoint(0, 0))
    for column in range(columns):
        for row in range(rows):
            x = 1 + (widget.width() - 3) * column // (columns - 1)
            y = 1 + (widget.height() - 3) * row // (rows - 1)
            top = window.childAt(origin + QPoint(x, y))
            if top is None or top is widget or widget.isAncestorOf(top):
                continue
            if top.isAncestorOf(widget):
                continue
            found.add(_name(top))
    return sorted(found)


def _tab_in_front(window: QMainWindow, dock: QDockWidget) -> str | None:
    """The title of the tab shown of the dock's tab group (None: the dock is not tabbed)."""
    if not window.tabifiedDockWidgets(dock):
        return None
    title = dock.windowTitle()
    bars = [
        bar
        for bar in window.findChildren(QTabBar, options=Qt.FindChildOption.FindDirectChildrenOnly)
        if title in [bar.tabText(index) for index in range(bar.count())]
    ]
    bars.sort(key=lambda bar: not bar.isVisible())
    return bars[0].tabText(bars[0].currentIndex()) if bars else None


def _dock_of(widget: QWidget) -> QDockWidget | None:
    parent = widget.parentWidget()
    while parent is not None and not isinstance(parent, QDockWidget):
        parent = parent.parentWidget()
    return parent


class LayoutReport(QObject):
    """Writes the report once the window has been still for DEBOUNCE_MS after a change."""

    def __init__(self, window: MainWindow, path: Path) -> None:
        super().__init__(window)
        self.window = window
        self.path = path
        self.sequence = 0
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(DEBOUNCE_MS)
        self._timer.timeout.connect(self.write)
        window.installEventFilter(self)
        window.statusBar().installEventFilter(self)
        for dock in window.findChildren(QDockWidget):
            dock.installEventFilter(self)
        window.layouts.group.triggered.connect(self.later)
        window.layouts.reset_action.triggered.connect(self.later)
        window.views.ready.connect(self.later)
        window.settled.connect(self.later)
        self.later()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """A resize, a dock shown or hidden: report again once still."""
        if event.type() in WATCHED:
            self.later()
        return False

    def later(self, *_: object) -> None:
        """Report once nothing has changed for DEBOUNCE_MS."""
        self._timer.start()

    def report(self) -> dict[str, object]:
        """What Qt shows of the current layout now."""
        window = self.window
        layout = window.layouts.current
        names = CONTROLS[layout]
        widgets = {name: window.findChild(QWidget, name) for name in names}
        controls = []
        for name, widget in widgets.items():
            if widget is None:
                controls.append({"name": name, "found": False})
                continue
            dock = _dock_of(widget)
            front = _tab_in_front(window, dock) if dock is not None else None
            behind = dock is not None and front is not None and front != dock.windowTitle()
            inside = [
                other
                for other, outer in widgets.items()
                if outer is not None and outer is not widget and outer.isAncestorOf(widget)
            ]
            controls.append(
                {
                    "name": name,
                    "found": True,
                    "visible": widget.isVisible(),
                    "dock": dock.objectName() if dock is not None else None,
                    "dock_shown": dock is None or not dock.isHidden(),
                    "behind_tab": front if behind else None,  # the tab in front of it
                    "rect": list(_rect(widget, window).getRect()),
                    "whole": whole(widget),
                    "shown_area": _area(shown_region(widget)) if widget.isVisible() else 0,
                    "covered_by": _covered_by(widget, window),
                    "inside": inside,
                }
            )
        plots = []
        bounds = window.rect()
        for name in PLOTS:
            widget = window.findChild(QWidget, name)
            if widget is None:
                continue
            rect = _rect(widget, window)
            plots.append(
                {
                    "name": name,
                    "visible": widget.isVisible(),
                    "rect": list(rect.getRect()),
                    "inside_window": bounds.contains(rect),
                    "whole": whole(widget),
                }
            )
        parts = [
            part
            for part in (
                *window.findChildren(
                    QDockWidget, options=Qt.FindChildOption.FindDirectChildrenOnly
                ),
                *window.findChildren(QToolBar, options=Qt.FindChildOption.FindDirectChildrenOnly),
                window.statusBar(),
                window.centralWidget(),
            )
            if part.isVisible()
        ]  # what asks the window for its minimum size
        return {
            "sequence": self.sequence,
            "layout": layout,
            "window": [window.width(), window.height()],
            "window_minimum": list(window.minimumSizeHint().toTuple()),
            "parts": [
                {
                    "name": _name(part),
                    "rect": list(part.geometry().getRect()),
                    "minimum": list(part.minimumSizeHint().toTuple()),
                    "need": need(part) if isinstance(part, QDockWidget) else None,
                }
                for part in parts
            ],
            "views_ready": window.views.is_ready(),
            "connected": window.connected,
            "controls": controls,
            "plots": plots,
            "parameter_rows": _whole_rows(window),
            "located": _located(window),
            "details": details(window),
            "columns": columns(window),
            "tab_bars": tab_bars(window),
        }

    def write(self) -> None:
        """Write the report (atomically: a reader never sees half of one)."""
        self.sequence += 1
        text = json.dumps(self.report(), indent=1)
        temporary = self.path.with_name(self.path.name + ".tmp")
        try:
            temporary.write_text(text, encoding="utf-8")
            os.replace(temporary, self.path)
        except OSError as exc:
            log.warning("layout report not written to %s: %s", self.path, exc)


def _located(window: QWidget) -> dict[str, dict[str, object]]:
    """Where each LOCATED widget is in the window, whether shown whole and enabled."""
    found = {name: window.findChild(QWidget, name) for name in LOCATED}
    return {
        name: {
            "rect": list(_rect(widget, window).getRect()),
            "whole": whole(widget),
            "enabled": widget.isEnabled(),
        }
        for name, widget in found.items()
        if widget is not None
    }


def _area(region: QRegion) -> int:
    return sum(rect.width() * rect.height() for rect in region)


def _whole_rows(window: QWidget) -> int | None:
    """How many rows of the parameter table are shown whole (None: the table is not shown)."""
    table = window.findChild(QTableView, "parameterTable")
    if table is None or not table.isVisible():
        return None
    viewport = table.viewport()
    return sum(
        1
        for row in range(table.model().rowCount())
        if not table.isRowHidden(row)
        and table.rowViewportPosition(row) >= 0
        and table.rowViewportPosition(row) + table.rowHeight(row) <= viewport.height()
    )
