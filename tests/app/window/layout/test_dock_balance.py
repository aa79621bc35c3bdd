"""The left panels share their column: none scrolls while another has room to spare."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QDockWidget, QLabel, QMainWindow, QWidget

from app.window.layout.dock_balance import DockBalance, balanced_heights, kept_height, need, stacked

pytestmark = pytest.mark.timeout(60)
LEFT = Qt.DockWidgetArea.LeftDockWidgetArea
BOTTOM = Qt.DockWidgetArea.BottomDockWidgetArea


def test_the_cramped_panel_gets_its_height_and_the_spare_goes_last() -> None:
    assert balanced_heights([100, 100, 100], [60, 180, 40]) == [60, 180, 60]
    assert balanced_heights([100, 100, 100], [60, 90, 40]) is None  # none is short
    assert balanced_heights([100, 100, 100], [150, 180, 40]) is None  # no room: they scroll


class Tall(QLabel):
    """A panel asking for a given height."""

    def __init__(self, height: int) -> None:
        super().__init__("panel")
        self._height = height

    def sizeHint(self) -> QSize:
        return QSize(120, self._height)

    def minimumSizeHint(self) -> QSize:
        return QSize(120, 20)


def _dock(window: QMainWindow, name: str, height: int) -> QDockWidget:
    dock = QDockWidget(name, window)
    dock.setObjectName(name)
    dock.setWidget(Tall(height))
    return dock


def _window(qtbot, heights: list[int]) -> tuple[QMainWindow, list[QDockWidget], QDockWidget]:
    window = QMainWindow()
    qtbot.addWidget(window)
    window.setCentralWidget(QWidget())
    docks = []
    for number, height in enumerate(heights):
        dock = _dock(window, f"dock{number}", height)
        window.addDockWidget(LEFT, dock)
        docks.append(dock)
    bottom = _dock(window, "bottom", 300)
    window.addDockWidget(BOTTOM, bottom)
    window.setCorner(Qt.Corner.BottomLeftCorner, LEFT)
    window.resize(900, 800)
    window.show()
    qtbot.waitExposed(window)
    return window, docks, bottom


def test_a_window_gives_a_cramped_panel_its_height_and_keeps_the_bottom_dock(qtbot) -> None:
    window, docks, bottom = _window(qtbot, [40, 420, 40])
    window.resizeDocks(docks, [240, 240, 240], Qt.Orientation.Vertical)  # the tall one is short
    qtbot.waitUntil(lambda: docks[1].height() < docks[1].sizeHint().height())
    assert stacked(window, LEFT) == docks
    bottom_height = bottom.height()
    balance = DockBalance(window, LEFT)
    balance.start()
    qtbot.waitUntil(lambda: docks[1].height() >= docks[1].sizeHint().height())
    assert docks[0].height() >= docks[0].sizeHint().height()
    assert bottom.height() == bottom_height  # the other areas keep their heights
    window.resize(900, 700)  # a resize balances again
    qtbot.waitUntil(lambda: window.height() == 700)
    qtbot.waitUntil(lambda: docks[1].height() >= docks[1].sizeHint().height())


def test_a_tab_hidden_behind_another_is_not_counted(qtbot) -> None:
    window, docks, _ = _window(qtbot, [40, 120, 40])
    extra = QDockWidget("tab", window)
    extra.setObjectName("tab")
    extra.setWidget(Tall(60))
    window.tabifyDockWidget(docks[2], extra)
    docks[2].raise_()
    qtbot.waitUntil(lambda: extra.visibleRegion().isEmpty())
    assert extra not in stacked(window, LEFT)
    assert docks[2] in stacked(window, LEFT)


def _scrolling(window) -> list[str]:
    from widgets.panel_scroll_area import PanelScrollArea

    return [
        dock.objectName()
        for dock in stacked(window, LEFT)
        if isinstance(dock.widget(), PanelScrollArea)
        and dock.widget().verticalScrollBar().isVisible()
    ]


def test_the_main_window_shows_every_left_panel_whole_when_there_is_room(qtbot, window) -> None:
    """At 1600×1000 the jog panel used to scroll while Go to and Speed had room to spare."""
    window.resize(1000, 600)
    qtbot.waitUntil(lambda: window.height() == 600)
    window.resize(1600, 1000)
    qtbot.waitUntil(lambda: window.height() == 1000)
    qtbot.waitUntil(lambda: _scrolling(window) == [])
    for dock in stacked(window, LEFT):
        assert dock.height() >= dock.sizeHint().height(), dock.objectName()


def test_a_column_too_short_for_all_keeps_the_top_panel_whole() -> None:
    """1024×640 (issue 28 item 26): the position panel whole, the lower panels give up room."""
    least = [96, 96, 96]
    assert balanced_heights([198, 197, 96], [243, 201, 154], least=least) == [243, 152, 96]
    assert balanced_heights([243, 152, 96], [243, 201, 154], least=least) is None  # done
    assert balanced_heights([100, 100, 100], [250, 200, 150], least=least) is None  # no room


def test_a_tab_brought_in_front_under_the_views_gets_its_height(qtbot) -> None:
    """Operate's Arc tab behind Go to: in front, it gets the height it needs (grow)."""
    window, _, bottom = _window(qtbot, [40, 40, 40])
    arc = QDockWidget("arc", window)
    arc.setObjectName("arc")
    arc.setWidget(Tall(420))
    window.tabifyDockWidget(bottom, arc)
    bottom.widget()._height = 100
    bottom.raise_()
    balance = DockBalance(window, BOTTOM, grow=True)
    balance.start()
    qtbot.waitUntil(lambda: bottom.height() == need(bottom) < 200)
    window.tabifiedDockWidgetActivated.emit(arc)  # as a click on its tab does
    arc.raise_()
    qtbot.waitUntil(lambda: arc.height() == need(arc) > 420)


# Issue 28 item 26: at 1024×640 Go to lost its tab bar's height, Home and Set Home cut.
def test_a_left_balance_keeps_the_height_of_a_tab_group_below(qtbot) -> None:
    window = QMainWindow()
    qtbot.addWidget(window)
    window.setCentralWidget(QWidget())
    docks = [_dock(window, f"left{n}", height) for n, height in enumerate((40, 420, 40))]
    for dock in docks:
        window.addDockWidget(LEFT, dock)
    goto, program = _dock(window, "goto", 150), _dock(window, "program", 150)
    window.addDockWidget(BOTTOM, goto)
    window.tabifyDockWidget(goto, program)
    goto.raise_()
    window.setCorner(Qt.Corner.BottomLeftCorner, LEFT)
    window.resize(900, 800)
    window.show()
    qtbot.waitExposed(window)
    window.resizeDocks([goto], [200], Qt.Orientation.Vertical)
    window.resizeDocks(docks, [240, 240, 240], Qt.Orientation.Vertical)  # the tall one is short
    qtbot.waitUntil(lambda: docks[1].height() < docks[1].sizeHint().height())
    qtbot.waitUntil(lambda: goto.height() > 0 and not goto.visibleRegion().isEmpty())
    height, group = goto.height(), kept_height(window, goto)
    assert group > height  # its tab bar is counted
    DockBalance(window, LEFT).start()
    qtbot.waitUntil(lambda: docks[1].height() >= docks[1].sizeHint().height())
    assert goto.height() == height  # (set in the same layout pass as the left column)
