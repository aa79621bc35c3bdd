"""Opening ports through pyserial URLs, and the traffic tap that reports every byte."""

from __future__ import annotations

import logging
import time
from collections.abc import Callable

import serial

from drivers.errors import PortError
from drivers.traffic import RX, TX, Traffic

log = logging.getLogger(__name__)

if "drivers.urlhandler" not in serial.protocol_handler_packages:
    serial.protocol_handler_packages.append("drivers.urlhandler")

POLL_INTERVAL = 0.02  # seconds a read waits for the first byte; bounds the reader's latency

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
        record = Traffic(direction, data, time.monotonic())
        for listener in list(self.listeners):
            listener(record)

    def write(self, data: bytes) -> None:
        """Write all of `data`.

        The bytes are reported before they are written, so that a log on disk holds every byte
        that may have reached the device even if this process is killed during the write; a
        write that fails is then a PortError saying so.
        """
        self._report(TX, data)
        try:
            written = self.port.write(data)
            self.port.flush()
        except (serial.SerialException, OSError, ValueError) as exc:
            raise PortError(f"writing to {self.url} failed: {exc}") from exc
        if written is not None and written != len(data):
            raise PortError(f"writing to {self.url}: only {written} of {len(data)} bytes sent")

    def read(self, wait: bool = True) -> bytes:
        """Whatever has arrived; with `wait`, waiting at most POLL_INTERVAL for the first byte."""
        try:
            waiting = self.port.in_waiting
            if not waiting and not wait:
                return b""
            data = self.port.read(waiting or 1)
        except (serial.SerialException, OSError, ValueError, TypeError) as exc:
            raise PortError(f"reading from {self.url} failed: {exc}") from exc
        if data:
            self._report(RX, bytes(data))
        return bytes(data)

    def close(self) -> None:
        """Close the port (idempotent)."""
        if self.closed:
            return
        self.closed = True
        try:
            self.port.close()
        except (serial.SerialException, OSError) as exc:
            log.warning("closing %s: %s", self.url, exc)


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
