"""The serial port's control lines: DTR and RTS toggles, CTS/DSR/CD/RI indicators, a break."""

from __future__ import annotations

import logging

from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtWidgets import QCheckBox, QHBoxLayout, QLabel, QPushButton, QWidget

from widgets._i18n import fill

log = logging.getLogger(__name__)

ON, OFF, UNKNOWN = "on", "off", "unknown"
BREAK_MS = 250  # the break the worker sends (drivers.link.control_lines.BREAK_S)
LINES = ("dtr", "rts", "cts", "dsr", "cd", "ri")
UNKNOWN_MARK = "\N{EN DASH}"  # after the name of a line the port cannot report
# Off and unknown follow the palette (light or dark theme), their outline and text of a contrast
# with the window of 3:1 and more in both (palette(mid) was 1.1:1 on the dark window); on is
# always green.
_STYLE = {
    ON: "background: #2e7d32; color: white; border: 1px solid #1b5e20;",
    OFF: "background: palette(button); color: palette(button-text);"
    " border: 1px solid palette(placeholder-text);",
    UNKNOWN: "background: transparent; color: palette(placeholder-text);"
    " border: 1px dashed palette(placeholder-text);",
}
_INDICATOR_STYLE = "QLabel {{ {colours} border-radius: 3px; padding: 0px 3px; }}"


class ControlLinesBar(QWidget):
    """DTR and RTS checkboxes, CTS/DSR/CD/RI indicators and a Break button.

    `line_toggled(name, on)` ("dtr" or "rts") and `break_requested()` come from the user only;
    `set_lines` shows the lines as the port reports them, emitting nothing.
    """

    line_toggled = Signal(str, bool)
    break_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("controlLines")
        self._connected = False
        self._lines: object = None  # a ControlLines (attributes dtr ... ri: bool or None)
        self._names = {
            "dtr": self.tr("DTR"),
            "rts": self.tr("RTS"),
            "cts": self.tr("CTS"),
            "dsr": self.tr("DSR"),
            "cd": self.tr("CD"),
            "ri": self.tr("RI"),
        }
        self._descriptions = {
            "dtr": self.tr("Data Terminal Ready"),
            "rts": self.tr("Request To Send"),
            "cts": self.tr("Clear To Send"),
            "dsr": self.tr("Data Set Ready"),
            "cd": self.tr("Carrier Detect"),
            "ri": self.tr("Ring Indicator"),
        }

        self.dtr_toggle = QCheckBox(self._names["dtr"])
        self.dtr_toggle.setObjectName("dtrToggle")
        self.rts_toggle = QCheckBox(self._names["rts"])
        self.rts_toggle.setObjectName("rtsToggle")
        self.toggles = {"dtr": self.dtr_toggle, "rts": self.rts_toggle}
        for name, toggle in self.toggles.items():
            toggle.setFocusPolicy(Qt.FocusPolicy.TabFocus)  # a click leaves the jog keys alone
            # `clicked` comes from the user only (a click, the space bar), never from setChecked
            toggle.clicked.connect(lambda on, name=name: self.line_toggled.emit(name, bool(on)))

        self.cts_led = self._indicator("ctsLed", self._names["cts"])
        self.dsr_led = self._indicator("dsrLed", self._names["dsr"])
        self.cd_led = self._indicator("cdLed", self._names["cd"])
        self.ri_led = self._indicator("riLed", self._names["ri"])
        self.indicators = {
            "cts": self.cts_led,
            "dsr": self.dsr_led,
            "cd": self.cd_led,
            "ri": self.ri_led,
        }

        self.break_button = QPushButton(self.tr("Break"))
        self.break_button.setObjectName("breakButton")
        self.break_button.setAutoDefault(False)
        self.break_button.setFocusPolicy(Qt.FocusPolicy.TabFocus)
        self.break_button.setToolTip(
            fill(
                self.tr(
                    "Send a break: hold the transmit line low for %1 ms (the device sees a "
                    "framing error; some boards take it as a reset or attention signal)"
                ),
                BREAK_MS,
            )
        )
        self.break_button.clicked.connect(self.break_requested)

        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(4)
        layout.addWidget(self.dtr_toggle)
        layout.addWidget(self.rts_toggle)
        layout.addSpacing(6)
        for indicator in self.indicators.values():
            layout.addWidget(indicator)
        layout.addSpacing(6)
        layout.addWidget(self.break_button)
        self.setToolTip(self.tr("The serial port's control lines"))
        self.set_connected(False)

    def _indicator(self, object_name: str, text: str) -> QLabel:
        label = QLabel(text)
        label.setObjectName(object_name)
        label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        width = label.fontMetrics().horizontalAdvance(f"{text} {UNKNOWN_MARK}") + 10
        label.setFixedWidth(width)  # the same width whatever the state: nothing moves
        return label

    # -- state -----------------------------------------------------------------------------
    def set_connected(self, connected: bool) -> None:
        """Enable the controls while connected; when not, every line is shown as unknown (the
        lines last set are kept, and shown again on reconnection until new ones come)."""
        self._connected = connected
        self._show()

    def set_lines(self, lines: object) -> None:
        """Show the lines as the port reports them (None: it cannot tell); emits nothing."""
        self._lines = lines
        self._show()

    def lines(self) -> object:
        """The lines as last set."""
        return self._lines

    def indicator_state(self, name: str) -> str:
        """ "on", "off" or "unknown": how input `name` ("cts", "dsr", "cd", "ri") is shown."""
        return str(self.indicators[name].property("state"))

    def changeEvent(self, event: QEvent) -> None:
        """Recolour the indicators when the palette changes (a light or dark theme)."""
        super().changeEvent(event)
        if event.type() == QEvent.Type.PaletteChange:
            self._show()

    def _show(self) -> None:
        lines = self._lines
        for name, toggle in self.toggles.items():
            value = getattr(lines, name, None)
            label = self._names[name]
            toggle.blockSignals(True)
            try:
                toggle.setChecked(bool(value) and self._connected)
            finally:
                toggle.blockSignals(False)
            toggle.setEnabled(self._connected and value is not None)
            if not self._connected:
                tip = self.tr("%1 (%2): not connected")
            elif value is None:
                tip = self.tr("%1 (%2): this port cannot set %1")
            else:
                tip = self.tr(
                    "%1 (%2), driven by this computer: tick to assert it, untick to release it"
                )
            toggle.setToolTip(fill(tip, label, self._descriptions[name]))
        for name, indicator in self.indicators.items():
            value = getattr(lines, name, None)
            state = UNKNOWN if value is None or not self._connected else ON if value else OFF
            label = self._names[name]
            indicator.setProperty("state", state)
            indicator.setText(label if state != UNKNOWN else f"{label} {UNKNOWN_MARK}")
            indicator.setStyleSheet(_INDICATOR_STYLE.format(colours=_STYLE[state]))
            if not self._connected:
                tip = self.tr("%1 (%2): not connected")
            elif state == UNKNOWN:
                tip = self.tr("this port cannot report %1")
            elif state == ON:
                tip = self.tr("%1 (%2), driven by the device: on")
            else:
                tip = self.tr("%1 (%2), driven by the device: off")
            indicator.setToolTip(fill(tip, label, self._descriptions[name]))
        has_lines = any(getattr(lines, name, None) is not None for name in LINES)
        self.break_button.setEnabled(self._connected and has_lines)
