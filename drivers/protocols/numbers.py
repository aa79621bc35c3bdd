"""Number grammar shared by the ASCII protocols: parsing user text and formatting for the wire."""

from __future__ import annotations

import math
import re
from decimal import Decimal

from drivers.errors import BadInput
from drivers.messages import Message

# What the COXIRIS firmware accepts: optional sign, digits, at most one '.', at least one digit
# (drivers/protocols/README.md §1: `+.5`, `1.`, `-2` accepted; `1e3`, `.`, `nan`, `0x10`, `1,5`
# rejected).
_DEVICE_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)")

# Arduino's Print::printFloat prints "ovf" beyond this magnitude.
ARDUINO_FLOAT_LIMIT = 4294967040.0


def parse_number(text: str, what: str = "value") -> float:
    """Parse user text with the device's number grammar; BadInput says why it is refused."""
    stripped = text.strip()
    if not _DEVICE_NUMBER.fullmatch(stripped):
        raise BadInput(
            Message(
                "{what} {text!r} is not a number the device accepts: "
                "use digits with an optional sign and one decimal point, e.g. -12.5",
                what=what,
                text=text,
            )
        )
    return float(stripped)


def format_number(value: float, what: str = "value", limit: float = ARDUINO_FLOAT_LIMIT) -> str:
    """Shortest fixed-point text for `value` (never exponent notation), within +-`limit`."""
    if not math.isfinite(value):
        raise BadInput(Message("{what} {value!r} is not a finite number", what=what, value=value))
    if abs(value) > limit:
        raise BadInput(
            Message(
                "{what} {value:g} is out of range: the device handles at most ±{limit:g}",
                what=what,
                value=value,
                limit=limit,
            )
        )
    text = format(Decimal(repr(float(value))), "f")
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    if text in ("-0", ""):
        text = "0"
    return text
