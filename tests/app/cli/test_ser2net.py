"""A motionsim pty served by ser2net over RFC 2217 on 127.0.0.1, driven by motionctl, the
scripting API and the window through the plain `rfc2217://127.0.0.1:PORT` URL."""

from __future__ import annotations

import contextlib
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

import drivers
from app.window.main_window import MainWindow
from drivers.link.transport import open_link
from tests.support.ser2net_proc import SER2NET, Ser2netProcess, free_port
from tests.support.simproc import ROOT, SimProcess

pytestmark = [
    pytest.mark.timeout(60),
    pytest.mark.e2e,
    pytest.mark.skipif(
        SER2NET is None, reason="ser2net is not installed (resources/setup.sh test installs it)"
    ),
]

IAC, SB, SE = 0xFF, 0xFA, 0xF0
COM_PORT = 44  # RFC 2217's telnet option
SET_CONTROL, SERVER_SET_CONTROL = 5, 105
DTR_ON, RTS_OFF, NO_FLOW_CONTROL = 8, 12, 1


def _sb(option: int, value: int) -> bytes:
    """An RFC 2217 subnegotiation as it crosses the wire."""
    return bytes((IAC, SB, COM_PORT, option, value, IAC, SE))


@pytest.fixture
def served(tmp_path: Path) -> Iterator[Ser2netProcess]:
    """motionsim (COXIRIS) on a pty, served by ser2net; both stopped afterwards."""
    sim = SimProcess("coxiris", "--no-line-timing")
    try:
        server = Ser2netProcess(sim.path, tmp_path)
        try:
            yield server
        finally:
            server.stop()
    finally:
        assert sim.stop() == 0


def motionctl(url: str, *args: str, timeout: float = 30) -> subprocess.CompletedProcess[str]:
    """Run motionctl on `url` (COXIRIS) and return what it did."""
    return subprocess.run(
        [sys.executable, "-m", "app.cli", "--port", url, "--protocol", "coxiris", *args],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=timeout,
    )


def test_motionctl_over_the_plain_rfc2217_url(served: Ser2netProcess) -> None:
    first = motionctl(served.url, "position")
    assert (first.returncode, first.stdout.strip()) == (0, "0.00 0.00 0.00"), first.stderr
    moved = motionctl(served.url, "move", "1", "2", "0")
    assert (moved.returncode, moved.stdout.strip()) == (0, "1.00 2.00 0.00"), moved.stderr
    after = motionctl(served.url, "position")  # a new connection: the device kept its place
    assert (after.returncode, after.stdout.strip()) == (0, "1.00 2.00 0.00"), after.stderr
    ident = motionctl(served.url, "id")
    assert ident.returncode == 0, ident.stderr
    assert ident.stdout.strip().startswith("CX"), ident.stdout


def test_the_scripting_api_over_ser2net(served: Ser2netProcess) -> None:
    with drivers.open_device(served.url, "coxiris") as stage:
        assert stage.identify().startswith("CX")
        stage.move_to(3, 4)
        here = stage.position()
        assert (here.x, here.y, here.z) == (3.0, 4.0, 0.0)
        stage.move_by(-1, 0)
        here = stage.position()
        assert (here.x, here.y, here.z, here.measured) == (2.0, 4.0, 0.0, True)
        notes = stage.link.opening_notes
    assert len(notes) == 1 and "did not confirm the control lines" in notes[0], notes


def test_a_second_client_is_refused_while_the_first_holds_the_port(
    served: Ser2netProcess,
) -> None:
    """The README's set-up serves one client at a time: a second program is told that another
    holds the port (exit 3, no traceback), and the first goes on unharmed."""
    with drivers.open_device(served.url, "coxiris") as stage:
        stage.move_to(1, 2)
        second = motionctl(served.url, "move", "9", "9", "0")
        assert second.returncode == 3, second.stderr
        assert "accepted this connection and closed it at once" in second.stderr, second.stderr
        assert "another client probably holds the port" in second.stderr, second.stderr
        assert "Traceback" not in second.stderr, second.stderr
        here = stage.position()
        assert (here.x, here.y, here.measured) == (1.0, 2.0, True)
    after = motionctl(served.url, "position")  # the first has let go: the port is free again
    assert (after.returncode, after.stdout.strip()) == (0, "1.00 2.00 0.00"), after.stderr


class RecordingRelay:
    """A TCP relay between one client and `port`, keeping what crosses each way."""

    def __init__(self, port: int) -> None:
        self.to_server = bytearray()
        self.to_client = bytearray()
        self._listener = socket.create_server(("127.0.0.1", 0))
        self.port = self._listener.getsockname()[1]
        self._target = port
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        client, _ = self._listener.accept()
        server = socket.create_connection(("127.0.0.1", self._target))
        pumps = [
            threading.Thread(target=self._pump, args=(client, server, self.to_server)),
            threading.Thread(target=self._pump, args=(server, client, self.to_client)),
        ]
        for pump in pumps:
            pump.start()
        for pump in pumps:
            pump.join()
        client.close()
        server.close()

    @staticmethod
    def _pump(source: socket.socket, sink: socket.socket, kept: bytearray) -> None:
        while data := _recv(source):
            kept.extend(data)
            try:
                sink.sendall(data)
            except OSError:
                break
        with contextlib.suppress(OSError):
            sink.shutdown(socket.SHUT_WR)

    def close(self) -> None:
        """Stop listening and wait for the relay to end (both sides closed)."""
        self._listener.close()
        self._thread.join(10)


def _recv(sock: socket.socket) -> bytes:
    try:
        return sock.recv(4096)
    except OSError:
        return b""


def test_control_lines_are_sent_and_ser2net_leaves_them_unanswered_on_a_pty(
    served: Ser2netProcess,
) -> None:
    relay = RecordingRelay(served.port)
    started = time.monotonic()
    link = open_link(f"rfc2217://127.0.0.1:{relay.port}", 115200, dtr=True)
    opened_in = time.monotonic() - started
    notes: list[str] = []
    link.note_listeners.append(notes.append)
    try:
        link.set_control("rts", False)
        lines = link.control_lines()
    finally:
        link.close()
    relay.close()
    # the requests went out: DTR asserted at the open, RTS dropped afterwards
    assert _sb(SET_CONTROL, DTR_ON) in relay.to_server
    assert _sb(SET_CONTROL, RTS_OFF) in relay.to_server
    # ser2net confirms the flow control it could set, and sends nothing for the lines a pty has not
    assert _sb(SERVER_SET_CONTROL, NO_FLOW_CONTROL) in relay.to_client
    assert _sb(SERVER_SET_CONTROL, DTR_ON) not in relay.to_client
    assert _sb(SERVER_SET_CONTROL, RTS_OFF) not in relay.to_client
    assert "DTR on unanswered" in link.opening_notes[0]
    assert notes == ["RTS off"]  # said once, at the open
    assert (lines.dtr, lines.rts) == (None, None)  # as asked, not known to be so
    assert opened_in < 2.5, f"the open waited {opened_in:.2f} s for answers that never come"


def test_the_window_shows_the_position_read_over_the_network(
    qtbot, window: MainWindow, served: Ser2netProcess
) -> None:
    moved = motionctl(served.url, "move", "5", "6", "0")
    assert moved.returncode == 0, moved.stderr
    with qtbot.waitSignal(window.settled, timeout=15000):
        window.connect_device(served.url, "coxiris", 115200)
    qtbot.waitUntil(lambda: window.readout.position() == (5.0, 6.0, 0.0), timeout=10000)
    window.jog_panel.jog_requested.emit("x", 1.0)
    qtbot.waitUntil(lambda: window.readout.position() == (6.0, 6.0, 0.0), timeout=10000)

    def console_says_the_lines_are_unconfirmed() -> None:
        window.console.flush()
        assert "did not confirm the control lines" in window.console.text()

    qtbot.waitUntil(console_says_the_lines_are_unconfirmed, timeout=5000)


def test_no_server_on_that_port_is_a_missing_device(tmp_path: Path) -> None:
    url = f"rfc2217://127.0.0.1:{free_port()}"
    started = time.monotonic()
    result = motionctl(url, "position", timeout=20)
    assert result.returncode == 3, (result.returncode, result.stderr)
    assert time.monotonic() - started < 15
    said = result.stderr.strip()
    assert "nothing answers at 127.0.0.1:" in said and "is ser2net" in said, said
    assert said.count("motionctl:") == 1, said


def test_a_raw_tcp_server_is_told_apart_from_rfc2217() -> None:
    listener = socket.create_server(("127.0.0.1", 0))
    port = listener.getsockname()[1]
    accepted: list[socket.socket] = []
    waiter = threading.Thread(target=lambda: accepted.append(listener.accept()[0]), daemon=True)
    waiter.start()
    try:
        result = motionctl(f"rfc2217://127.0.0.1:{port}?timeout=0.5", "position", timeout=20)
    finally:
        waiter.join(5)
        for sock in accepted:
            sock.close()
        listener.close()
    assert result.returncode == 3, (result.returncode, result.stderr)
    assert "not as an RFC 2217 server" in result.stderr, result.stderr
    assert f"socket://127.0.0.1:{port}" in result.stderr, result.stderr
