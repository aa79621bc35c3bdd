"""The Visiomex firmware's own arithmetic (drivers/protocols/README.md §2b): its parameters from
power-on, the recalculation after every set, C number parsing and printing, and a move's step
counts.

One source for the simulator and for the driver's estimates. Every figure is computed as the
firmware computes it: 32-bit floats rounded at every operation, unsigned 32-bit integers, and
float-to-integer conversions as the host build does them (the recordings come from it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from drivers.protocols.visiomex.timing import MovePlan, plan_move

SILENCE = 1.0  # Serial.readString() ends a packet after 1 s without bytes
PARAMETER_COUNT = 28  # ids 1-28 are answered FSnnnn (28 is stored and never read)
U32 = 1 << 32
OVF_LIMIT = 4294967040.0  # Print::printFloat writes `ovf` beyond this

# Declared values, before the boot's recalculation (drivers/protocols/README.md §2b, "decl.").
_DECLARED: dict[int, float] = {
    1: 10, 2: 10, 3: 38.2, 4: 38.2, 5: 400, 6: 400, 7: 1, 8: 1, 9: 3, 10: 3,
    11: 1000, 12: 1000, 13: 5000, 14: 5000, 15: 4000, 16: 4000, 17: 500, 18: 500,
    19: 50, 20: 50, 21: 100, 22: 100, 23: 10, 24: 10, 25: 0, 26: 0, 27: 0,
}  # fmt: skip
FLOAT_IDS = frozenset({1, 2, 3, 4, 7, 8, 25, 26})  # the rest are unsigned 32-bit integers
OVERWRITTEN_AFTER_SET = frozenset({11, 12, 17, 18, 25, 26})
OVERWRITTEN_AT_MOVE = frozenset({19, 20})
BOOT_ONLY = frozenset({1, 2})  # read into the cycle length C at boot only
NEVER_READ = frozenset({3, 4, 9, 10, 27})
DRIVING_MECHANISM = 27
# Per axis (x, y): the ids the recalculation and a move read.
THREAD, FULLCYCLE, MICROSTEP = (1, 2), (5, 6), (7, 8)
STEADY, MINIMUM, INSTANT, AVERAGE, RAMP_COUNT = (11, 12), (13, 14), (15, 16), (17, 18), (19, 20)
SPEED, ACCELERATION, DELTA_T = (21, 22), (23, 24), (25, 26)
AXES = {"x": 0, "y": 1}


def f32(value: float) -> float:
    """A value rounded to a 32-bit float (as a C `float` holds it)."""
    with np.errstate(over="ignore", invalid="ignore"):
        return float(np.float32(value))


def f32_div(a: float, b: float) -> float:
    """A 32-bit float division: x/0 is inf (nan for 0/0), never an exception."""
    if b == 0:
        return math.nan if a == 0 or math.isnan(a) else math.copysign(math.inf, a)
    return f32(a / b)


def to_u32(value: float) -> int:
    """A float converted to an unsigned 32-bit integer as on the host: truncation, then
    modulo 2^32 (a negative wraps); inf and nan give 0."""
    if math.isnan(value) or math.isinf(value):
        return 0
    return int(value) % U32


def _u32_div(a: int, b: int) -> int:
    """Unsigned integer division; x/0 is 0 (the Cortex-M4 and the host build both)."""
    return (a % U32) // (b % U32) if b % U32 else 0


def c_div(a: int, b: int) -> int:
    """C integer division of signed values (truncates toward zero); x/0 is 0."""
    if b == 0:
        return 0
    quotient = abs(a) // abs(b)
    return quotient if (a >= 0) == (b >= 0) else -quotient


def parse_atol(text: str) -> int:
    """C `atol`: leading white space, a sign, then digits up to the first non-digit (else 0)."""
    i, n = 0, len(text)
    while i < n and text[i] in " \t\n\v\f\r":
        i += 1
    sign = 1
    if i < n and text[i] in "+-":
        sign = -1 if text[i] == "-" else 1
        i += 1
    start = i
    while i < n and "0" <= text[i] <= "9":
        i += 1
    return sign * int(text[start:i]) if i > start else 0


def parse_atof(text: str) -> float:
    """C `atof`: leading blanks, a sign, digits with a decimal point, an exponent; parsing stops
    at the first character that does not fit; nothing parsable is 0."""
    i, n = 0, len(text)
    while i < n and text[i] in " \t\n\v\f\r":
        i += 1
    start = i
    if i < n and text[i] in "+-":
        i += 1
    digits = i
    while i < n and "0" <= text[i] <= "9":
        i += 1
    if i < n and text[i] == ".":
        i += 1
        while i < n and "0" <= text[i] <= "9":
            i += 1
    mantissa = text[start:i]
    if not any(c.isdigit() for c in text[digits:i]):
        return 0.0
    if i < n and text[i] in "eE":
        j = i + 1
        if j < n and text[j] in "+-":
            j += 1
        if j < n and "0" <= text[j] <= "9":
            while j < n and "0" <= text[j] <= "9":
                j += 1
            return float(mantissa + text[i:j])
    return float(mantissa)


def format_float(value: float, digits: int = 2) -> str:
    """`Serial.print(value, 2)` on the STM32: half up, in 64-bit double on the value's exact
    double (a float32 rounding, as on an AVR, gives 0.27 for 0.275; this gives 0.28)."""
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf"
    if value > OVF_LIMIT or value < -OVF_LIMIT:
        return "ovf"
    sign = ""
    if value < 0:
        sign, value = "-", -value
    rounding = 0.5
    for _ in range(digits):
        rounding /= 10.0
    value += rounding
    whole = int(value)
    remainder = value - whole
    out = sign + str(whole) + ("." if digits else "")
    for _ in range(digits):
        remainder *= 10.0
        digit = int(remainder)
        out += str(digit)
        remainder -= digit
    return out


def format_steps(steps: int) -> str:
    """A step count as the firmware prints it: unsigned 32-bit."""
    return str(steps % U32)


@dataclass(frozen=True)
class AxisCount:
    """One axis of a move as the firmware computes it: mm, degrees and the step count."""

    mm: float
    degrees: float
    steps: int


@dataclass
class FirmwareState:
    """What the firmware holds: the 27 values (and 28), the cycle lengths C read from 01/02 at
    boot, and the ramp lengths A of the last recalculation; 15/16 are the current step delays."""

    values: dict[int, float] = field(default_factory=dict)
    cycle: tuple[float, float] = (10.0, 10.0)
    ramp: tuple[int, int] = (0, 0)

    @classmethod
    def boot(cls) -> FirmwareState:
        """The state at power-on: the declared values, C from 01/02, then the recalculation."""
        state = cls(dict(_DECLARED), (_DECLARED[1], _DECLARED[2]))
        state.recalculate()
        return state

    @property
    def delays(self) -> tuple[int, int]:
        """The current step delays D15, D16 (µs)."""
        return int(self.values[INSTANT[0]]), int(self.values[INSTANT[1]])

    def set(self, param_id: int, value: float) -> None:
        """A set packet's storage (`value` as on the wire, `atol`), then the recalculation.

        Integer parameters keep an unsigned 32-bit integer (a negative wraps), float ones
        their float; 03/04 keep the value ÷ 4 (a firmware bug). An id outside 1-28 stores
        nothing (`EP0006`), but the recalculation runs all the same."""
        if param_id in (3, 4):
            self.values[param_id] = float(c_div(int(value), 4))
        elif param_id in FLOAT_IDS:
            self.values[param_id] = f32(value)
        elif 1 <= param_id <= PARAMETER_COUNT:
            self.values[param_id] = int(value) % U32
        self.recalculate()

    def recalculate(self) -> None:
        """What the firmware recomputes after every set and at boot: 27, 11/12, 25/26, 17/18, A."""
        v = self.values
        v[DRIVING_MECHANISM] = 1  # an assignment in a condition
        ramp = []
        for axis in (0, 1):
            per_turn = (int(v[SPEED[axis]]) * int(v[FULLCYCLE[axis]])) % U32
            divisor = f32(f32(per_turn * v[MICROSTEP[axis]]) * 2)
            # The source's power of ten is a C exclusive-or: 10 ^ 6 = 12.
            v[STEADY[axis]] = to_u32(f32_div(f32(v[THREAD[axis]] * 12), divisor))
            v[DELTA_T[axis]] = float(_u32_div(int(v[SPEED[axis]]), int(v[ACCELERATION[axis]])))
            v[AVERAGE[axis]] = ((int(v[MINIMUM[axis]]) - int(v[STEADY[axis]])) % U32) // 2
            twice = (int(v[AVERAGE[axis]]) * 2) % U32
            ramp.append(to_u32(f32_div(f32(v[DELTA_T[axis]] * 12), float(twice))))
        self.ramp = (ramp[0], ramp[1])

    def count(self, axis: str, micrometres: float) -> AxisCount:
        """One axis's distance, degrees and step count for a move field's value, in float32."""
        i = AXES[axis]
        mm = f32_div(f32(micrometres), 1000)
        degrees = f32(f32_div(mm, float(int(self.cycle[i]))) * 360)
        per_turn = f32(f32(degrees * float(int(self.values[FULLCYCLE[i]]))))
        turns = f32(per_turn * float(int(self.values[MICROSTEP[i]])))
        return AxisCount(mm, degrees, to_u32(f32_div(turns, 360)))

    def steps(self, axis: str, micrometres: float) -> int:
        """The step count of a move field (µm, as `atof` read it): truncated, wrapped to 32 bits."""
        return self.count(axis, micrometres).steps

    def move(self, x_um: float, y_um: float) -> MovePlan:
        """A move packet's stepping: the plan of both loops; 19/20 and the delays 15/16 advance."""
        return self.move_steps(self.steps("x", x_um), self.steps("y", y_um))

    def move_steps(self, step_x: int, step_y: int, *, y_runs_steps: bool = False) -> MovePlan:
        """Stepping for given step counts; `y_runs_steps`: the documented Y loop (Step y times,
        ramped like X) instead of the firmware's (the ramp count R_y times)."""
        v = self.values
        plan = plan_move(
            (step_x, step_y),
            self.ramp,
            self.delays,
            (int(v[MINIMUM[0]]), int(v[MINIMUM[1]])),
            (int(v[STEADY[0]]), int(v[STEADY[1]])),
            y_runs_steps=y_runs_steps,
        )
        v[RAMP_COUNT[0]], v[RAMP_COUNT[1]] = plan.ramp_steps
        v[INSTANT[0]], v[INSTANT[1]] = plan.delays_after
        return plan

    def copy(self) -> FirmwareState:
        """An independent copy (to try a move without advancing this state)."""
        return FirmwareState(dict(self.values), self.cycle, self.ramp)


POWER_ON: dict[int, float] = {
    i: value for i, value in FirmwareState.boot().values.items() if i <= 27
}


def debug_lines(state: FirmwareState, x_um: float, y_um: float) -> list[str]:
    """The nine lines a move prints before `FP0001` (signed distance and degrees)."""
    x, y = state.count("x", x_um), state.count("y", y_um)
    return [
        f"Driving Mechanism: {int(state.values[DRIVING_MECHANISM])}",
        f"System cycle linear distance x: {format_float(state.cycle[0])}",
        f"System cycle linear distance y: {format_float(state.cycle[1])}",
        f"Distance x (mm): {format_float(x.mm)}",
        f"Distance y (mm): {format_float(y.mm)}",
        f"Degree x: {format_float(x.degrees)}",
        f"Degree y: {format_float(y.degrees)}",
        f"Step x: {format_steps(x.steps)}",
        f"Step y: {format_steps(y.steps)}",
    ]
