"""Serial control lines: DTR/RTS toggles, modem inputs and breaks, on sim://, a pty and sockets."""

from __future__ import annotations

import os
import socket
import time
from collections.abc import Iterator

import pytest

from drivers.errors import BadInput, NoControlLines
from drivers.link.control_lines import ControlLines
from drivers.link.transport import Link, open_link
from drivers.sim.clock import ManualClock
from drivers.sim.coxiris_device import CoxirisDevice
from drivers.sim.faults import FaultyDevice
from drivers.sim.firmata_device import FirmataDevice
from drivers.sim.piframe_device import PiFrameDevice

pytestmark = pytest.mark.timeout(20)

VERSION = bytes.fromhex("F9 02 05")
NAME = (
    bytes.fromhex("F0 79 02 05")
    + b"".join(bytes((ord(c), 0)) for c in "FirmataPlus.ino")
    + bytes.fromhex("F7")
)
BANNER = VERSION + NAME
CONFIG_200 = bytes.fromhex("F0 72 00 48 01 08 09 F7")
STEP_500_AT_300 = bytes.fromhex("F0 72 01 2C 02 00 74 03 01 F7")  # 0.5 s at 300 rpm
SEED_LINEAR = bytes.fromhex("7B7D01 0064 0032 0000 0000 0000 0000 0000 0000 0000 0000 00 2A")
POWERED = ControlLines(dtr=True, rts=True, cts=True, dsr=True, cd=False, ri=False)


def _read_exactly(link: Link, count: int, seconds: float = 5.0) -> bytes:
    """Read until `count` bytes came (each read waits at most the link's poll interval)."""
    data = b""
    deadline = time.monotonic() + seconds
    while len(data) < count and time.monotonic() < deadline:
        data += link.read()
    return data


@pytest.fixture
def notes() -> list[str]:
    return []


@pytest.fixture
def firmata(notes: list[str]) -> Iterator[Link]:
    link = open_link("sim://firmata?reset_delay=0&line_timing=0", 57600)
    link.note_listeners.append(notes.append)
    assert _read_exactly(link, len(BANNER)) == BANNER
    yield link
    link.close()


# -- ControlLines ------------------------------------------------------------------------------
def test_describe_and_changes() -> None:
    assert POWERED.describe() == "DTR on, RTS on, CTS on, DSR on, CD off, RI off"
    assert ControlLines().describe() == "no modem control lines"
    assert ControlLines(dtr=True).describe().endswith("CTS ?, DSR ?, CD ?, RI ?")
    after = ControlLines(dtr=False, rts=True, cts=False, dsr=True, cd=False, ri=None)
    assert after.changes(POWERED) == ["DTR off", "CTS off", "RI ?"]
    assert POWERED.changes(POWERED) == []


# -- Link on sim:// ----------------------------------------------------------------------------
def test_sim_lines_reach_the_device_and_are_noted(firmata: Link, notes: list[str]) -> None:
    device = firmata.port.device
    assert firmata.control_lines() == POWERED
    firmata.set_control("rts", False)
    assert device.rts is False
    assert firmata.control_lines() == ControlLines(True, False, True, True, False, False)
    firmata.set_control("RTS", True)
    assert notes == ["RTS off", "RTS on"]
    assert device.resets == 0  # RTS is wired to nothing on an Uno
    with pytest.raises(BadInput, match="DTR or RTS"):
        firmata.set_control("cts", True)


def test_firmata_dtr_off_then_on_resets_the_board(firmata: Link, notes: list[str]) -> None:
    device = firmata.port.device
    firmata.write(CONFIG_200)
    firmata.read(wait=False)
    assert device.configured
    firmata.set_control("dtr", False)
    assert firmata.read(wait=False) == b""  # DTR released: nothing happens
    assert device.resets == 0 and device.configured
    firmata.set_control("dtr", True)  # asserted again: the auto-reset pulse
    assert _read_exactly(firmata, len(BANNER)) == BANNER  # the banner comes again
    assert device.resets == 1
    assert not device.configured  # the stepper must be configured again
    assert notes == ["DTR off", "DTR on"]


def test_firmata_dtr_on_when_on_changes_nothing(firmata: Link) -> None:
    firmata.set_control("dtr", True)
    assert firmata.port.device.resets == 0
    assert firmata.read(wait=False) == b""


def test_piframe_ignores_frames_while_dtr_is_off() -> None:
    link = open_link("sim://pi-frame?instant=1&line_timing=0", 115200, dtr=False)
    try:
        device = link.port.device
        assert device.dtr is False  # as asked at open
        link.write(SEED_LINEAR)
        assert device.position() == (0.0, 0.0, 0.0)
        assert device.ignored_bytes == len(SEED_LINEAR) and device.frames_ok == 0
        link.set_control("dtr", True)
        link.write(SEED_LINEAR)
        assert device.position() == (100.0, 50.0, 0.0)
        assert device.frames_ok == 1
    finally:
        link.close()


def test_open_link_sets_rts() -> None:
    link = open_link("sim://coxiris?line_timing=0", 115200, rts=False)
    try:
        assert link.port.device.rts is False
        assert link.control_lines().rts is False
    finally:
        link.close()


def test_a_break_is_noted_and_reaches_the_device_as_a_nul(notes: list[str]) -> None:
    link = open_link("sim://coxiris?line_timing=0", 115200)
    link.note_listeners.append(notes.append)
    try:
        link.send_break(0.01)
        assert link.port.device.breaks == 1
        assert notes == ["break 10 ms"]
        # The NUL stays in the line (only CR and LF end one) and empties its command.
        link.write(b"GET_ID\nGET_POSITION\n")
        assert _read_exactly(link, 40).startswith(b"ACK GET_POSITION\r\n")
        with pytest.raises(BadInput, match="break"):
            link.send_break(0)
    finally:
        link.close()


def test_loop_url_wires_rts_to_cts() -> None:
    link = open_link("loop://", 9600)
    try:
        assert link.control_lines().cts is True
        link.set_control("rts", False)
        assert link.control_lines().cts is False
    finally:
        link.close()


# -- ports without modem lines -----------------------------------------------------------------
def test_a_pty_has_no_modem_lines(notes: list[str]) -> None:
    master, slave = os.openpty()
    link = open_link(os.ttyname(slave), 115200, dtr=True)  # the open ignores DTR on a pty
    link.note_listeners.append(notes.append)
    try:
        assert link.control_lines() == ControlLines()
        for name in ("dtr", "rts"):
            with pytest.raises(NoControlLines) as caught:
                link.set_control(name, False)
            assert "has no modem control lines (a pseudo-terminal)" in str(caught.value)
            assert f"{name.upper()} cannot be set" in str(caught.value)
        with pytest.raises(NoControlLines, match=r"pseudo-terminal\): no break can be sent"):
            link.send_break()
        assert notes == []
        link.write(b"still works")  # the port itself is fine
        assert os.read(master, 100) == b"still works"
    finally:
        link.close()
        os.close(master)
        os.close(slave)


def test_a_tcp_socket_has_no_modem_lines() -> None:
    server = socket.create_server(("127.0.0.1", 0))
    port = server.getsockname()[1]
    try:
        link = open_link(f"socket://127.0.0.1:{port}", 115200)
        try:
            assert link.control_lines() == ControlLines()
            with pytest.raises(NoControlLines, match=r"\(a TCP socket\): DTR cannot be set"):
                link.set_control("dtr", False)
        finally:
            link.close()
    finally:
        server.close()


# -- the simulated devices, on a manual clock ---------------------------------------------------
def test_modem_inputs_of_a_powered_device() -> None:
    for device in (CoxirisDevice(ManualClock()), PiFrameDevice(ManualClock())):
        assert device.modem_inputs() == POWERED
        device.set_lines(False, False)
        assert device.modem_inputs() == ControlLines(False, False, True, True, False, False)


def test_a_dtr_reset_stops_a_step_and_keeps_what_was_sent() -> None:
    clock = ManualClock()
    device = FirmataDevice(clock, 57600, reset_delay=0.1)
    device.boot()
    clock.advance(0.2)
    assert device.read_output() == BANNER
    device.receive(CONFIG_200 + STEP_500_AT_300)
    clock.advance(0.01)
    device.receive(b"\xf9")  # a version query, read once the step has returned
    clock.advance(0.24)  # half-way through the 0.5 s step (the paced input took ~3.5 ms)
    device.set_lines(False, True)
    device.set_lines(True, True)  # reset
    assert 200 < device.steps() < 300  # stopped where it was
    clock.advance(1.0)
    assert device.steps() == device.steps(clock.now - 0.5)  # and does not move on
    assert device.read_output() == BANNER  # the queued query was lost; the banner came
    assert not device.configured


def test_a_dtr_reset_keeps_bytes_already_on_the_line() -> None:
    clock = ManualClock()
    device = FirmataDevice(clock, 57600, reset_delay=0.0)
    device.boot()
    clock.advance(0.1)  # the banner is on the line by now, not read yet
    device.set_lines(False, True)
    device.set_lines(True, True)
    clock.advance(0.1)
    assert device.read_output() == BANNER + BANNER


def test_piframe_drops_a_frame_cut_by_dtr() -> None:
    clock = ManualClock()
    device = PiFrameDevice(clock, instant=True)
    device.receive(SEED_LINEAR[:10])
    device.set_lines(False, True)
    device.set_lines(True, True)
    device.receive(SEED_LINEAR[10:])  # the rest alone is no frame
    assert device.frames_ok == 0
    device.receive(SEED_LINEAR)
    assert device.frames_ok == 1 and device.position() == (100.0, 50.0, 0.0)


def test_a_break_is_a_nul_the_firmata_parser_skips() -> None:
    clock = ManualClock()
    device = FirmataDevice(clock, reset_delay=0.0)
    device.boot()
    device.read_output()
    device.receive_break()
    assert device.breaks == 1 and device.ignored_messages == 1
    device.receive(b"\xf9")
    assert device.read_output() == VERSION


def test_faulty_device_forwards_the_lines() -> None:
    clock = ManualClock()
    faulty = FaultyDevice(lambda: FirmataDevice(clock, reset_delay=0.0))
    faulty.boot()
    assert faulty.read_output() == BANNER
    assert faulty.modem_inputs() == POWERED
    faulty.control("hang")
    faulty.receive_break()  # a hung firmware reads nothing
    assert faulty.device.breaks == 0
    faulty.set_lines(False, True)
    faulty.set_lines(True, True)  # the reset is hardware: it happens even while hung
    assert faulty.device.resets == 1
    faulty.control("resume")
    assert faulty.read_output() == BANNER
    faulty.set_lines(False, True)
    faulty.control("reboot")
    assert faulty.device.dtr is False  # the host's lines survive a power cycle
