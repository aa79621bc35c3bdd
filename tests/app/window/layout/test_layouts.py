"""The window's three layouts (Operate, Set up, Traffic): switched by menu, shortcut and switcher,
remembered per layout across a restart, reset; each one's controls whole at laptop sizes."""

from __future__ import annotations

from itertools import permutations
from pathlib import Path

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtGui import QAction, QRegion
from PySide6.QtWidgets import QApplication, QDockWidget, QToolButton, QWidget

from app.window.layout.arrangements import NAMES, OPERATE, SETUP, TRAFFIC
from app.window.main_window import MainWindow

pytestmark = pytest.mark.timeout(60)

SIZES = [(1280, 720), (1024, 640)]


def _connect(
    qtbot,
    win: MainWindow,
    url: str = "sim://coxiris?speed=100",
    protocol: str = "coxiris",
    baud: int = 115200,
    variant: str | None = None,
) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(url, protocol, baud, variant)


def _action(win: MainWindow, name: str) -> QAction:
    action = win.findChild(QAction, name)
    assert action is not None, name
    return action


def _dock(win: MainWindow, name: str) -> QDockWidget:
    dock = win.findChild(QDockWidget, name)
    assert dock is not None, name
    return dock


def _whole(widget: QWidget) -> bool:
    """Shown, and not clipped by a scroll area, a neighbour or the window's edge."""
    if not widget.isVisible() or widget.width() <= 0 or widget.height() <= 0:
        return False
    region = QRegion(widget.visibleRegion())  # (less its opaque children: added back below)
    for child in widget.findChildren(QWidget):
        if child.isVisible():
            origin = child.mapTo(widget, QPoint(0, 0))
            region += child.visibleRegion().translated(origin)
    return region.intersected(QRegion(widget.rect())) == QRegion(widget.rect())


def _seen(widget: QWidget) -> bool:
    """Shown to the operator: not only isVisible() (a dock tab behind another is "visible", moved
    off the window), but some of it painted, inside the window."""
    if not widget.isVisible() or widget.visibleRegion().isEmpty():
        return False
    window = widget.window()
    origin = widget.mapTo(window, QPoint(0, 0))
    return window.rect().intersects(widget.rect().translated(origin))


def _settle(qtbot, win: MainWindow, width: int, height: int) -> None:
    win.resize(width, height)
    qtbot.waitUntil(lambda: win.width() == width and win.height() == height, timeout=3000)
    for _ in range(5):  # the dock balance runs from a zero timer after the resize
        QApplication.processEvents()
        qtbot.wait(20)


def _controls(win: MainWindow, layout: str) -> list[QWidget]:
    if layout == OPERATE:
        c = win.coordinates
        return [
            win.readout,
            win.jog_panel,
            c.go_button,
            c.home_button,
            c.set_home_button,
            c.stop_button,
            win.speed,
            win.status_line,
        ]
    if layout == SETUP:
        return [win.readout, win.jog_panel, win.tools.macros.panel, win.status_line]
    console = win.console
    compact = win.layouts.compact
    assert compact is not None
    return [compact, console.view, console.send_line, win.timeline, win.status_line]


def test_switching_by_menu_shortcut_and_switcher(qtbot, window: MainWindow) -> None:
    assert window.layouts.current == OPERATE and _action(window, "layoutOperate").isChecked()
    assert window.view_tabs.isVisible() and not window.console_dock.isVisible()
    for name in ("layoutSwitchOperate", "layoutSwitchSetup", "layoutSwitchTraffic"):
        button = window.findChild(QToolButton, name)
        assert button is not None and button.isVisible(), name
    _action(window, "layoutTraffic").trigger()
    assert window.layouts.current == TRAFFIC and _action(window, "layoutTraffic").isChecked()
    assert _seen(window.console_dock) and _seen(window.timeline_dock)
    assert not window.view_tabs.isVisible() and not window.jog_panel.isVisible()
    qtbot.keyClick(window, Qt.Key.Key_2, Qt.KeyboardModifier.ControlModifier)
    assert window.layouts.current == SETUP and _action(window, "layoutSetup").isChecked()
    assert _seen(window.tools.macro_dock) and not window.console_dock.isVisible()
    qtbot.mouseClick(
        window.findChild(QToolButton, "layoutSwitchOperate"), Qt.MouseButton.LeftButton
    )
    assert window.layouts.current == OPERATE
    qtbot.keyClick(window, Qt.Key.Key_3, Qt.KeyboardModifier.ControlModifier)
    assert window.layouts.current == TRAFFIC
    qtbot.keyClick(window, Qt.Key.Key_1, Qt.KeyboardModifier.ControlModifier)
    assert window.layouts.current == OPERATE and _seen(window.coordinates)


def test_each_layout_keeps_its_changes_across_a_restart_until_reset(qtbot, tmp_path: Path) -> None:
    first = MainWindow()
    qtbot.addWidget(first)
    first.show()
    qtbot.waitUntil(first.views.is_ready, timeout=10_000)
    first.layouts.switch(TRAFFIC)
    first.timeline_dock.close()  # the operator's own change to Traffic
    first.layouts.switch(OPERATE)
    assert first.coordinates_dock.isVisible()
    first.coordinates_dock.close()  # and to Operate
    first.close()
    assert (tmp_path / "settings.ini").exists()

    second = MainWindow()
    qtbot.addWidget(second)
    second.show()
    qtbot.waitUntil(second.views.is_ready, timeout=10_000)
    assert second.layouts.current == OPERATE  # the panel opens in Operate, as left
    assert not second.coordinates_dock.isVisible() and second.jog_panel.isVisible()
    _action(second, "layoutTraffic").trigger()
    assert second.console_dock.isVisible() and not second.timeline_dock.isVisible()
    _action(second, "layoutReset").trigger()
    assert second.timeline_dock.isVisible() and second.console_dock.isVisible()
    _action(second, "layoutOperate").trigger()
    assert not second.coordinates_dock.isVisible()  # Reset put back Traffic only
    _action(second, "layoutReset").trigger()
    assert second.coordinates_dock.isVisible()
    second.close()


def test_a_device_with_parameters_is_offered_set_up_not_switched(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://visiomex?instant=1", "visiomex", 9600, "seed")
    assert window.layouts.current == OPERATE  # never switched by itself
    assert not _dock(window, "parameterEditor").isVisible()
    offer = window.layouts.offer
    assert offer.isVisible() and "Ctrl+2 for Set up" in offer.text()
    window.layouts.switch(SETUP)
    dock = _dock(window, "parameterEditor")
    assert _seen(dock) and _whole(window.parameters.editor) and not offer.isVisible()
    window.layouts.switch(OPERATE)
    assert not dock.isVisible()


@pytest.mark.parametrize("layout", [OPERATE, SETUP, TRAFFIC])
def test_every_control_of_the_layout_is_whole_at_laptop_sizes(
    qtbot, window: MainWindow, layout: str
) -> None:
    _connect(qtbot, window)
    window.layouts.switch(layout)
    for width, height in SIZES:
        _settle(qtbot, window, width, height)
        for control in _controls(window, layout):
            assert _whole(control), (layout, width, height, control.objectName())
        if layout == OPERATE:
            views = window.view_tabs
            assert views.isVisible()
            share = views.width() * views.height() / (width * height)
            if (width, height) == (1280, 720):
                assert share >= 1 / 3, share
            assert not window.console_dock.isVisible()
        if layout == TRAFFIC:
            view = window.console.view
            assert not view.horizontalScrollBar().isVisible(), (width, height)
            header = view.horizontalHeader()
            if (width, height) == (1280, 720):
                assert header.length() <= view.viewport().width()
                for column in range(header.count()):
                    assert header.sectionSize(column) >= 40 or header.isSectionHidden(column)
            assert window.console_dock.width() == window.width()
            assert window.timeline_dock.width() == window.width()
            assert not _dock(window, "positionReadoutDock").isVisible()  # a line instead


def test_set_up_shows_twelve_parameter_rows_at_1280_by_720(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://visiomex?instant=1", "visiomex", 9600, "seed")
    window.layouts.switch(SETUP)
    _settle(qtbot, window, 1280, 720)
    table = window.parameters.editor.table
    viewport = table.viewport()
    whole = [
        row
        for row in range(table.model().rowCount())
        if not table.isRowHidden(row)
        and table.rowViewportPosition(row) >= 0
        and table.rowViewportPosition(row) + table.rowHeight(row) <= viewport.height()
    ]
    assert _whole(viewport)
    assert len(whole) >= 12, len(whole)


def test_traffic_shows_the_position_on_one_line(qtbot, window: MainWindow) -> None:
    compact = window.layouts.compact
    assert compact is not None and not compact.isVisible()  # Operate has the large readout
    window.layouts.switch(TRAFFIC)
    assert compact.isVisible()
    window.readout.set_axes_enabled("xy")
    window.readout.set_position(1.5, -2.25, 0.0)
    assert compact.text() == "X 1.50 mm  Y -2.25 mm"
    window.readout.set_status("estimated")
    assert "estimated" in compact.toolTip()
    window.layouts.switch(SETUP)
    assert not compact.isVisible()


def _drag(qtbot, win: MainWindow, start: QPoint, dy: int) -> None:
    """The operator drags the window's dock separator at `start` by `dy` pixels."""
    qtbot.mouseMove(win, start)  # (over the separator first, as a hand gets there)
    QApplication.processEvents()
    qtbot.mousePress(win, Qt.MouseButton.LeftButton, pos=start)
    for step in range(1, 5):
        QApplication.processEvents()
        qtbot.mouseMove(win, start + QPoint(0, dy * step // 4))
    QApplication.processEvents()
    qtbot.mouseRelease(win, Qt.MouseButton.LeftButton, pos=start + QPoint(0, dy))


def test_traffic_keeps_the_operators_split_across_resizes(qtbot, window: MainWindow) -> None:
    window.layouts.switch(TRAFFIC)
    _settle(qtbot, window, 1280, 720)
    timeline, console = window.timeline_dock, window.console_dock
    before = timeline.height()
    gap = (timeline.geometry().bottom() + console.geometry().top()) // 2
    _drag(qtbot, window, QPoint(window.width() // 2, gap), -50)  # a smaller timeline
    qtbot.waitUntil(lambda: timeline.height() <= before - 40, timeout=3000)
    share = timeline.height() / (timeline.height() + console.height())
    for width, height in ((1024, 640), (1600, 1000), (1280, 720)):
        _settle(qtbot, window, width, height)
        now = timeline.height() / (timeline.height() + console.height())
        assert abs(now - share) < 0.02, (width, height, now, share)


def _after_switch(qtbot, win: MainWindow, name: str) -> None:
    """Switch to `name` and wait until the layout has settled (its deferred sizing done)."""
    win.layouts.switch(name)
    qtbot.waitUntil(lambda: win.layouts.held is None, timeout=3000)
    QApplication.processEvents()  # (a layout request posted last)


@pytest.mark.parametrize("device", ["coxiris", "visiomex"])
@pytest.mark.parametrize("size", SIZES, ids=[f"{w}x{h}" for w, h in SIZES])
def test_a_layout_switch_never_changes_the_window_size(
    qtbot, window: MainWindow, size: tuple[int, int], device: str
) -> None:
    """Every layout after every other, in every order, without a resize in between: the window
    keeps its size (once the docks shown in their old places widened it for good)."""
    if device == "visiomex":
        _connect(qtbot, window, "sim://visiomex?instant=1", "visiomex", 9600, "seed")
    else:
        _connect(qtbot, window)
    window.resize(*size)
    qtbot.waitUntil(lambda: window.size().toTuple() == size, timeout=3000)
    seen = []
    for order in permutations(NAMES):
        for name in order:
            _after_switch(qtbot, window, name)
            seen.append((name, window.size().toTuple()))
    assert [entry for entry in seen if entry[1] != size] == [], seen
    assert window.minimumSizeHint().width() <= size[0]


def test_set_up_puts_a_new_devices_parameters_in_front(qtbot, window: MainWindow) -> None:
    """Set up kept with Macros in front (a device without parameters); then a Visiomex device:
    in Set up its parameters are the tab in front, all of the editor painted."""
    _connect(qtbot, window)
    window.resize(1280, 720)
    _after_switch(qtbot, window, SETUP)
    assert _seen(window.tools.macro_dock)
    _after_switch(qtbot, window, OPERATE)
    window.disconnect_device()
    _connect(qtbot, window, "sim://visiomex?instant=1", "visiomex", 9600, "seed")
    _after_switch(qtbot, window, SETUP)
    dock = _dock(window, "parameterEditor")
    assert _seen(dock), dock.geometry()
    assert _whole(window.parameters.editor)
    assert not _seen(window.tools.macro_dock)  # behind it, as a tab
    assert window.tabifiedDockWidgets(dock)
