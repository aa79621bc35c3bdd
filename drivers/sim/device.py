"""The simulated-device base: bytes in with arrival times, bytes out with due times."""

from __future__ import annotations

import logging
from abc import ABC, abstractmethod
from collections import deque
from collections.abc import Container
from typing import ClassVar

from drivers.link.control_lines import ControlLines
from drivers.sim.clock import Clock, monotonic

log = logging.getLogger(__name__)

BITS_PER_BYTE = 10  # 8N1: start bit, 8 data bits, stop bit


class SimulatedDevice(ABC):
    """A device seen from its serial line.

    `receive(data)` hands it bytes written by the host now; `read_output()` returns what it has
    sent by now; `next_due()` says when something will next happen, so a server can sleep until
    then. With `baud` set, both directions are paced at the line rate, as on a real UART.
    A device that is busy (a blocking firmware callback) leaves input in its receive buffer, which
    holds `rx_capacity` bytes like an Arduino's; what does not fit is lost.

    The control lines (`set_lines`, `modem_inputs`, `receive_break`): the host's DTR and RTS start
    asserted, as a port opened by pyserial has them, so a device nobody touches the lines of
    behaves as it always did. A board that resets when its port opens (`resets_on_open`: an
    Arduino) resets on every DTR assertion, as its auto-reset capacitor turns the edge into a
    reset pulse; RTS is wired to nothing on these boards. A break reaches the firmware as one
    NUL byte (see `receive_break`).
    """

    protocol: ClassVar[str]
    default_baud: int = 115200  # per instance where a variant has its own (Visiomex)
    rx_capacity: ClassVar[int] = 63  # Arduino's 64-byte ring buffer holds 63
    resets_on_open: ClassVar[bool] = False  # an Arduino resets when its port opens (DTR)

    def __init__(self, clock: Clock = monotonic, baud: int | None = None) -> None:
        self.clock = clock
        self.baud = baud
        self._rx: deque[tuple[float, int]] = deque()
        self._rx_line_free = 0.0
        self._tx: deque[tuple[float, bytes]] = deque()
        self._tx_line_free = 0.0
        self.busy_until = 0.0
        self.dropped_rx = 0
        self.dtr = True  # the host's lines as the device sees them (asserted: True)
        self.rts = True
        self.resets = 0  # resets by a DTR assertion
        self.breaks = 0

    # -- host side -------------------------------------------------------------------------
    def boot(self) -> None:
        """Power-on: schedule whatever the firmware prints at start."""

    def power_cycle(self) -> None:
        """A reset (an Arduino's, when its port opens): what was in flight is gone, then boot."""
        self._rx.clear()
        self._tx.clear()
        self.busy_until = 0.0
        self.boot()

    def receive(self, data: bytes) -> None:
        """Bytes written by the host at the current time."""
        now = self.clock()
        self._process(now)
        byte_time = BITS_PER_BYTE / self.baud if self.baud else 0.0
        t = max(now, self._rx_line_free)
        for byte in data:
            t += byte_time
            if self.busy_until > t and self._pending_rx(t) >= self.rx_capacity:
                self.dropped_rx += 1
                log.debug("receive buffer full while busy: byte %#04x lost", byte)
                continue
            self._rx.append((t, byte))
        self._rx_line_free = t
        self._process(now)

    def set_lines(self, dtr: bool, rts: bool) -> None:
        """The host drives DTR and RTS (True: asserted) from now on.

        Input that has arrived by now is read under the lines as they were. A board that resets
        when its port opens (an Arduino's DTR auto-reset) resets when DTR is asserted again.
        """
        now = self.clock()
        self._process(now)
        asserted = dtr and not self.dtr
        self.dtr, self.rts = bool(dtr), bool(rts)
        if asserted and self.resets_on_open:
            log.debug("DTR asserted: the board resets")
            self.dtr_reset(now)

    def dtr_reset(self, now: float) -> None:
        """The reset a DTR assertion causes: what the device had already put on the line by
        `now` still reaches the host; the rest, and the input not read yet, is lost; it boots."""
        sent = [(t, data) for t, data in self._tx if t <= now]
        self.resets += 1
        self._tx_line_free = self._rx_line_free = now  # bytes on their way are cut short
        self.power_cycle()
        self._tx.extendleft(reversed(sent))

    def modem_inputs(self) -> ControlLines:
        """The lines the device drives, with the host's as it sees them.

        A powered device asserts DSR (it is there and ready) and CTS (none of these boards does
        hardware flow control, so it is always clear to send); CD (a modem's carrier) and RI (a
        modem's ring) are off, as there is no modem.
        """
        return ControlLines(dtr=self.dtr, rts=self.rts, cts=True, dsr=True, cd=False, ri=False)

    def receive_break(self) -> None:
        """A break from the host: the UART reads one NUL byte with a framing error, which the
        firmware takes as a NUL (an AVR's HardwareSerial checks only parity errors; a Linux tty
        in raw mode without IGNBRK or BRKINT also reads a break as a NUL); the line then stays
        low until the break ends, so nothing more is read meanwhile."""
        self.breaks += 1
        self.receive(b"\x00")

    def read_output(self) -> bytes:
        """Everything the device has sent by now."""
        now = self.clock()
        self._process(now)
        out = bytearray()
        while self._tx and self._tx[0][0] <= now:
            out += self._tx.popleft()[1]
        return bytes(out)

    def next_due(self) -> float | None:
        """When the next output, input or internal event is due (None: nothing pending)."""
        times = [t for t in (self.wake_at(),) if t is not None]
        if self._tx:
            times.append(self._tx[0][0])
        if self._rx:
            times.append(max(self._rx[0][0], self.busy_until))
        return min(times) if times else None

    # -- firmware side ---------------------------------------------------------------------
    def tx_byte_seconds(self) -> float:
        """Seconds each sent byte takes on the line (with `baud` set)."""
        return BITS_PER_BYTE / self.baud if self.baud else 0.0

    def emit(self, data: bytes, at: float) -> None:
        """Send `data` starting at time `at` (paced at the line rate when emulated)."""
        if not data:
            return
        if not self.baud:
            self._tx.append((at, data))
            return
        byte_time = self.tx_byte_seconds()
        t = max(at, self._tx_line_free)
        for byte in data:
            t += byte_time
            self._tx.append((t, bytes((byte,))))
        self._tx_line_free = t

    def discard_available(self, t: float, until: Container[int] = ()) -> int:
        """Throw away the input that has arrived by `t`, up to and including a byte in `until`."""
        count = 0
        while self._rx and self._rx[0][0] <= t:
            _, byte = self._rx.popleft()
            count += 1
            if byte in until:
                break
        return count

    def wake_at(self) -> float | None:
        """A time at which the firmware wants `tick` called (None: never)."""
        return None

    def tick(self, now: float) -> None:
        """Time-driven firmware behaviour at a `wake_at` time; must move `wake_at` past `now`."""

    @abstractmethod
    def handle_byte(self, byte: int, t: float) -> None:
        """The firmware reads one byte at time `t`."""

    def _pending_rx(self, t: float) -> int:
        return sum(1 for arrival, _ in self._rx if arrival <= t)

    def _process(self, now: float) -> None:
        while True:
            wake = self.wake_at()
            next_rx = max(self._rx[0][0], self.busy_until) if self._rx else None
            if wake is not None and wake <= now and (next_rx is None or wake <= next_rx):
                self.tick(wake)
                if self.wake_at() == wake:  # tick did not reschedule: avoid spinning
                    break
                continue
            if next_rx is None or next_rx > now:
                break
            _, byte = self._rx.popleft()
            self.handle_byte(byte, next_rx)
