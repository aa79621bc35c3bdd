"""Opening ports by URL, the traffic tap, and what happens when a port fails."""

from __future__ import annotations

import io

import pytest
import serial

from drivers.device.client import Client
from drivers.errors import DeviceTimeout, PortError
from drivers.link.records import Traffic, TrafficLogWriter, hexdump_lines
from drivers.link.transport import open_link
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.sim.urlhandler.protocol_sim import parse_sim_url

pytestmark = pytest.mark.timeout(20)


def test_loop_url_and_tap_report_both_directions() -> None:
    link = open_link("loop://", 9600)
    records: list[Traffic] = []
    link.listeners.append(records.append)
    link.write(b"HELLO")
    got = b""
    while len(got) < 5:
        got += link.read()
    link.close()
    assert got == b"HELLO"
    assert next(r.direction for r in records) == "tx"
    assert b"".join(r.data for r in records if r.direction == "rx") == b"HELLO"
    assert all(r.time > 0 for r in records)


def test_garbage_answer_is_a_clear_timeout_naming_what_came() -> None:
    link = open_link("loop://", 115200)  # echoes the command back: never an ACK
    client = Client(link, CoxirisProtocol(), timeout=0.2)
    with pytest.raises(DeviceTimeout, match=r"unexpected frame.*GET_ID"):
        client.execute(cmd.GetId())
    link.close()


def test_missing_port_is_a_port_error() -> None:
    with pytest.raises(PortError, match="/dev/does-not-exist"):
        open_link("/dev/does-not-exist", 115200)


def test_empty_port_is_a_port_error() -> None:
    with pytest.raises(PortError, match="no port"):
        open_link("", 115200)


def test_unknown_sim_device_is_a_port_error() -> None:
    with pytest.raises(PortError, match="no simulator"):
        open_link("sim://nothing", 115200)


def test_closed_port_read_is_a_port_error() -> None:
    link = open_link("sim://coxiris", 115200)
    link.port.close()
    with pytest.raises(PortError):
        link.read()
    with pytest.raises(PortError):
        link.write(b"GET_ID\n")


def test_sim_url_options() -> None:
    name, options, timing = parse_sim_url("sim://coxiris?blocking=0&speed=5&fault=A&fault=B")
    assert name == "coxiris"
    assert options == {"blocking": False, "speed": 5.0, "faults": ("A", "B")}
    assert timing is True
    assert parse_sim_url("sim://coxiris?line_timing=off")[2] is False
    with pytest.raises(serial.SerialException, match="unknown sim"):
        parse_sim_url("sim://coxiris?colour=red")


def test_hexdump() -> None:
    record = Traffic("tx", b"HELLO", 3.001)
    assert hexdump_lines(record, 0.0) == ["000003.001 TX   48 45 4C 4C 4F" + " " * 33 + "   HELLO"]


def test_log_writer_flushes_every_record() -> None:
    stream = io.StringIO()
    writer = TrafficLogWriter(stream, start=0.0)
    writer(Traffic("rx", b"A" * 20, 1.0))
    assert stream.getvalue().count("\n") == 2
