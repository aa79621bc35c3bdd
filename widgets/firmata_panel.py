"""Settings of a stepper on a Firmata board: steps per revolution, pins, steps per mm."""

from __future__ import annotations

import itertools
import logging
from collections.abc import Sequence

from PySide6.QtCore import QT_TRANSLATE_NOOP, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QDoubleSpinBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from widgets._buttons import make_button
from widgets._i18n import fill
from widgets._number_field import wheel_needs_focus

log = logging.getLogger(__name__)

MAX_STEPS_PER_REV = 16383  # 14 bits, as Firmata's stepper messages carry it
MAX_PIN = 127
PIN_COUNTS = (2, 4)
DEFAULT_PINS = (8, 9, 10, 11)
NO_VERSION = QT_TRANSLATE_NOOP("FirmataPanel", "version unknown")  # translated at use


class FirmataPanel(QWidget):
    """Steps per revolution, 2 or 4 pins, steps per mm, the speed in rpm; Configure; version.

    `configure_requested(steps_per_rev, pins, steps_per_mm)` on Configure,
    `version_requested()` on Library version, `steps_per_mm_changed(v)` when the field is edited.
    """

    configure_requested = Signal(int, list, float)
    version_requested = Signal()
    steps_per_mm_changed = Signal(float)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("firmataPanel")
        self._speed: float | None = None

        self.steps_per_rev_spin = QSpinBox()
        self.steps_per_rev_spin.setObjectName("firmataStepsPerRev")
        self.steps_per_rev_spin.setRange(1, MAX_STEPS_PER_REV)
        self.steps_per_rev_spin.setValue(200)
        self.steps_per_rev_spin.setSuffix(" steps/rev")
        self.steps_per_rev_spin.setKeyboardTracking(False)
        self.steps_per_rev_spin.setAccelerated(True)
        self.steps_per_rev_spin.setMinimumWidth(120)
        self.steps_per_rev_spin.setToolTip(
            fill(
                self.tr("Full steps per revolution of the motor, 1 to %1 (e.g. 200)"),
                MAX_STEPS_PER_REV,
            )
        )
        self.steps_per_rev_spin.valueChanged.connect(self._update_rpm)
        wheel_needs_focus(self.steps_per_rev_spin)

        self.pin_count_combo = QComboBox()
        self.pin_count_combo.setObjectName("firmataPinCount")
        for count in PIN_COUNTS:
            self.pin_count_combo.addItem(fill(self.tr("%1 pins"), count), count)
        self.pin_count_combo.setCurrentIndex(PIN_COUNTS.index(4))
        self.pin_count_combo.setToolTip(
            self.tr(
                "2 pins: a driver with step and direction inputs; 4 pins: the motor's four wires"
            )
        )
        self.pin_count_combo.currentIndexChanged.connect(self._pin_count_changed)
        wheel_needs_focus(self.pin_count_combo)

        self.pin_spins: list[QSpinBox] = []
        self.pin_labels: list[QLabel] = []
        pins_row = QHBoxLayout()
        for index, default in enumerate(DEFAULT_PINS, start=1):
            spin = QSpinBox()
            spin.setObjectName(f"firmataPin{index}")
            spin.setRange(0, MAX_PIN)
            spin.setValue(default)
            spin.setPrefix(self.tr("pin "))
            spin.setMinimumWidth(70)
            wheel_needs_focus(spin)
            label = QLabel(f"{index}:")
            label.setBuddy(spin)
            pins_row.addWidget(label)
            pins_row.addWidget(spin, 1)
            self.pin_spins.append(spin)
            self.pin_labels.append(label)

        self.steps_per_mm_spin = QDoubleSpinBox()
        self.steps_per_mm_spin.setObjectName("firmataStepsPerMm")
        self.steps_per_mm_spin.setDecimals(3)
        self.steps_per_mm_spin.setRange(0.001, 1_000_000.0)
        self.steps_per_mm_spin.setValue(100.0)
        self.steps_per_mm_spin.setSuffix(" steps/mm")
        self.steps_per_mm_spin.setKeyboardTracking(False)
        wheel_needs_focus(self.steps_per_mm_spin)
        self.steps_per_mm_spin.setAccelerated(True)
        self.steps_per_mm_spin.setMinimumWidth(120)
        self.steps_per_mm_spin.setToolTip(
            self.tr("Motor steps per mm of travel (more than 0): converts mm and mm/s to steps")
        )
        self.steps_per_mm_spin.valueChanged.connect(self._steps_per_mm_edited)

        self.rpm_label = QLabel()
        self.rpm_label.setObjectName("firmataRpm")
        self.rpm_label.setToolTip(
            self.tr("The speed in mm/s and the motor speed it means, in revolutions per minute")
        )

        self.configure_button = make_button(
            self.tr("Configure"),
            "firmataConfigure",
            self.tr("Set up the stepper on the board with these settings"),
        )
        self.configure_button.clicked.connect(self._configure)
        self.version_button = make_button(
            self.tr("Library version"),
            "firmataVersion",
            self.tr("Ask the board for its stepper library's version"),
        )
        self.version_button.clicked.connect(self.version_requested)
        self.version_label = QLabel(self.tr(NO_VERSION))
        self.version_label.setObjectName("firmataVersionLabel")
        self.version_label.setToolTip(self.tr("The stepper library version the board reported"))

        grid = QGridLayout()
        rows = (
            (self.tr("Steps/rev:"), self.steps_per_rev_spin, self.pin_count_combo),
            (self.tr("Steps per mm:"), self.steps_per_mm_spin, self.rpm_label),
        )
        for row, (text, field, beside) in enumerate(rows):
            label = QLabel(text)
            label.setBuddy(field)
            label.setToolTip(field.toolTip())
            grid.addWidget(label, row, 0)
            grid.addWidget(field, row, 1)
            grid.addWidget(beside, row, 2)
        pins_label = QLabel(self.tr("Pins:"))
        pins_label.setToolTip(
            fill(self.tr("The board's pin numbers (0 to %1) wired to the motor"), MAX_PIN)
        )
        grid.addWidget(pins_label, 2, 0)
        grid.addLayout(pins_row, 2, 1, 1, 2)
        grid.setColumnStretch(2, 1)

        buttons = QHBoxLayout()
        buttons.addWidget(self.configure_button)
        buttons.addStretch(1)
        buttons.addWidget(self.version_label)
        buttons.addWidget(self.version_button)

        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addLayout(buttons)
        layout.addStretch(1)

        order = [
            self.steps_per_rev_spin,
            self.pin_count_combo,
            *self.pin_spins,
            self.steps_per_mm_spin,
            self.configure_button,
            self.version_button,
        ]
        for first, second in itertools.pairwise(order):
            QWidget.setTabOrder(first, second)

        self._pin_count_changed()
        self._update_rpm()

    # -- values ----------------------------------------------------------------------------

    def pin_count(self) -> int:
        """2 or 4."""
        return int(self.pin_count_combo.currentData())

    def pins(self) -> list[int]:
        """The pin numbers in use (2 or 4)."""
        for spin in self.pin_spins:
            spin.interpretText()
        return [int(spin.value()) for spin in self.pin_spins[: self.pin_count()]]

    def steps_per_mm(self) -> float:
        """Steps per mm in the field."""
        return float(self.steps_per_mm_spin.value())

    def steps_per_rev(self) -> int:
        """Steps per revolution in the field."""
        return int(self.steps_per_rev_spin.value())

    def settings(self) -> dict:
        """{"steps_per_rev": int, "pins": list[int], "steps_per_mm": float}, for saving."""
        self.steps_per_rev_spin.interpretText()
        self.steps_per_mm_spin.interpretText()
        return {
            "steps_per_rev": self.steps_per_rev(),
            "pins": self.pins(),
            "steps_per_mm": self.steps_per_mm(),
        }

    def set_settings(self, steps_per_rev: int, pins: Sequence[int], steps_per_mm: float) -> None:
        """Restore saved settings (2 or 4 pins; steps per mm more than 0); emits nothing."""
        pins = [int(p) for p in pins]
        if len(pins) not in PIN_COUNTS:
            raise ValueError(f"a Firmata stepper has 2 or 4 pins, not {pins!r}")
        if not steps_per_mm > 0:
            raise ValueError(f"steps per mm must be more than 0, not {steps_per_mm!r}")
        widgets = [
            self.steps_per_rev_spin,
            self.pin_count_combo,
            self.steps_per_mm_spin,
            *self.pin_spins,
        ]
        blocked = [w.blockSignals(True) for w in widgets]
        try:
            self.steps_per_rev_spin.setValue(int(steps_per_rev))
            self.pin_count_combo.setCurrentIndex(PIN_COUNTS.index(len(pins)))
            for spin, pin in zip(self.pin_spins, pins, strict=False):
                spin.setValue(pin)
            self.steps_per_mm_spin.setValue(float(steps_per_mm))
        finally:
            for widget, was in zip(widgets, blocked, strict=True):
                widget.blockSignals(was)
        self._pin_count_changed()
        self._update_rpm()

    def set_speed_mm_s(self, speed: float | None) -> None:
        """Show a speed in mm/s and the rpm it means (None: unknown)."""
        self._speed = None if speed is None else float(speed)
        self._update_rpm()

    def rpm(self) -> float | None:
        """The rpm of the speed shown, or None."""
        if self._speed is None:
            return None
        return self._speed * self.steps_per_mm() * 60.0 / self.steps_per_rev()

    def set_library_version(self, text: str) -> None:
        """Show the library version the board reported ("" : unknown)."""
        self.version_label.setText(text or self.tr(NO_VERSION))

    # -- updates -----------------------------------------------------------------------------

    def _pin_count_changed(self, *_: object) -> None:
        count = self.pin_count()
        for index, (spin, label) in enumerate(zip(self.pin_spins, self.pin_labels, strict=True)):
            used = index < count
            spin.setVisible(used)
            label.setVisible(used)
            if count == 2:
                role = (self.tr("step"), self.tr("direction"))
            else:
                role = (self.tr("motor wire"),) * 4
            spin.setToolTip(
                fill(self.tr("Pin %1 (%2), 0 to %3"), index + 1, role[index], MAX_PIN)
                if used
                else self.tr("not used")
            )

    def _update_rpm(self, *_: object) -> None:
        rpm = self.rpm()
        if rpm is None:
            self.rpm_label.setText(fill(self.tr("speed: %1 mm/s = %2 rpm"), "—", "—"))
        else:
            speed = fill(self.tr("speed: %1 mm/s = %2 rpm"), f"{self._speed:g}", f"{rpm:.4g}")
            self.rpm_label.setText(speed)

    def _steps_per_mm_edited(self, value: float) -> None:
        self._update_rpm()
        self.steps_per_mm_changed.emit(float(value))

    def _configure(self) -> None:
        if not self.isEnabled() or not self.configure_button.isEnabled():
            return
        settings = self.settings()
        log.debug("firmata configure: %s", settings)
        self.configure_requested.emit(
            settings["steps_per_rev"], settings["pins"], settings["steps_per_mm"]
        )
