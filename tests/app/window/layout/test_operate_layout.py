"""Issue 28 item 20: Operate's controls in one column at the left, the position views as tabs
filling the centre; a state saved by the old arrangement does not bring it back."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QDockWidget

from app.window.layout.arrangements import OPERATE
from app.window.layout.layouts import KEY
from app.window.main_window import MainWindow
from widgets.view_tabs import VIEW_2D, ViewTabs

pytestmark = pytest.mark.timeout(60)

LEFT = Qt.DockWidgetArea.LeftDockWidgetArea
BOTTOM = Qt.DockWidgetArea.BottomDockWidgetArea


def _dock(window: MainWindow, name: str) -> QDockWidget:
    dock = window.findChild(QDockWidget, name)
    assert dock is not None, name
    return dock


def _open(qtbot) -> MainWindow:
    window = MainWindow()
    qtbot.addWidget(window)
    window.resize(1024, 640)
    window.show()
    qtbot.waitExposed(window)
    qtbot.waitUntil(window.views.is_ready, timeout=10_000)
    for _ in range(5):
        QApplication.processEvents()
    return window


def test_the_views_are_tabs_and_the_controls_a_column(qtbot) -> None:
    window = _open(qtbot)
    assert isinstance(window.centralWidget(), ViewTabs)
    assert window.view3d.isVisible() and not window.view2d.isVisible()
    for name in ("positionReadoutDock", "jogPanelDock", "speedControlDock"):
        assert window.dockWidgetArea(_dock(window, name)) == LEFT, name
    assert window.dockWidgetArea(_dock(window, "coordinateEntryDock")) == BOTTOM
    share = window.view3d.width() * window.view3d.height() / (window.width() * window.height())
    assert share >= 1 / 3, share
    window.view_tabs.setCurrentIndex(VIEW_2D)
    assert window.view2d.isVisible() and window.view2d.width() == window.view3d.width()


def test_a_state_saved_by_the_old_arrangement_is_not_restored(qtbot) -> None:
    window = _open(qtbot)
    speed = _dock(window, "speedControlDock")
    window.addDockWidget(BOTTOM, speed)  # the old Operate had Speed under the views
    old = window.saveState(22)  # the old arrangement's version
    window.close()  # (keeps its own state: replaced by the old one next)
    window.settings.setValue(KEY.format(name=OPERATE), old)
    window.settings.sync()
    again = _open(qtbot)
    assert again.dockWidgetArea(_dock(again, "speedControlDock")) == LEFT
