"""Axis names shared by the widgets: lower-case `x`, `y`, `z`, as the drivers' capabilities."""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterable

AXES: tuple[str, str, str] = ("x", "y", "z")


def normalize_axes(axes: Iterable[str]) -> frozenset[str]:
    """The known axes named in `axes`, lower-cased (`"X"` and `"x"` are the same axis)."""
    return frozenset(a.strip().lower() for a in axes) & frozenset(AXES)


def modifier_bits(modifiers: object) -> int:
    """The integer value of a Qt keyboard-modifier flag, an int, or None (no modifiers)."""
    if modifiers is None:
        return 0
    if isinstance(modifiers, int):
        return modifiers
    value = getattr(modifiers, "value", None)
    return int(value) if value is not None else 0


def target_point(
    x: object, y: float | None = None, z: float | None = None
) -> tuple[float, float, float | None] | None:
    """The target of `set_target(x, y, z)`, `set_target((x, y, z))` or `set_target(None)`.

    A sequence may hold two or three numbers; z is None when not given. Raises ValueError when
    y is missing.
    """
    if x is None:
        return None
    if y is None and z is None and not isinstance(x, numbers.Real):
        values = tuple(x)  # type: ignore[call-overload]
        if len(values) not in (2, 3):
            raise ValueError(f"a target has 2 or 3 coordinates, not {values!r}")
        x, y, z = values[0], values[1], values[2] if len(values) == 3 else None
    if y is None:
        raise ValueError("a target needs at least x and y")
    return float(x), float(y), None if z is None else float(z)  # type: ignore[arg-type]


Box = tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
"""A travel box in mm: ((x_min, x_max), (y_min, y_max), (z_min, z_max))."""


def decimals_for(resolution: float | None) -> int:
    """Decimals to type a length in mm to the device's resolution (None: 0.001 mm, 3 decimals)."""
    return 3 if not resolution else max(0, min(3, round(-math.log10(resolution))))
