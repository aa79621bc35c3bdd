"""The left panels share their column so that none scrolls while another has room to spare."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt, QTimer
from PySide6.QtWidgets import QDockWidget, QMainWindow, QTabBar

OTHER_AREAS = (
    Qt.DockWidgetArea.LeftDockWidgetArea,
    Qt.DockWidgetArea.RightDockWidgetArea,
    Qt.DockWidgetArea.TopDockWidgetArea,
    Qt.DockWidgetArea.BottomDockWidgetArea,
)


def stacked(window: QMainWindow, area: Qt.DockWidgetArea) -> list[QDockWidget]:
    """The docks shown one above the other in `area`, top first (of a tab group, the tab shown)."""
    shown = [
        dock
        for dock in window.findChildren(QDockWidget)
        if dock.isVisible()
        and not dock.isFloating()
        and window.dockWidgetArea(dock) == area
        and not (window.tabifiedDockWidgets(dock) and dock.visibleRegion().isEmpty())
    ]
    return sorted(shown, key=lambda dock: dock.geometry().top())


def balanced_heights(heights: list[int], needs: list[int], grow: bool = False) -> list[int] | None:
    """New heights giving each dock what it needs and the spare to the last one; None when no
    dock is short of room, or when the column cannot hold them all (then they scroll). `grow`:
    the docks' area may grow or shrink (the central widget takes the rest): each gets exactly
    what it needs."""
    total = sum(heights)
    if grow:  # each exactly what it needs
        return None if heights == needs else list(needs)
    if all(have >= need for have, need in zip(heights, needs, strict=True)):
        return None
    if sum(needs) > total:
        return None
    new = list(needs)
    new[-1] += total - sum(needs)
    return new


def _tab_bar_height(window: QMainWindow, dock: QDockWidget) -> int:
    """The height of the tab bar under `dock` when it is in a tab group (0: it is not): the
    group's height holds it besides the dock's."""
    if not window.tabifiedDockWidgets(dock):
        return 0
    title = dock.windowTitle()
    for bar in window.findChildren(QTabBar, options=Qt.FindChildOption.FindDirectChildrenOnly):
        if bar.isVisible() and any(bar.tabText(i) == title for i in range(bar.count())):
            return bar.height()
    return 0


class DockBalance(QObject):
    """Watches the window's size: once started and after each resize, a panel in `area` that would
    scroll while another panel has spare room is given its full height (the spare goes to the
    bottom panel). A separator the operator drags stays where it is until the next resize.
    `grow`: the area may take room from the central widget for its panels (the panels under the
    views)."""

    def __init__(self, window: QMainWindow, area: Qt.DockWidgetArea, grow: bool = False) -> None:
        super().__init__(window)
        self.window = window
        self.area = area
        self.grow = grow
        self.started = False
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(0)
        self._timer.timeout.connect(self.balance)

    def start(self) -> None:
        """Balance now (once the layout has settled) and after every resize of the window; called
        when the docks built after the first paint are in (their sizes count)."""
        self.window.installEventFilter(self)
        self.started = True
        self._timer.start()

    def request(self) -> None:
        """Balance once the layout has settled (after a new layout; nothing before `start`)."""
        if self.started:
            self._timer.start()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Balance once the layout has settled after a resize."""
        if watched is self.window and event.type() == QEvent.Type.Resize:
            self._timer.start()
        return False

    def balance(self) -> None:
        """Give cramped panels their height now, if the column has room for all of them."""
        central = self.window.centralWidget()
        if self.grow and (central is None or central.isHidden()):
            return  # nothing to take room from
        docks = stacked(self.window, self.area)
        if len(docks) < (1 if self.grow else 2):
            return
        for dock in docks:  # (a scroll area does not pass on its panel's new size hint)
            if (content := dock.widget()) is not None:
                content.updateGeometry()
        tabs = [_tab_bar_height(self.window, dock) for dock in docks]  # a tab group's bar
        heights = [dock.height() + tab for dock, tab in zip(docks, tabs, strict=True)]
        needs = [dock.sizeHint().height() + tab for dock, tab in zip(docks, tabs, strict=True)]
        new = balanced_heights(heights, needs, self.grow)
        if new is None:
            return
        # resizeDocks lays out every area again: the others keep their heights only if named
        others = [
            dock for area in OTHER_AREAS if area != self.area for dock in stacked(self.window, area)
        ]
        self.window.resizeDocks(
            docks + others, new + [dock.height() for dock in others], Qt.Orientation.Vertical
        )
