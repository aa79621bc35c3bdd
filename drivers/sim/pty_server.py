"""Serving a simulated device on a pseudo-terminal, for programs that want a real tty path."""

from __future__ import annotations

import contextlib
import errno
import logging
import os
import select
import threading
import time
import tty

from drivers.sim.device import SimulatedDevice
from drivers.traffic import RX, TX, Traffic
from drivers.transport import TrafficListener

log = logging.getLogger(__name__)

USB_FRAME = 0.002  # deliver paced output in chunks, like a USB-serial adapter
IDLE_WAKE = 0.5
CLIENT_POLL = 0.01  # seconds between looks for a client opening a resetting device's port


class PtyServer:
    """A device behind the master side of a pty; the slave's path is what clients open."""

    def __init__(self, device: SimulatedDevice, recorder: TrafficListener | None = None) -> None:
        self.device = device
        self.recorder = recorder
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        os.set_blocking(self.master, False)
        self.path = os.ttyname(self.slave)
        self.client_open = not device.resets_on_open
        if device.resets_on_open:
            # Without a slave descriptor of our own, the master reads EIO until a client opens
            # the path: that is how an open is seen, and the board resets then.
            os.close(self.slave)
            self.slave = -1
        self._stop = threading.Event()
        self._wake_r, self._wake_w = os.pipe()
        self._unsent = bytearray()

    def stop(self) -> None:
        """Ask `serve_forever` to return (safe from a signal handler or another thread)."""
        self._stop.set()
        with contextlib.suppress(OSError):
            os.write(self._wake_w, b"x")

    def serve_forever(self) -> None:
        """Move bytes between the pty and the device until stopped."""
        self.device.boot()
        while not self._stop.is_set():
            if not self.client_open:
                self._wait_for_client()
                continue
            self._unsent += self.device.read_output()
            self._flush()
            due = self.device.next_due()
            now = time.monotonic()
            wait = IDLE_WAKE if due is None else min(IDLE_WAKE, max(USB_FRAME, due - now))
            writers = [self.master] if self._unsent else []
            readable, _, _ = select.select([self.master, self._wake_r], writers, [], wait)
            if self.master in readable:
                self._read()
        self.close()

    def _wait_for_client(self) -> None:
        """No client has the port open: look again soon; on an open, the board resets."""
        data = b""
        try:
            data = os.read(self.master, 4096)
        except OSError as exc:
            if exc.errno == errno.EIO:
                self._stop.wait(CLIENT_POLL)  # still closed
                return
            if exc.errno != errno.EAGAIN:
                raise
        self.client_open = True
        self._unsent.clear()
        self.device.power_cycle()
        log.debug("a client opened %s: the device resets", self.path)
        if data:  # written at once: it reaches a board that is still resetting
            self._record(RX, data)
            self.device.receive(data)

    def _read(self) -> None:
        try:
            data = os.read(self.master, 4096)
        except OSError as exc:
            if exc.errno == errno.EIO and self.device.resets_on_open:
                self.client_open = False  # the client closed the port
                return
            if exc.errno in (errno.EAGAIN, errno.EIO):
                return
            raise
        if data:
            self._record(RX, data)
            self.device.receive(data)

    def _flush(self) -> None:
        if not self._unsent:
            return
        try:
            written = os.write(self.master, bytes(self._unsent))
        except OSError as exc:
            if exc.errno in (errno.EAGAIN, errno.EIO):
                return
            raise
        self._record(TX, bytes(self._unsent[:written]))
        del self._unsent[:written]

    def _record(self, direction: str, data: bytes) -> None:
        """Report traffic from the device's side: RX is what the host wrote."""
        if self.recorder is not None:
            self.recorder(Traffic(direction, data, time.monotonic()))

    def close(self) -> None:
        """Close every descriptor."""
        for fd in (self.master, self.slave, self._wake_r, self._wake_w):
            with contextlib.suppress(OSError):
                os.close(fd)
