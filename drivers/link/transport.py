"""Opening ports through pyserial URLs, and the traffic tap that reports every byte."""

from __future__ import annotations

import errno
import logging
import os
import re
import select
import struct
import time
from collections.abc import Callable

import serial

if os.name == "posix":
    import fcntl
    import termios

    from serial import serialposix

from drivers.errors import BadInput, NoControlLines, PortBusy, PortError
from drivers.link.control_lines import BREAK_S, OUTPUTS, ControlLines
from drivers.link.records import RX, TX, Traffic
from drivers.link.rfc2217_port import PortInUse, Rfc2217Port
from drivers.messages import Message

log = logging.getLogger(__name__)

if "drivers.sim.urlhandler" not in serial.protocol_handler_packages:
    serial.protocol_handler_packages.append("drivers.sim.urlhandler")

POLL_INTERVAL = 0.02  # seconds a read waits for the first byte; bounds the reader's latency
READ_SIZE = 4096  # bytes taken from a descriptor at once (a whole tty input buffer)

TrafficListener = Callable[[Traffic], None]
NoteListener = Callable[[str], None]
NO_MODEM_LINES = (errno.ENOTTY, errno.EINVAL)  # a modem-line ioctl on a tty that has none
MAX_BREAK_S = 5.0  # a longer break is refused (the caller's thread waits it out)
_PTY_PATH = re.compile(r"^/dev/(pts/\d+|ttys\d+|ttyp\w+)$")  # Linux, macOS, BSD pty slaves


class Link:
    """A port with a traffic tap: every byte read or written is reported to the listeners.

    Wraps any pyserial object (device path, `loop://`, `socket://`, `rfc2217://`, `sim://`);
    pyserial and OS errors become PortError, so a vanished device is one clear error.
    """

    def __init__(self, port: serial.SerialBase, url: str = "") -> None:
        self.port = port
        self.url = url or str(getattr(port, "portstr", "") or port.port)
        self.listeners: list[TrafficListener] = []
        self.note_listeners: list[NoteListener] = []
        """Told of every control-line change and break made here ("DTR off", "break 250 ms")."""
        self.opening_notes: list[str] = []
        """What opening the port found worth noting, before anyone could listen (a network
        server that does not confirm control-line changes); the owner logs them."""
        self.closed = False
        self._no_lines: str | None = None  # why the port has no modem lines ("": it has them)
        self._unconfirmed_noted = False
        self._note_unconfirmed(self.opening_notes.append)

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
            raise PortError(Message("{url} is not open", url=self.url))
        descriptor: int = self.port.fd  # (pyserial has no type hints)
        return descriptor

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
            raise PortError(
                Message("writing to {url} failed: {error}", url=self.url, error=exc)
            ) from exc
        if written is not None and written != len(data):
            raise PortError(
                Message(
                    "writing to {url}: only {written} of {total} bytes sent",
                    url=self.url,
                    written=written,
                    total=len(data),
                )
            )

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
            raise PortError(
                Message("reading from {url} failed: {error}", url=self.url, error=exc)
            ) from exc
        if data:
            self._report(RX, data)
        return data

    # -- control lines ---------------------------------------------------------------------
    def set_control(self, name: str, on: bool) -> None:
        """Drive the DTR or RTS line (`name`: "dtr" or "rts"); the change is noted ("DTR off").

        NoControlLines where the port has none (a pseudo-terminal); PortError if it fails.
        """
        key = name.strip().lower()
        if key not in OUTPUTS:
            raise BadInput(
                Message("{name!r} is not a line the host drives (DTR or RTS)", name=name)
            )
        label = key.upper()
        self._require_lines(Message("{line} cannot be set", line=label))
        before = getattr(self.port, f"_{key}_state", None)
        try:
            setattr(self.port, key, bool(on))
        except (serial.SerialException, OSError, ValueError) as exc:
            if before is not None:  # pyserial keeps the asked state even when the ioctl fails
                setattr(self.port, f"_{key}_state", before)
            if isinstance(exc, OSError) and exc.errno in NO_MODEM_LINES:
                self._no_lines = self._why_no_lines()
                raise NoControlLines(
                    self._no_lines_text(Message("{line} cannot be set", line=label))
                ) from exc
            raise PortError(
                Message(
                    "setting {line} on {url} failed: {error}", line=label, url=self.url, error=exc
                )
            ) from exc
        self._note(Message("{line} on", line=label) if on else Message("{line} off", line=label))
        self._note_unconfirmed(self._note)

    def _note_unconfirmed(self, note: NoteListener) -> None:
        """Say once that an RFC 2217 server left a control-line change unconfirmed."""
        what = getattr(self.port, "unconfirmed", "")
        if not what or self._unconfirmed_noted:
            return
        self._unconfirmed_noted = True
        note(
            Message(
                "the server did not confirm the control lines ({what} unanswered); they are "
                "set without confirmation (ser2net does not answer when the port it serves "
                "has no modem lines, e.g. a pseudo-terminal)",
                what=what,
            )
        )

    def control_lines(self) -> ControlLines:
        """All six lines as the port reports them; all None on a port without modem lines.

        On a POSIX serial port, one ioctl reads them all (the outputs as they really are); other
        ports report the outputs as last set and each input on its own.
        """
        if self._lines_missing():
            return ControlLines()
        fd = self._modem_descriptor()
        if fd is not None:
            bits = self._modem_bits(fd)
            if bits is None:
                return ControlLines()
            return ControlLines(
                dtr=bool(bits & serialposix.TIOCM_DTR),
                rts=bool(bits & serialposix.TIOCM_RTS),
                cts=bool(bits & serialposix.TIOCM_CTS),
                dsr=bool(bits & serialposix.TIOCM_DSR),
                cd=bool(bits & serialposix.TIOCM_CD),
                ri=bool(bits & serialposix.TIOCM_RI),
            )
        unconfirmed = bool(getattr(self.port, "unconfirmed", ""))  # as asked, not as they are
        return ControlLines(
            dtr=None if unconfirmed else bool(self.port.dtr),
            rts=None if unconfirmed else bool(self.port.rts),
            cts=self._input("cts"),
            dsr=self._input("dsr"),
            cd=self._input("cd"),
            ri=self._input("ri"),
        )

    def send_break(self, seconds: float = BREAK_S) -> None:
        """Hold the transmit line in the break state for `seconds` (the calling thread waits
        that long), then note it ("break 250 ms"). NoControlLines where the port has no line to
        break (a pseudo-terminal: the break would go nowhere); PortError if it fails."""
        if not 0 < seconds <= MAX_BREAK_S:
            raise BadInput(
                Message("a break lasts more than 0 and at most {most:g} s", most=MAX_BREAK_S)
            )
        self._require_lines(Message("no break can be sent"))
        try:
            self.port.break_condition = True
            try:
                time.sleep(seconds)  # the line is held, not a synchronisation
            finally:
                self.port.break_condition = False
        except (serial.SerialException, OSError, ValueError) as exc:
            raise PortError(
                Message("sending a break on {url} failed: {error}", url=self.url, error=exc)
            ) from exc
        self._note(Message("break {ms:.0f} ms", ms=seconds * 1000))

    def _note(self, text: str) -> None:
        for listener in list(self.note_listeners):
            listener(text)

    def _input(self, name: str) -> bool | None:
        """One input line through pyserial (None where this kind of port cannot tell)."""
        try:
            return bool(getattr(self.port, name))
        except (AttributeError, NotImplementedError):
            return None
        except OSError as exc:
            if exc.errno in NO_MODEM_LINES:
                return None
            raise self._input_failed(name, exc) from exc
        except (serial.SerialException, ValueError) as exc:
            raise self._input_failed(name, exc) from exc

    def _input_failed(self, name: str, exc: Exception) -> PortError:
        return PortError(
            Message(
                "reading {line} on {url} failed: {error}",
                line=name.upper(),
                url=self.url,
                error=exc,
            )
        )

    def _modem_descriptor(self) -> int | None:
        """The descriptor of a POSIX serial port (spy:// on one included), for modem ioctls."""
        if os.name != "posix" or not isinstance(self.port, serial.Serial):
            return None
        if not self.port.is_open:
            raise PortError(Message("{url} is not open", url=self.url))
        descriptor: int = self.port.fd  # (pyserial has no type hints)
        return descriptor

    def _modem_bits(self, fd: int) -> int | None:
        """TIOCMGET's bits; None when the tty has no modem lines (remembered)."""
        try:
            packed = fcntl.ioctl(fd, serialposix.TIOCMGET, struct.pack("I", 0))
        except OSError as exc:
            if exc.errno in NO_MODEM_LINES:
                self._no_lines = self._why_no_lines()
                return None
            raise PortError(
                Message(
                    "reading the control lines of {url} failed: {error}", url=self.url, error=exc
                )
            ) from exc
        return int(struct.unpack("I", packed)[0])

    def _lines_missing(self) -> str:
        """Why the port has no modem lines ("": it has them); looked at once per link."""
        if self._no_lines is None:
            self._no_lines = ""
            if _is_socket(self.port):
                self._no_lines = Message(
                    "a TCP socket"
                )  # pyserial's socket:// ignores them silently
            else:
                fd = self._modem_descriptor()
                if fd is not None:
                    self._modem_bits(fd)  # sets the reason if the tty has none
        return self._no_lines

    def _require_lines(self, what: Message) -> None:
        if self._lines_missing():
            raise NoControlLines(self._no_lines_text(what))

    def _no_lines_text(self, what: Message) -> Message:
        return Message(
            "{url} has no modem control lines ({why}): {what}",
            url=self.url,
            why=self._no_lines,
            what=what,
        )

    def _why_no_lines(self) -> str:
        """ "a pseudo-terminal" for a pty's slave, else what the driver says."""
        try:
            path = os.ttyname(self.port.fd)
        except (OSError, AttributeError, TypeError):
            path = ""
        if _PTY_PATH.match(path):
            return Message("a pseudo-terminal")
        return Message("its driver has no modem-line control")

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


def _is_socket(port: serial.SerialBase) -> bool:
    """Whether `port` is pyserial's socket:// (raw TCP: no modem lines, no break)."""
    return type(port).__module__ == "serial.urlhandler.protocol_socket"


def open_link(url: str, baud: int, *, dtr: bool | None = None, rts: bool | None = None) -> Link:
    """Open `url` (path, COM name or pyserial URL, `sim://NAME` included) at `baud`, 8N1, with
    DTR and RTS as given (None: as the port opens them, asserted with pyserial)."""
    if not url:
        raise PortError(Message("no port given"))
    try:
        port = _port_for_url(url, baud)
        if os.name == "posix" and isinstance(port, serial.Serial):
            port.exclusive = True  # flock: a second program's open fails (spy:// included)
        if dtr is not None:
            port.dtr = dtr
        if rts is not None:
            port.rts = rts
        port.open()
    except (serial.SerialException, OSError, ValueError) as exc:
        if isinstance(exc, PortInUse):
            raise PortBusy(str(exc)) from exc
        if _busy(exc):
            raise PortBusy(
                Message("{url} is in use by another program", url=_port_name(url))
            ) from exc
        raise PortError(
            Message("cannot open {url}: {error}", url=url, error=_open_error(exc))
        ) from exc
    return Link(port, url)


def _open_error(exc: BaseException) -> object:
    """Why a port did not open, its errno and path said once (pyserial's text repeats both:
    `[Errno 2] could not open port P: [Errno 2] No such file or directory: 'P'`)."""
    cause = exc.__context__
    if (
        isinstance(exc, serial.SerialException)
        and isinstance(cause, OSError)
        and not isinstance(cause, serial.SerialException)
        and cause.strerror
    ):
        return f"[Errno {cause.errno}] {cause.strerror}" if cause.errno else cause.strerror
    return exc  # (a Message inside it stays translatable)


def _port_for_url(url: str, baud: int) -> serial.SerialBase:
    """The pyserial port object for `url`, not opened yet; `rfc2217://` is ours (servers that
    do not confirm control lines, clearer errors)."""
    if url[:10].lower() == "rfc2217://":
        port = Rfc2217Port(None, baudrate=baud, timeout=POLL_INTERVAL)
        port.port = url
        return port
    return serial.serial_for_url(url, baudrate=baud, timeout=POLL_INTERVAL, do_not_open=True)


def _busy(exc: Exception) -> bool:
    """Whether an open failed because another program holds the port: the exclusive lock
    taken (POSIX), or the port opened elsewhere (Windows: access denied)."""
    if getattr(exc, "errno", None) in (errno.EWOULDBLOCK, errno.EAGAIN):
        return True
    return os.name == "nt" and "PermissionError(13" in str(exc)


def _port_name(url: str) -> str:
    """The port a URL opens: `/dev/ttyUSB0` for `spy:///dev/ttyUSB0?file=x`, else the URL."""
    if url.startswith("spy://"):
        return url.removeprefix("spy://").split("?", 1)[0]
    return url
