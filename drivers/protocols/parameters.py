"""Device parameters: numbered settings written as scaled integers (the Visiomex kind).

A protocol with parameters lists them as `Parameter`s; the interface value (e.g. 38.2 mm) is
scaled to the integer the wire carries (`000382`) and checked against what fits before sending.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from drivers.errors import BadInput
from drivers.messages import Message

RELATIVE_TOLERANCE = 1e-9


@dataclass(frozen=True)
class Parameter:
    """One device parameter: its id, name, unit, wire scaling and range."""

    id: int
    name: str
    unit: str
    description: str
    scale: int = 1  # wire value = interface value × scale (pulley diameter in mm: ×10)
    digits: int = 6  # the wire's width in decimal digits
    output: bool = False  # computed by the firmware; writing it is allowed but overwritten
    default: float = 0.0  # what the firmware holds at power-on
    maximum_value: float | None = None  # a tighter bound than the digits give (e.g. 0..1)

    @property
    def minimum(self) -> float:
        """The lowest value the wire carries (no sign on the wire)."""
        return 0.0

    @property
    def maximum(self) -> float:
        """The highest value that fits the wire's digits after scaling (or a tighter bound)."""
        fits: float = (10**self.digits - 1) / self.scale  # (int ** int is typed Any)
        return fits if self.maximum_value is None else min(fits, self.maximum_value)

    @property
    def step(self) -> float:
        """The finest value the wire carries, in the interface unit."""
        return 1.0 / self.scale

    @property
    def decimals(self) -> int:
        """Decimals needed to show any wire value exactly."""
        return len(str(self.scale)) - 1

    def with_unit(self, value: float) -> str:
        """`value` formatted with this parameter's unit, e.g. `38.2 mm`."""
        text = f"{value:.{self.decimals}f}"
        return f"{text} {self.unit}" if self.unit else text

    def range_text(self) -> str:
        """E.g. `0 to 99999.9 mm in steps of 0.1 mm`."""
        low, high = self.with_unit(self.minimum), self.with_unit(self.maximum)
        if self.scale != 1:
            return Message(
                "{low} to {high} in steps of {step}",
                low=low,
                high=high,
                step=self.with_unit(self.step),
            )
        if self.digits:
            return Message("{low} to {high} (whole numbers)", low=low, high=high)
        return Message("{low} to {high}", low=low, high=high)

    def to_wire(self, value: object) -> int:
        """The wire integer; BadInput naming the parameter, its unit and range if it cannot be."""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise BadInput(
                Message(
                    "{name}: {value!r} is not a number ({range})",
                    name=self.name,
                    value=value,
                    range=self.range_text(),
                )
            )
        if not math.isfinite(value):
            raise BadInput(
                Message(
                    "{name}: {value} refused: {range}",
                    name=self.name,
                    value=value,
                    range=self.range_text(),
                )
            )
        scaled = value * self.scale
        wire = round(scaled)
        if abs(scaled - wire) > RELATIVE_TOLERANCE * max(1.0, abs(scaled)):
            raise BadInput(
                Message(
                    "{name}: {value} refused: the device takes {range}",
                    name=self.name,
                    value=self._given(value),
                    range=self.range_text(),
                )
            )
        if not self.minimum <= wire / self.scale <= self.maximum:
            raise BadInput(
                Message(
                    "{name}: {value} refused: {range}",
                    name=self.name,
                    value=self._given(value),
                    range=self.range_text(),
                )
            )
        return wire

    def _given(self, value: float) -> str:
        return f"{value:g} {self.unit}".rstrip()

    def from_wire(self, wire: float) -> float:
        """The interface value of a wire integer."""
        return wire / self.scale


@dataclass(frozen=True)
class ParameterWritten:
    """A parameter the device confirmed, and what it now holds as a consequence."""

    parameter: Parameter
    value: float
    device_values: dict[str, float] = field(default_factory=dict)
    """Other parameters whose value the device changed by itself (name -> value)."""
    notes: tuple[str, ...] = ()


def find_parameter(parameters: tuple[Parameter, ...], key: str | int) -> Parameter:
    """A parameter by name or id (`pulley_diameter_x`, `3`, `03`); BadInput if unknown."""
    text = str(key).strip()
    for parameter in parameters:
        if text == parameter.name or (text.isdigit() and int(text) == parameter.id):
            return parameter
    if not parameters:
        raise BadInput(Message("this protocol has no parameters"))
    close = [p.name for p in parameters if text.lower() in p.name]
    if close and text:
        raise BadInput(
            Message(
                "unknown parameter {name!r} (did you mean {close}?): use a name or an id "
                "1..{count}; 'motionctl ... param list' lists them",
                name=text,
                close=", ".join(close[:3]),
                count=len(parameters),
            )
        )
    raise BadInput(
        Message(
            "unknown parameter {name!r}: use a name or an id 1..{count}; "
            "'motionctl ... param list' lists them",
            name=text,
            count=len(parameters),
        )
    )
