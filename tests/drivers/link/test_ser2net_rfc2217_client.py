"""The rfc2217:// client against a server that honours control lines: pyserial's own RFC 2217
server (PortManager) in front of a simulated device that sees DTR and RTS. What ser2net does for
a pty (no answer) is in test_ser2net.py; here the lines must reach the device, confirmed."""

from __future__ import annotations

import socket
import threading
import time
from collections.abc import Iterator

import pytest
import serial
from serial import rfc2217

from drivers.link.transport import open_link
from drivers.sim.device import SimulatedDevice

pytestmark = pytest.mark.timeout(30)


class _Connection:
    """What PortManager writes its answers to: the client's socket."""

    def __init__(self, sock: socket.socket) -> None:
        self.sock = sock

    def write(self, data: bytes) -> None:
        self.sock.sendall(data)


class HonouringServer:
    """An RFC 2217 server for one client, serving `sim://coxiris` (which sees DTR and RTS)."""

    def __init__(self) -> None:
        self.port = serial.serial_for_url("sim://coxiris?line_timing=0&instant=1", timeout=0.02)
        self.device: SimulatedDevice = self.port.device
        self._listener = socket.create_server(("127.0.0.1", 0))
        self.url = f"rfc2217://127.0.0.1:{self._listener.getsockname()[1]}"
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        client, _ = self._listener.accept()
        client.settimeout(0.02)
        manager = rfc2217.PortManager(self.port, _Connection(client))
        while not self._stop.is_set():
            try:
                data = client.recv(4096)
                if not data:
                    break
                self.port.write(b"".join(manager.filter(data)))
            except TimeoutError:
                pass
            waiting = self.port.in_waiting
            if waiting:
                client.sendall(b"".join(manager.escape(self.port.read(waiting))))
        client.close()

    def close(self) -> None:
        """Stop serving and close the device."""
        self._stop.set()
        self._listener.close()
        self._thread.join(10)
        self.port.close()


@pytest.fixture
def server() -> Iterator[HonouringServer]:
    served = HonouringServer()
    yield served
    served.close()


def test_lines_reach_the_device_and_are_confirmed(server: HonouringServer) -> None:
    started = time.monotonic()
    link = open_link(server.url, 115200, dtr=False, rts=True)
    opened_in = time.monotonic() - started
    try:
        assert (server.device.dtr, server.device.rts) == (False, True)  # as asked at the open
        link.set_control("dtr", True)
        assert server.device.dtr is True
        link.set_control("rts", False)
        assert server.device.rts is False
        lines = link.control_lines()
        assert (lines.dtr, lines.rts) == (True, False)
        assert link.opening_notes == []  # every change was confirmed: nothing to say
        link.write(b"GET_POSITION\n")
        received = b""
        deadline = time.monotonic() + 5
        while b"DONE GET_POSITION" not in received and time.monotonic() < deadline:
            received += link.read()
        assert b"DONE GET_POSITION: 0.00 0.00 0.00" in received, received
    finally:
        link.close()
    assert opened_in < 2.0, f"the open took {opened_in:.2f} s with a server that answers"
