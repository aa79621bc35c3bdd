"""Jog buttons for X, Y and Z with a step size, and the keyboard jog map."""

from __future__ import annotations

import logging
from collections.abc import Iterable

from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import (
    QApplication,
    QButtonGroup,
    QDoubleSpinBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, modifier_bits, normalize_axes

log = logging.getLogger(__name__)

STEP_PRESETS: tuple[float, ...] = (0.01, 0.1, 1.0, 10.0, 100.0)
SHIFT_FACTOR = 10.0
KEY_HINT = "Keys: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10"  # noqa: RUF001 (the multiplication sign is meant)

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


def _fmt_mm(value: float) -> str:
    return f"{value:g} mm"


class JogPanel(QWidget):
    """Six jog buttons, a step size, Shift for a ten times bigger step; emits `jog_requested`."""

    jog_requested = Signal(str, float)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("jogPanel")
        self.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.setToolTip(f"Move the stage by one step.\n{KEY_HINT} (while the panel has focus).")
        self._axes = frozenset(AXES)
        self.buttons: dict[tuple[str, float], QPushButton] = {}

        pad = QGridLayout()
        pad.setSpacing(4)
        for axis, direction, row, column in _BUTTONS:
            sign = "+" if direction > 0 else "-"
            button = QPushButton(f"{axis.upper()}{sign}")
            button.setObjectName(f"jog{axis.upper()}{'Plus' if direction > 0 else 'Minus'}")
            button.setMinimumSize(52, 40)
            button.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Preferred)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)  # clicks focus the panel, for keys
            button.clicked.connect(lambda _=False, a=axis, d=direction: self._button_clicked(a, d))
            pad.addWidget(button, row, column)
            self.buttons[(axis, direction)] = button
        pad.setColumnMinimumWidth(3, 16)

        self._preset_group = QButtonGroup(self)
        self._preset_group.setExclusive(True)
        presets = QHBoxLayout()
        presets.setSpacing(2)
        step_label = QLabel("Step:")
        step_label.setToolTip("Distance of one jog")
        presets.addWidget(step_label)
        self.preset_buttons: dict[float, QPushButton] = {}
        for value in STEP_PRESETS:
            button = QPushButton(_fmt_mm(value))
            button.setObjectName(f"jogStep{value:g}".replace(".", "_"))
            button.setCheckable(True)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            button.setToolTip(f"Jog by {_fmt_mm(value)} per press")
            button.clicked.connect(lambda _=False, v=value: self.set_step(v))
            self._preset_group.addButton(button)
            presets.addWidget(button)
            self.preset_buttons[value] = button

        self.step_spin = QDoubleSpinBox()
        self.step_spin.setObjectName("jogStepSpin")
        self.step_spin.setDecimals(3)
        self.step_spin.setRange(0.001, 1000.0)
        self.step_spin.setSuffix(" mm")
        self.step_spin.setToolTip("Any step size (0.001 to 1000 mm)")
        self.step_spin.valueChanged.connect(self._step_edited)
        presets.addWidget(self.step_spin)
        presets.addStretch(1)

        self.hint_label = QLabel(KEY_HINT)
        self.hint_label.setObjectName("jogHint")
        self.hint_label.setToolTip(
            "Keyboard jog works anywhere in the window except in text fields;\n"
            "hold Shift for a step ten times bigger (also with the buttons)."
        )
        self.hint_label.setStyleSheet("color: #616161;")

        layout = QVBoxLayout(self)
        layout.addLayout(pad)
        layout.addLayout(presets)
        layout.addWidget(self.hint_label)
        self.set_step(1.0)

    # -- step ------------------------------------------------------------------------------

    def step(self) -> float:
        """The current step in mm (without the Shift factor)."""
        return float(self.step_spin.value())

    def set_step(self, step_mm: float) -> None:
        """Set the step in mm; emits nothing."""
        self.step_spin.setValue(step_mm)
        self._sync_presets()  # valueChanged is not emitted when the value is unchanged

    def _step_edited(self, _value: float) -> None:
        self._sync_presets()

    def _sync_presets(self) -> None:
        step = self.step()
        match = next((b for v, b in self.preset_buttons.items() if abs(v - step) < 1e-9), None)
        self._preset_group.setExclusive(False)
        for button in self.preset_buttons.values():
            button.setChecked(button is match)
        self._preset_group.setExclusive(True)
        for (axis, direction), button in self.buttons.items():
            normal, big = direction * step, direction * step * SHIFT_FACTOR
            button.setToolTip(f"Jog {axis.upper()} by {normal:+g} mm (Shift: {big:+g} mm)")

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

    def handle_key(self, key: int, modifiers: object = None, *, auto_repeat: bool = False) -> bool:
        """Jog for an arrow/PgUp/PgDn key; True if the key is a jog key and was consumed.

        Auto-repeated presses are consumed but jog nothing (a held key must not queue moves).
        Keys with Ctrl, Alt or Meta are left alone, and so is everything while disabled.
        """
        key = int(getattr(key, "value", key))
        target = KEY_MAP.get(key)
        bits = modifier_bits(modifiers)
        if target is None or bits & ~(_SHIFT | _KEYPAD) or not self.isEnabled():
            return False
        axis, direction = target
        if axis not in self._axes:
            return False
        if not auto_repeat:
            self._jog(axis, direction, bool(bits & _SHIFT))
        return True

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Jog keys while the panel itself has focus."""
        if self.handle_key(event.key(), event.modifiers(), auto_repeat=event.isAutoRepeat()):
            event.accept()
        else:
            super().keyPressEvent(event)

    def _button_clicked(self, axis: str, direction: float) -> None:
        shift = bool(modifier_bits(QApplication.keyboardModifiers()) & _SHIFT)
        self._jog(axis, direction, shift)

    def _jog(self, axis: str, direction: float, shift: bool) -> None:
        distance = direction * self.step() * (SHIFT_FACTOR if shift else 1.0)
        log.debug("jog %s by %g mm", axis, distance)
        self.jog_requested.emit(axis, distance)
