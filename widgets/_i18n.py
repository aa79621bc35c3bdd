"""Filling translated templates (Qt's %1, %2 … placeholders, in one pass) and numbers in the
interface's locale."""

from __future__ import annotations

import re

from PySide6.QtCore import QLocale

_PLACEHOLDER = re.compile(r"%(\d)")


def fill(template: str, *values: object) -> str:
    """`template` with %1, %2 … replaced by `values` (a value's own "%2" is left alone)."""

    def value(match: re.Match[str]) -> str:
        number = int(match.group(1))
        return str(values[number - 1]) if 1 <= number <= len(values) else match.group(0)

    return _PLACEHOLDER.sub(value, template)


def number_text(
    value: float,
    decimals: int,
    *,
    signed: bool = False,
    trim: bool = True,
    locale: QLocale | None = None,
) -> str:
    """`value` to `decimals` decimals in the interface's locale (2,5 in French), no thousands
    separator, trailing zeros dropped (unless not `trim`); `signed`: "+" before a positive
    value; `locale`: another than the interface's."""
    locale = QLocale(locale) if locale is not None else QLocale()
    locale.setNumberOptions(locale.numberOptions() | QLocale.NumberOption.OmitGroupSeparator)
    decimals = max(int(decimals), 0)
    rounded = round(float(value), decimals) + 0.0  # no "-0"
    text = locale.toString(rounded, "f", decimals)
    if decimals and trim:
        text = text.rstrip(locale.zeroDigit()).rstrip(locale.decimalPoint())
    return f"+{text}" if signed and rounded > 0 else text
