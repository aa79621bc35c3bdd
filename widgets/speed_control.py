"""Speed slider and field, kept in sync; the device-reported speed beside them."""

from __future__ import annotations

import logging

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSlider,
    QVBoxLayout,
    QWidget,
)

from widgets._i18n import fill, number_text
from widgets._number_field import label_name, wheel_needs_focus
from widgets._units import INCH, MM, MM_PER_INCH, UnitSpinBox, check_units

log = logging.getLogger(__name__)

SLIDER_STEPS = 1000
EDGE = 3  # px around and between the rows: the panel fits a short column (1024×640)


def lead(note: str) -> str:
    """What the panel shows of a note on one line: its first clause (up to its first colon),
    else its first sentence, else all of it; the whole note is the tooltip."""
    for mark in (": ", ". "):
        first, found, rest = note.partition(mark)
        if found and first.strip() and rest.strip():
            return first.strip()
    return note


class SpeedControl(QWidget):
    """Slider + spin box, shown in mm/s or in/s (`set_units`) and always set, read and sent
    in mm/s; `speed_requested` (mm/s) on slider release, Enter or Apply only."""

    speed_requested = Signal(float)
    refused = Signal(str)  # why Apply (or Enter) sent nothing: the field's text cannot be used

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("speedControl")
        self._min, self._max = 0.0, 100.0
        self._units = MM
        self._reported: float | None = None
        self._fixed = ""  # why the speed cannot be set here ("" when it can)
        self._note = ""  # what setting the speed does on this device, in full

        label = QLabel(self.tr("Speed:"))
        label.setToolTip(self.tr("Speed of the next moves"))
        self.slider = QSlider(Qt.Orientation.Horizontal)
        self.slider.setObjectName("speedSlider")
        self.slider.setRange(0, SLIDER_STEPS)
        self.slider.setTracking(False)  # valueChanged on release, not on every drag tick
        self.slider.setMinimumWidth(120)
        wheel_needs_focus(self.slider)  # a wheel step would send a speed
        self.slider.sliderMoved.connect(self._slider_moved)
        self.slider.valueChanged.connect(self._slider_committed)

        self.spin = UnitSpinBox(per_second=True)
        self.spin.setObjectName("speedSpin")
        self.spin.set_what(label_name(label.text()))
        self.spin.set_mm_decimals(2)
        self.spin.setKeyboardTracking(False)
        self.spin.setMinimumWidth(100)
        self.spin.valueChanged.connect(self._spin_changed)
        self.spin.lineEdit().returnPressed.connect(self.apply)

        self.apply_button = QPushButton(self.tr("Apply"))
        self.apply_button.setObjectName("speedApply")
        self.apply_button.setToolTip(self.tr("Send the speed in the field to the device"))
        self.apply_button.clicked.connect(self.apply)

        self.reported_label = QLabel()
        self.reported_label.setObjectName("speedReported")
        self.reported_label.setToolTip(self.tr("The speed the device reports (it may round)"))
        self.reported_label.setMinimumWidth(110)
        self.set_reported(None)

        top = QHBoxLayout()
        top.addWidget(label)
        top.addWidget(self.slider, 1)
        bottom = QHBoxLayout()
        bottom.addWidget(self.spin)
        bottom.addWidget(self.apply_button)
        bottom.addWidget(self.reported_label, 1)
        self.note_label = QLabel()
        self.note_label.setObjectName("speedNote")
        self.note_label.setWordWrap(True)  # (a long first clause wraps in a narrow column)
        self.note_label.setStyleSheet("color: #616161;")
        self.note_label.setVisible(False)
        layout = QVBoxLayout(self)
        margins = layout.contentsMargins()
        layout.setContentsMargins(margins.left(), EDGE, margins.right(), EDGE)
        layout.setSpacing(EDGE)
        layout.addLayout(top)
        layout.addLayout(bottom)
        layout.addWidget(self.note_label)
        layout.addStretch(1)  # extra height goes below the panel, not between its rows
        label.setBuddy(self.spin)
        self.set_range(0.0, 100.0)

    # -- programmatic API (emits nothing) ------------------------------------------------

    def set_note(self, text: str) -> None:
        """Say what setting the speed does on this device (hidden when empty): its first clause
        under the field (`lead`; "…" when there is more), all of it as the tooltip."""
        self._note = text
        shown = lead(text)
        self.note_label.setText(shown if shown == text else f"{shown.rstrip('.')}…")
        self.note_label.setToolTip(text)
        self.note_label.setCursor(
            Qt.CursorShape.WhatsThisCursor if shown != text else Qt.CursorShape.ArrowCursor
        )
        self.note_label.setVisible(bool(text))
        tip = self.tr("Send the speed in the field to the device")
        self.apply_button.setToolTip(tip + (f"\n{text}" if text else ""))

    def set_fixed(self, reason: str) -> None:
        """The device sets its speed itself (`reason` says how; "" lifts it): the field, the
        slider and Apply are off, with the reason as their tooltip, and Apply sends nothing."""
        self._fixed = reason
        for widget in (self.spin, self.apply_button):
            widget.setEnabled(not reason)
        self.slider.setEnabled(not reason and self._max > self._min)
        if reason:
            for widget in (self.spin, self.slider, self.apply_button):
                widget.setToolTip(reason)
        else:
            self._range_tips()
            self.set_note(self._note)

    def note(self) -> str:
        """The note on what setting the speed does, in full ("" when none)."""
        return self._note

    def fixed(self) -> str:
        """Why the speed cannot be set on this device ("" when it can)."""
        return self._fixed

    def set_decimals(self, decimals: int) -> None:
        """The decimals the device takes (0: whole mm/s); in in/s, two more (at most 4), and
        the speed is sent rounded to the device's decimals."""
        self.spin.set_mm_decimals(decimals)
        self._range_tips()

    def problem(self) -> str:
        """Why the typed speed cannot be sent ("" when it can)."""
        return self.spin.problem()

    def value(self) -> float:
        """The speed in the field, in mm/s (the last usable one: see `problem()`)."""
        return self.spin.mm_value()

    def set_value(self, speed: float) -> None:
        """Show `speed` mm/s (clamped to the range) in the field and the slider; emits nothing."""
        self.spin.blockSignals(True)
        self.spin.set_mm_value(speed)
        self.spin.blockSignals(False)
        self._move_slider(self.value())

    def set_units(self, units: str) -> None:
        """Show speeds in mm/s ("mm") or in/s ("in"); what is sent stays in mm/s. Emits
        nothing."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        self.spin.set_units(units)
        self._range_tips()
        self.set_reported(self._reported)

    def units(self) -> str:
        """The length unit speeds are shown in: "mm" (mm/s) or "in" (in/s)."""
        return self._units

    def set_range(self, minimum: float, maximum: float) -> None:
        """Limit the speed to minimum..maximum mm/s; emits nothing."""
        if not minimum <= maximum:
            raise ValueError(f"empty speed range {minimum}..{maximum}")
        self._min, self._max = float(minimum), float(maximum)
        current = self.value()
        self.spin.blockSignals(True)
        self.spin.set_mm_range(self._min, self._max)
        step = (self._max - self._min) / 100.0
        self.spin.set_single_steps(max(step, 0.01), max(step / MM_PER_INCH, 0.0001))
        self.spin.blockSignals(False)
        self.slider.setEnabled(self._max > self._min and not self._fixed)
        self._range_tips()
        self.set_value(current)

    def _range_tips(self) -> None:
        """The field's and the slider's tooltips, with the range in the unit shown."""
        if self._fixed:
            return  # they say why the speed cannot be set
        if self._units == INCH:
            low, high = self.spin.range_texts()
            tip = self.tr("Speed, %1 to %2 in/s; press Enter or Apply to send")
            drag = self.tr("Drag and release to send (%1 to %2 in/s)")
        else:
            low, high = number_text(self._min, 6), number_text(self._max, 6)
            tip = self.tr("Speed, %1 to %2 mm/s; press Enter or Apply to send")
            drag = self.tr("Drag and release to send (%1 to %2 mm/s)")
        self.spin.setToolTip(fill(tip, low, high))
        self.slider.setToolTip(fill(drag, low, high))

    def speed_range(self) -> tuple[float, float]:
        """The (minimum, maximum) speed in mm/s."""
        return self._min, self._max

    def set_reported(self, speed: float | None) -> None:
        """Show the device-reported speed in mm/s, e.g. "device: 13 mm/s" (None: unknown);
        in in/s when speeds are shown in inches."""
        self._reported = speed
        if self._units == INCH:
            text = "—" if speed is None else number_text(speed / MM_PER_INCH, self.spin.decimals())
            self.reported_label.setText(fill(self.tr("device: %1 in/s"), text))
        else:
            text = "—" if speed is None else number_text(speed, 6)
            self.reported_label.setText(fill(self.tr("device: %1 mm/s"), text))

    # -- user actions --------------------------------------------------------------------

    def apply(self) -> None:
        """Send the speed in the field (what Enter and Apply do); if it cannot be used, say why
        (`refused`) and send nothing."""
        if self._fixed:
            self.refused.emit(fill(self.tr("%1; nothing sent"), self._fixed))
            return
        if self.problem():
            why = fill(self.tr("%1; nothing sent"), self.problem())
            log.info("speed refused: %s", why)
            self.refused.emit(why)
            return
        self.spin.interpretText()
        speed = self.value()
        log.debug("speed requested: %g mm/s", speed)
        self.speed_requested.emit(speed)

    def _to_slider(self, speed: float) -> int:
        span = self._max - self._min
        return 0 if span <= 0 else round((speed - self._min) / span * SLIDER_STEPS)

    def _from_slider(self, position: int) -> float:
        return self._min + (self._max - self._min) * position / SLIDER_STEPS

    def _move_slider(self, speed: float) -> None:
        self.slider.blockSignals(True)
        self.slider.setValue(self._to_slider(speed))
        self.slider.blockSignals(False)

    def _slider_moved(self, position: int) -> None:
        """While dragging: show the value, send nothing."""
        self.spin.blockSignals(True)
        self.spin.set_mm_value(self._from_slider(position))
        self.spin.blockSignals(False)

    def _slider_committed(self, position: int) -> None:
        """Released after a drag, or a click on the groove / a key on the slider: send."""
        self._slider_moved(position)
        self.apply()

    def _spin_changed(self, _shown: float) -> None:
        """Typed or stepped: move the slider along, send nothing until Enter or Apply."""
        self._move_slider(self.value())
