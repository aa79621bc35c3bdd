"""The simulated-device base: bytes in with arrival times, bytes out with due times."""

from __future__ import annotations

import logging
from abc import ABC, abstractmethod
from collections import deque
from collections.abc import Container
from typing import ClassVar

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
    """

    protocol: ClassVar[str]
    default_baud: ClassVar[int] = 115200
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
    def emit(self, data: bytes, at: float) -> None:
        """Send `data` starting at time `at` (paced at the line rate when emulated)."""
        if not data:
            return
        if not self.baud:
            self._tx.append((at, data))
            return
        byte_time = BITS_PER_BYTE / self.baud
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
