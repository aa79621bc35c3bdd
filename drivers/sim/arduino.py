"""Arduino behaviours the simulators reproduce: 32-bit floats and Print::printFloat."""

from __future__ import annotations

import math
import struct

_F32_MAX = 3.4028234663852886e38  # FLT_MAX
_F32_INFINITE = 2.0**128 - 2.0**103  # FLT_MAX + half its ulp: from here on a cast gives inf
OVF_LIMIT = 4294967040.0
_F32 = struct.Struct("<f")


def to_float32(value: float) -> float:
    """A C cast to the AVR's 32-bit float: round to nearest, so only a value past FLT_MAX's
    half-ulp becomes infinity (3.4028235e38 is FLT_MAX, which Serial.print shows as `ovf`).
    A sum, difference, product or quotient of two such floats, done in doubles and cast, is the
    AVR's own float result (a double holds the exact result to more than twice the bits)."""
    if math.isnan(value) or math.isinf(value):
        return value
    if abs(value) >= _F32_INFINITE:
        return math.copysign(math.inf, value)
    if abs(value) > _F32_MAX:
        return math.copysign(_F32_MAX, value)
    result: float = _F32.unpack(_F32.pack(value))[0]
    return result


def print_float(value: float, digits: int = 2) -> str:
    """Text exactly as Arduino's Print::printFloat(value, digits) on an AVR writes it."""
    value = to_float32(value)
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf"
    if value > OVF_LIMIT or value < -OVF_LIMIT:
        return "ovf"
    f32 = to_float32
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
