"""Enter in the Port field connects, with the key delivered as a keyboard delivers it: to the
widget that has the focus after a click on the field (the drop-down, not its inner text field)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QApplication, QWidget

from widgets.connection_bar import ConnectionBar

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def bar(qtbot) -> ConnectionBar:
    widget = ConnectionBar()
    qtbot.addWidget(widget)
    widget.set_ports([("/dev/ttyUSB0", "FTDI FT232R")])
    widget.set_protocols(["coxiris", "visiomex"])
    widget.show()
    widget.activateWindow()
    qtbot.waitActive(widget)
    return widget


def _focus_after_click(qtbot, bar: ConnectionBar) -> QWidget:
    """Click the port field as a mouse does; the widget that then has the keyboard focus."""
    edit = bar.port_combo.lineEdit()
    qtbot.mouseClick(edit, LEFT, pos=QPoint(5, edit.height() // 2))
    qtbot.waitUntil(lambda: QApplication.focusWidget() is not None, timeout=5000)
    return QApplication.focusWidget()


@pytest.mark.parametrize("key", (Qt.Key.Key_Return, Qt.Key.Key_Enter))
def test_enter_to_the_focus_widget_connects_once(qtbot, bar: ConnectionBar, record, key) -> None:
    calls = record(bar.connect_requested)
    focus = _focus_after_click(qtbot, bar)
    assert focus in (bar.port_combo, bar.port_combo.lineEdit())
    qtbot.keyClicks(focus, "sim://coxiris")
    qtbot.keyClick(QApplication.focusWidget(), key)
    assert calls == [("sim://coxiris", "coxiris", 115200)]


def test_enter_with_the_combo_itself_focused_connects(qtbot, bar: ConnectionBar, record) -> None:
    calls = record(bar.connect_requested)
    bar.set_port("/dev/ttyUSB0")
    bar.port_combo.setFocus(Qt.FocusReason.TabFocusReason)  # as Tab from the widget before
    qtbot.waitUntil(lambda: QApplication.focusWidget() is not None, timeout=5000)
    qtbot.keyClick(QApplication.focusWidget(), Qt.Key.Key_Return)
    assert calls == [("/dev/ttyUSB0", "coxiris", 115200)]


def test_enter_while_connected_does_nothing(qtbot, bar: ConnectionBar, record) -> None:
    bar.set_state("connected")
    bar.port_combo.setEnabled(True)  # even if the field could take keys
    connects, disconnects = record(bar.connect_requested), record(bar.disconnect_requested)
    bar.port_combo.setFocus(Qt.FocusReason.TabFocusReason)
    qtbot.waitUntil(lambda: QApplication.focusWidget() is not None, timeout=5000)
    qtbot.keyClick(QApplication.focusWidget(), Qt.Key.Key_Return)
    assert connects == [] and disconnects == []
