"""`sim://PROTOCOL?option=value` for pyserial: a simulated device as an in-process serial port.

Options: `instant=0|1`, `mute=0|1`, `line_timing=0|1` (emulate the baud rate, on by default);
COXIRIS: `blocking=0|1`, `speed=S`, `fault=TEXT` (repeatable, CHECK_ERRORS);
Visiomex: `variant=seed|prefixed|board12`, `bugs=0|1` (the public firmware's bugs, on by default),
`pace=recorded|uart` (bytes paced as in the recording, or at the UART's rate);
Firmata: `reset_delay=S` (seconds the board ignores input after the port opens);
laser-frame: fault rates `corrupt=F`, `drop=F`, `drop_reply=F`, `delay_reply=F`, `garbage=F`
(probabilities 0..1), `seed=N` (their random generator), `queue=N` (queue depth in instructions).
Only the options given are passed to the device.

The control lines reach the device: DTR and RTS as pyserial sets them (at open too), a break
as it starts, and CTS, DSR, RI and CD as the device drives them (see SimulatedDevice).
"""

from __future__ import annotations

import threading
import time
import urllib.parse
from typing import Any

import serial
from serial.serialutil import PortNotOpenError, SerialBase, SerialException

from drivers.errors import MotionError
from drivers.link.control_lines import ControlLines
from drivers.messages import Message
from drivers.sim.device import SimulatedDevice
from drivers.sim.registry import create_device

USB_FRAME = 0.002
_FLAGS = {"blocking", "instant", "mute", "line_timing", "bugs"}
_RATES = {"corrupt", "drop", "drop_reply", "delay_reply", "garbage"}
_INTEGERS = {"seed", "queue"}


def parse_sim_url(url: str) -> tuple[str, dict[str, Any], bool]:
    """Split `sim://name?opts` into the protocol name, device options and line timing."""
    parts = urllib.parse.urlsplit(url)
    if parts.scheme != "sim":
        raise SerialException(Message("expected a sim:// URL, got {url!r}", url=url))
    name = (parts.netloc or parts.path).strip("/")
    options: dict[str, Any] = {}
    line_timing = True
    for key, value in urllib.parse.parse_qsl(parts.query, keep_blank_values=True):
        if key in _FLAGS:
            flag = value.lower() not in ("0", "false", "no", "off")
            if key == "line_timing":
                line_timing = flag
            else:
                options[key] = flag
        elif key in _RATES or key in ("speed", "reset_delay", "chatter"):
            options[key] = float(value)
        elif key in _INTEGERS:
            options[key] = int(value)
        elif key in ("variant", "pace"):
            options[key] = value
        elif key == "fault":
            options["faults"] = (*options.get("faults", ()), value)
        else:
            raise SerialException(Message("unknown sim:// option {key!r}", key=key))
    return name, options, line_timing


def with_sim_variant(url: str, variant: str) -> str:
    """A `sim://` URL with the protocol's wire variant added, so the simulated device speaks it
    (a URL that names a variant already, or any other port, is kept as it is)."""
    if not variant or not url.startswith("sim://"):
        return url
    parts = urllib.parse.urlsplit(url)
    options = urllib.parse.parse_qsl(parts.query, keep_blank_values=True)
    if any(key == "variant" for key, _ in options):
        return url
    query = urllib.parse.urlencode([*options, ("variant", variant)])
    return urllib.parse.urlunsplit((parts.scheme, parts.netloc, parts.path, query, parts.fragment))


class Serial(SerialBase):
    """A pyserial port whose other end is a simulated device running on the real clock."""

    is_open: bool  # SerialBase's (pyserial has no type hints)

    def open(self) -> None:
        """Create and boot the device named by the URL."""
        if self._port is None:
            raise SerialException(Message("port must be configured before it can be used"))
        if self.is_open:
            raise SerialException(Message("port already open"))
        try:
            name, options, line_timing = parse_sim_url(self._port)
            baud = self._baudrate if line_timing else None
            self.device: SimulatedDevice = create_device(name, time.monotonic, baud, **options)
        except (MotionError, ValueError, TypeError) as exc:  # TypeError: option not for it
            raise SerialException(
                Message("cannot open {port}: {error}", port=self._port, error=exc)
            ) from exc
        self._pending = bytearray()
        self._wakeup = threading.Event()
        self.is_open = True
        self.device.set_lines(self._dtr_state, self._rts_state)  # as asked before the open
        self.device.boot()

    def close(self) -> None:
        """Close the port; a blocked read returns."""
        self.is_open = False
        if hasattr(self, "_wakeup"):
            self._wakeup.set()

    def _reconfigure_port(self) -> None:
        """Nothing to configure: the device is in-process."""

    def _update_dtr_state(self) -> None:
        """DTR reaches the device (an Arduino resets when it is asserted again)."""
        self.device.set_lines(self._dtr_state, self._rts_state)

    def _update_rts_state(self) -> None:
        """RTS reaches the device."""
        self.device.set_lines(self._dtr_state, self._rts_state)

    def _update_break_state(self) -> None:
        """A break reaches the device as it starts (its end changes nothing more)."""
        if not self.is_open:
            raise PortNotOpenError()
        if self._break_state:
            self.device.receive_break()

    def _modem_inputs(self) -> ControlLines:
        if not self.is_open:
            raise PortNotOpenError()
        return self.device.modem_inputs()

    @property
    def cts(self) -> bool:
        """Clear To Send, as the device drives it."""
        return bool(self._modem_inputs().cts)

    @property
    def dsr(self) -> bool:
        """Data Set Ready, as the device drives it."""
        return bool(self._modem_inputs().dsr)

    @property
    def ri(self) -> bool:
        """Ring Indicator, as the device drives it."""
        return bool(self._modem_inputs().ri)

    @property
    def cd(self) -> bool:
        """Carrier Detect, as the device drives it."""
        return bool(self._modem_inputs().cd)

    def from_url(self, url: str) -> str:
        """Keep the URL; options are read at open."""
        return url

    @property
    def in_waiting(self) -> int:
        """Bytes the device has sent and nobody has read yet."""
        if not self.is_open:
            raise PortNotOpenError()
        self._pending += self.device.read_output()
        return len(self._pending)

    def read(self, size: int = 1) -> bytes:
        """Up to `size` bytes, waiting at most `timeout` as a serial port does."""
        if not self.is_open:
            raise PortNotOpenError()
        deadline = None if self._timeout is None else time.monotonic() + self._timeout
        while True:
            self._pending += self.device.read_output()
            if len(self._pending) >= size:
                break
            now = time.monotonic()
            if deadline is not None and now >= deadline:
                break
            due = self.device.next_due()
            # Wake no more often than a USB-serial adapter delivers (about every 2 ms), so a
            # paced reply arrives in chunks rather than one byte per read.
            wait = 0.5 if due is None else max(USB_FRAME, due - now)
            if deadline is not None:
                wait = min(wait, deadline - now)
            if self._wakeup.wait(wait) and not self.is_open:
                raise PortNotOpenError()
        data = bytes(self._pending[:size])
        del self._pending[:size]
        return data

    def write(self, data: bytes) -> int:
        """Hand the bytes to the device."""
        if not self.is_open:
            raise PortNotOpenError()
        data = serial.to_bytes(data)
        self.device.receive(data)
        return len(data)

    def reset_input_buffer(self) -> None:
        """Drop what the device has sent so far."""
        self._pending.clear()
        self.device.read_output()

    def reset_output_buffer(self) -> None:
        """Nothing is buffered on the way out."""

    @property
    def out_waiting(self) -> int:
        """Always 0."""
        return 0
