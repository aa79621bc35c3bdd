"""Stopping a simulator's pty server from a signal handler, as `motionsim` does on SIGTERM."""

from __future__ import annotations

import os
import signal
import sys
import threading
import time

import pytest

from drivers.sim.firmata_device import FirmataDevice
from drivers.sim.pty_server import PtyServer

pytestmark = pytest.mark.timeout(20)


@pytest.mark.parametrize("delay", [0.003, 0.011, 0.02, 0.037, 0.05])
def test_a_signal_stops_a_server_waiting_for_its_client(delay: float) -> None:
    # A resetting board with no client open: the server sits in its short client-poll wait, where
    # a handler that took a lock (Event.set) could interrupt the same lock's holder and hang.
    server = PtyServer(FirmataDevice(instant=True))
    previous = signal.signal(signal.SIGUSR1, lambda signum, frame: server.stop())
    timer = threading.Timer(delay, os.kill, (os.getpid(), signal.SIGUSR1))
    try:
        timer.start()
        started = time.monotonic()
        server.serve_forever()
        assert time.monotonic() - started < 2.0
    finally:
        timer.join()
        signal.signal(signal.SIGUSR1, previous)
    assert not server.client_open


def test_stop_takes_no_lock() -> None:
    # The deterministic half of the above: nothing in threading (Event, Condition, Lock) runs in
    # stop(), so a signal cannot wait for the lock it interrupted.
    server = PtyServer(FirmataDevice(instant=True))
    seen: list[str] = []

    def profile(frame, event, arg) -> None:
        if event == "call":
            seen.append(frame.f_code.co_filename)
        elif event == "c_call":
            seen.append(getattr(arg, "__qualname__", str(arg)))

    sys.setprofile(profile)
    try:
        server.stop()
    finally:
        sys.setprofile(None)
        server.close()
    assert not [where for where in seen if "threading" in where or "acquire" in where]
    assert seen  # the profile did see stop()'s calls
