"""Visiomex VMR2P0R0001 packet layouts and wire variants (the arithmetic: visiomex_model)."""

from __future__ import annotations

from dataclasses import dataclass

from drivers.protocols.visiomex.model import PARAMETER_COUNT, POWER_ON, parse_atof, parse_atol

__all__ = [
    "MOVE_TYPE",
    "PARAMETER_COUNT",
    "POWER_ON",
    "SET_ID",
    "SET_VALUE",
    "VARIANTS",
    "X_DIR",
    "Variant",
    "char_at",
    "parse_atof",
    "parse_atol",
]


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


def char_at(text: str, index: int) -> str:
    """Arduino `String::operator[]`: NUL past the end."""
    return text[index] if index < len(text) else "\0"
