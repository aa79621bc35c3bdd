"""`rfc2217://HOST:PORT`: pyserial's RFC 2217 client, for servers that leave control lines
unconfirmed, and with errors that say what to do.

ser2net 4.x (through gensio) sets DTR and RTS on the port it serves with TIOCMGET/TIOCMSET; on a
port without modem lines (a pseudo-terminal, some adapters) that ioctl fails and ser2net sends
no answer at all to the SET_CONTROL request. pyserial waits for the answer and fails the open with
"timeout while waiting for option 'control'" unless the URL says `?ign_set_control`. This port
waits a bounded time (scaled to how fast the server confirmed the settings); when no answer
comes it goes on without confirmation and says so (`unconfirmed`): the request was sent, so a
server that can set the line has set it. URL options are pyserial's (`ign_set_control`,
`poll_modem`, `timeout=S`, `logging=LEVEL`).
"""

from __future__ import annotations

import logging
import threading
import time
import urllib.parse

from serial import rfc2217
from serial.serialutil import SerialException

from drivers.messages import Message

log = logging.getLogger(__name__)

CONFIRM_MIN_S = 0.25  # the least time an unanswered SET_CONTROL is waited for
CONFIRM_FACTOR = 10  # times the slowest answer seen so far (a busy network)
HANGUP_READ_S = 0.5  # how long a server's last words are waited for after it hung up
HANGUP_READ_BYTES = 4096
IAC = 0xFF  # telnet's "interpret as command"
ANSWER_POLL_S = 0.002  # how often the wait looks at the answer (pyserial: every 50 ms)
_CONTROL_NAMES = {
    rfc2217.SET_CONTROL_DTR_ON: "DTR on",
    rfc2217.SET_CONTROL_DTR_OFF: "DTR off",
    rfc2217.SET_CONTROL_RTS_ON: "RTS on",
    rfc2217.SET_CONTROL_RTS_OFF: "RTS off",
    rfc2217.SET_CONTROL_BREAK_ON: "break on",
    rfc2217.SET_CONTROL_BREAK_OFF: "break off",
}


class NoModemState(SerialException, NotImplementedError):  # type: ignore[misc]
    """The server has reported no modem lines (CTS, DSR, CD, RI): they are unknown."""


class PortInUse(SerialException):  # type: ignore[misc]
    """The server refused this client: another one holds the port (ser2net's
    `max-connections`)."""


class Rfc2217Port(rfc2217.Serial):  # type: ignore[misc]  # (pyserial has no type hints)
    """An RFC 2217 client port; `unconfirmed` names the first control change the server left
    unanswered ("" while every change was confirmed)."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        self.unconfirmed = ""
        self._slowest = 0.0  # seconds the slowest confirmed SET_CONTROL took (0: none yet)
        self._hung_up = False  # the server closed the connection while it was being opened
        super().__init__(*args, **kwargs)

    def open(self) -> None:
        """Connect and negotiate; a SerialException that says why when it cannot."""
        self.unconfirmed = ""
        self._slowest = 0.0
        self._hung_up = False
        try:
            super().open()
        except (SerialException, OSError) as exc:
            refusal = self._refusal()
            if refusal:
                raise PortInUse(refusal) from exc
            if isinstance(exc, SerialException):
                raise SerialException(self._explain(exc)) from exc
            raise
        deadline = time.monotonic() + CONFIRM_MIN_S  # ser2net reports them just after connecting
        while self._modemstate is None and time.monotonic() < deadline:
            time.sleep(ANSWER_POLL_S)

    def _telnet_read_loop(self) -> None:
        """pyserial's reader thread, quiet when the server hangs up while it answers an option
        (ser2net refusing a second client closes as soon as it has said so)."""
        try:
            super()._telnet_read_loop()
            if self.is_open:  # the loop ended on the server's end of file, not our close
                self._hung_up = True
        except OSError as exc:
            log.debug("%s: the server closed the connection: %s", self.portstr, exc)
            self._hung_up = True
            self._read_what_is_left()

    def _read_what_is_left(self) -> None:
        """Keep the text a server sent before hanging up (its reason), telnet commands left
        out, for `_refusal`; bounded in bytes and time."""
        sock, queue = self._socket, self._read_buffer
        if sock is None or queue is None:
            return
        left = bytearray()
        try:
            sock.settimeout(HANGUP_READ_S)
            while len(left) < HANGUP_READ_BYTES and (data := sock.recv(1024)):
                left += data
        except OSError:
            pass
        skip = 0
        for byte in left:
            if byte == IAC:
                skip = 3  # IAC, its verb, its option: negotiation, not text
            if skip:
                skip -= 1
                continue
            queue.put(bytes((byte,)))
        queue.put(None)

    def _internal_raw_write(self, data: bytes) -> None:
        """Write to the server; when it has hung up, let the reader keep what it said first."""
        try:
            super()._internal_raw_write(data)
        except OSError:
            self._hung_up = True
            reader = self._thread
            if reader is not None and reader is not threading.current_thread():
                reader.join(HANGUP_READ_S)
            raise

    def _refusal(self) -> str:
        """Why a server that accepted this client hung up while negotiating, as the error to
        show ("" if it did not hang up): ser2net says "Port already in use" and closes when
        another client holds the port; its words are quoted when they arrived before the hang-up
        (a reset can discard them)."""
        said = bytearray()
        hung_up = self._hung_up
        queue = self._read_buffer
        while queue is not None and not queue.empty():
            byte = queue.get_nowait()
            if byte is not None:
                said += byte
        if not hung_up:
            return ""
        text = said.decode("latin-1", "replace").strip()
        return Message(
            "{where} accepted this connection and closed it at once{said}: another client "
            "probably holds the port (ser2net serves one at a time with max-connections: 1); "
            "close it there first",
            where=self._where(),
            said=f" ({text})" if text else "",
        )

    def _where(self) -> str:
        """HOST:PORT of this port's URL."""
        parts = urllib.parse.urlsplit(self.portstr or "")
        try:
            return f"{parts.hostname}:{parts.port}"
        except ValueError:
            return str(self.portstr)

    def get_modem_state(self) -> int:
        """The modem lines as the server last reported them; NoModemState if it never has."""
        if self._modemstate is None and not self._poll_modem_state:
            raise NoModemState(Message("the server has not reported the modem lines"))
        return int(super().get_modem_state())

    def _explain(self, exc: SerialException) -> str:
        """What a failed open means for someone serving a port with ser2net."""
        parts = urllib.parse.urlsplit(self.portstr or "")
        try:
            where = f"{parts.hostname}:{parts.port}"
        except ValueError:
            return str(exc)
        cause = exc.__context__
        if isinstance(cause, OSError) and str(exc).startswith("Could not open port"):
            return Message(
                "nothing answers at {where} ({error}): is ser2net (or another RFC 2217 "
                "server) running there and serving that port?",
                where=where,
                error=cause.strerror or cause,
            )
        if "does not seem to support RFC2217" in str(exc):
            return Message(
                "{where} answers, but not as an RFC 2217 server: serve the port with ser2net's "
                "`accepter: telnet(rfc2217),tcp,PORT`, or open a raw TCP server as "
                "socket://{where}",
                where=where,
            )
        return str(exc)

    def rfc2217_set_control(self, value: bytes) -> None:
        """Ask the server to change a line (or the flow control); wait for its confirmation a
        bounded time, and no more once the server has left one unconfirmed."""
        item = self._rfc2217_options["control"]
        item.set(value)
        if self._ignore_set_control_answer or self.unconfirmed:
            return
        started = time.monotonic()
        if _answered(item, self._confirm_wait()):
            self._slowest = max(self._slowest, time.monotonic() - started)
            return
        self.unconfirmed = _CONTROL_NAMES.get(value, f"SET_CONTROL {value.hex()}")
        log.info(
            "%s: the server did not confirm %s; control lines are set without confirmation",
            self.portstr,
            self.unconfirmed,
        )

    def rfc2217_send_purge(self, value: bytes) -> None:
        """Ask the server to purge a buffer and wait for its confirmation (as pyserial, polled
        more often: opening waits for two of them)."""
        item = self._rfc2217_options["purge"]
        item.set(value)
        if not _answered(item, self._network_timeout):
            raise SerialException(Message("timeout while waiting for option 'purge'"))

    def _confirm_wait(self) -> float:
        """How long an answer to SET_CONTROL is waited for."""
        if not self._slowest:
            return float(self._network_timeout)
        return float(min(self._network_timeout, max(CONFIRM_MIN_S, CONFIRM_FACTOR * self._slowest)))


def _answered(item: rfc2217.TelnetSubnegotiation, timeout: float) -> bool:
    """Whether the server confirmed `item` within `timeout` seconds (an answer with another
    value than asked is no confirmation)."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            if item.is_ready():
                return True
        except ValueError:  # older pyserial: the server answered another value
            return False
        if time.monotonic() >= deadline:
            return False
        time.sleep(ANSWER_POLL_S)  # the reader thread fills in the answer
