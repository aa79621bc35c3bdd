"""The Visiomex VMR2P0R0001 firmware as it behaves on the wire (PROTOCOLS.md §2)."""

from __future__ import annotations

import logging
from dataclasses import dataclass

from drivers.protocols.visiomex import BOOT_BANNER
from drivers.sim.arduino import print_float, to_float32
from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice
from drivers.sim.visiomex_firmware import (
    BOOT_PARAMETERS,
    DRIVING_MECHANISM,
    FULLCYCLE,
    MICROSTEP,
    MOVE_TYPE,
    PARAMETER_COUNT,
    SET_ID,
    SET_VALUE,
    STEP_COUNT_ACCELERATION_Y,
    STEP_DELAY,
    VARIANTS,
    X_DIR,
    Variant,
    atol,
    c_div,
    char_at,
    cycle_length,
    f32_div,
    steps_for,
)

__all__ = ["BOOT_PARAMETERS", "LOOP_OVERHEAD", "SILENCE", "VARIANTS", "VisiomexDevice"]

log = logging.getLogger(__name__)

SILENCE = 1.0  # Serial.readString() returns after this long without a byte
LOOP_OVERHEAD = 575e-6  # per step, on top of the two step delays (fits the recording)


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

    `variant` picks the packet profile (`seed`, `prefixed`, `board12`); `bugs=True` reproduces
    the public firmware's bugs, `bugs=False` the documented behaviour. `instant` makes stepping
    take no time; `mute` makes a device that never sends anything.
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
    ) -> None:
        if variant not in VARIANTS:
            known = ", ".join(VARIANTS)
            raise ValueError(f"unknown Visiomex variant {variant!r} (variants: {known})")
        super().__init__(clock, baud)
        self.variant: Variant = VARIANTS[variant]
        self.default_baud = self.variant.baud
        self.bugs = bugs
        self.instant = instant
        self.mute = mute
        self._params = dict(BOOT_PARAMETERS)
        # Computed once at power-on; later sets of 01-04 do not change it.
        self.cycle: tuple[float, float] = (
            cycle_length(self._params, 0),
            cycle_length(self._params, 1),
        )
        self._packet = bytearray()
        self._last_read = 0.0
        self._count = (0.0, 0.0)
        self._segment = _Segment()

    # -- accessors -------------------------------------------------------------------------
    @property
    def parameters(self) -> dict[int, int]:
        """The stored parameters (wire integers by id), as the firmware holds them now."""
        return dict(self._params)

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
        """Power-on: the sketch prints `Checkpoint 2`."""
        self._line(BOOT_BANNER, self.clock())

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
        self._execute(packet, now)

    # -- output ----------------------------------------------------------------------------
    def _line(self, text: str, t: float) -> None:
        self.emit(text.encode("latin-1") + b"\r\n", t)

    def _feedback(self, code: str, t: float) -> None:
        self._line(self.variant.prefix + code, t)

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
            self._go(-self._count[0], -self._count[1], t)
        else:
            self._feedback("EP0002", t)

    def _set_packet(self, packet: str, t: float) -> None:
        ident, value = atol(packet[SET_ID]), atol(packet[SET_VALUE])
        if not 1 <= ident <= PARAMETER_COUNT:
            self._feedback("EP0006", t)
            return
        if self.bugs and ident in (3, 4):
            value = c_div(value, 4)  # firmware bug: the pulley diameter is stored divided by 4
        if not self.bugs and ident == DRIVING_MECHANISM and value not in (0, 1):
            self._feedback("EF0002", t)
            return
        self._params[ident] = value
        if self.bugs:
            self._params[DRIVING_MECHANISM] = 1  # firmware bug: an assignment in a condition
        self._feedback(f"FS{ident:04d}", t)

    def _move_packet(self, packet: str, t: float) -> None:
        v = self.variant
        kind = char_at(packet, MOVE_TYPE)
        if not self.bugs and kind not in ("L", "R", "S"):
            self._feedback("EP0003", t)
            return
        signs = []
        for axis, index in enumerate((X_DIR, v.y_dir)):
            direction = char_at(packet, index)
            if direction in ("P", "N"):
                signs.append(-1 if direction == "N" else 1)
            elif self.bugs:
                self._feedback("EP0003", t)  # firmware bug: EP0003, and the axis runs positive
                signs.append(1)
            else:
                self._feedback("EP0004" if axis == 0 else "EP0005", t)
                return
        amounts = (atol(packet[v.x_digits]), atol(packet[v.y_digits]))
        steps: tuple[int, int] | None = None
        if self.bugs or kind == "L":  # the buggy firmware does not look at the type letter
            distances = [f32_div(a, v.per_mm) for a in amounts]
        elif kind == "R":
            distances = [
                to_float32(f32_div(a, 360) * c) for a, c in zip(amounts, self.cycle, strict=True)
            ]
        else:
            distances = [
                to_float32(f32_div(a, self._per_rev(i)) * self.cycle[i])
                for i, a in enumerate(amounts)
            ]
            steps = (amounts[0], amounts[1])
        self._go(signs[0] * distances[0], signs[1] * distances[1], t, steps)

    def _per_rev(self, axis: int) -> int:
        return self._params[FULLCYCLE[axis]] * self._params[MICROSTEP[axis]]

    def _go(self, dx: float, dy: float, t: float, steps: tuple[int, int] | None = None) -> None:
        """Print the debug lines and FP0001, step (blocking), then FA0001."""
        p = self._params
        distances = (abs(dx), abs(dy))
        if steps is None:
            x, y = (
                steps_for(d, c, p[FULLCYCLE[i]], p[MICROSTEP[i]])
                for i, (d, c) in enumerate(zip(distances, self.cycle, strict=True))
            )
            steps = (x, y)
        degrees = [
            to_float32(f32_div(d, c) * 360) for d, c in zip(distances, self.cycle, strict=True)
        ]
        lines = [
            f"Driving Mechanism: {p[DRIVING_MECHANISM]}",
            f"System cycle linear distance x: {print_float(self.cycle[0], 2)}",
            f"System cycle linear distance y: {print_float(self.cycle[1], 2)}",
            f"Distance x (mm): {print_float(distances[0], 2)}",
            f"Distance y (mm): {print_float(distances[1], 2)}",
            f"Degree x: {print_float(degrees[0], 2)}",
            f"Degree y: {print_float(degrees[1], 2)}",
            f"Step x: {steps[0]}",
            f"Step y: {steps[1]}",
        ]
        for text in lines:
            self._line(text, t)
        self._feedback("FP0001", t)
        # Firmware bug: the Y loop counts step_count_acceleration_y, not Step y.
        y_loop = p[STEP_COUNT_ACCELERATION_Y] if self.bugs else steps[1]
        loops = (max(0, steps[0]), max(0, y_loop))
        durations = [0.0, 0.0]
        moved = [0.0, 0.0]
        for axis, sign in enumerate((-1 if dx < 0 else 1, -1 if dy < 0 else 1)):
            if self._per_rev(axis):
                moved[axis] = sign * loops[axis] * self.cycle[axis] / self._per_rev(axis)
            if not self.instant:
                step_time = max(0.0, 2 * p[STEP_DELAY[axis]] * 1e-6 + LOOP_OVERHEAD)
                durations[axis] = loops[axis] * step_time
        start = self.position(t)
        self._segment = _Segment(
            t, start, (start[0] + moved[0], start[1] + moved[1]), durations[0], durations[1]
        )
        self._count = (to_float32(self._count[0] + dx), to_float32(self._count[1] + dy))
        done = t + durations[0] + durations[1]
        self.busy_until = done
        self._feedback("FA0001", done)
