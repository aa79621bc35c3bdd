"""Opening ports through pyserial URLs, and the traffic tap that reports every byte."""

from __future__ import annotations

import logging
import os
import select
import time
from collections.abc import Callable

import serial

if os.name == "posix":
    import termios

from drivers.errors import PortError
from drivers.traffic import RX, TX, Traffic

log = logging.getLogger(__name__)

if "drivers.urlhandler" not in serial.protocol_handler_packages:
    serial.protocol_handler_packages.append("drivers.urlhandler")

POLL_INTERVAL = 0.02  # seconds a read waits for the first byte; bounds the reader's latency
READ_SIZE = 4096  # bytes taken from a descriptor at once (a whole tty input buffer)

TrafficListener = Callable[[Traffic], None]


class Link:
    """A port with a traffic tap: every byte read or written is reported to the listeners.

    Wraps any pyserial object (device path, `loop://`, `socket://`, `rfc2217://`, `sim://`);
    pyserial and OS errors become PortError, so a vanished device is one clear error.
    """

    def __init__(self, port: serial.SerialBase, url: str = "") -> None:
        self.port = port
        self.url = url or str(getattr(port, "portstr", "") or port.port)
        self.listeners: list[TrafficListener] = []
        self.closed = False

    def _report(self, direction: str, data: bytes) -> None:
        if not self.listeners:
            return
        record = Traffic(direction, data, time.monotonic())
        for listener in list(self.listeners):
            listener(record)

    def _descriptor(self) -> int | None:
        """The descriptor of a plain POSIX serial port (a device path, a pty), read and written
        directly; None for any other port (URL handlers, spy:// which must see every byte)."""
        if os.name != "posix" or type(self.port) is not serial.Serial:
            return None
        if not self.port.is_open:
            raise PortError(f"{self.url} is not open")
        return self.port.fd  # type: ignore[no-any-return]

    def write(self, data: bytes) -> None:
        """Write all of `data`, and wait until the port has sent it.

        The bytes are reported before they are written, so that a log on disk holds every byte
        that may have reached the device even if this process is killed during the write; a
        write that fails is then a PortError saying so.
        """
        self._report(TX, data)
        try:
            fd = self._descriptor()
            if fd is not None:
                _write_all(fd, data)
                return
            written = self.port.write(data)
            self.port.flush()
        except (serial.SerialException, OSError, ValueError) as exc:
            raise PortError(f"writing to {self.url} failed: {exc}") from exc
        if written is not None and written != len(data):
            raise PortError(f"writing to {self.url}: only {written} of {len(data)} bytes sent")

    def read(self, wait: bool = True) -> bytes:
        """Everything that has arrived; with `wait`, waiting at most POLL_INTERVAL for it.

        The wait ends as soon as a byte arrives (select on the descriptor, or a one-byte read
        with the port's timeout), and all the bytes there are then are taken at once.
        """
        try:
            fd = self._descriptor()
            if fd is not None:
                data = _read_available(fd, POLL_INTERVAL if wait else 0.0)
            else:
                waiting = self.port.in_waiting
                if not waiting and not wait:
                    return b""
                data = bytes(self.port.read(waiting or 1))
                more = self.port.in_waiting if data and not waiting else 0
                if more:  # the first byte ended the wait: take the rest that came with it
                    data += bytes(self.port.read(more))
        except (serial.SerialException, OSError, ValueError, TypeError) as exc:
            raise PortError(f"reading from {self.url} failed: {exc}") from exc
        if data:
            self._report(RX, data)
        return data

    def close(self) -> None:
        """Close the port (idempotent)."""
        if self.closed:
            return
        self.closed = True
        try:
            self.port.close()
        except (serial.SerialException, OSError) as exc:
            log.warning("closing %s: %s", self.url, exc)


def _read_available(fd: int, timeout: float) -> bytes:
    """The bytes waiting on a non-blocking descriptor, waiting up to `timeout` for the first."""
    if not select.select([fd], [], [], timeout)[0]:
        return b""
    try:
        data = os.read(fd, READ_SIZE)
    except BlockingIOError:
        return b""
    if not data:  # readable but empty: the device went away (pyserial says so too)
        raise OSError("the device reports data but none comes (disconnected?)")
    return data


def _write_all(fd: int, data: bytes) -> None:
    """Write every byte to a non-blocking tty descriptor, waiting while its buffer is full,
    then until the port has sent them (as pyserial's write and flush do)."""
    view = memoryview(data)
    while view:
        try:
            view = view[os.write(fd, view) :]
        except BlockingIOError:
            select.select([], [fd], [], None)
    try:
        termios.tcdrain(fd)
    except termios.error as exc:
        raise OSError(*exc.args) from exc


def open_link(url: str, baud: int, *, dtr: bool | None = None) -> Link:
    """Open `url` (path, COM name or pyserial URL, `sim://NAME` included) at `baud`, 8N1."""
    if not url:
        raise PortError("no port given")
    try:
        port = serial.serial_for_url(url, baudrate=baud, timeout=POLL_INTERVAL, do_not_open=True)
        if dtr is not None:
            port.dtr = dtr
        port.open()
    except (serial.SerialException, OSError, ValueError) as exc:
        raise PortError(f"cannot open {url}: {exc}") from exc
    return Link(port, url)
