"""Messages for people: English text that keeps its template and values, so the window can show
it in the operator's language.

The driver layer has no Qt, so it cannot translate; it says what it has to say as
`Message("the device did not answer {command} within {seconds:g} s", command=..., seconds=...)`.
A Message is a `str` (the English text, what the command-line tools print and the logs keep), and
remembers its template and values: `app/common/messages.py` looks the template up in the interface's
language and fills in the values, translating those that are Messages (or errors carrying one)
in turn. `resources/i18n/update.py` collects every `Message("…")` template in drivers/ and app/
for the translators, so a template must be a plain string literal.
"""

from __future__ import annotations

import math
import string
from collections.abc import Mapping
from decimal import Decimal

CONTEXT = "messages"
"""The translation context of every Message template."""


class Message(str):
    """The English text of `template` filled with `values`; keeps both for translation."""

    template: str
    values: Mapping[str, object]

    def __new__(cls, template: str, /, **values: object) -> Message:
        """The message; `template` uses str.format fields named after `values`."""
        text = fill(template, values) if values else template
        made = super().__new__(cls, text)
        made.template = template
        made.values = values
        return made

    def __reduce__(self) -> tuple[object, ...]:
        """Pickled with its template and values (multiprocessing, copy)."""
        return (_rebuild, (self.template, dict(self.values)))


def plain_number(value: float, spec: str = "g") -> str:
    """`value` formatted with a `g` spec, in plain digits where `g` would use an exponent
    (`1e+08` as `100000000`, `1.5e-07` as `0.00000015`)."""
    text = format(value, spec)
    if "e" not in text or not math.isfinite(value):
        return text
    exact = Decimal(repr(float(value))) if spec == "g" else Decimal(text)
    digits = format(exact, "f")
    if "." in digits:
        digits = digits.rstrip("0").rstrip(".")
    return digits


class _PlainNumbers(string.Formatter):
    """str.format, with numbers formatted `g` in plain digits."""

    def format_field(self, value: object, format_spec: str) -> str:
        """A field as str.format fills it; a `g` number without an exponent."""
        text = str(super().format_field(value, format_spec))
        if (
            isinstance(value, (int, float))
            and not isinstance(value, bool)
            and format_spec.endswith("g")
            and "e" in text
        ):
            return plain_number(float(value), format_spec)
        return text


_PLAIN = _PlainNumbers()


def fill(template: str, values: Mapping[str, object]) -> str:
    """`template.format(**values)`, numbers formatted `g` in plain digits (no `1e+08`)."""
    text = template.format(**values)
    if "e+" in text or "e-" in text:  # maybe a number in exponent notation: formatted again
        return _PLAIN.vformat(template, (), values)
    return text


def _rebuild(template: str, values: dict[str, object]) -> Message:
    """A pickled Message made again."""
    return Message(template, **values)


def message_template(text: str) -> str:
    """Marks `text` as a Message template used later (`Message(text, axis="X")`), for the
    translators to see it where it is written; returns it unchanged."""
    return text


def message_of(value: object) -> Message | None:
    """The Message that `value` says: itself, or the one an error was raised with; else None."""
    if isinstance(value, Message):
        return value
    if isinstance(value, BaseException) and len(value.args) == 1:
        first = value.args[0]
        if isinstance(first, Message) and str(value) == first:
            return first
    return None
