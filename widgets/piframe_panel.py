"""Settings and state of a PI frame: ticks per mm, the DTR line, the reachable range."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, Signal
from PySide6.QtWidgets import (
    QDoubleSpinBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QWidget,
)

from widgets._number_field import wheel_needs_focus

DTR_TEXT = {  # translated at use
    True: QT_TRANSLATE_NOOP("PiFramePanel", "DTR on"),
    False: QT_TRANSLATE_NOOP("PiFramePanel", "DTR off"),
    None: QT_TRANSLATE_NOOP("PiFramePanel", "DTR unknown"),
}


class PiFramePanel(QWidget):
    """Ticks per mm (`ticks_per_mm_changed` on edits), the DTR state and the reachable range."""

    ticks_per_mm_changed = Signal(float)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("piFramePanel")
        self._dtr: bool | None = None

        self.ticks_spin = QDoubleSpinBox()
        self.ticks_spin.setObjectName("piFrameTicksPerMm")
        self.ticks_spin.setDecimals(3)
        self.ticks_spin.setRange(0.001, 1_000_000.0)
        self.ticks_spin.setValue(100.0)
        self.ticks_spin.setSuffix(" ticks/mm")
        self.ticks_spin.setKeyboardTracking(False)
        wheel_needs_focus(self.ticks_spin)
        self.ticks_spin.setAccelerated(True)
        self.ticks_spin.setMinimumWidth(130)
        self.ticks_spin.setToolTip(
            self.tr(
                "Encoder ticks per mm of travel (more than 0): converts the frame's ticks to mm"
            )
        )
        self.ticks_spin.valueChanged.connect(self._ticks_changed)

        self.dtr_label = QLabel()
        self.dtr_label.setObjectName("piFrameDtr")
        self.dtr_label.setToolTip(
            self.tr("The state of the serial DTR line, which powers the frame")
        )

        self.range_line = QLineEdit()
        self.range_line.setObjectName("piFrameRange")
        self.range_line.setReadOnly(True)
        self.range_line.setToolTip(
            self.tr("The range the frame can reach, from its travel and ticks/mm")
        )
        self.range_line.setPlaceholderText(self.tr("unknown"))

        form = QFormLayout(self)
        form.addRow(self.tr("Ticks per mm:"), self.ticks_spin)
        form.addRow(self.tr("DTR:"), self.dtr_label)
        form.addRow(self.tr("Reachable:"), self.range_line)
        for row in range(form.rowCount()):
            label = form.itemAt(row, QFormLayout.ItemRole.LabelRole).widget()
            field = form.itemAt(row, QFormLayout.ItemRole.FieldRole).widget()
            label.setToolTip(field.toolTip())
        QWidget.setTabOrder(self.ticks_spin, self.range_line)
        self.set_dtr(None)

    def ticks_per_mm(self) -> float:
        """Ticks per mm in the field."""
        return float(self.ticks_spin.value())

    def set_ticks_per_mm(self, value: float) -> None:
        """Show ticks per mm (must be more than 0); emits nothing."""
        if not value > 0:
            raise ValueError(f"ticks per mm must be more than 0, not {value!r}")
        self.ticks_spin.blockSignals(True)
        self.ticks_spin.setValue(float(value))
        self.ticks_spin.blockSignals(False)

    def set_dtr(self, on: bool | None) -> None:
        """Show "DTR on", "DTR off" or "DTR unknown" (None)."""
        self._dtr = None if on is None else bool(on)
        self.dtr_label.setText(self.tr(DTR_TEXT[self._dtr]))

    def dtr(self) -> bool | None:
        """The DTR state shown."""
        return self._dtr

    def set_range_text(self, text: str) -> None:
        """Say what range the frame can reach, e.g. "X 0 to 120 mm, Y 0 to 80 mm"."""
        self.range_line.setText(text)
        self.range_line.setCursorPosition(0)

    def range_text(self) -> str:
        """The reachable range shown."""
        return self.range_line.text()

    def _ticks_changed(self, value: float) -> None:
        self.ticks_per_mm_changed.emit(float(value))
