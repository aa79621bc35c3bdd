"""Number fields that keep what the operator typed: a keystroke is never refused, a number out
of range or unreadable stays as typed, shown in red with why, and is never sent.

Both "." and the locale's decimal mark are read as the decimal point (12.5 and 12,5 in
Spanish); whole-number fields also take the locale's thousands separator. A field's `problem()`
says why its text cannot be used ("" when it can); the panels ask it before they send.
"""

from __future__ import annotations

import math
import re

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QEvent, QLocale, QObject, Qt
from PySide6.QtGui import (
    QCloseEvent,
    QColor,
    QFocusEvent,
    QHideEvent,
    QKeyEvent,
    QPalette,
    QValidator,
)
from PySide6.QtWidgets import QAbstractSpinBox, QDoubleSpinBox, QSpinBox, QWidget

from widgets._i18n import fill, number_text

INVALID_PROPERTY = "invalidInput"  # True on a field whose text cannot be used
WHEEL_PROPERTY = "wheelNeedsFocus"  # True on a field the wheel changes only while focused
INVALID_TEXT = "#c62828"
INVALID_TEXT_DARK = "#ff8a80"
_DECIMAL = re.compile(r"[+-]?(?:\d+(?:\.(\d*))?|\.(\d+))")
_MINUSES = ("\u2212", "\u2013")  # a typographic minus, an en dash
# Why typed text cannot be used; translated at use. %1 the text typed, then the range, the unit.
EMPTY = QT_TRANSLATE_NOOP("NumberField", "a number is needed, %1 to %2%3")
NOT_WHOLE = QT_TRANSLATE_NOOP("NumberField", "%1%2 is not a whole number")
NOT_A_NUMBER = QT_TRANSLATE_NOOP("NumberField", "“%1” is not a number (%2 to %3%4)")
OUTSIDE = QT_TRANSLATE_NOOP("NumberField", "%1%4 is outside %2 to %3%4")
TOO_FINE = QT_TRANSLATE_NOOP("NumberField", "%1%2 has more than %3 decimals")
NAMED = QT_TRANSLATE_NOOP("NumberField", "%1: %2")  # a field's name: why its text is refused
# A refused number cleared when the units changed: %1 why it was refused, %2 the new unit.
CLEARED = QT_TRANSLATE_NOOP("NumberField", "%1; cleared when the units changed to %2")


def _t(text: str) -> str:
    return QCoreApplication.translate("NumberField", text)


def _ascii_digits(text: str, locale: QLocale) -> str:
    zero = locale.zeroDigit()
    if zero == "0" or len(zero) != 1:
        return text
    base = ord(zero)
    return "".join(str(ord(c) - base) if 0 <= ord(c) - base <= 9 else c for c in text)


def _signs(text: str, locale: QLocale) -> str:
    for minus in (locale.negativeSign(), *_MINUSES):
        if minus and minus != "-":
            text = text.replace(minus, "-")
    plus = locale.positiveSign()
    return text.replace(plus, "+") if plus and plus != "+" else text


def parse_decimal(text: str, locale: QLocale | None = None) -> tuple[float, int] | None:
    """(value, decimals typed, trailing zeros not counted) of `text`, read with "." or the
    locale's decimal mark, no thousands separator; None when it is not such a number."""
    locale = QLocale(locale) if locale is not None else QLocale()
    typed = _signs(_ascii_digits(text.strip(), locale), locale)
    mark = locale.decimalPoint()
    if mark and mark != ".":
        typed = typed.replace(mark, ".")
    match = _DECIMAL.fullmatch(typed)
    if match is None:
        return None
    value = float(typed)
    if not math.isfinite(value):
        return None
    fraction = (match.group(1) or match.group(2) or "").rstrip("0")
    return value + 0.0, len(fraction)


def parse_whole(text: str, locale: QLocale | None = None) -> int | None:
    """The whole number in `text` (the locale's thousands separator allowed), or None."""
    locale = QLocale(locale) if locale is not None else QLocale()
    typed = _signs(_ascii_digits(text.strip(), locale), locale)
    if re.fullmatch(r"[+-]?\d+", typed):
        return int(typed)
    value, ok = locale.toLongLong(typed)
    return int(value) if ok else None


def label_name(label: str) -> str:
    """A field's name from its label's text: "Speed:" gives "Speed" (French, Chinese too)."""
    return label.rstrip(" :\uff1a\u00a0\u202f")


def mark_invalid(widget: QWidget, invalid: bool) -> None:
    """Show `widget`'s text in red (its palette and the `invalidInput` property), or not."""
    if bool(widget.property(INVALID_PROPERTY)) == invalid:
        return
    widget.setProperty(INVALID_PROPERTY, invalid)
    if not invalid:
        widget.setPalette(QPalette())  # inherits the application's again (themes included)
        return
    palette = QPalette(widget.palette())
    dark = palette.color(QPalette.ColorRole.Base).lightness() < 128
    red = QColor(INVALID_TEXT_DARK if dark else INVALID_TEXT)
    base = palette.color(QPalette.ColorRole.Base)
    tint = QColor(
        (base.red() * 3 + red.red()) // 4,
        (base.green() * 3 + red.green()) // 4,
        (base.blue() * 3 + red.blue()) // 4,
    )
    for group in (QPalette.ColorGroup.Active, QPalette.ColorGroup.Inactive):
        palette.setColor(group, QPalette.ColorRole.Text, red)
        palette.setColor(group, QPalette.ColorRole.Base, tint)
    widget.setPalette(palette)


class _WheelNeedsFocus(QObject):
    """Lets a wheel event over an unfocused field go on to what holds it (a dock scrolls)."""

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """A wheel over `watched` without the focus: ignored there, passed to its parents."""
        wheel = event.type() == QEvent.Type.Wheel
        if wheel and isinstance(watched, QWidget) and not watched.hasFocus():
            event.ignore()  # not accepted: Qt offers it to the parent (the scroll area)
            return True
        return False


_wheel_filter: _WheelNeedsFocus | None = None


def wheel_needs_focus(widget: QWidget) -> None:
    """The mouse wheel changes `widget` (a number field, a slider, a list of choices) only
    while it has the focus (a click or Tab gives it); over it unfocused, the dock scrolls."""
    global _wheel_filter
    if _wheel_filter is None:
        _wheel_filter = _WheelNeedsFocus()
    widget.setFocusPolicy(Qt.FocusPolicy.StrongFocus)  # not WheelFocus: the wheel gives none
    widget.installEventFilter(_wheel_filter)
    widget.setProperty(WHEEL_PROPERTY, True)


class TypedNumber:
    """What makes a QSpinBox or QDoubleSpinBox keep the operator's text (mixed in before it).

    No keystroke is refused: text out of range, with too many decimals or unreadable is
    Intermediate, stays as typed through Enter, focus loss and hiding, is shown in red with
    why (tooltip), and `problem()` says why. `interpretText()` takes only usable text. Enter
    still emits the line edit's `returnPressed`, so the panel can say why it sends nothing.
    """

    _what = ""
    _base_tip = ""
    _typed_problem = ""
    _cleared = ""  # why the field was emptied (`clear_refused`), until the operator types

    # -- what the panels ask -------------------------------------------------------------

    def set_what(self, what: str) -> None:
        """The field's name in its messages (e.g. "X"); "" for none."""
        self._what = what
        self._refresh_problem()

    def problem(self) -> str:
        """Why the typed text cannot be used ("" when it can), with the field's range."""
        return self._find_problem(self.lineEdit().displayText())  # type: ignore[attr-defined]

    def clear_refused(self, reason: str) -> None:
        """Empty the field; `problem()` says `reason` until something is typed in it."""
        self.lineEdit().setText(self.prefix() + self.suffix())  # type: ignore[attr-defined]
        self.lineEdit().setCursorPosition(len(self.prefix()))  # type: ignore[attr-defined]
        self._cleared = reason
        self._refresh_problem()

    def typed_value(self) -> float | None:
        """The number typed, in the units shown (out of range too); None when unreadable."""
        text = self._number_text(self.lineEdit().displayText())  # type: ignore[attr-defined]
        special = self.specialValueText()  # type: ignore[attr-defined]
        if special and self.lineEdit().displayText() == special:  # type: ignore[attr-defined]
            return float(self.minimum())  # type: ignore[attr-defined]
        if isinstance(self, QSpinBox):
            whole = parse_whole(text, self.locale())
            return None if whole is None else float(whole)
        parsed = parse_decimal(text, self.locale())  # type: ignore[attr-defined]
        return None if parsed is None else parsed[0]

    def range_texts(self) -> tuple[str, str]:
        """The field's range as shown (in its units and decimals, the locale's digits)."""
        decimals = self.decimals() if isinstance(self, QDoubleSpinBox) else 0
        locale = self.locale()  # type: ignore[attr-defined]
        return (
            number_text(self.minimum(), decimals, locale=locale),  # type: ignore[attr-defined]
            number_text(self.maximum(), decimals, locale=locale),  # type: ignore[attr-defined]
        )

    def setToolTip(self, tip: str) -> None:
        """The field's own tooltip; while its text cannot be used, why comes first."""
        self._base_tip = tip
        self._show_problem()

    # -- checking --------------------------------------------------------------------------

    def _number_text(self, text: str) -> str:
        text = text.strip()
        prefix = self.prefix().strip()  # type: ignore[attr-defined]
        suffix = self.suffix().strip()  # type: ignore[attr-defined]
        if prefix and text.startswith(prefix):
            text = text[len(prefix) :]
        if suffix and text.endswith(suffix):
            text = text[: -len(suffix)]
        return text.strip()

    def _find_problem(self, text: str) -> str:
        special = self.specialValueText()  # type: ignore[attr-defined]
        if special and text == special:
            return ""
        number = self._number_text(text)
        unit = self.suffix().rstrip()  # type: ignore[attr-defined]
        low, high = self.range_texts()
        if not number and self._cleared:
            return self._cleared
        if not number:
            reason = fill(_t(EMPTY), low, high, unit)
        elif isinstance(self, QSpinBox):
            whole = parse_whole(number, self.locale())
            if whole is None:
                if parse_decimal(number, self.locale()) is not None:
                    reason = fill(_t(NOT_WHOLE), number, unit)
                else:
                    reason = fill(_t(NOT_A_NUMBER), number, low, high, unit)
            elif not self.minimum() <= whole <= self.maximum():
                reason = fill(_t(OUTSIDE), number, low, high, unit)
            else:
                return ""
        else:
            parsed = parse_decimal(number, self.locale())  # type: ignore[attr-defined]
            decimals = self.decimals()  # type: ignore[attr-defined]
            if parsed is None:
                reason = fill(_t(NOT_A_NUMBER), number, low, high, unit)
            elif not self._in_range(parsed[0]):
                reason = fill(_t(OUTSIDE), number, low, high, unit)
            elif parsed[1] > decimals:
                reason = fill(_t(TOO_FINE), number, unit, decimals)
            else:
                return ""
        return fill(_t(NAMED), self._what, reason) if self._what else reason

    def _in_range(self, value: float) -> bool:
        low, high = self.minimum(), self.maximum()  # type: ignore[attr-defined]
        slack = 1e-9 * max(1.0, abs(low), abs(high))
        return low - slack <= value <= high + slack

    def _refresh_problem(self, *_: object) -> None:
        problem = self.problem()
        if problem != self._typed_problem:
            self._typed_problem = problem
            self._show_problem()

    def _edited(self, _text: str) -> None:
        """Typed again after `clear_refused`: the new text is checked on its own."""
        if self._cleared:
            self._cleared = ""
            self._refresh_problem()

    def _show_problem(self) -> None:
        problem = self._typed_problem
        tip = self._base_tip
        shown = f"{problem}\n{tip}" if problem and tip else (problem or tip)
        QWidget.setToolTip(self, shown)  # type: ignore[arg-type]
        mark_invalid(self.lineEdit(), bool(problem))  # type: ignore[attr-defined]
        self.setProperty(INVALID_PROPERTY, bool(problem))  # type: ignore[attr-defined]

    def _watch_text(self) -> None:
        """Mark the text at every change: typed, or shown for a value (the spin box writes
        that with the line edit's signals blocked)."""
        self.lineEdit().textChanged.connect(self._refresh_problem)  # type: ignore[attr-defined]
        self.lineEdit().textEdited.connect(self._edited)  # type: ignore[attr-defined]
        self.textChanged.connect(self._refresh_problem)  # type: ignore[attr-defined]
        self._refresh_problem()
        wheel_needs_focus(self)  # type: ignore[arg-type]

    def setValue(self, value: float) -> None:
        """Qt's setValue (the text shows the value), and the mark refreshed."""
        super().setValue(value)  # type: ignore[misc]
        self._refresh_problem()

    def setSuffix(self, suffix: str) -> None:
        """Qt's setSuffix, and the mark refreshed."""
        super().setSuffix(suffix)  # type: ignore[misc]
        self._refresh_problem()

    def setSpecialValueText(self, text: str) -> None:
        """Qt's setSpecialValueText, and the mark refreshed."""
        super().setSpecialValueText(text)  # type: ignore[misc]
        self._refresh_problem()

    # -- Qt's virtuals ---------------------------------------------------------------------

    def validate(self, text: str, pos: int) -> QValidator.State:
        """Acceptable for a usable number, else Intermediate: no keystroke is refused."""
        if self._find_problem(text):
            return QValidator.State.Intermediate
        return QValidator.State.Acceptable

    def fixup(self, text: str) -> str:
        """Nothing is changed behind the operator's back."""
        return text

    def valueFromText(self, text: str) -> float:
        """The typed number ("." or the locale's mark); the current value if unreadable."""
        special = self.specialValueText()  # type: ignore[attr-defined]
        if special and text == special:
            return self.minimum()  # type: ignore[attr-defined]
        number = self._number_text(text)
        if isinstance(self, QSpinBox):
            whole = parse_whole(number, self.locale())
            return self.value() if whole is None else whole  # type: ignore[return-value]
        parsed = parse_decimal(number, self.locale())  # type: ignore[attr-defined]
        return self.value() if parsed is None else parsed[0]  # type: ignore[attr-defined]

    def interpretText(self) -> None:
        """Take the typed value, if it can be used (else the text stays, and the value)."""
        if not self.problem():
            QAbstractSpinBox.interpretText(self)  # type: ignore[arg-type]

    def stepBy(self, steps: int) -> None:
        """An arrow step from the typed number (brought into the range), not an older one."""
        if self.problem():
            typed = self.typed_value()
            if typed is None:
                return
            low, high = self.minimum(), self.maximum()  # type: ignore[attr-defined]
            self.setValue(min(max(typed, low), high))  # type: ignore[attr-defined]
            self.lineEdit().setText(self.textFromValue(self.value()))  # type: ignore[attr-defined]
            self._refresh_problem()
        super().stepBy(steps)  # type: ignore[misc]

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Enter on unusable text: the text stays; the panel hears Enter and says why."""
        enter = event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter)
        if enter and self.problem():
            event.ignore()  # as the spin box does: a dialog's default button may take it
            self.editingFinished.emit()  # type: ignore[attr-defined]
            self.lineEdit().returnPressed.emit()  # type: ignore[attr-defined]
            return
        super().keyPressEvent(event)  # type: ignore[misc]

    def focusOutEvent(self, event: QFocusEvent) -> None:
        """Leaving unusable text: it stays (Qt would put the last value back)."""
        if not self.problem():
            super().focusOutEvent(event)  # type: ignore[misc]
            return
        QCoreApplication.sendEvent(self.lineEdit(), event)  # type: ignore[attr-defined]
        QWidget.focusOutEvent(self, event)  # type: ignore[arg-type]
        self.editingFinished.emit()  # type: ignore[attr-defined]

    def hideEvent(self, event: QHideEvent) -> None:
        """Hidden with unusable text (a tab or dock closed): it stays."""
        if self.problem():
            QWidget.hideEvent(self, event)  # type: ignore[arg-type]
        else:
            super().hideEvent(event)  # type: ignore[misc]

    def closeEvent(self, event: QCloseEvent) -> None:
        """Closed with unusable text: it stays."""
        if self.problem():
            QWidget.closeEvent(self, event)  # type: ignore[arg-type]
        else:
            super().closeEvent(event)  # type: ignore[misc]

    def changeEvent(self, event: QEvent) -> None:
        """A new locale: the text is read again with its decimal mark."""
        super().changeEvent(event)  # type: ignore[misc]
        if event.type() == QEvent.Type.LocaleChange:
            self._refresh_problem()


class NumberSpinBox(TypedNumber, QDoubleSpinBox):
    """A QDoubleSpinBox that keeps what is typed (see TypedNumber)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._watch_text()

    def setRange(self, low: float, high: float) -> None:
        """Qt's setRange, and the text checked against the new range."""
        QDoubleSpinBox.setRange(self, low, high)
        self._refresh_problem()

    def setDecimals(self, decimals: int) -> None:
        """Qt's setDecimals, and the text checked against them."""
        QDoubleSpinBox.setDecimals(self, decimals)
        self._refresh_problem()


class WholeSpinBox(TypedNumber, QSpinBox):
    """A QSpinBox that keeps what is typed (see TypedNumber)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._watch_text()

    def setRange(self, low: int, high: int) -> None:
        """Qt's setRange, and the text checked against the new range."""
        QSpinBox.setRange(self, low, high)
        self._refresh_problem()
