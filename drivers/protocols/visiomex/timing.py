"""The Visiomex firmware's stepping loops, ramps and timing on the wire (drivers/protocols/README.md
§2b).

X steps Step x times, high for D15 and low for D16 (Y's delay); its ramps follow 13 ↔ 11 over the
ramp length A. Y then steps R_y times (the ramp count, not Step y), high and low for D16. Neither
loop restores the delays: the next move starts from what these ramps left.
"""

from __future__ import annotations

from dataclasses import dataclass

UART_BYTE_SECONDS = 10 / 9600  # 9600 8N1 on the board's UART
# The recorded firmware (the host build behind a pty, tests/data/visiomex-moves.json) sends a
# byte every ~1.1 ms, not 1.042: its 382 lines before stepping fit 1.4 ms + 1.117 ms a byte.
HOST_PACING = 1.06
BYTE_SECONDS = UART_BYTE_SECONDS * HOST_PACING
REPLY_LATENCY = 0.0015  # s from the end of the 1 s silence to the reply's first byte leaving
TX_BUFFER = 64  # the firmware blocks on a full 64-byte transmit buffer
FEEDBACK_BYTES = 8  # `FA0001\r\n`
I32 = 1 << 32

Segment = tuple[int, int, int]  # steps, µs high, µs low


def _i32(value: int) -> int:
    """A value wrapped to a signed 32-bit integer."""
    value %= I32
    return value - I32 if value >= I32 // 2 else value


def _c_div(a: int, b: int) -> int:
    quotient = abs(a) // abs(b)
    return quotient if (a >= 0) == (b >= 0) else -quotient


def interpolate(k: int, a: int, b: int, p: int, q: int) -> int:
    """Arduino `map(k, a, b, p, q)` in signed 32-bit: p + (k - a)(q - p) / (b - a), truncated."""
    if a == b:
        return p
    product = _i32(_i32(k - a) * _i32(q - p))
    return _i32(_c_div(product, _i32(b - a)) + p) % I32


@dataclass(frozen=True)
class MovePlan:
    """One move's stepping: counts, the delays each step used, and how long it takes."""

    steps: tuple[int, int]  # Step x, Step y as computed (unsigned 32-bit)
    ramp_steps: tuple[int, int]  # R_x, R_y: stored into 19/20
    x_segments: tuple[Segment, ...]  # runs of X steps: (count, µs high, µs low)
    y_segments: tuple[Segment, ...]
    delays_after: tuple[int, int]  # D15, D16 as the loops leave them

    @property
    def x_seconds(self) -> float:
        """Time of the X loop."""
        return sum(n * (high + low) for n, high, low in self.x_segments) * 1e-6

    @property
    def y_seconds(self) -> float:
        """Time of the Y loop."""
        return sum(n * (high + low) for n, high, low in self.y_segments) * 1e-6

    @property
    def seconds(self) -> float:
        """Stepping time: the X loop, then the Y loop."""
        return self.x_seconds + self.y_seconds

    @property
    def loops(self) -> tuple[int, int]:
        """The steps each loop actually makes."""
        return (
            sum(n for n, _, _ in self.x_segments),
            sum(n for n, _, _ in self.y_segments),
        )


def _add(segments: list[list[int]], count: int, high: int, low: int) -> None:
    if count <= 0:
        return
    if segments and segments[-1][1] == high and segments[-1][2] == low:
        segments[-1][0] += count
    else:
        segments.append([count, high, low])


def _ramped_loop(
    steps: int, ramp: int, limit: int, delay: int, low: int | None, ends: tuple[int, int]
) -> tuple[list[list[int]], int]:
    """A loop of `steps` steps with `ramp` steps of acceleration and deceleration over the ramp
    length `limit` between `ends` (slow, fast); `low`: the low phase's delay (None: the same as
    the high one). Returns the segments and the delay left."""
    slow, fast = ends
    segments: list[list[int]] = []
    for k in range(min(ramp, steps)):
        _add(segments, 1, delay, delay if low is None else low)
        delay = interpolate(k, 0, limit, slow, fast)
    middle = steps - 2 * ramp + 1 if ramp else steps
    _add(segments, middle, delay, delay if low is None else low)
    for k in range(steps - ramp + 1, steps if ramp else 0):
        _add(segments, 1, delay, delay if low is None else low)
        delay = interpolate(k, steps - limit, steps, fast, slow)
    return segments, delay


def plan_move(
    steps: tuple[int, int],
    ramp: tuple[int, int],
    delays: tuple[int, int],
    slow: tuple[int, int],
    fast: tuple[int, int],
    *,
    y_runs_steps: bool = False,
) -> MovePlan:
    """Both loops of a move from the step counts, the ramp lengths A, the current delays
    D15/D16 and the ramp ends (13/14 slow, 11/12 fast)."""
    ramps = tuple(a if s // 2 > a else s // 2 for s, a in zip(steps, ramp, strict=True))
    x, d15 = _ramped_loop(steps[0], ramps[0], ramp[0], delays[0], delays[1], (slow[0], fast[0]))
    if y_runs_steps:
        y, d16 = _ramped_loop(steps[1], ramps[1], ramp[1], delays[1], None, (slow[1], fast[1]))
    else:  # the Y loop counts the ramp, with no deceleration branch
        y, d16 = [], delays[1]
        for j in range(ramps[1]):
            _add(y, 1, d16, d16)
            d16 = interpolate(j, 0, ramp[1], slow[1], fast[1])
    return MovePlan(
        (steps[0], steps[1]),
        (ramps[0], ramps[1]),
        tuple((n, h, lo) for n, h, lo in x),
        tuple((n, h, lo) for n, h, lo in y),
        (d15, d16),
    )


def stepping_start(reply_bytes: int, byte_seconds: float = BYTE_SECONDS) -> float:
    """Seconds from the reply's first byte to the start of stepping: when `FP0001` enters the
    64-byte transmit buffer (its last byte goes out 64 byte times later)."""
    return max(0, reply_bytes - TX_BUFFER) * byte_seconds


def move_reply_seconds(
    reply_bytes: int, stepping: float, byte_seconds: float = BYTE_SECONDS
) -> float:
    """Seconds from the reply's first byte to the last byte of `FA0001`: `reply_bytes` (up to
    and including `FP0001`'s) go out, stepping runs meanwhile, then `FA0001` is sent."""
    fp_done = reply_bytes * byte_seconds
    step_end = stepping_start(reply_bytes, byte_seconds) + stepping
    return max(fp_done, step_end) + FEEDBACK_BYTES * byte_seconds
