"""Lengths shown in millimetres or inches: the units, their symbols, and a field that shows
either while the panel reads and sets it in mm."""

from __future__ import annotations

import math

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from widgets._i18n import fill
from widgets._number_field import CLEARED, NumberSpinBox

MM, INCH = "mm", "in"
MM_PER_INCH = 25.4


def unit_text(units: str, per_second: bool = False) -> str:
    """The unit symbol shown after a length ("mm", "in") or a speed ("mm/s", "in/s")."""
    if units == INCH:
        if per_second:
            return QCoreApplication.translate("UnitSpinBox", "in/s", "inches per second")
        return QCoreApplication.translate("UnitSpinBox", "in", "inches")
    return "mm/s" if per_second else "mm"


def check_units(units: str) -> None:
    """Refuse units other than "mm" and "in"."""
    if units not in (MM, INCH):
        raise ValueError(f"units must be {MM!r} or {INCH!r}, not {units!r}")


class UnitSpinBox(NumberSpinBox):
    """A length field (or a speed: `per_second`) shown in mm or inches, set and read in mm.

    The mm API (`set_mm_value`, `mm_value`, `set_mm_range`, `set_mm_decimals`) is what the rest
    of the panel uses; in mm it is the plain spin box. In inches the field shows two decimals
    more than in mm (at most 4), its range is the mm range rounded inwards, and `mm_value()` is
    on the mm grid (`10**-mm_decimals`, the device's resolution) and within the mm range; a
    value set in mm and not edited since is read back from that mm value, not from the inches
    shown (no drift through their rounding).

    What is typed is kept as typed (NumberSpinBox): out of range or unreadable, it is shown in
    red, `problem()` says why, and the value stays the last usable one. A change of units
    converts a usable number (typed or set), keeps unreadable text as typed, and empties a
    refused number, saying why: it never shows a value nobody typed."""

    def __init__(self, per_second: bool = False, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._per_second = per_second
        self._units = MM
        self._mm_decimals = self.decimals()
        self._mm_range = (self.minimum(), self.maximum())
        self._steps = (self.singleStep(), self.singleStep() / 10.0)  # (mm, inches)
        self._exact: tuple[float, float] | None = None  # (shown, mm) as last set in mm
        self.setSuffix(" " + unit_text(MM, per_second))

    def units(self) -> str:
        """The units shown: "mm" or "in"."""
        return self._units

    def set_units(self, units: str) -> None:
        """Show the same length in "mm" or "in"; emits nothing."""
        check_units(units)
        if units == self._units:
            return
        typed = self._typed_state()
        mm = self._raw_mm()
        if not typed[1] and typed[2] is not None and typed[2] != self.value():
            mm = typed[2] * self.factor()  # typed, not yet taken: that is what is converted
        blocked = self.blockSignals(True)
        try:
            self._units = units
            self.setSuffix(" " + unit_text(units, self._per_second))
            self._show(mm, typed, switched=True)
        finally:
            self.blockSignals(blocked)

    def factor(self) -> float:
        """mm per unit shown (1 or 25.4)."""
        return MM_PER_INCH if self._units == INCH else 1.0

    def shown_decimals(self, mm_decimals: int | None = None) -> int:
        """The decimals shown for `mm_decimals` decimals of a mm (default: the field's)."""
        mm_decimals = self._mm_decimals if mm_decimals is None else mm_decimals
        return mm_decimals if self._units == MM else max(0, min(4, mm_decimals + 2))

    def set_mm_decimals(self, decimals: int) -> None:
        """Type to `decimals` decimals of a mm (the device's resolution); inches: two more."""
        mm = self._raw_mm()
        self._mm_decimals = int(decimals)
        if self._units == MM:
            self.setDecimals(self._mm_decimals)  # as a plain spin box: Qt rounds the value
        else:
            self._show(mm)

    def mm_decimals(self) -> int:
        """The decimals of a mm the field is typed to."""
        return self._mm_decimals

    def set_mm_range(self, low: float, high: float) -> None:
        """Bound the field by low..high mm (clamps the value)."""
        self._mm_range = (float(low), float(high))
        if self._units == MM:
            self.setRange(low, high)
        else:
            self._show(self._raw_mm())

    def mm_range(self) -> tuple[float, float]:
        """The field's range in mm."""
        return self._mm_range

    def set_single_steps(self, mm_step: float, inch_step: float) -> None:
        """What an arrow key or wheel step adds, in mm and in inches."""
        self._steps = (float(mm_step), float(inch_step))
        self.setSingleStep(self._steps[0] if self._units == MM else self._steps[1])

    def set_mm_value(self, mm: float) -> None:
        """Show `mm` (clamped to the range) in the units shown."""
        mm = float(mm)
        if self._units == MM:
            self._exact = None
            self.setValue(mm)
            return
        shown = mm / MM_PER_INCH
        self._exact = None
        self.setValue(shown)
        if abs(self.value() - shown) <= 0.5 * 10.0 ** -self.decimals() + 1e-12:
            self._exact = (self.value(), mm)

    def mm_value(self) -> float:
        """The value in mm (in inches: on the mm grid, within the mm range)."""
        if self._units == MM:
            return float(self.value())
        return self._on_grid(self._raw_mm())

    def _raw_mm(self) -> float:
        """The value in mm, not yet on the grid: as set in mm while the field still shows it."""
        if self._units == MM:
            return float(self.value())
        exact = self._exact
        if exact is not None and exact[0] == self.value():
            return exact[1]
        return self.value() * MM_PER_INCH

    def _on_grid(self, mm: float) -> float:
        grid = 10.0**-self._mm_decimals
        low, high = self._mm_range
        steps = math.copysign(math.floor(abs(mm) / grid + 0.5), mm)  # halves away from 0
        if steps * grid < low - 1e-9:
            steps = math.ceil(low / grid - 1e-9)
        if steps * grid > high + 1e-9:
            steps = math.floor(high / grid + 1e-9)
        return round(steps * grid, self._mm_decimals) + 0.0

    def _typed_state(self) -> tuple[str, str, float | None]:
        """The number typed (without the unit), why it cannot be used ("" when it can), the
        number it reads as."""
        text = self._number_text(self.lineEdit().displayText())
        return text, self.problem(), self.typed_value()

    def _show(
        self,
        mm: float,
        typed: tuple[str, str, float | None] | None = None,
        switched: bool = False,
    ) -> None:
        """Decimals, range and step in the units shown, then `mm`; text that cannot be used
        (`typed`, as it was before, default now) is not replaced by `mm` (`_keep_typed`)."""
        typed = self._typed_state() if typed is None else typed
        decimals = self.shown_decimals()
        low, high = self._mm_range
        self.setDecimals(decimals)
        if self._units == MM:
            self.setRange(low, high)
            self.setSingleStep(self._steps[0])
        else:
            scale = 10.0**decimals
            shown_low = math.ceil(round(low / MM_PER_INCH * scale, 6)) / scale  # inwards
            shown_high = math.floor(round(high / MM_PER_INCH * scale, 6)) / scale
            if shown_low > shown_high:
                shown_low = shown_high = round(low / MM_PER_INCH, decimals)
            self.setRange(shown_low, shown_high)
            self.setSingleStep(self._steps[1])
        self.set_mm_value(mm)
        self._keep_typed(*typed, switched)

    def _keep_typed(self, text: str, problem: str, number: float | None, switched: bool) -> None:
        """Put back text that could not be used: unreadable text (or a number, the units kept)
        as typed, with the unit shown; a refused number after a change of units is cleared,
        saying why, never shown converted (it was not typed in these units)."""
        if not problem:
            return  # a usable value: shown converted
        if number is None or not switched:
            self.lineEdit().setText(self.prefix() + text + self.suffix())
            self.lineEdit().setCursorPosition(len(self.prefix() + text))  # before the unit
            return
        why = QCoreApplication.translate("NumberField", CLEARED)
        self.clear_refused(fill(why, problem, unit_text(self._units, self._per_second)))
