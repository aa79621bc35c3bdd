"""ControlLinesBar: DTR/RTS toggles, CTS/DSR/CD/RI indicators, Break; in the connection bar."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QCheckBox, QLabel, QPushButton

from drivers.link.control_lines import ControlLines
from widgets.connection_bar import ConnectionBar
from widgets.control_lines_bar import ControlLinesBar

pytestmark = pytest.mark.timeout(30)

LEFT = Qt.MouseButton.LeftButton
POWERED = ControlLines(dtr=True, rts=False, cts=True, dsr=True, cd=False, ri=False)


@pytest.fixture
def bar(qtbot) -> ControlLinesBar:
    widget = ControlLinesBar()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def test_object_names_and_tooltips(bar: ControlLinesBar) -> None:
    assert bar.objectName() == "controlLines"
    names = {
        "dtrToggle": QCheckBox,
        "rtsToggle": QCheckBox,
        "ctsLed": QLabel,
        "dsrLed": QLabel,
        "cdLed": QLabel,
        "riLed": QLabel,
        "breakButton": QPushButton,
    }
    for name, kind in names.items():
        child = bar.findChild(kind, name)
        assert child is not None, name
        assert child.toolTip(), name
    assert "250 ms" in bar.break_button.toolTip()
    bar.set_connected(True)
    bar.set_lines(POWERED)
    for name, kind in names.items():
        assert bar.findChild(kind, name).toolTip(), name


def test_disconnected_everything_is_off_and_unknown(bar: ControlLinesBar) -> None:
    bar.set_lines(POWERED)  # lines of before, e.g.: not shown while disconnected
    for widget in (bar.dtr_toggle, bar.rts_toggle, bar.break_button):
        assert not widget.isEnabled()
    assert not bar.dtr_toggle.isChecked()
    assert all(bar.indicator_state(name) == "unknown" for name in ("cts", "dsr", "cd", "ri"))
    assert "not connected" in bar.cts_led.toolTip()


def test_set_lines_shows_them_and_emits_nothing(bar: ControlLinesBar, record) -> None:
    toggled = record(bar.line_toggled)
    bar.set_connected(True)
    bar.set_lines(POWERED)
    assert bar.dtr_toggle.isChecked() and not bar.rts_toggle.isChecked()
    assert bar.dtr_toggle.isEnabled() and bar.rts_toggle.isEnabled()
    assert bar.break_button.isEnabled()
    assert [bar.indicator_state(n) for n in ("cts", "dsr", "cd", "ri")] == [
        "on",
        "on",
        "off",
        "off",
    ]
    assert bar.cts_led.text() == "CTS"
    assert bar.cts_led.toolTip().endswith(": on") and bar.cd_led.toolTip().endswith(": off")
    bar.set_lines(ControlLines(dtr=False, rts=True, cts=False, dsr=True, cd=True, ri=None))
    assert not bar.dtr_toggle.isChecked() and bar.rts_toggle.isChecked()
    assert [bar.indicator_state(n) for n in ("cts", "dsr", "cd", "ri")] == [
        "off",
        "on",
        "on",
        "unknown",
    ]
    assert bar.ri_led.toolTip() == "this port cannot report RI"
    assert bar.ri_led.text() == "RI \N{EN DASH}"
    assert toggled == []
    assert bar.lines().ri is None


def test_user_toggles_emit(bar: ControlLinesBar, qtbot, record) -> None:
    toggled = record(bar.line_toggled)
    bar.set_connected(True)
    bar.set_lines(POWERED)
    qtbot.mouseClick(bar.dtr_toggle, LEFT)
    qtbot.mouseClick(bar.rts_toggle, LEFT)
    assert toggled == [("dtr", False), ("rts", True)]
    bar.rts_toggle.setFocus()
    qtbot.keyClick(bar.rts_toggle, Qt.Key.Key_Space)
    assert toggled[-1] == ("rts", False)


def test_break_button(bar: ControlLinesBar, qtbot, record) -> None:
    breaks = record(bar.break_requested)
    bar.set_connected(True)
    bar.set_lines(POWERED)
    qtbot.mouseClick(bar.break_button, LEFT)
    assert breaks == [()]


def test_a_port_without_modem_lines(bar: ControlLinesBar) -> None:
    bar.set_connected(True)
    bar.set_lines(ControlLines())  # a pseudo-terminal
    for widget in (bar.dtr_toggle, bar.rts_toggle, bar.break_button):
        assert not widget.isEnabled()
    for name in ("cts", "dsr", "cd", "ri"):
        assert bar.indicator_state(name) == "unknown"
        assert bar.indicators[name].toolTip() == f"this port cannot report {name.upper()}"
    assert "cannot set DTR" in bar.dtr_toggle.toolTip()


def test_indicators_keep_their_width(bar: ControlLinesBar) -> None:
    bar.set_connected(True)
    widths = [led.width() for led in bar.indicators.values()]
    bar.set_lines(POWERED)
    assert [led.width() for led in bar.indicators.values()] == widths


def test_in_the_connection_bar(qtbot) -> None:
    connection = ConnectionBar()
    qtbot.addWidget(connection)
    connection.set_protocols(["coxiris", "visiomex", "pi-frame", "firmata", "laser-frame"])
    connection.show()
    lines = connection.control_lines
    assert isinstance(lines, ControlLinesBar)
    assert connection.findChild(ControlLinesBar, "controlLines") is lines
    assert connection.objectName() == "connectionBar"
    assert connection.findChild(QPushButton, "connectButton") is connection.connect_button
    # a row of its own, under the connection's: the bar is no wider for it
    assert lines.mapTo(connection, lines.rect().topLeft()).y() > connection.connect_button.y()
    assert connection.minimumSizeHint().width() <= 1024
    connection.set_state("connected")  # a bridge is "connected" too, with no worker's port:
    assert not lines.dtr_toggle.isEnabled()  # the window enables the lines, not the state
