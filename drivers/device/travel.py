"""Travel limits (a box the stage must stay in) and the device's coordinate resolution.

Both are checked before a move is sent: a target outside the box is refused (or clamped to its
edge, as the user chooses), unless the stage is outside the box and the move brings it closer;
a value finer than the device can represent is refused.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from drivers.errors import BadInput
from drivers.messages import Message

AXIS_NAMES = ("x", "y", "z")
Box = tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
Point = tuple[float, float, float]


def _fmt(value: float) -> str:
    return f"{value:g}"


@dataclass(frozen=True)
class TravelLimits:
    """A box in mm, ((x_min, x_max), (y_min, y_max), (z_min, z_max)); `clamp` or refuse."""

    box: Box
    clamp: bool = False

    def __post_init__(self) -> None:
        if len(self.box) != 3:
            raise BadInput(Message("travel limits need a range for each of x, y and z"))
        for axis, (low, high) in zip(AXIS_NAMES, self.box, strict=True):
            if not (math.isfinite(low) and math.isfinite(high)) or low > high:
                raise BadInput(
                    Message(
                        "travel limits for {axis} ({low:g} to {high:g} mm) "
                        "are not a range: the minimum must be at most the maximum",
                        axis=axis.upper(),
                        low=low,
                        high=high,
                    )
                )

    def describe(self) -> str:
        """E.g. `X -100..100, Y -50..50, Z 0..20 mm`."""
        parts = [
            f"{a.upper()} {_fmt(lo)}..{_fmt(hi)}"
            for a, (lo, hi) in zip(AXIS_NAMES, self.box, strict=True)
        ]
        return ", ".join(parts) + " mm"

    def contains(self, point: Point) -> bool:
        """Whether `point` is inside the box (edges included)."""
        return all(lo <= v <= hi for v, (lo, hi) in zip(point, self.box, strict=True))

    def outside(self, point: Point) -> list[tuple[str, float, float, float]]:
        """The axes of `point` outside the box: (axis, value, low, high) each."""
        return [
            (axis, value, lo, hi)
            for axis, value, (lo, hi) in zip(AXIS_NAMES, point, self.box, strict=True)
            if not lo <= value <= hi
        ]

    def comes_back(self, target: Point, here: Point) -> bool:
        """Whether a move from `here` (outside the box) to `target` ends closer to the box on
        every axis where `target` is outside it (on the same side), and inside on the others."""
        for value, start, (lo, hi) in zip(target, here, self.box, strict=True):
            over, was = _beyond(value, lo, hi), _beyond(start, lo, hi)
            if over == 0:
                continue
            if was == 0 or (over > 0) != (was > 0) or abs(over) >= abs(was):
                return False
        return True

    def apply(
        self, target: Point, what: str | None = None, here: Point | None = None
    ) -> tuple[Point, str | None]:
        """The target to send and a note when it was clamped; BadInput when it is refused.

        `what` names the move for people (a Message; default "the move"). `here` is where the
        stage is: a stage outside the box may move towards it (a move that ends closer to the
        box on every axis it is outside of, and inside on the others), with a note saying so."""
        if what is None:
            what = Message("the move")
        outside = self.outside(target)
        if not outside:
            return target, None
        details = joined(
            [
                Message(
                    "{axis} {value:g} mm is outside {low:g}..{high:g} mm",
                    axis=a.upper(),
                    value=v,
                    low=lo,
                    high=hi,
                )
                for a, v, lo, hi in outside
            ]
        )
        if here is not None and self.comes_back(target, here):
            note = Message(
                "the stage is outside its travel limits: {what} brings it closer ({details})",
                what=what,
                details=details,
            )
            return target, note
        if not self.clamp:
            raise BadInput(
                Message("{what} refused: {details} (travel limits)", what=what, details=details)
            )
        x, y, z = (min(max(v, lo), hi) for v, (lo, hi) in zip(target, self.box, strict=True))
        note = Message(
            "{what} clamped to the travel limits: {details}; going to ({x:g}, {y:g}, {z:g}) mm",
            what=what,
            details=details,
            x=x,
            y=y,
            z=z,
        )
        return (x, y, z), note


def parse_travel(text: str) -> TravelLimits | None:
    """`X0:X1,Y0:Y1,Z0:Z1` in mm (`none` for no limits); BadInput says what is wrong."""
    stripped = text.strip().lower()
    if stripped in ("", "none", "off"):
        return None
    parts = stripped.split(",")
    if len(parts) != 3:
        raise BadInput(
            Message(
                "travel limits {text!r}: write three ranges in mm, X0:X1,Y0:Y1,Z0:Z1 "
                "(e.g. -100:100,-50:50,0:20), or none",
                text=text,
            )
        )
    ranges = []
    for axis, part in zip(AXIS_NAMES, parts, strict=True):
        low_text, sep, high_text = part.partition(":")
        try:
            if not sep:
                raise ValueError
            low, high = float(low_text), float(high_text)
        except ValueError:
            raise BadInput(
                Message(
                    "travel limits for {axis}: {part!r} is not MIN:MAX in mm (e.g. -100:100)",
                    axis=axis.upper(),
                    part=part,
                )
            ) from None
        ranges.append((low, high))
    return TravelLimits((ranges[0], ranges[1], ranges[2]))


def check_resolution(values: Point, names: tuple[str, ...], resolution: float | None) -> None:
    """Refuse a value the device cannot represent (finer than `resolution` mm)."""
    if not resolution:
        return
    for name, value in zip(names, values, strict=True):
        if not math.isfinite(value):
            raise BadInput(
                Message("{name} {value!r} is not a finite number", name=name, value=value)
            )
        steps = value / resolution
        if abs(steps - round(steps)) > 1e-6 * max(1.0, abs(steps)):
            nearest = round(steps) * resolution
            raise BadInput(
                Message(
                    "{name} {value:g} mm refused: the device works to {resolution:g} mm "
                    "(the nearest it can do is {nearest} mm)",
                    name=name,
                    value=value,
                    resolution=resolution,
                    nearest=f"{nearest:.{_decimals(resolution)}f}",
                )
            )


def joined(parts: list[Message]) -> Message:
    """Phrases for people as one, separated by "; " (each translated whole)."""
    said = parts[0]
    for part in parts[1:]:
        said = Message("{earlier}; {later}", earlier=said, later=part)
    return said


def _beyond(value: float, low: float, high: float) -> float:
    """How far `value` is past the range: positive above it, negative below, 0 inside."""
    if value > high:
        return value - high
    if value < low:
        return value - low
    return 0.0


def _decimals(resolution: float) -> int:
    return max(0, -math.floor(math.log10(resolution) + 1e-9))
