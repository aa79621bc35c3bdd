"""The Visiomex VMR2P0R0001 firmware as it behaves on the wire (drivers/protocols/README.md §2 and
§2b)."""

from __future__ import annotations

import logging
from dataclasses import dataclass

from drivers.protocols.visiomex.model import (
    DRIVING_MECHANISM,
    FULLCYCLE,
    MICROSTEP,
    POWER_ON,
    SILENCE,
    FirmwareState,
    debug_lines,
)
from drivers.protocols.visiomex.protocol import BOOT_BANNER
from drivers.protocols.visiomex.timing import HOST_PACING, REPLY_LATENCY, stepping_start
from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import BITS_PER_BYTE, SimulatedDevice
from drivers.sim.visiomex_firmware import (
    MOVE_TYPE,
    PARAMETER_COUNT,
    SET_ID,
    SET_VALUE,
    VARIANTS,
    X_DIR,
    Variant,
    char_at,
    parse_atof,
    parse_atol,
)

__all__ = ["PACES", "POWER_ON", "SILENCE", "VARIANTS", "VisiomexDevice"]

PACES = {"recorded": HOST_PACING, "uart": 1.0}  # byte times per sent byte

log = logging.getLogger(__name__)


@dataclass
class _Segment:
    """A blocking move: X steps first, then the Y loop."""

    t0: float = 0.0
    start: tuple[float, float] = (0.0, 0.0)
    end: tuple[float, float] = (0.0, 0.0)
    x_duration: float = 0.0
    y_duration: float = 0.0


class VisiomexDevice(SimulatedDevice):
    """The Nucleo sketch: fixed-position ASCII packets, framed by 1 s of silence.

    `variant` picks the packet profile (`seed`, `prefixed`, `board12`); `bugs=True` is the public
    firmware (drivers/protocols/README.md §2b), `bugs=False` the documented behaviour (the same
    arithmetic and timing, with the documented checks, units and Y loop). `instant` makes stepping
    take no time; `mute` makes a device that never sends anything. `pace`: "recorded" sends a byte
    every 1.06 byte times, as the recorded firmware does (tests/data/visiomex-moves.json), "uart" at
    the board UART's line rate.
    """

    protocol = "visiomex"
    rx_capacity = 63  # STM32 core: 64-byte ring buffer

    def __init__(
        self,
        clock: Clock = monotonic,
        baud: int | None = None,
        *,
        variant: str = "seed",
        bugs: bool = True,
        instant: bool = False,
        mute: bool = False,
        pace: str = "recorded",
    ) -> None:
        if variant not in VARIANTS:
            known = ", ".join(VARIANTS)
            raise ValueError(f"unknown Visiomex variant {variant!r} (variants: {known})")
        if pace not in PACES:
            raise ValueError(f"unknown pace {pace!r} (paces: {', '.join(PACES)})")
        super().__init__(clock, baud)
        self.variant: Variant = VARIANTS[variant]
        self.default_baud = self.variant.baud
        self.bugs = bugs
        self.instant = instant
        self.mute = mute
        self.pacing = PACES[pace]
        self.state = FirmwareState.boot()
        self._packet = bytearray()
        self._last_read = 0.0
        self._count = (0.0, 0.0)
        self._segment = _Segment()

    # -- accessors -------------------------------------------------------------------------
    @property
    def parameters(self) -> dict[int, float]:
        """The stored parameters by id, as the firmware holds them now."""
        return dict(self.state.values)

    @property
    def cycle(self) -> tuple[float, float]:
        """The cycle lengths C (mm) read from 01/02 at boot."""
        return self.state.cycle

    @property
    def firmware_position(self) -> tuple[float, float]:
        """Where the firmware believes it is (mm from power-on): the sum of commanded moves."""
        return self._count

    def position(self, t: float | None = None) -> tuple[float, float]:
        """Where the axes physically are at `t` (mm from power-on; default: now)."""
        now = self.clock() if t is None else t
        seg = self._segment
        (x0, y0), (x1, y1) = seg.start, seg.end
        if now <= seg.t0:
            return seg.start
        x_end = seg.t0 + seg.x_duration
        if now < x_end:
            return (x0 + (x1 - x0) * (now - seg.t0) / seg.x_duration, y0)
        if now < x_end + seg.y_duration:
            return (x1, y0 + (y1 - y0) * (now - x_end) / seg.y_duration)
        return seg.end

    # -- serial framing ----------------------------------------------------------------------
    def boot(self) -> None:
        """Power-on: the values are the declared ones again; the sketch prints `Checkpoint 2`."""
        self.state = FirmwareState.boot()
        self._packet = bytearray()
        self._line(BOOT_BANNER, self.clock())

    def tx_byte_seconds(self) -> float:
        """A sent byte's time: the line rate's, slowed by the recorded firmware's pacing."""
        return super().tx_byte_seconds() * self.pacing

    def emit(self, data: bytes, at: float) -> None:
        """Send `data` at `at`, unless the device is mute."""
        if not self.mute:
            super().emit(data, at)

    def handle_byte(self, byte: int, t: float) -> None:
        """Serial.readString(): append the byte; the packet ends after SILENCE without one."""
        self._packet.append(byte)
        self._last_read = t

    def wake_at(self) -> float | None:
        """The end of the packet being read, if any."""
        return self._last_read + SILENCE if self._packet else None

    def tick(self, now: float) -> None:
        """readString() timed out: act on the packet."""
        packet, self._packet = self._packet.decode("latin-1"), bytearray()
        log.debug("visiomex packet %r at %.3f", packet, now)
        self._execute(packet, now + (REPLY_LATENCY if self.baud else 0.0))

    # -- output ----------------------------------------------------------------------------
    def _line(self, text: str, t: float) -> int:
        data = text.encode("latin-1") + b"\r\n"
        self.emit(data, t)
        return len(data)

    def _feedback(self, code: str, t: float) -> int:
        return self._line(self.variant.prefix + code, t)

    # -- the sketch ------------------------------------------------------------------------
    def _execute(self, packet: str, t: float) -> None:
        kind = packet[0]
        if not self.bugs and kind in "MS" and len(packet) != self.variant.packet_size:
            self._feedback("EP0001", t)
        elif kind == "M":
            self._move_packet(packet, t)
        elif kind == "S":
            self._set_packet(packet, t)
        elif kind == "G":
            pass  # no reply at all
        elif kind == "D" and self.variant.go_home:
            self._go_home(t)
        else:
            self._feedback("EP0002", t)

    def _set_packet(self, packet: str, t: float) -> None:
        ident, value = parse_atol(packet[SET_ID]), parse_atol(packet[SET_VALUE])
        if not 1 <= ident <= PARAMETER_COUNT:
            self._feedback("EP0006", t)
            if self.bugs:
                self.state.recalculate()  # after every S packet, EP0006 included
            return
        if self.bugs:
            self._feedback(f"FS{ident:04d}", t)
            self.state.set(ident, value)  # stores, then recalculates (27 forced to 1)
            return
        if ident == DRIVING_MECHANISM and value not in (0, 1):
            self._feedback("EF0002", t)
            return
        # The documented firmware stores what it is sent and keeps the mechanism it was given.
        mechanism = value if ident == DRIVING_MECHANISM else self.state.values[DRIVING_MECHANISM]
        self.state.values[ident] = value
        self.state.recalculate()
        self.state.values[DRIVING_MECHANISM] = mechanism
        self._feedback(f"FS{ident:04d}", t)

    def _move_packet(self, packet: str, t: float) -> None:
        v = self.variant
        kind = char_at(packet, MOVE_TYPE)
        if not self.bugs and kind not in ("L", "R", "S"):
            self._feedback("EP0003", t)
            return
        signs = []
        sent = 0
        for axis, index in enumerate((X_DIR, v.y_dir)):
            direction = char_at(packet, index)
            if direction in ("P", "N"):
                signs.append(-1 if direction == "N" else 1)
            elif self.bugs:
                sent += self._feedback("EP0003", t)  # and the axis runs positive
                signs.append(1)
            else:
                self._feedback("EP0004" if axis == 0 else "EP0005", t)
                return
        if self.bugs:  # the type letter is not read: the digits are µm (`atof`)
            fields = (parse_atof(packet[v.x_digits]), parse_atof(packet[v.y_digits]))
            micrometres = [f * 1000 / v.per_mm for f in fields]
            self._go(micrometres, signs, t, sent)
            return
        amounts = (parse_atol(packet[v.x_digits]), parse_atol(packet[v.y_digits]))
        steps: tuple[int, int] | None = None
        if kind == "L":
            micrometres = [a * 1000 / v.per_mm for a in amounts]
        elif kind == "R":
            micrometres = [a / 360 * c * 1000 for a, c in zip(amounts, self.cycle, strict=True)]
        else:
            micrometres = [a / max(self._per_rev(i), 1) * self.cycle[i] * 1000 for i, a in
                           enumerate(amounts)]  # fmt: skip
            steps = (amounts[0], amounts[1])
        self._go(micrometres, signs, t, sent, steps)

    def _go_home(self, t: float) -> None:
        """`D` (board12): back to the origin by the commanded count."""
        count = self._count
        signs = [-1 if c > 0 else 1 for c in count]
        self._go([abs(c) * 1000 for c in count], signs, t, 0)

    def _per_rev(self, axis: int) -> int:
        values = self.state.values
        return int(values[FULLCYCLE[axis]]) * int(values[MICROSTEP[axis]])

    def _go(
        self,
        micrometres: list[float],
        signs: list[int],
        t: float,
        sent: int,
        steps: tuple[int, int] | None = None,
    ) -> None:
        """Print the debug lines and FP0001, step (blocking), then FA0001."""
        state = self.state
        if not self.bugs:  # the documented firmware prints distances without their sign
            micrometres = [abs(m) for m in micrometres]
        for text in debug_lines(state, micrometres[0], micrometres[1]):
            sent += self._line(text, t)
        sent += self._feedback("FP0001", t)
        if steps is None:
            steps = (state.steps("x", micrometres[0]), state.steps("y", micrometres[1]))
        plan = state.move_steps(steps[0], steps[1], y_runs_steps=not self.bugs)
        moved = [0.0, 0.0]
        for axis, loops in enumerate(plan.loops):
            if self._per_rev(axis):
                moved[axis] = signs[axis] * loops * self.cycle[axis] / self._per_rev(axis)
        # Stepping starts once FP0001 is in the 64-byte transmit buffer.
        begin = t + stepping_start(
            sent, BITS_PER_BYTE / (self.baud or self.variant.baud) * self.pacing
        )
        durations = (0.0, 0.0) if self.instant else (plan.x_seconds, plan.y_seconds)
        start = self.position(begin)
        self._segment = _Segment(
            begin, start, (start[0] + moved[0], start[1] + moved[1]), *durations
        )
        dx, dy = (s * m / 1000 for s, m in zip(signs, micrometres, strict=True))
        self._count = (self._count[0] + dx, self._count[1] + dy)
        done = begin + durations[0] + durations[1] if not self.instant else t
        self.busy_until = done
        self._feedback("FA0001", done)
