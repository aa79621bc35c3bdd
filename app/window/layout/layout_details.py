"""The small parts of a layout the layout report (layout_report.py) looks at one by one: a few
buttons and lines inside the controls, whether each is shown whole and given the room its text
needs; and the columns of the tables, each one's width against the width its text needs."""

from __future__ import annotations

from PySide6.QtCore import QPoint, QRect
from PySide6.QtGui import QRegion
from PySide6.QtWidgets import QHeaderView, QLabel, QTabBar, QTableView, QWidget

# Parts inside the controls that were seen cut (issue 28 item 26), by objectName.
DETAILS = (
    "arcCw",
    "arcCcw",
    "arcPreview",
    "runArcButton",
    "positionStatus",  # "position unknown ..." (red), "estimated ..." (blue)
    "positionNotMeasured",  # "commanded, move confirmed"
    "view3dFollow",
    "homeButton",
    "setHomeButton",
    "stopButton",
    "goButton",
)
TABLES = ("parameterTable", "consoleView")
_MODES = {
    QHeaderView.ResizeMode.Interactive: "interactive",
    QHeaderView.ResizeMode.Fixed: "fixed",
    QHeaderView.ResizeMode.Stretch: "stretch",
    QHeaderView.ResizeMode.ResizeToContents: "contents",
}


def shown_region(widget: QWidget) -> QRegion:
    """The part of `widget` Qt paints: its visible region and its children's (Qt leaves the
    opaque children out of a widget's own)."""
    region = QRegion(widget.visibleRegion())
    for child in widget.findChildren(QWidget):
        if child.isVisible():
            region += child.visibleRegion().translated(child.mapTo(widget, QPoint(0, 0)))
    return region.intersected(QRegion(widget.rect()))


def whole(widget: QWidget) -> bool:
    """Whether Qt shows all of the widget (not clipped by a scroll area, a neighbour or the
    window's edge)."""
    if not widget.isVisible() or widget.width() <= 0 or widget.height() <= 0:
        return False
    return shown_region(widget) == QRegion(widget.rect())


def squeezed(widget: QWidget) -> bool:
    """Whether the widget is given less room than its text needs (a line cut in half by a
    layout that gave it too little height, a button narrower than its text)."""
    if isinstance(widget, QLabel) and widget.wordWrap():
        return widget.height() < widget.heightForWidth(widget.width())
    least = widget.minimumSizeHint()
    if isinstance(widget, QLabel):
        least = least.expandedTo(widget.sizeHint())
    return widget.width() < least.width() or widget.height() < least.height()


def details(window: QWidget) -> dict[str, dict[str, object]]:
    """Each DETAILS part the window has: shown, where, whole, squeezed."""
    found: dict[str, dict[str, object]] = {}
    for name in DETAILS:
        widget = window.findChild(QWidget, name)
        if widget is None:
            continue
        found[name] = {
            "visible": widget.isVisible(),
            "rect": list(QRect(widget.mapTo(window, QPoint(0, 0)), widget.size()).getRect()),
            "whole": whole(widget),
            "squeezed": widget.isVisible() and squeezed(widget),
        }
    return found


def columns(window: QWidget) -> dict[str, dict[str, object]]:
    """Each TABLES table shown: its viewport's width and, per column, the header, its width,
    the width its header and the rows on screen need, and how the header resizes it."""
    found: dict[str, dict[str, object]] = {}
    for name in TABLES:
        table = window.findChild(QTableView, name)
        if table is None or not table.isVisible():
            continue
        header = table.horizontalHeader()
        model = table.model()
        found[name] = {
            "viewport": table.viewport().width(),
            "columns": [
                {
                    "title": str(model.headerData(column, header.orientation())),
                    "hidden": table.isColumnHidden(column),
                    "width": table.columnWidth(column),
                    "needed": max(table.sizeHintForColumn(column), header.sectionSizeHint(column)),
                    "mode": _MODES.get(header.sectionResizeMode(column), "?"),
                }
                for column in range(model.columnCount())
            ],
        }
    return found


def tab_bars(window: QWidget) -> list[dict[str, object]]:
    """The dock tab bars and the views' tab bar shown: each tab's text and rectangle in the
    window, and the current."""
    found: list[dict[str, object]] = []
    for bar in window.findChildren(QTabBar):
        parent = bar.parentWidget()
        views = parent is not None and parent.objectName() == "viewTabs"
        if not bar.isVisible() or (parent is not window and not views):
            continue
        origin = bar.mapTo(window, QPoint(0, 0))
        found.append(
            {
                "current": bar.tabText(bar.currentIndex()),
                "tabs": [
                    {
                        "text": bar.tabText(index),
                        "rect": list(bar.tabRect(index).translated(origin).getRect()),
                    }
                    for index in range(bar.count())
                ],
            }
        )
    return found
