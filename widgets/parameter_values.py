"""Parameter rows as plain data, and the checks and formats of their values (Qt for words only).

A row is an id, a name, a unit, a range and a step; a value is acceptable when it is a finite
number inside the range and a multiple of the step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QLocale

from widgets._i18n import fill


def translated(text: str) -> str:
    """A word marked with QT_TRANSLATE_NOOP in this module's context, translated."""
    return QCoreApplication.translate("ParameterValues", text)


@dataclass(frozen=True)
class ParameterRow:
    """One numbered device parameter, as plain data."""

    id: int  # 1..27
    name: str  # e.g. "pulley_diameter_x"
    unit: str  # e.g. "mm", "steps", "µs", "mm/s", "mm/s²", "s", ""
    minimum: float
    maximum: float
    step: float  # the finest value the wire carries, e.g. 0.1 for the pulley (mm * 10)
    output: bool  # computed by the firmware: never in "Write changed", warned when written
    description: str
    power_on: float | None = None  # what the device holds until written (None: unknown)
    warning: str = ""  # what writing it will not do (e.g. the firmware recomputes it), if any


NOT_WRITTEN, PENDING, CONFIRMED, ERROR, TIMED_OUT, CANCELLED = (  # keys; shown translated
    QT_TRANSLATE_NOOP("ParameterValues", "not written"),
    QT_TRANSLATE_NOOP("ParameterValues", "pending"),
    QT_TRANSLATE_NOOP("ParameterValues", "confirmed"),
    QT_TRANSLATE_NOOP("ParameterValues", "error"),
    QT_TRANSLATE_NOOP("ParameterValues", "timed out"),
    QT_TRANSLATE_NOOP("ParameterValues", "cancelled"),
)
STATUS_COLOURS = {
    NOT_WRITTEN: "#616161",
    PENDING: "#ef6c00",
    CONFIRMED: "#2e7d32",
    ERROR: "#c62828",
    TIMED_OUT: "#ad1457",
    CANCELLED: "#6d4c41",
}
AFTER_SET, AT_MOVE = (  # when the firmware recomputed a value; shown translated
    QT_TRANSLATE_NOOP("ParameterValues", "after the last set"),
    QT_TRANSLATE_NOOP("ParameterValues", "at the last move"),
)
OUTPUT_TIP = QT_TRANSLATE_NOOP(
    "ParameterValues",
    "Output: computed by the firmware. Writing it is allowed, but the firmware may replace "
    "what is written.",
)  # translated at use: translated(OUTPUT_TIP)


def decimals(step: float) -> int:
    """The decimals a multiple of `step` needs: 0.1 → 1, 0.25 → 2, 1 → 0."""
    exponent = Decimal(repr(float(step))).normalize().as_tuple().exponent
    return min(max(-int(exponent), 0), 9)


def plain(value: float) -> str:
    """A number without trailing zeros: 99999.9, 0, 0.025."""
    text = f"{value:.9f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def with_unit(text: str, unit: str) -> str:
    return f"{text} {unit}" if unit else text


def allowed(row: ParameterRow) -> str:
    """E.g. "0 to 99999.9 mm in steps of 0.1 mm"."""
    low, high = plain(row.minimum), with_unit(plain(row.maximum), row.unit)
    if row.step == 1:
        return fill(
            QCoreApplication.translate("ParameterValues", "%1 to %2, whole numbers"), low, high
        )
    step = with_unit(plain(row.step), row.unit)
    return fill(
        QCoreApplication.translate("ParameterValues", "%1 to %2 in steps of %3"), low, high, step
    )


def format_value(row: ParameterRow, value: float) -> str:
    """The value with the decimals of the row's step (no unit)."""
    return f"{value:.{decimals(row.step)}f}"


def check_value(
    row: ParameterRow, text: str, locale: QLocale | None = None
) -> tuple[float | None, str]:
    """(value on the step grid, "") for acceptable text, else (None, why it is refused).

    The decimal point is "." or the decimal mark of `locale` (default: the interface's)."""
    typed = text.strip()
    mark = (QLocale(locale) if locale is not None else QLocale()).decimalPoint()

    def refuse(shown: str, reason: str) -> tuple[None, str]:
        why = QCoreApplication.translate("ParameterValues", "%1: %2 refused (%3): %4")
        return None, fill(why, row.name, shown, reason, allowed(row))

    if not typed:
        return refuse('""', QCoreApplication.translate("ParameterValues", "empty"))
    number_text = typed
    if mark not in ("", ".") and mark in typed and "." not in typed:
        number_text = typed.replace(mark, ".")  # 38,2 in Spanish or French
    elif "," in typed and "." not in typed:
        return refuse(
            f'"{typed}"', QCoreApplication.translate("ParameterValues", "use a point for decimals")
        )
    try:
        number = float(number_text)
    except ValueError:
        return refuse(f'"{typed}"', QCoreApplication.translate("ParameterValues", "not a number"))
    shown = with_unit(typed, row.unit)
    if not math.isfinite(number):
        return refuse(shown, QCoreApplication.translate("ParameterValues", "not a finite number"))
    tolerance = 1e-9 * max(abs(row.minimum), abs(row.maximum), row.step)
    if number < row.minimum - tolerance:
        return refuse(shown, QCoreApplication.translate("ParameterValues", "below the minimum"))
    if number > row.maximum + tolerance:
        return refuse(shown, QCoreApplication.translate("ParameterValues", "above the maximum"))
    snapped = round(number / row.step) * row.step
    if abs(number - snapped) > 1e-9 * max(abs(number), row.step):
        step = with_unit(plain(row.step), row.unit)
        return refuse(
            shown, fill(QCoreApplication.translate("ParameterValues", "not a multiple of %1"), step)
        )
    return round(snapped, decimals(row.step)) + 0.0, ""  # + 0.0: no -0.0


def check_row(row: ParameterRow) -> None:
    finite = all(math.isfinite(v) for v in (row.minimum, row.maximum, row.step))
    if not finite or row.step <= 0 or row.minimum > row.maximum:
        raise ValueError(f"parameter {row.name}: bad range or step in {row}")


@dataclass
class RowState:
    """One row as the editor holds it: its value, last written value and write status."""

    row: ParameterRow
    value: float | None = None
    written: float | None = None
    status: str = NOT_WRITTEN
    message: str = ""
    note: str = ""
    computed: str = ""  # when the firmware recomputed `written` itself (e.g. at the last move)

    def held(self) -> float | None:
        """What the device holds as far as the panel knows: the value last written, else the
        power-on value (None: unknown)."""
        return self.written if self.written is not None else self.row.power_on

    def changed(self) -> bool:
        """A value the device does not hold as far as we know (different, or unknown)."""
        if self.value is None:
            return False
        held = self.held()
        if held is None:
            return True
        return not math.isclose(self.value, held, rel_tol=1e-9, abs_tol=self.row.step / 1e6)

    def status_text(self) -> str:
        """The status (translated), its message and the row's note, as the Status cell shows."""
        status = translated(self.status)
        text = f"{status}: {self.message}" if self.message else status
        return f"{text} — {self.note}" if self.note else text
