"""Serving a simulated device on a pseudo-terminal, for programs that want a real tty path."""

from __future__ import annotations

import contextlib
import errno
import logging
import math
import os
import select
import time
import tty

from drivers.link.records import RX, TX, Traffic
from drivers.link.transport import TrafficListener
from drivers.sim.device import SimulatedDevice

log = logging.getLogger(__name__)

USB_FRAME = 0.001
"""A USB full-speed frame. What the device has sent by a frame's start reaches the host then,
on a free-running 1 ms grid, as from an adapter that passes on what its UART received at the
next frame (an FTDI chip with its latency timer at the 1 ms minimum, "the same as the USB frame
length"; its default is 16 ms). An Arduino Uno R3's 16U2 (Arduino-usbserial) is slower: it
flushes when its Timer0 overflows, every 4.096 ms (16 MHz / 256 / 256), or when its buffer
nearly fills: `PtyServer(usb_frame=0.004096)`."""
SPIN = 0.0002  # the last seconds before a frame are waited out exactly (select oversleeps)
IDLE_WAKE = 0.5
CLIENT_POLL = 0.01  # seconds between looks for a client opening a resetting device's port


class PtyServer:
    """A device behind the master side of a pty; the slave's path is what clients open."""

    def __init__(
        self,
        device: SimulatedDevice,
        recorder: TrafficListener | None = None,
        usb_frame: float = USB_FRAME,
        link: str | None = None,
    ) -> None:
        """`link`: a path kept as a symlink to the pty while serving (like socat's `link=`),
        so that a device served again later is found under the same name."""
        self.device = device
        self.recorder = recorder
        self.usb_frame = usb_frame
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
        # A plain flag and a pipe, no lock: a signal handler that took a lock the interrupted
        # main thread holds (Event.set inside Event.wait) would wait for itself forever.
        self._stopping = False
        self._wake_r, self._wake_w = os.pipe()
        os.set_blocking(self._wake_w, False)
        self._unsent = bytearray()
        self.link: str | None = None
        if link is not None:
            try:
                make_link(self.path, link)
            except OSError:
                self.close()
                raise
            self.link = link

    def stop(self) -> None:
        """Ask `serve_forever` to return (safe from a signal handler or another thread)."""
        self._stopping = True
        with contextlib.suppress(OSError):
            os.write(self._wake_w, b"x")

    def serve_forever(self) -> None:
        """Move bytes between the pty and the device until stopped.

        What the host writes reaches the device at once; what the device sends is handed to the
        host at the first frame start (a multiple of `usb_frame` on the monotonic clock) at or
        after the time it is due, never sooner.
        """
        self.device.boot()
        frame: float | None = None
        while not self._stopping:
            if not self.client_open:
                self._wait_for_client()
                continue
            now = time.monotonic()
            if frame is not None and frame <= now:
                self._unsent += self.device.read_output()
            self._flush()
            frame = self._next_frame(now)
            wait = IDLE_WAKE if frame is None else min(IDLE_WAKE, max(0.0, frame - now - SPIN))
            writers = [self.master] if self._unsent else []
            readable, _, _ = select.select([self.master, self._wake_r], writers, [], wait)
            if self.master in readable:
                self._read()
            elif frame is not None and frame - time.monotonic() <= SPIN:
                while time.monotonic() < frame:  # wait out the last instants: select oversleeps
                    pass
        self.close()

    def _next_frame(self, after: float) -> float | None:
        """The first frame start after `after` at or after the device's next event (None: none
        is pending); an event already due is looked at in the next frame."""
        due = self.device.next_due()
        if due is None:
            return None
        return max(math.ceil(due / self.usb_frame), math.floor(after / self.usb_frame) + 1) * (
            self.usb_frame
        )

    def _wait_for_client(self) -> None:
        """No client has the port open: look again soon; on an open, the board resets."""
        data = b""
        try:
            data = os.read(self.master, 4096)
        except OSError as exc:
            if exc.errno == errno.EIO:
                select.select([self._wake_r], [], [], CLIENT_POLL)  # still closed
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
        """Close every descriptor; remove the link if it still points to this pty."""
        if self.link is not None:
            remove_link(self.path, self.link)
            self.link = None
        for fd in (self.master, self.slave, self._wake_r, self._wake_w):
            with contextlib.suppress(OSError):
                os.close(fd)


def make_link(target: str, link: str) -> None:
    """Make `link` a symlink to `target`, replacing what is there at once (never missing, never
    half made: a new link beside it, renamed over it)."""
    temporary = f"{link}.{os.getpid()}.tmp"
    with contextlib.suppress(FileNotFoundError):
        os.unlink(temporary)
    os.symlink(target, temporary)
    try:
        os.replace(temporary, link)
    except OSError:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise


def remove_link(target: str, link: str) -> None:
    """Remove `link` if it is still a symlink to `target` (another server may have taken it)."""
    try:
        if os.readlink(link) == target:
            os.unlink(link)
    except OSError as exc:
        log.debug("leaving %s: %s", link, exc)
