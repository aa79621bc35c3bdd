"""A transparent bridge (snoop mode): a device's port on one side, a pseudo-terminal on the other.

Another program opens `Bridge.path` as if it were the device; every byte it writes goes to the
device unchanged (`tx`), every byte the device writes goes back to it unchanged (`rx`), and each
chunk is reported to the tap, before it is written onward, so a log holds every byte the device
was given even if the process dies during the write.

One thread does everything: `serve_forever` waits in `poll` on the device's descriptor, the pty's
master and a wake pipe, and forwards a chunk with `os.read`/`os.write` the moment it is readable:
no polling sleeps, no extra thread, so the added latency is a system call or two (the tap's own
time included). A direction whose destination is not ready keeps its bytes and stops reading its
source until they are written (back-pressure, nothing lost). A device URL that has no descriptor
(`loop://`, `sim://`, `rfc2217://`) is read through pyserial instead, looked at every
FALLBACK_POLL seconds: that mode adds up to that much latency.

The bridge keeps a descriptor of its own on the pty's slave, so the path stays valid (and the
master readable, never EIO) while the other program closes and reopens it.
"""

from __future__ import annotations

import contextlib
import logging
import os
import select
import threading
import time
import tty
from collections.abc import Callable
from types import TracebackType

import serial

from drivers.errors import PortError
from drivers.link.records import RX, TX, Traffic
from drivers.link.transport import Link
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.session.setup import open_device_link

log = logging.getLogger(__name__)

Tap = Callable[[Traffic], None]

CHUNK = 65536  # bytes read at once
FALLBACK_POLL = 0.001  # seconds between looks at a device that has no descriptor
_READ = select.POLLIN
_WRITE = select.POLLOUT
_TROUBLE = select.POLLERR | select.POLLHUP | select.POLLNVAL


class DeviceVanished(PortError):
    """The device's port failed or went away while the bridge was forwarding."""


class Bridge:
    """Forwards bytes between a device's port and a pseudo-terminal, reporting every chunk.

    `tap` is called from the thread that runs `serve_forever`, once per chunk, before the chunk
    is written onward; direction `tx` is from the other program to the device, `rx` from the
    device to the other program, time is `time.monotonic()`. It should be quick: forwarding
    waits for it. An exception it raises is logged and forwarding goes on.
    """

    def __init__(
        self,
        device: str,
        baud: int | None = None,
        tap: Tap | None = None,
        *,
        dtr: bool | None = None,
        protocol: Protocol | None = None,
    ) -> None:
        """A bridge to `device`, opened as `protocol` needs it where one is given (its default
        baud, its DTR, a `sim://` device in its variant), as a device session opens it."""
        self.device = device
        self.baud = baud
        self.tap = tap
        self.dtr = dtr
        self.protocol = protocol
        self.path = ""
        self.bytes_to_device = 0
        self.bytes_from_device = 0
        self.tap_errors = 0
        self._link: Link | None = None
        self._device_fd: int | None = None
        self._master = -1
        self._slave = -1
        self._wake_r, self._wake_w = -1, -1
        self._stopping = False  # a plain flag: a lock could deadlock a signal handler
        self._idle = threading.Event()
        self._idle.set()
        self._serving_thread: int | None = None
        self._closed = False
        self._to_device = bytearray()
        self._to_program = bytearray()

    # -- life cycle -------------------------------------------------------------------------
    def open(self) -> None:
        """Open the device's port and create the pty (`path`); PortError if the port won't open."""
        if self._closed:
            raise PortError(Message("the bridge to {device} is closed", device=self.device))
        if self._link is not None:
            return
        link = open_device_link(self.device, self.protocol, baud=self.baud, dtr=self.dtr)
        try:
            self._device_fd = _descriptor(link.port)
            master, slave = os.openpty()
            tty.setraw(slave)
            os.set_blocking(master, False)
            self._master, self._slave = master, slave
            self.path = os.ttyname(slave)
            self._wake_r, self._wake_w = os.pipe()
            os.set_blocking(self._wake_r, False)
            os.set_blocking(self._wake_w, False)  # stop() from a signal handler never blocks
        except OSError as exc:
            link.close()
            self._close_descriptors()
            raise PortError(
                Message(
                    "cannot create a pseudo-terminal for {device}: {error}",
                    device=self.device,
                    error=exc,
                )
            ) from exc
        self._link = link
        mode = "its descriptor" if self._device_fd is not None else "pyserial reads"
        log.info("bridging %s (%s) <-> %s", self.device, mode, self.path)

    def stop(self) -> None:
        """Make `serve_forever` return soon (safe from another thread or a signal handler).

        From a signal handler, with `serve_forever` in the main thread: block the signal in
        every other thread, or the kernel may deliver it to one of those, and the main thread,
        asleep in `poll`, runs the Python handler only when the next byte crosses.
        """
        self._stopping = True
        if self._wake_w >= 0:
            with contextlib.suppress(OSError):
                os.write(self._wake_w, b"x")

    def close(self) -> None:
        """Stop, wait for `serve_forever` to return (at most 2 s), close everything (idempotent)."""
        if self._closed:
            return
        self.stop()
        if self._serving_thread not in (None, threading.get_ident()) and not self._idle.wait(2.0):
            log.warning("the bridge's thread did not return within 2 s")
        self._closed = True
        if self._link is not None:
            self._link.close()
            self._link = None
        self._close_descriptors()

    def _close_descriptors(self) -> None:
        for fd in (self._master, self._slave, self._wake_r, self._wake_w):
            if fd >= 0:
                with contextlib.suppress(OSError):
                    os.close(fd)
        self._master = self._slave = self._wake_r = self._wake_w = -1

    def __enter__(self) -> Bridge:
        self.open()
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        value: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()

    # -- forwarding -------------------------------------------------------------------------
    def serve_forever(self) -> None:
        """Forward both ways until `stop()`; DeviceVanished if the device's port fails."""
        if self._link is None:
            raise PortError(Message("the bridge is not open"))
        self._idle.clear()
        self._serving_thread = threading.get_ident()
        try:
            if self._device_fd is None:
                self._serve_without_descriptor()
            else:
                self._serve(self._device_fd)
            self._write_what_waits()
        finally:
            self._serving_thread = None
            self._idle.set()

    def _serve(self, device: int) -> None:
        poller = select.poll()
        poller.register(self._wake_r, _READ)
        interest: dict[int, int] = {}
        while not self._stopping:
            wanted = {
                device: (_WRITE if self._to_device else 0) | (0 if self._to_program else _READ),
                self._master: (_WRITE if self._to_program else 0)
                | (0 if self._to_device else _READ),
            }
            for fd, events in wanted.items():
                if interest.get(fd) != events:
                    poller.register(fd, events)  # registering again modifies
                    interest[fd] = events
            for fd, events in poller.poll():
                if fd == self._wake_r:
                    self._drain_wake()
                elif fd == device:
                    # A hang-up is read at once (EIO or end of file), even while bytes wait.
                    if events & _TROUBLE or (events & _READ and not self._to_program):
                        self._from_device(device)
                    if events & _WRITE and self._to_device:
                        self._write_device(device)
                elif fd == self._master:
                    if events & _TROUBLE or (events & _READ and not self._to_device):
                        self._from_program(device)
                    if events & _WRITE and self._to_program:
                        self._write_program()

    def _serve_without_descriptor(self) -> None:
        """For a port with no descriptor: the pty by `poll`, the device by pyserial every 1 ms."""
        assert self._link is not None
        port = self._link.port
        poller = select.poll()
        poller.register(self._wake_r, _READ)
        interest = -1
        while not self._stopping:
            events = (_WRITE if self._to_program else 0) | _READ
            if events != interest:
                poller.register(self._master, events)
                interest = events
            for fd, ready in poller.poll(FALLBACK_POLL * 1000):
                if fd == self._wake_r:
                    self._drain_wake()
                    continue
                if ready & (_READ | _TROUBLE):
                    self._from_program(None)
                if ready & _WRITE and self._to_program:
                    self._write_program()
            if not self._to_program:
                try:
                    waiting = port.in_waiting
                    data = bytes(port.read(waiting)) if waiting else b""
                except (serial.SerialException, OSError, ValueError, TypeError) as exc:
                    raise DeviceVanished(
                        Message(
                            "the device on {device} failed: {error}", device=self.device, error=exc
                        )
                    ) from exc
                if data:
                    self._report(RX, data)
                    self._to_program += data
                    self._write_program()

    def _write_what_waits(self) -> None:
        """On stop: one last try at writing the bytes already reported and not yet written."""
        with contextlib.suppress(PortError):
            if self._to_device:
                if self._device_fd is None:
                    self._write_device_port()
                else:
                    self._write_device(self._device_fd)
            if self._to_program:
                self._write_program()
        if self._to_device or self._to_program:
            log.warning(
                "stopped with %d bytes for the device and %d for the program not written",
                len(self._to_device),
                len(self._to_program),
            )

    def _drain_wake(self) -> None:
        with contextlib.suppress(OSError):
            os.read(self._wake_r, 512)

    def _from_device(self, device: int) -> None:
        try:
            data = os.read(device, CHUNK)
        except BlockingIOError:
            return
        except OSError as exc:
            raise DeviceVanished(
                Message("the device on {device} went away: {error}", device=self.device, error=exc)
            ) from exc
        if not data:
            raise DeviceVanished(
                Message(
                    "the device on {device} went away (its port was closed)", device=self.device
                )
            )
        self._report(RX, data)
        self._to_program += data
        self._write_program()

    def _from_program(self, device: int | None) -> None:
        try:
            data = os.read(self._master, CHUNK)
        except BlockingIOError:
            return
        except OSError as exc:  # not while the bridge holds the slave open
            raise PortError(
                Message("the pseudo-terminal {path} failed: {error}", path=self.path, error=exc)
            ) from exc
        if not data:
            return
        self._report(TX, data)
        self._to_device += data
        if device is None:
            self._write_device_port()
        else:
            self._write_device(device)

    def _write_device(self, device: int) -> None:
        try:
            written = os.write(device, self._to_device)
        except BlockingIOError:
            return
        except OSError as exc:
            raise self._write_failed(exc) from exc
        del self._to_device[:written]
        self.bytes_to_device += written

    def _write_failed(self, exc: Exception) -> DeviceVanished:
        return DeviceVanished(
            Message(
                "writing to the device on {device} failed: {error}", device=self.device, error=exc
            )
        )

    def _write_device_port(self) -> None:
        assert self._link is not None
        data = bytes(self._to_device)
        try:
            written = self._link.port.write(data)
            self._link.port.flush()
        except (serial.SerialException, OSError, ValueError) as exc:
            raise self._write_failed(exc) from exc
        written = len(data) if written is None else written
        del self._to_device[:written]
        self.bytes_to_device += written

    def _write_program(self) -> None:
        try:
            written = os.write(self._master, self._to_program)
        except BlockingIOError:
            return  # the other program reads slowly (or not at all): kept until it does
        except OSError as exc:
            raise PortError(
                Message(
                    "writing to the pseudo-terminal {path} failed: {error}",
                    path=self.path,
                    error=exc,
                )
            ) from exc
        del self._to_program[:written]
        self.bytes_from_device += written

    def _report(self, direction: str, data: bytes) -> None:
        if self.tap is None:
            return
        try:
            self.tap(Traffic(direction, data, time.monotonic()))
        except Exception:
            self.tap_errors += 1
            if self.tap_errors == 1:
                log.exception("the bridge's tap failed; forwarding goes on")
            else:
                log.error(
                    "the bridge's tap failed again (%d times); forwarding goes on", self.tap_errors
                )


def _descriptor(port: serial.SerialBase) -> int | None:
    """The port's own file descriptor if it is a plain POSIX serial port, else None."""
    try:
        from serial.serialposix import Serial as PosixSerial
    except ImportError:  # pragma: no cover - not a POSIX system
        return None
    if isinstance(port, PosixSerial) and getattr(port, "fd", None) is not None:
        fd: int = port.fd
        os.set_blocking(fd, False)
        return fd
    return None
