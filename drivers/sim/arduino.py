"""Arduino behaviours the simulators reproduce: 32-bit floats and Print::printFloat."""

from __future__ import annotations

import math

import numpy as np

_F32_MAX = float(np.finfo(np.float32).max)
OVF_LIMIT = 4294967040.0


def to_float32(value: float) -> float:
    """A C cast to the AVR's 32-bit float: round to nearest, so only a value past FLT_MAX's
    half-ulp becomes infinity (3.4028235e38 is FLT_MAX, which Serial.print shows as `ovf`)."""
    with np.errstate(over="ignore"):
        return float(np.float32(value))


def print_float(value: float, digits: int = 2) -> str:
    """Text exactly as Arduino's Print::printFloat(value, digits) on an AVR writes it."""
    value = to_float32(value)
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf"
    if value > OVF_LIMIT or value < -OVF_LIMIT:
        return "ovf"
    f32 = np.float32
    number = f32(value)
    sign = ""
    if number < 0:
        sign = "-"
        number = -number
    rounding = f32(0.5)
    for _ in range(digits):
        rounding = f32(rounding / f32(10.0))
    number = f32(number + rounding)
    int_part = int(number)
    remainder = f32(number - f32(int_part))
    out = sign + str(int_part)
    if digits > 0:
        out += "."
    for _ in range(digits):
        remainder = f32(remainder * f32(10.0))
        digit = int(remainder)
        out += str(digit)
        remainder = f32(remainder - f32(digit))
    return out
