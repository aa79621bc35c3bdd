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
    widget.resize(1400, widget.sizeHint().height())  # as in the window (a narrower one elides)
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


def test_enter_in_the_port_field_connects(bar: ConnectionBar, qtbot, record) -> None:
    connects, disconnects = record(bar.connect_requested), record(bar.disconnect_requested)
    edit = bar.port_combo.lineEdit()
    edit.clear()
    qtbot.keyClicks(edit, "sim://coxiris?mute=1")
    qtbot.keyClick(edit, Qt.Key.Key_Return)
    assert connects == [("sim://coxiris?mute=1", "coxiris", 115200)]
    bar.set_state("connected")
    bar.port_combo.setEnabled(True)  # even if the field could take keys, Enter does not disconnect
    qtbot.keyClick(edit, Qt.Key.Key_Return)
    assert connects == [("sim://coxiris?mute=1", "coxiris", 115200)]
    assert disconnects == []


def _button_x(bar: ConnectionBar) -> int:
    bar.layout().activate()
    return bar.connect_button.mapTo(bar, bar.connect_button.rect().topLeft()).x()


def test_the_connect_button_does_not_move(bar: ConnectionBar) -> None:
    bar.resize(1600, bar.sizeHint().height())
    bar.set_ports([("/dev/ttyS0", "x"), ("/dev/ttyUSB0", "FTDI FT232R USB UART " * 4)])
    bar.set_port("/dev/ttyS0")
    x = _button_x(bar)
    bar.set_port("/dev/ttyUSB0")  # a long description
    assert bar.description_label.text().endswith("…")  # elided; the whole text in the tooltip
    assert bar.description_label.toolTip().startswith("FTDI FT232R USB UART FTDI")
    assert _button_x(bar) == x
    bar.set_port("sim://nowhere")  # none
    assert _button_x(bar) == x
    for state in ("connecting", "connected", "disconnected", "error"):
        bar.set_state(state, "could not open port /dev/ttyUSB0: [Errno 16] Device or resource busy")
        assert _button_x(bar) == x, state
        bar.set_state(state)
        assert _button_x(bar) == x, state


def test_a_port_with_options_stays_after_refreshes_and_states(bar: ConnectionBar, qtbot) -> None:
    ports = [("sim://coxiris", "simulated coxiris device"), *PORTS]
    bar.set_ports(ports)
    edit = bar.port_combo.lineEdit()
    edit.clear()
    qtbot.keyClicks(edit, "sim://coxiris?mute=1")  # completed inline from the list on the way
    assert bar.port() == "sim://coxiris?mute=1"
    assert bar.description_label.toolTip() == "simulated coxiris device"  # options aside
    for state in ("connecting", "connected", "error", "disconnected"):
        bar.set_ports(ports)  # every 2 s
        assert bar.port() == "sim://coxiris?mute=1"
        bar.set_state(state)
        assert bar.port() == "sim://coxiris?mute=1"
        assert edit.text() == "sim://coxiris?mute=1"
    bar.set_ports([])  # the port list is gone for a moment
    bar.set_ports(ports)
    assert bar.port() == "sim://coxiris?mute=1"


def test_a_refresh_while_typing_keeps_the_cursor_and_the_inline_completion(
    bar: ConnectionBar, qtbot
) -> None:
    ports = [("sim://coxiris", "simulated coxiris device"), *PORTS]
    bar.set_ports(ports)
    edit = bar.port_combo.lineEdit()
    edit.clear()
    qtbot.keyClicks(edit, "sim://co")
    completed = edit.selectedText()  # e.g. "xiris", or "" without inline completion
    bar.set_ports(ports)
    assert edit.selectedText() == completed
    edit.setText("sim://coxiris")
    edit.setCursorPosition(6)
    bar.set_ports(list(reversed(ports)))
    assert edit.cursorPosition() == 6
    qtbot.keyClicks(edit, "x")
    assert bar.port() == "sim://xcoxiris"


def test_a_long_state_never_widens_the_bar(bar: ConnectionBar, qtbot) -> None:
    """A long error is elided to the room the bar has (a 1024 px screen): its minimum width
    stays, the whole text is in the tooltip."""
    minimum = bar.minimumSizeHint().width()
    bar.resize(minimum, bar.height())
    qtbot.waitUntil(lambda: bar.width() == minimum, timeout=3000)
    detail = "port /dev/ttyUSB0 is busy"
    bar.set_state("error", detail)
    assert bar.minimumSizeHint().width() == minimum
    assert bar.state_label.text().endswith("…")
    assert bar.state_label.toolTip() == detail
    bar.resize(1400, bar.height())
    qtbot.waitUntil(lambda: bar.state_label.text().endswith(detail), timeout=3000)  # whole


def test_the_variant_box_moves_nothing_before_it(bar: ConnectionBar, qtbot) -> None:
    """Issue 28 item 29: choosing a protocol with variants (Visiomex) shows the Variant box
    without moving Connect (or anything else the pointer may be on) along the bar."""
    bar.resize(1200, bar.sizeHint().height())
    bar.show()
    qtbot.waitExposed(bar)
    watched = (bar.protocol_combo, bar.baud_combo, bar.bridge_check, bar.connect_button)
    before = [widget.x() for widget in watched]
    bar.set_variants([("seed", "the seed firmware"), ("board12", "the 12-bit board")])
    qtbot.waitUntil(lambda: bar.variant_combo.isVisible() and bar.variant_combo.width() > 0)
    bar.layout().activate()
    assert [widget.x() for widget in watched] == before
    assert bar.variant_combo.x() > bar.connect_button.x()
