"""A balance of the left column leaves a tab group under the views as it was, its tab bar
included (issue 28 item 26: at 1024×640 Go to lost its bar's height, Home and Set Home cut)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QDockWidget, QLabel, QMainWindow, QWidget

from app.window.dock_balance import DockBalance, kept_height

pytestmark = pytest.mark.timeout(60)
LEFT = Qt.DockWidgetArea.LeftDockWidgetArea
BOTTOM = Qt.DockWidgetArea.BottomDockWidgetArea


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
