"""Jog buttons for X, Y and Z with a step size, and the keyboard jog map."""

from __future__ import annotations

import logging
from collections.abc import Iterable

from PySide6.QtCore import QT_TRANSLATE_NOOP, Qt, Signal
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import (
    QApplication,
    QButtonGroup,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, decimals_for, modifier_bits, normalize_axes
from widgets._i18n import fill, number_text
from widgets._key_pairs import KeyReleases
from widgets._number_field import label_name
from widgets._units import INCH, MM, MM_PER_INCH, UnitSpinBox, check_units

log = logging.getLogger(__name__)

STEP_PRESETS: tuple[float, ...] = (0.01, 0.1, 1.0, 10.0, 100.0)
INCH_STEP_PRESETS: tuple[float, ...] = (0.001, 0.01, 0.1, 1.0)  # inches, as Candle and UGS
STEP_RANGE_MM = (0.001, 1000.0)
SHIFT_FACTOR = 10.0
EDGE = 3  # px above, below and between the rows: the panel fits a short column (1024×640)
KEY_HINT = QT_TRANSLATE_NOOP("JogPanel", "Keys: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10")

_SHIFT = Qt.KeyboardModifier.ShiftModifier.value
_KEYPAD = Qt.KeyboardModifier.KeypadModifier.value

# key -> (axis, direction)
KEY_MAP: dict[int, tuple[str, float]] = {
    Qt.Key.Key_Left.value: ("x", -1.0),
    Qt.Key.Key_Right.value: ("x", 1.0),
    Qt.Key.Key_Down.value: ("y", -1.0),
    Qt.Key.Key_Up.value: ("y", 1.0),
    Qt.Key.Key_PageDown.value: ("z", -1.0),
    Qt.Key.Key_PageUp.value: ("z", 1.0),
}

# (axis, direction, grid row, grid column) of each jog button
_BUTTONS: tuple[tuple[str, float, int, int], ...] = (
    ("y", 1.0, 0, 1),
    ("x", -1.0, 1, 0),
    ("x", 1.0, 1, 2),
    ("y", -1.0, 2, 1),
    ("z", 1.0, 0, 4),
    ("z", -1.0, 2, 4),
)


def _narrow(button: QPushButton) -> None:
    """A step preset as narrow as its text (a push button's own minimum is wider): the five fit
    a narrow column of panels."""
    margin = 2 * button.style().pixelMetric(button.style().PixelMetric.PM_ButtonMargin)
    button.setMinimumWidth(button.fontMetrics().horizontalAdvance(button.text()) + margin)
    button.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Fixed)


class JogPanel(QWidget):
    """Six jog buttons, a step size, Shift for a ten times bigger step.

    Pressing a button or a jog key emits `jog_requested` (one step) and holds the jog until
    it is released (`jog_released`): the window repeats steps while `held()` says so.
    """

    jog_requested = Signal(str, float)
    jog_released = Signal()
    refused = Signal(str)  # why a press jogged nothing: the step field's text cannot be used

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("jogPanel")
        self.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.setToolTip(
            fill(
                self.tr(
                    "Move the stage by one step; hold a button or key to keep stepping.\n"
                    "%1 (see the hint below for where the keys work)."
                ),
                self.tr(KEY_HINT),
            )
        )
        self._axes = frozenset(AXES)
        self.key_map: dict[int, tuple[str, float]] = dict(KEY_MAP)  # key -> (axis, direction)
        self.step_keys: dict[int, int] = {}  # key -> -1 (a smaller step) or +1 (larger)
        self.key_hint = self.tr(KEY_HINT)
        self._held: tuple[str, float] | None = None
        self._held_key: int | None = None
        self._releases = KeyReleases()  # of the jog and step keys
        self._down_after_pair: int | None = None  # a jog key still down after a split pair
        self._held_button: QPushButton | None = None
        self.buttons: dict[tuple[str, float], QPushButton] = {}

        pad = QGridLayout()
        pad.setHorizontalSpacing(4)
        pad.setVerticalSpacing(2)
        for axis, direction, row, column in _BUTTONS:
            sign = "+" if direction > 0 else "-"
            button = QPushButton(f"{axis.upper()}{sign}")
            button.setObjectName(f"jog{axis.upper()}{'Plus' if direction > 0 else 'Minus'}")
            button.setMinimumSize(52, 28)
            button.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Preferred)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)  # clicks focus the panel, for keys
            button.setAutoRepeat(False)  # held: the window steps while it is down, no clicks
            button.pressed.connect(lambda a=axis, d=direction: self._button_pressed(a, d))
            button.released.connect(self.release)
            pad.addWidget(button, row, column)
            self.buttons[(axis, direction)] = button
        pad.setColumnMinimumWidth(3, 16)

        self._preset_group = QButtonGroup(self)
        self._preset_group.setExclusive(True)
        presets = QHBoxLayout()
        presets.setSpacing(2)
        step_label = QLabel(self.tr("Step:"))
        step_label.setToolTip(self.tr("Distance of one jog"))
        self.preset_buttons: dict[float, QPushButton] = {}
        for value in STEP_PRESETS:
            text = fill(self.tr("%1 mm"), number_text(value, 2))  # the locale's decimal mark
            button = QPushButton(text)
            button.setObjectName(f"jogStep{value:g}".replace(".", "_"))
            button.setCheckable(True)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            button.setToolTip(fill(self.tr("Jog by %1 per press"), text))
            _narrow(button)
            button.clicked.connect(lambda _=False, v=value: self.set_step(v))
            self._preset_group.addButton(button)
            presets.addWidget(button)
            self.preset_buttons[value] = button
        # Shown instead of the mm presets when lengths are shown in inches (`set_units`).
        self.inch_preset_buttons: dict[float, QPushButton] = {}
        for value in INCH_STEP_PRESETS:
            text = fill(self.tr("%1 in"), number_text(value, 3))
            button = QPushButton(text)
            button.setObjectName(f"jogStepIn{value:g}".replace(".", "_"))
            button.setCheckable(True)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            button.setToolTip(fill(self.tr("Jog by %1 per press"), text))
            _narrow(button)
            button.clicked.connect(lambda _=False, v=value: self.set_step(v * MM_PER_INCH))
            button.setVisible(False)
            self._preset_group.addButton(button)
            presets.addWidget(button)
            self.inch_preset_buttons[value] = button
        self._units = MM

        self.step_spin = UnitSpinBox()
        self.step_spin.setObjectName("jogStepSpin")
        self.step_spin.set_what(label_name(step_label.text()))
        self.step_spin.set_mm_decimals(3)
        self.step_spin.set_mm_range(*STEP_RANGE_MM)
        self.step_spin.set_single_steps(1.0, 0.1)
        self._step_tip()
        self.step_spin.valueChanged.connect(self._step_edited)
        presets.addStretch(1)
        # The step beside X+, under Z+: a row less in a column of panels (issue 28 item 20);
        # its label before it, in the gap, so that the row is no taller than a jog button.
        step_label.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        step_label.setBuddy(self.step_spin)
        pad.addWidget(step_label, 1, 3)
        pad.addWidget(self.step_spin, 1, 4)

        self.hint_label = QLabel(self.key_hint)
        self.hint_label.setObjectName("jogHint")
        self.hint_label.setWordWrap(True)
        self.hint_label.setStyleSheet("color: #616161;")
        self.set_keyboard_state(True, "")

        layout = QVBoxLayout(self)
        margins = layout.contentsMargins()  # the dock's title bar is the gap above
        layout.setContentsMargins(margins.left(), EDGE, margins.right(), EDGE)
        layout.setSpacing(EDGE)
        layout.addLayout(pad)
        layout.addLayout(presets)
        layout.addWidget(self.hint_label)
        layout.addStretch(1)  # extra height goes below the panel, not between its rows
        self.set_step(1.0)

    # -- step ------------------------------------------------------------------------------

    def set_keyboard_state(self, active: bool, reason: str) -> None:
        """Say whether the jog keys act now, and if not, why (e.g. "the focus is in a field")."""
        self._keyboard_state = (active, reason)
        state = self.tr("keys active") if active else fill(self.tr("keys off: %1"), reason)
        self.hint_label.setText(f"{self.key_hint} · {state}")
        self.hint_label.setToolTip(
            self.tr(
                "The jog keys work while this window is active and no menu, list, dialog or "
                "popup\nis open, except when the focus is in a field that uses the arrow keys "
                "itself\n(text and number fields, drop-down lists, the speed slider, the "
                "console).\nClick the views or this panel to give the keys back to jogging.\n"
                "Hold a key to keep stepping; Shift for a step ten times bigger."
            )
        )

    def set_key_map(
        self, key_map: dict[int, tuple[str, float]], step_keys: dict[int, int], hint: str
    ) -> None:
        """The jog keys (key code -> (axis, direction)), the step keys (key code -> -1 for the
        next smaller preset step, +1 for the next larger) and the hint naming them."""
        self.release()
        self.key_map, self.step_keys, self.key_hint = dict(key_map), dict(step_keys), hint
        self.set_keyboard_state(*self._keyboard_state)

    def is_jog_key(self, key: int) -> bool:
        """Whether `key` (a key code) jogs or changes the step."""
        key = int(getattr(key, "value", key))
        return key in self.key_map or key in self.step_keys

    def change_step(self, direction: int) -> float:
        """The next preset step below (-1) or above (+1) the current one, among the presets
        of the units shown; returns the step in mm."""
        inch = self._units == INCH
        presets = self.inch_preset_buttons if inch else self.preset_buttons
        step = self.step_spin.value() if inch else self.step()  # in the units shown
        usable = [v for v, b in presets.items() if b.isEnabled()]
        if direction < 0:
            smaller = [v for v in usable if v < step - 1e-12]
            chosen = max(smaller) if smaller else None
        else:
            larger = [v for v in usable if v > step + 1e-12]
            chosen = min(larger) if larger else None
        if chosen is not None:
            self.set_step(chosen * MM_PER_INCH if inch else chosen)
        return self.step()

    def set_resolution(self, resolution: float | None) -> None:
        """Step sizes are typed to the device's resolution in mm (None: 0.001 mm); in inches,
        to two decimals more (at most 4), and a step is sent on the device's resolution."""
        decimals = decimals_for(resolution)
        finest = 10.0**-decimals
        self.step_spin.set_mm_decimals(decimals)
        self.step_spin.set_mm_range(finest, STEP_RANGE_MM[1])
        for value, button in self.preset_buttons.items():
            button.setEnabled(value >= finest - 1e-12)
        for value, button in self.inch_preset_buttons.items():
            button.setEnabled(value * MM_PER_INCH >= finest - 1e-12)
        self._step_tip()
        self._sync_presets()

    def set_units(self, units: str) -> None:
        """Show the step in "mm" or "in", with that unit's preset steps (mm: 0.01 to 100;
        inches: 0.001 to 1); the step stays the same length, and is still read in mm. Emits
        nothing."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        self.step_spin.set_units(units)
        for button in self.preset_buttons.values():
            button.setVisible(units == MM)
        for button in self.inch_preset_buttons.values():
            button.setVisible(units == INCH)
        self._step_tip()
        self._sync_presets()

    def units(self) -> str:
        """The units the step is shown in: "mm" or "in"."""
        return self._units

    def _step_tip(self) -> None:
        if self._units == INCH:
            low, high = self.step_spin.range_texts()
            self.step_spin.setToolTip(fill(self.tr("Any step size (%1 to %2 in)"), low, high))
        else:
            self.step_spin.setToolTip(self.tr("Any step size (0.001 to 1000 mm)"))

    def step(self) -> float:
        """The current step in mm (without the Shift factor)."""
        return self.step_spin.mm_value()

    def set_step(self, step_mm: float) -> None:
        """Set the step in mm; emits nothing."""
        self.step_spin.set_mm_value(step_mm)
        self._sync_presets()  # valueChanged is not emitted when the value is unchanged

    def _step_edited(self, _value: float) -> None:
        self._sync_presets()

    def _sync_presets(self) -> None:
        inch = self._units == INCH
        presets = self.inch_preset_buttons if inch else self.preset_buttons
        shown = self.step_spin.value() if inch else self.step()
        match = next((b for v, b in presets.items() if abs(v - shown) < 1e-9), None)
        self._preset_group.setExclusive(False)
        for button in (*self.preset_buttons.values(), *self.inch_preset_buttons.values()):
            button.setChecked(button is match)
        self._preset_group.setExclusive(True)
        step = self.step()
        if inch:
            template = self.tr("Jog %1 by %2 in (Shift: %3 in)")
            step /= MM_PER_INCH  # what is sent, on the device's resolution, in inches
            decimals = self.step_spin.decimals()
        else:
            template = self.tr("Jog %1 by %2 mm (Shift: %3 mm)")
            decimals = max(self.step_spin.decimals(), 6)
        for (axis, direction), button in self.buttons.items():
            normal, big = direction * step, direction * step * SHIFT_FACTOR
            button.setToolTip(
                fill(
                    template,
                    axis.upper(),
                    number_text(normal, decimals, signed=True),
                    number_text(big, decimals, signed=True),
                )
            )

    # -- axes ------------------------------------------------------------------------------

    def set_axes_enabled(self, axes: Iterable[str]) -> None:
        """Enable the buttons and keys of `axes` only (e.g. `("x", "y")`); others are disabled."""
        self._axes = normalize_axes(axes)
        for (axis, _direction), button in self.buttons.items():
            button.setEnabled(axis in self._axes)

    def axes_enabled(self) -> frozenset[str]:
        """The axes that can be jogged."""
        return self._axes

    # -- jogging ---------------------------------------------------------------------------

    def is_repeat(self, key: int, timestamp: int = 0, *, auto_repeat: bool = False) -> bool:
        """Whether a press of `key` at `timestamp` (the key event's, in ms; 0: unknown) repeats
        a held key: Qt says so, or it came at the time of that key's last release (an X11
        auto-repeat pair Qt did not flag, see `KeyReleases`)."""
        return auto_repeat or self._releases.pairs(int(getattr(key, "value", key)), timestamp)

    def handle_key(
        self,
        key: int,
        modifiers: object = None,
        *,
        auto_repeat: bool = False,
        timestamp: int = 0,
    ) -> bool:
        """Jog for an arrow/PgUp/PgDn key; True if the key is a jog key and was consumed.

        Auto-repeated presses are consumed but jog nothing (a held key must not queue moves),
        and so is a press at the `timestamp` of its key's release (see `is_repeat`): the key is
        still down, and a jog its release stopped does not start again. Keys with Ctrl, Alt or
        Meta are left alone, and so is everything while disabled.
        """
        key = int(getattr(key, "value", key))
        paired = not auto_repeat and self.is_repeat(key, timestamp)
        if paired:
            log.info("jog key %#x pressed at its release's time: paired with its release", key)
            auto_repeat = True
        bits = modifier_bits(modifiers)
        if key in self.step_keys and not bits & ~_KEYPAD and self.isEnabled():
            if not auto_repeat:
                self.change_step(self.step_keys[key])
            return True
        target = self.key_map.get(key)
        if target is None or bits & ~(_SHIFT | _KEYPAD) or not self.isEnabled():
            return False
        axis, direction = target
        if axis not in self._axes:
            return False
        if auto_repeat:  # an auto-repeat, even one queued before the release, starts nothing
            if paired:
                self._down_after_pair = key  # its real release is still to come
        else:
            self._down_after_pair = None
            self._held_key = key
            self._held_button = None
            self._jog(axis, direction, bool(bits & _SHIFT))
        return True

    def handle_key_release(
        self, key: int, *, auto_repeat: bool = False, timestamp: int = 0
    ) -> bool:
        """End a held jog when its key is released, at once; True if the key is a jog key.

        The release's `timestamp` (ms; 0: unknown) is kept: a press of the key at that time is
        an auto-repeat (`is_repeat`)."""
        key = int(getattr(key, "value", key))
        if key not in self.step_keys and key not in self.key_map:
            return False
        self._releases.released(key, timestamp)
        if key in self.step_keys:
            return True
        if not auto_repeat and key == self._held_key:
            self.release()
        elif not auto_repeat and key == self._down_after_pair:
            # The key is let go at last: a step still under way (its split release was taken
            # for a tap's) is told so, and stops where the device can stop; none starts.
            self._down_after_pair = None
            self.jog_released.emit()
        return True

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Jog keys while the panel itself has focus."""
        if self.handle_key(
            event.key(),
            event.modifiers(),
            auto_repeat=event.isAutoRepeat(),
            timestamp=event.timestamp(),
        ):
            event.accept()
        else:
            super().keyPressEvent(event)

    def keyReleaseEvent(self, event: QKeyEvent) -> None:
        """A released jog key ends the held jog."""
        if self.handle_key_release(
            event.key(), auto_repeat=event.isAutoRepeat(), timestamp=event.timestamp()
        ):
            event.accept()
        else:
            super().keyReleaseEvent(event)

    def held(self) -> tuple[str, float] | None:
        """The (axis, distance) being held now, or None: a key counts as held from its press
        to its release (auto-repeated events change nothing), a button while it is down."""
        button = self._held_button
        if button is not None and not (button.isDown() and button.isEnabled()):
            return None  # let go (its release may not have been delivered yet)
        return self._held

    def held_by_key(self) -> bool:
        """Whether the held jog is held by a key (not a button)."""
        return self._held is not None and self._held_key is not None

    def release(self) -> None:
        """End the held jog (a key or button released, or the window lost the keyboard)."""
        self._held_key = self._down_after_pair = None
        self._held_button = None
        if self._held is not None:
            self._held = None
            self.jog_released.emit()

    def _button_pressed(self, axis: str, direction: float) -> None:
        shift = bool(modifier_bits(QApplication.keyboardModifiers()) & _SHIFT)
        self._held_key = self._down_after_pair = None
        self._held_button = self.buttons[(axis, direction)]
        self._jog(axis, direction, shift)

    def _jog(self, axis: str, direction: float, shift: bool) -> None:
        if self.step_spin.problem():  # a step typed out of range is never replaced by another
            why = fill(self.tr("%1; no jog"), self.step_spin.problem())
            log.info("jog refused: %s", why)
            self.refused.emit(why)
            return
        distance = direction * self.step() * (SHIFT_FACTOR if shift else 1.0)
        log.debug("jog %s by %g mm", axis, distance)
        self._held = (axis, distance)
        self.jog_requested.emit(axis, distance)
