"""A port held by one program cannot be opened by another: the second is told who holds it."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator

import pytest

from app.cli.main import EXIT_NO_DEVICE
from app.window.main_window import MainWindow
from drivers.errors import PortBusy
from drivers.link.transport import open_link
from tests.support.simproc import ROOT, SimProcess

pytestmark = [
    pytest.mark.e2e,
    pytest.mark.timeout(60),
    pytest.mark.skipif(sys.platform == "win32", reason="ptys and flock are POSIX"),
]


@pytest.fixture
def sim() -> Iterator[SimProcess]:
    process = SimProcess("coxiris", "--instant")
    yield process
    if process.proc.poll() is None:
        process.stop()


def test_a_second_open_of_a_held_port_is_refused_naming_it(sim: SimProcess) -> None:
    first = open_link(sim.path, 115200)
    try:
        with pytest.raises(PortBusy, match=rf"^{sim.path} is in use by another program$"):
            open_link(sim.path, 115200)
        assert not first.closed  # the holder keeps it and still talks to the device
        first.write(b"GET_ID\n")
        reply = b""
        for _ in range(200):
            reply += first.read()
            if b"\n" in reply:
                break
        assert reply.startswith(b"ACK")
    finally:
        first.close()
    open_link(sim.path, 115200).close()  # free again once the holder closed it


def test_motionctl_on_a_held_port_exits_with_the_port_error_code(sim: SimProcess) -> None:
    holder = open_link(sim.path, 115200)
    try:
        done = subprocess.run(
            [
                sys.executable,
                "-m",
                "app.cli.main",
                "--port",
                sim.path,
                "--protocol",
                "coxiris",
                "position",
            ],
            capture_output=True,
            text=True,
            timeout=30,
            cwd=ROOT,
        )
    finally:
        holder.close()
    assert done.returncode == EXIT_NO_DEVICE
    assert f"{sim.path} is in use by another program" in done.stderr


def test_the_panel_on_a_held_port_says_so(qtbot, window: MainWindow, sim: SimProcess) -> None:
    holder = open_link(sim.path, 115200)
    try:
        window.connect_device(sim.path, "coxiris", 115200)
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=10_000)
        assert f"{sim.path} is in use by another program" in window.status_line.message()
    finally:
        holder.close()
    with qtbot.waitSignal(window.settled, timeout=10_000):
        window.connect_device(sim.path, "coxiris", 115200)
