"""ConnectionBar: ports, protocols, baud, connect/disconnect, states."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from widgets.connection_bar import COMMON_BAUDS, ConnectionBar

LEFT = Qt.MouseButton.LeftButton
PORTS = [("/dev/ttyUSB0", "FTDI FT232R"), ("/dev/ttyACM0", "Arduino Uno")]


@pytest.fixture
def bar(qtbot) -> ConnectionBar:
    widget = ConnectionBar()
    qtbot.addWidget(widget)
    widget.set_ports(PORTS)
    widget.set_protocols(["coxiris", "visiomex"])
    widget.show()
    return widget


def test_object_names_and_tooltips(bar: ConnectionBar) -> None:
    assert bar.objectName() == "connectionBar"
    for widget in (bar.port_combo, bar.protocol_combo, bar.baud_combo, bar.refresh_button):
        assert widget.toolTip()
    assert bar.port_combo.isEditable()
    assert bar.baud_combo.isEditable()
    assert 115200 in COMMON_BAUDS
    assert bar.baud() == 115200


def test_set_ports_keeps_the_selection(bar: ConnectionBar) -> None:
    bar.set_port("/dev/ttyACM0")
    assert bar.description_label.text() == "Arduino Uno"
    bar.set_ports([("/dev/ttyS0", "built-in"), *reversed(PORTS)])
    assert bar.port() == "/dev/ttyACM0"
    assert bar.description_label.text() == "Arduino Uno"
    assert bar.port_combo.itemData(0, Qt.ItemDataRole.ToolTipRole) == "built-in"


def test_a_typed_url_survives_a_refresh(bar: ConnectionBar, qtbot) -> None:
    bar.port_combo.lineEdit().clear()
    qtbot.keyClicks(bar.port_combo.lineEdit(), "sim://coxiris?speed=50")
    bar.set_ports(PORTS)
    assert bar.port() == "sim://coxiris?speed=50"


def test_refresh_button(bar: ConnectionBar, qtbot, record) -> None:
    calls = record(bar.refresh_requested)
    qtbot.mouseClick(bar.refresh_button, LEFT)
    assert calls == [()]


def test_protocols(bar: ConnectionBar, qtbot, record) -> None:
    calls = record(bar.protocol_changed)
    bar.set_protocol("visiomex")
    bar.set_protocols(["laser", "visiomex", "coxiris"])
    assert bar.protocol() == "visiomex"
    assert calls == []  # programmatic changes are silent
    qtbot.keyClick(bar.protocol_combo, Qt.Key.Key_Down)  # the user picks the next one
    assert calls == [("coxiris",)]
    assert bar.set_protocol("nope") is False  # e.g. a stale setting: the selection stays
    assert bar.protocol() == "coxiris"
    assert calls == [("coxiris",)]


def test_baud(bar: ConnectionBar) -> None:
    bar.set_baud(9600)
    assert bar.baud() == 9600
    bar.set_baud(123456)  # any rate, not only common ones
    assert bar.baud() == 123456
    bar.baud_combo.setCurrentText("")
    assert bar.baud() is None
    bar.set_baud(9600)
    assert bar.set_baud(0) is False  # ignored
    assert bar.baud() == 9600


def test_connect_and_disconnect(bar: ConnectionBar, qtbot, record) -> None:
    connects, disconnects = record(bar.connect_requested), record(bar.disconnect_requested)
    bar.set_port("/dev/ttyACM0")
    bar.set_baud(57600)
    qtbot.mouseClick(bar.connect_button, LEFT)
    assert connects == [("/dev/ttyACM0", "coxiris", 57600)]
    bar.set_state("connecting")
    assert bar.connect_button.text() == "Cancel"
    assert not bar.port_combo.isEnabled()
    qtbot.mouseClick(bar.connect_button, LEFT)
    bar.set_state("connected")
    assert bar.connect_button.text() == "Disconnect"
    qtbot.mouseClick(bar.connect_button, LEFT)
    assert disconnects == [(), ()]
    bar.set_state("disconnected")
    assert bar.connect_button.text() == "Connect"
    assert bar.port_combo.isEnabled()


@pytest.mark.parametrize(
    ("state", "text", "colour"),
    [
        ("disconnected", "Disconnected", "#616161"),
        ("connecting", "Connecting", "#ef6c00"),
        ("connected", "Connected", "#2e7d32"),
        ("error", "Error", "#c62828"),
    ],
)
def test_states_are_shown(bar: ConnectionBar, state: str, text: str, colour: str) -> None:
    bar.set_state(state)
    assert bar.state() == state
    assert text in bar.state_label.text()
    assert colour in bar.state_label.styleSheet()


def test_error_detail_and_bad_state(bar: ConnectionBar) -> None:
    bar.set_state("error", "port busy")
    assert bar.state_label.text().endswith("Error: port busy")
    with pytest.raises(ValueError):
        bar.set_state("sleeping")


def test_missing_port_is_reported_not_emitted(bar: ConnectionBar, qtbot, record) -> None:
    calls = record(bar.connect_requested)
    bar.port_combo.setEditText("  ")
    qtbot.mouseClick(bar.connect_button, LEFT)
    assert calls == []
    assert bar.state() == "error"
    assert "port" in bar.state_label.text()
