"""Pause the device for a number of milliseconds (a dwell)."""

from __future__ import annotations

import logging

from PySide6.QtCore import Signal
from PySide6.QtWidgets import QHBoxLayout, QLabel, QWidget

from widgets._buttons import make_button
from widgets._i18n import fill
from widgets._number_field import WholeSpinBox, label_name

log = logging.getLogger(__name__)

MAX_DWELL_MS = 65535


class DwellEntry(QWidget):
    """A milliseconds field and a Dwell button; `dwell_requested(ms)` on the button or Enter."""

    dwell_requested = Signal(int)
    refused = Signal(str)  # why Dwell (or Enter) sent nothing: the field's text cannot be used

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dwellEntry")
        label = QLabel(self.tr("Dwell:"))
        self.spin = WholeSpinBox()
        self.spin.setObjectName("dwellMs")
        self.spin.set_what(label_name(label.text()))
        self.spin.setRange(0, MAX_DWELL_MS)
        self.spin.setSuffix(" ms")
        self.spin.setValue(500)
        self.spin.setSingleStep(100)
        self.spin.setAccelerated(True)
        self.spin.setMinimumWidth(100)
        self.spin.setToolTip(
            fill(
                self.tr("How long the device waits, 0 to %1 ms; press Enter or Dwell to send"),
                MAX_DWELL_MS,
            )
        )
        self.spin.lineEdit().returnPressed.connect(self._dwell)
        label.setBuddy(self.spin)
        label.setToolTip(self.spin.toolTip())
        self.dwell_button = make_button(
            self.tr("Dwell"),
            "dwellButton",
            self.tr("Make the device wait this long before its next command"),
        )
        self.dwell_button.clicked.connect(self._dwell)
        layout = QHBoxLayout(self)
        layout.addWidget(label)
        layout.addWidget(self.spin, 1)
        layout.addWidget(self.dwell_button)
        QWidget.setTabOrder(self.spin, self.dwell_button)

    def problem(self) -> str:
        """Why the typed dwell cannot be sent ("" when it can)."""
        return self.spin.problem()

    def value(self) -> int:
        """The dwell in the field, in ms (the last usable one: see `problem()`)."""
        self.spin.interpretText()
        return int(self.spin.value())

    def set_value(self, ms: int) -> None:
        """Fill the field (clamped to 0..65535 ms); emits nothing."""
        self.spin.setValue(int(ms))

    def _dwell(self) -> None:
        if not self.isEnabled() or not self.dwell_button.isEnabled():
            return
        if self.problem():
            why = fill(self.tr("%1; nothing sent"), self.problem())
            log.info("dwell refused: %s", why)
            self.refused.emit(why)
            return
        ms = self.value()
        log.debug("dwell requested: %d ms", ms)
        self.dwell_requested.emit(ms)
