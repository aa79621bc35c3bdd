"""Visiomex VMR2P0R0001 firmware details: parameters, packet layouts and C number parsing."""

from __future__ import annotations

import math
from dataclasses import dataclass

from drivers.sim.arduino import to_float32

PARAMETER_COUNT = 28

# Wire integers at power-on, by parameter id (PROTOCOLS.md §2).
BOOT_PARAMETERS: dict[int, int] = {
    1: 10,  # thread_distance_x (mm)
    2: 10,  # thread_distance_y (mm)
    3: 382,  # pulley_diameter_x (mm x 10)
    4: 382,  # pulley_diameter_y (mm x 10)
    5: 200,  # motor_fullcycle_step_x
    6: 200,  # motor_fullcycle_step_y
    7: 2,  # microstep_coeff_x
    8: 2,  # microstep_coeff_y
    9: 50,  # max_speed_x (mm/s)
    10: 50,  # max_speed_y (mm/s)
    11: 4000,  # step_delay_speed_steady_x (us)
    12: 4000,  # step_delay_speed_steady_y (us)
    13: 8000,  # step_delay_speed_min_x (us)
    14: 8000,  # step_delay_speed_min_y (us)
    15: 4000,  # step_delay_instantaneous_x (us)
    16: 4000,  # step_delay_instantaneous_y (us)
    17: 6000,  # step_delay_acceleration_avg_x (us)
    18: 6000,  # step_delay_acceleration_avg_y (us)
    19: 0,  # step_count_acceleration_x
    20: 0,  # step_count_acceleration_y
    21: 10,  # input_speed_steady_x (mm/s)
    22: 10,  # input_speed_steady_y (mm/s)
    23: 100,  # input_acceleration_x (mm/s^2)
    24: 100,  # input_acceleration_y (mm/s^2)
    25: 0,  # delta_t_x (s)
    26: 0,  # delta_t_y (s)
    27: 1,  # driving_mechanism (0 pulley, 1 lead screw)
    28: 1,  # driving_mechanism_y (in the seed's feedback list; stored only)
}

# Per axis (x, y): thread distance, pulley diameter, full-cycle steps, microstep, delay ids.
THREAD = (1, 2)
PULLEY = (3, 4)
FULLCYCLE = (5, 6)
MICROSTEP = (7, 8)
STEP_DELAY = (15, 16)
STEP_COUNT_ACCELERATION_Y = 20
DRIVING_MECHANISM = 27


@dataclass(frozen=True)
class Variant:
    """One firmware/board profile: line rate, packet layout, units and feedback prefix."""

    name: str
    baud: int
    packet_size: int
    x_digits: slice
    y_dir: int
    y_digits: slice
    per_mm: int  # linear units on the wire per mm (1000: um, 1: mm)
    prefix: str = ""
    go_home: bool = False


X_DIR = 2
MOVE_TYPE = 1
SET_ID = slice(1, 3)
SET_VALUE = slice(3, 9)

VARIANTS: dict[str, Variant] = {
    "seed": Variant("seed", 9600, 18, slice(3, 10), 10, slice(11, 18), 1000),
    "prefixed": Variant("prefixed", 9600, 18, slice(3, 10), 10, slice(11, 18), 1000, ">"),
    "board12": Variant("board12", 115200, 12, slice(3, 7), 7, slice(8, 12), 1, go_home=True),
}


def atol(text: str) -> int:
    """C `atol`: skip leading white space, optional sign, digits up to the first non-digit."""
    i = 0
    while i < len(text) and text[i] in " \t\n\v\f\r":
        i += 1
    sign = 1
    if i < len(text) and text[i] in "+-":
        sign = -1 if text[i] == "-" else 1
        i += 1
    value = 0
    while i < len(text) and text[i].isascii() and text[i].isdigit():
        value = value * 10 + int(text[i])
        i += 1
    return sign * value


def char_at(text: str, index: int) -> str:
    """Arduino `String::operator[]`: NUL past the end."""
    return text[index] if index < len(text) else "\0"


def c_div(a: int, b: int) -> int:
    """C integer division (truncates toward zero)."""
    quotient = abs(a) // abs(b)
    return quotient if (a >= 0) == (b >= 0) else -quotient


def f32_div(a: float, b: float) -> float:
    """A 32-bit float division as the Cortex-M4 does it (x/0 is inf or nan, no exception)."""
    if b == 0:
        return math.nan if a == 0 or math.isnan(a) else math.copysign(math.inf, a)
    return to_float32(a / b)


def cycle_length(params: dict[int, int], axis: int) -> float:
    """Linear distance (mm) of one motor revolution, as computed at boot."""
    if params[DRIVING_MECHANISM] == 1:
        return to_float32(params[THREAD[axis]])
    return to_float32(math.pi * to_float32(params[PULLEY[axis]] / 10))


def steps_for(distance: float, cycle: float, fullcycle: int, microstep: int) -> int:
    """`(long)(distance / cycle * fullcycle * microstep)` in 32-bit floats."""
    value = to_float32(to_float32(f32_div(distance, cycle) * fullcycle) * microstep)
    if math.isnan(value) or math.isinf(value):
        return 0  # float-to-int of inf/nan on the STM32 is not modelled: no steps
    return int(value)
