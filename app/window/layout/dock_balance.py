"""The left panels share their column so that none scrolls while another has room to spare."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt, QTimer
from PySide6.QtWidgets import QDockWidget, QMainWindow, QScrollArea, QTabBar

OTHER_AREAS = (
    Qt.DockWidgetArea.LeftDockWidgetArea,
    Qt.DockWidgetArea.RightDockWidgetArea,
    Qt.DockWidgetArea.TopDockWidgetArea,
    Qt.DockWidgetArea.BottomDockWidgetArea,
)

FORGET_MS = 100  # a balance's heights are applied by then (a later drag is the operator's)


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


def balanced_heights(
    heights: list[int], needs: list[int], grow: bool = False, least: list[int] | None = None
) -> list[int] | None:
    """New heights giving each dock what it needs and the spare to the last one; None when no
    dock is short of room. When the column cannot hold them all: None (they scroll), or with
    `least` (each dock's smallest height) the top docks get what they need and the lower ones
    give up room first, down to their least (None if even that does not fit). `grow`: the
    docks' area may grow or shrink (the central widget takes the rest): each gets exactly what
    it needs."""
    total = sum(heights)
    if grow:  # each exactly what it needs
        return None if heights == needs else list(needs)
    if all(have >= need for have, need in zip(heights, needs, strict=True)):
        return None
    if sum(needs) > total:
        new = _from_the_bottom(needs, least, total) if least is not None else None
        return None if new == heights else new
    new = list(needs)
    new[-1] += total - sum(needs)
    return new


def _from_the_bottom(needs: list[int], least: list[int], total: int) -> list[int] | None:
    """`needs` cut to `total`, the lowest docks first, none below its `least`; the top dock
    (the position) keeps what it needs. None: they do not fit even so."""
    new = list(needs)
    excess = sum(new) - total
    for index in reversed(range(1, len(new))):
        cut = min(excess, max(0, new[index] - least[index]))
        new[index] -= cut
        excess -= cut
        if excess <= 0:
            return new
    return None


def need(dock: QDockWidget) -> int:
    """The height `dock` needs to show its panel whole: its size hint, or, for a panel of wrapped
    text in a scroll area, the panel's height at the width it has (which the hint misses)."""
    hint = dock.sizeHint().height()
    content = dock.widget()
    panel = content.widget() if isinstance(content, QScrollArea) else None
    if panel is not None and panel.hasHeightForWidth():
        frame = dock.height() - content.viewport().height()
        hint = max(hint, frame + panel.heightForWidth(content.width()))
    return hint


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


def kept_height(window: QMainWindow, dock: QDockWidget) -> int:
    """The height to name for `dock` in a resizeDocks call that must leave it as it is: that of
    its tab group when it is in one (resizeDocks sizes the group, its tab bar included; the
    dock's own height would take the bar's height off the group, Go to under the views cut)."""
    return dock.height() + _tab_bar_height(window, dock)


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
        self._watched: set[QObject] = set()  # the panels whose layout requests are heard
        self._needs: dict[str, int] = {}  # each dock's need at the last balance
        self.asked: dict[str, int] = {}  # the heights just asked for, until the layout has them
        self._forget = QTimer(self)
        self._forget.setSingleShot(True)
        self._forget.setInterval(FORGET_MS)
        self._forget.timeout.connect(lambda: setattr(self, "asked", {}))
        window.tabifiedDockWidgetActivated.connect(self._tab_chosen)

    def _tab_chosen(self, dock: QDockWidget) -> None:
        """Another tab of a tab group in front (Arc after Go to): balance for what it needs."""
        if self.started and self.window.dockWidgetArea(dock) == self.area:
            self._timer.start()

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
        """Balance once the layout has settled after a resize, or after a panel's contents
        changed what it needs (a note set once the device is known, a line shown)."""
        resized = watched is self.window and event.type() == QEvent.Type.Resize
        if resized or (event.type() == QEvent.Type.LayoutRequest and self._changed(watched)):
            self._timer.start()
        return False

    def _watch(self, docks: list[QDockWidget]) -> None:
        """Hear each dock's panel asking for a new layout (installed once each)."""
        for dock in docks:
            panel = dock.widget()
            if isinstance(panel, QScrollArea):
                panel = panel.widget()
            if panel is not None and panel not in self._watched:
                self._watched.add(panel)
                panel.setProperty("balancedDock", dock.objectName())
                panel.installEventFilter(self)

    def _changed(self, panel: QObject) -> bool:
        """Whether the dock of `panel` needs another height than at the last balance."""
        name = panel.property("balancedDock")
        dock = self.window.findChild(QDockWidget, str(name)) if name else None
        if dock is None or not dock.isVisible() or name not in self._needs:
            return False
        return need(dock) + _tab_bar_height(self.window, dock) != self._needs[name]

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
        needs = [need(dock) + tab for dock, tab in zip(docks, tabs, strict=True)]
        least = [
            dock.minimumSizeHint().height() + tab for dock, tab in zip(docks, tabs, strict=True)
        ]
        self._needs = {dock.objectName(): height for dock, height in zip(docks, needs, strict=True)}
        self._watch(docks)
        new = balanced_heights(heights, needs, self.grow, least)
        if new is None:
            return
        # resizeDocks lays out every area again: the others keep their heights only if named
        others = [
            dock for area in OTHER_AREAS if area != self.area for dock in stacked(self.window, area)
        ]
        # (heights another balance has just asked for, not applied yet, are kept: not undone)
        asked = {
            name: height
            for peer in self.window.findChildren(DockBalance)
            if peer is not self
            for name, height in peer.asked.items()
        }
        self.window.resizeDocks(
            docks + others,
            new + [asked.get(dock.objectName(), kept_height(self.window, dock)) for dock in others],
            Qt.Orientation.Vertical,
        )
        self.asked = {dock.objectName(): height for dock, height in zip(docks, new, strict=True)}
        self._forget.start()
