"""A `sim://NAME` port names its protocol (choosing it sets the protocol), and a device that
answers in another protocol's way is said to be one ("this looks like a Visiomex controller,
not COXIRIS")."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from app.window.main_window import MainWindow
from drivers.protocols.sniff import looks_like, sniff
from tests.support.simproc import SimProcess
from widgets.connection_bar import ConnectionBar, sim_protocol

pytestmark = pytest.mark.timeout(60)

WAIT_MS = 20_000
VISIOMEX_BOOT = b"Checkpoint 2\r\n"
LASER_ERROR = b"\xeb\x90\x82\xf0\x7f\xf2\x02\x00\x01\x90\x82t"  # its answer to `GET_ID\n`
FIRMATA_BOOT = (
    b"\xf9\x02\x05\xf0y\x02\x05F\x00i\x00r\x00m\x00a\x00t\x00a\x00P\x00l\x00u\x00s\x00.\x00"
    b"i\x00n\x00o\x00\xf7"
)
COXIRIS_REPLY = b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"


def test_sim_protocol_reads_the_name_of_a_sim_url() -> None:
    assert sim_protocol("sim://visiomex") == "visiomex"
    assert sim_protocol(" SIM://laser-frame?mute=1 ") == "laser-frame"
    assert sim_protocol("/dev/ttyUSB0") == ""
    assert sim_protocol("socket://host:1234") == ""


@pytest.mark.parametrize(
    ("data", "expected", "found"),
    (
        (VISIOMEX_BOOT, "coxiris", "visiomex"),
        (VISIOMEX_BOOT.rstrip(), "coxiris", "visiomex"),  # its CR LF not come yet
        (LASER_ERROR, "coxiris", "laser-frame"),
        (FIRMATA_BOOT, "coxiris", "firmata"),
        (COXIRIS_REPLY, "visiomex", "coxiris"),
        (COXIRIS_REPLY, "coxiris", None),  # its own: nothing to say
        (b"", "coxiris", None),
        (b"\x00\x01hello\xff\xfe", "coxiris", None),  # noise reads as nothing
    ),
)
def test_sniff_names_the_protocol_the_bytes_read_as(data, expected, found) -> None:
    assert sniff(data, expected) == found


def test_looks_like_says_it_in_a_sentence() -> None:
    assert looks_like(VISIOMEX_BOOT, "coxiris") == (
        "this looks like a Visiomex controller, not COXIRIS"
    )
    assert looks_like(COXIRIS_REPLY, "coxiris") is None


def test_choosing_a_sim_port_sets_its_protocol(qtbot) -> None:
    bar = ConnectionBar()
    qtbot.addWidget(bar)
    bar.set_protocols(["coxiris", "visiomex"])
    bar.set_ports([("sim://coxiris", "simulated"), ("sim://visiomex", "simulated")])
    bar.set_protocol("coxiris")
    changed: list[str] = []
    bar.protocol_changed.connect(changed.append)
    bar.show()
    bar.port_combo.setFocus()
    qtbot.keyClick(bar.port_combo, Qt.Key.Key_Down)  # the next item in the list, as a user does
    assert bar.port() == "sim://visiomex"
    assert bar.protocol() == "visiomex"
    assert changed == ["visiomex"]


@pytest.mark.e2e
def test_a_sim_url_typed_with_another_protocol_connects_with_its_own(
    qtbot, window: MainWindow
) -> None:
    bar = window.connection_bar
    bar.set_protocol("coxiris")
    bar.port_combo.lineEdit().clear()
    qtbot.keyClicks(bar.port_combo.lineEdit(), "sim://visiomex")
    assert bar.protocol() == "visiomex"
    with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
        qtbot.mouseClick(bar.connect_button, Qt.MouseButton.LeftButton)
    assert window.machine.info is not None and window.machine.info.protocol == "visiomex"


@pytest.mark.e2e
def test_connect_device_follows_the_protocol_a_sim_url_names(qtbot, window: MainWindow) -> None:
    with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
        window.connect_device("sim://visiomex", "coxiris", 115200)
    assert window.machine.info is not None and window.machine.info.protocol == "visiomex"
    assert window.connection_bar.protocol() == "visiomex"


def _sent(window: MainWindow) -> bytes:
    window.console.flush()
    return b"".join(data for direction, data, _ in window.console.records() if direction == "tx")


@pytest.mark.e2e
@pytest.mark.parametrize(("device", "said"), (("visiomex", "Visiomex"), ("laser-frame", "laser")))
def test_a_device_of_another_protocol_is_named_in_the_error(
    qtbot, window: MainWindow, device: str, said: str
) -> None:
    sim = SimProcess(device, "--instant", control=True)
    try:
        window.connect_device(sim.path, "coxiris", 115200)
        if device == "visiomex":
            # A Visiomex board says something only when it boots (it answers no COXIRIS line):
            # restarted while the panel waits for its identity, as opening its port does to
            # an Arduino (the simulator booted before the port was open).
            qtbot.waitUntil(lambda: b"GET_ID" in _sent(window), timeout=WAIT_MS)
            sim.fault("reboot")
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=WAIT_MS)
        message = window.status_line.message()
        assert f"this looks like a {said}" in message and "controller, not COXIRIS" in message
    finally:
        window.disconnect_device()
        sim.stop()
