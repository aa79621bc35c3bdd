"""How a reply is waited for: the reader wakes when bytes arrive and takes all there are; the
simulator's pty hands the device's output over once a USB frame, never before it is due."""

from __future__ import annotations

import math
import os
import threading
import time
import tty
from collections.abc import Iterator
from pathlib import Path

import pytest

from drivers.device.client import Client
from drivers.link import transport
from drivers.link.records import Traffic
from drivers.link.transport import Link, open_link
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.sim.coxiris_device import CoxirisDevice
from drivers.sim.pty_server import USB_FRAME, PtyServer
from tests.conftest import Recorder

pytestmark = pytest.mark.timeout(20)

BAUD = 115200
GET_POSITION_WIRE_S = (13 + 53) * 10 / BAUD  # the command and its 53-byte reply at 10 bits a byte


@pytest.fixture
def pty() -> Iterator[tuple[int, str]]:
    """A raw pty: the master's descriptor and the slave's path."""
    master, slave = os.openpty()
    tty.setraw(slave)
    yield master, os.ttyname(slave)
    os.close(master)
    os.close(slave)


@pytest.fixture
def served() -> Iterator[tuple[PtyServer, list[Traffic]]]:
    """A COXIRIS device paced at 115200 baud behind a pty, served in a thread."""
    records: list[Traffic] = []
    server = PtyServer(CoxirisDevice(baud=BAUD), records.append)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield server, records
    server.stop()
    thread.join(5)


def test_a_read_wakes_when_bytes_arrive_not_at_its_timeout(
    pty: tuple[int, str], monkeypatch: pytest.MonkeyPatch
) -> None:
    master, path = pty
    monkeypatch.setattr(transport, "POLL_INTERVAL", 10.0)
    link = open_link(path, BAUD)
    writer = threading.Thread(target=os.write, args=(master, b"DONE GET_ID: X\r\n"))
    start = time.monotonic()
    writer.start()
    data = link.read()
    took = time.monotonic() - start
    writer.join()
    link.close()
    assert data == b"DONE GET_ID: X\r\n"
    assert took < 5.0  # woken by the bytes, not by the 10 s timeout


def test_a_read_takes_everything_that_has_arrived_at_once(pty: tuple[int, str]) -> None:
    master, path = pty
    link = open_link(path, BAUD)
    recorder = Recorder()
    link.listeners.append(recorder)
    os.write(master, b"x" * 300)
    assert link.read() == b"x" * 300
    assert link.read(wait=False) == b""
    link.close()
    assert [len(r.data) for r in recorder.records] == [300]


class TrickleAfterFirstByte:
    """A pyserial-like port whose bytes are all there once the first one has been read."""

    port = "trickle"

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.first_read = False

    @property
    def in_waiting(self) -> int:
        return len(self.data) if self.first_read else 0

    def read(self, size: int) -> bytes:
        self.first_read = True
        out, self.data = self.data[:size], self.data[size:]
        return out

    def close(self) -> None:
        pass


def test_any_port_hands_over_the_rest_with_the_byte_that_ended_the_wait() -> None:
    link = Link(TrickleAfterFirstByte(b"ACK GET_ID\r\n"), "trickle")  # type: ignore[arg-type]
    assert link.read() == b"ACK GET_ID\r\n"


def test_a_spy_port_still_sees_every_byte(pty: tuple[int, str], tmp_path: Path) -> None:
    master, path = pty
    capture = tmp_path / "spy.txt"
    link = open_link(f"spy://{path}?file={capture}", BAUD)
    link.write(b"GET_ID\n")
    assert os.read(master, 100) == b"GET_ID\n"
    os.write(master, b"ACK GET_ID\r\n")
    got = b""
    while len(got) < 12:
        got += link.read()
    link.close()
    text = capture.read_text()
    assert "TX" in text and "RX" in text  # read and written through spy's own methods


class OneByteAt:
    """A device with one byte due at `due`; notes when the server takes its output."""

    resets_on_open = False

    def __init__(self, due: float) -> None:
        self.due: float | None = due
        self.taken_at: list[float] = []

    def boot(self) -> None:
        pass

    def receive(self, data: bytes) -> None:
        pass

    def next_due(self) -> float | None:
        return self.due

    def read_output(self) -> bytes:
        now = time.monotonic()
        self.taken_at.append(now)
        if self.due is not None and now >= self.due:
            self.due = None
            return b"!"
        return b""


@pytest.mark.parametrize("frame", [USB_FRAME, 0.004096])
def test_output_is_handed_over_at_the_first_frame_start_after_it_is_due(
    frame: float, pty: tuple[int, str]
) -> None:
    due = time.monotonic() + 0.0123
    device = OneByteAt(due)
    server = PtyServer(device, usb_frame=frame)  # type: ignore[arg-type]
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    link = open_link(server.path, BAUD)
    got = b""
    while not got:
        got = link.read()
    server.stop()
    thread.join(5)
    link.close()
    frame_start = math.ceil(due / frame) * frame
    assert got == b"!"
    assert device.taken_at and min(device.taken_at) >= frame_start  # never sooner


def test_a_round_trip_never_beats_the_wire(served: tuple[PtyServer, list[Traffic]]) -> None:
    server, records = served
    link = open_link(server.path, BAUD)
    client = Client(link, CoxirisProtocol())
    client.execute(cmd.GetId())
    for _ in range(5):
        start = time.monotonic()
        client.execute(cmd.GetPosition())
        assert time.monotonic() - start >= GET_POSITION_WIRE_S
    link.close()
    sent = [r for r in records if r.direction == "tx"]
    assert len(sent) > 6  # the replies came in several frames, not at once


def test_a_round_trip_waits_for_no_timeout(
    served: tuple[PtyServer, list[Traffic]], monkeypatch: pytest.MonkeyPatch
) -> None:
    server, _ = served
    monkeypatch.setattr(transport, "POLL_INTERVAL", 10.0)
    link = open_link(server.path, BAUD)
    client = Client(link, CoxirisProtocol())
    start = time.monotonic()
    for _ in range(5):
        client.execute(cmd.GetPosition())
    link.close()
    assert time.monotonic() - start < 5.0  # every read ended when its bytes came
