"""Port, protocol and baud rate, a connect/disconnect button, and the connection state; below
them, the port's control lines (DTR, RTS, CTS, DSR, CD, RI, a break)."""

from __future__ import annotations

import logging

from PySide6.QtCore import QT_TRANSLATE_NOOP, QEvent, QObject, QSize, Qt, Signal
from PySide6.QtGui import QIntValidator, QKeyEvent, QResizeEvent
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from widgets._i18n import fill
from widgets.control_lines_bar import ControlLinesBar

log = logging.getLogger(__name__)

COMMON_BAUDS = (
    9600, 19200, 38400, 57600, 115200, 230400, 250000, 460800, 500000, 921600, 1000000
)  # fmt: skip
DISCONNECTED, CONNECTING, CONNECTED, ERROR = "disconnected", "connecting", "connected", "error"
_STATE_STYLE = {
    # the texts are marked here and translated at use
    DISCONNECTED: (QT_TRANSLATE_NOOP("ConnectionBar", "Disconnected"), "#616161"),
    CONNECTING: (QT_TRANSLATE_NOOP("ConnectionBar", "Connecting…"), "#ef6c00"),
    CONNECTED: (QT_TRANSLATE_NOOP("ConnectionBar", "Connected"), "#2e7d32"),
    ERROR: (QT_TRANSLATE_NOOP("ConnectionBar", "Error"), "#c62828"),
}
DESCRIPTION_WIDTH = 120  # px, fixed: a longer description is elided (whole in the tooltip)
DESCRIPTION_MIN_WIDTH = 40  # px: narrower when the window is (a 1024 px screen, in Spanish)
STATE_MAX_WIDTH = 360  # px: a longer state text is elided (whole in the tooltip)
STATE_MIN_WIDTH = 110  # px: the state's word, at least


def sim_protocol(port: str) -> str:
    """The protocol a `sim://NAME` port names ("" for any other port)."""
    scheme, _, rest = port.strip().partition("://")
    if scheme.lower() != "sim":
        return ""
    return rest.split("?", 1)[0].split("/", 1)[0].lower()


def _restore_edit(edit: QLineEdit, text: str, cursor: int, start: int, length: int) -> None:
    """Put back a line edit's text, cursor and selection (e.g. an inline completion)."""
    if edit.text() != text:
        edit.setText(text)
    if length and cursor == start:
        edit.setSelection(start + length, -length)
    elif length:
        edit.setSelection(start, length)
    else:
        edit.setCursorPosition(cursor)


class ElidedLabel(QLabel):
    """A text elided to the label's width (whole in the tooltip): between `minimum` and
    `maximum` px wide, as wide as its text asks when there is room (`steady`: `maximum` whatever
    the text, so that the widgets after it stay put); narrower only when the window is."""

    def __init__(self, minimum: int, maximum: int, steady: bool = False) -> None:
        super().__init__()
        self.full = ""
        self.steady = steady
        self.setMinimumWidth(minimum)
        self.setMaximumWidth(maximum)

    def sizeHint(self) -> QSize:
        """The whole text's width (at most the maximum; `steady`: the maximum)."""
        text = self.fontMetrics().horizontalAdvance(self.full) + 8  # (room for rounding)
        width = self.maximumWidth() if self.steady else min(text, self.maximumWidth())
        return QSize(max(width, self.minimumWidth()), super().sizeHint().height())

    def minimumSizeHint(self) -> QSize:
        """The minimum width, whatever the text."""
        return QSize(self.minimumWidth(), super().minimumSizeHint().height())

    def set_full_text(self, text: str) -> None:
        """Show `text`, elided to the width the label gets for it (the maximum before a
        layout)."""
        self.full = text
        self.setText(self._elided(self.maximumWidth()))
        parent = self.parentWidget()
        if self.isVisible() and parent is not None and (layout := parent.layout()) is not None:
            layout.activate()  # (its new width now: the resize elides it again)
        self.setText(self._elided(self.width() if self.isVisible() else self.maximumWidth()))

    def _elided(self, width: int) -> str:
        return self.fontMetrics().elidedText(self.full, Qt.TextElideMode.ElideRight, width - 4)

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Elided again to the new width."""
        super().resizeEvent(event)
        self.setText(self._elided(self.width()))


class ConnectionBar(QWidget):
    """Choose where and how to connect; emits `connect_requested` / `disconnect_requested`.

    A second row holds `control_lines` (a ControlLinesBar: its signals are the window's to
    forward to the worker; it is enabled with `control_lines.set_connected`).
    """

    connect_requested = Signal(str, str, int)  # port (device or pyserial URL), protocol, baud
    disconnect_requested = Signal()
    refresh_requested = Signal()
    protocol_changed = Signal(str)
    variant_changed = Signal(str)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("connectionBar")
        self._state = DISCONNECTED
        self._descriptions: dict[str, str] = {}

        self.port_combo = QComboBox()
        self.port_combo.setObjectName("portCombo")
        self.port_combo.setEditable(True)
        self.port_combo.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
        self.port_combo.setMinimumContentsLength(13)
        self.port_combo.lineEdit().setPlaceholderText(self.tr("/dev/ttyUSB0, COM3 or a URL"))
        self.port_combo.setToolTip(
            self.tr(
                "Serial port, or any pyserial URL (e.g. sim://coxiris, socket://host:port, loop://)"
            )
        )
        self.port_combo.currentTextChanged.connect(self._port_text_changed)
        # Enter connects. An editable combo box keeps the keyboard focus itself, so a key from
        # the keyboard reaches the combo, not its line edit: the filter is on both, and the
        # first to see Return takes it (the line edit's returnPressed would come twice or never).
        self.port_combo.installEventFilter(self)
        self.port_combo.lineEdit().installEventFilter(self)
        self.description_label = ElidedLabel(DESCRIPTION_MIN_WIDTH, DESCRIPTION_WIDTH, steady=True)
        self.description_label.setObjectName("portDescription")
        self.description_label.setStyleSheet("color: #616161;")
        self.refresh_button = QPushButton("⟳")
        self.refresh_button.setObjectName("refreshPortsButton")
        self.refresh_button.setToolTip(self.tr("Look for serial ports again"))
        self.refresh_button.setMaximumWidth(36)
        self.refresh_button.clicked.connect(self.refresh_requested)

        self.protocol_combo = QComboBox()
        self.protocol_combo.setObjectName("protocolCombo")
        self.protocol_combo.setToolTip(self.tr("The language the device speaks"))
        self.protocol_combo.currentIndexChanged.connect(self._protocol_index_changed)
        self._quiet = False

        self.variant_label = QLabel(self.tr("Variant:"))
        self.variant_combo = QComboBox()
        self.variant_combo.setObjectName("variantCombo")
        self.variant_combo.setToolTip(
            self.tr("The wire variant of this protocol (packet format and rate)")
        )
        self.variant_combo.currentIndexChanged.connect(self._variant_index_changed)
        self.variant_label.setBuddy(self.variant_combo)

        self.baud_combo = QComboBox()
        self.baud_combo.setObjectName("baudCombo")
        self.baud_combo.setEditable(True)
        self.baud_combo.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
        self.baud_combo.addItems([str(b) for b in COMMON_BAUDS])
        self.baud_combo.setValidator(QIntValidator(1, 100_000_000, self))
        self.baud_combo.setToolTip(self.tr("Baud rate in bit/s (type any rate the device uses)"))
        self.baud_combo.setCurrentText("115200")

        self.bridge_check = QCheckBox(self.tr("Bridge"))
        self.bridge_check.setObjectName("bridgeCheck")
        self.bridge_check.setToolTip(
            self.tr(
                "Bridge (snoop) mode: open the device's port and offer another program a "
                "pseudo-terminal; every byte is forwarded both ways unchanged and shown decoded "
                "here (motion controls are off while bridging)"
            )
        )

        self.connect_button = QPushButton(self.tr("Connect"))
        self.connect_button.setObjectName("connectButton")
        self.connect_button.setAutoDefault(False)  # Enter in the port field is handled here
        metrics = self.connect_button.fontMetrics()
        widest = max(
            metrics.horizontalAdvance(t)
            for t in (self.tr("Connect"), self.tr("Cancel"), self.tr("Disconnect"))
        )
        self.connect_button.setMinimumWidth(max(96, widest + 24))
        self.connect_button.clicked.connect(self._connect_clicked)
        self.state_label = ElidedLabel(STATE_MIN_WIDTH, STATE_MAX_WIDTH)
        self.state_label.setObjectName("connectionState")

        self.control_lines = ControlLinesBar(self)
        self.control_lines_label = QLabel(self.tr("Lines:"))
        self.control_lines_label.setToolTip(self.control_lines.toolTip())

        rows = QVBoxLayout(self)
        rows.setSpacing(2)
        layout = QHBoxLayout()
        rows.addLayout(layout)
        lines_row = QHBoxLayout()
        lines_row.addWidget(self.control_lines_label)
        lines_row.addWidget(self.control_lines)
        lines_row.addStretch(1)
        rows.addLayout(lines_row)
        for text, widget in (
            (self.tr("&Port:"), self.port_combo),
            (None, self.description_label),
            (None, self.refresh_button),
            (self.tr("Protocol:"), self.protocol_combo),
            (self.tr("Baud:"), self.baud_combo),
            (None, self.bridge_check),
            (None, self.connect_button),
            # After Connect: shown for a protocol with variants, it moves nothing under the
            # pointer (before Baud, choosing Visiomex slid Connect away from it).
            (self.variant_label, self.variant_combo),
        ):
            if isinstance(text, QLabel):
                layout.addWidget(text)
            elif text:
                label = QLabel(text)
                label.setBuddy(widget)
                layout.addWidget(label)
            layout.addWidget(widget)
        self.set_variants([])
        layout.addStretch(1)
        layout.addWidget(self.state_label)  # after the stretch: its text never moves the rest
        self.set_state(DISCONNECTED)

    # -- ports ---------------------------------------------------------------------------

    def set_ports(self, ports: list[tuple[str, str]]) -> None:
        """List (device, description) pairs, keeping what is selected or typed as it is.

        The text (with any options, e.g. `sim://coxiris?mute=1`), the cursor and the selection
        (an inline completion) stay: this runs every few seconds, maybe while the user types.
        """
        combo, edit = self.port_combo, self.port_combo.lineEdit()
        self._descriptions = {device: description for device, description in ports}
        text, cursor = edit.text(), edit.cursorPosition()
        start, length = edit.selectionStart(), len(edit.selectedText())
        devices = [device for device, _ in ports]
        combo.blockSignals(True)
        try:
            rebuild = devices != [combo.itemText(i) for i in range(combo.count())]
            if rebuild:
                combo.clear()
                combo.addItems(devices)
            for index, (_, description) in enumerate(ports):
                if combo.itemData(index, Qt.ItemDataRole.ToolTipRole) != description:
                    combo.setItemData(index, description, Qt.ItemDataRole.ToolTipRole)
            index = combo.findText(text)
            if rebuild and index >= 0:
                combo.setCurrentIndex(index)
            # last: changing items resets the edit text to the current item's
            _restore_edit(edit, text, cursor, start, length)
        finally:
            combo.blockSignals(False)
        self._port_text_changed(self.port())

    def port(self) -> str:
        """The selected or typed port."""
        return self.port_combo.currentText().strip()

    def set_port(self, port: str) -> None:
        """Select or type a port."""
        self.port_combo.setCurrentText(port)

    def port_description(self, port: str) -> str:
        """The listed description of `port`, or of the port it adds options to ("" if none)."""
        port = port.strip()
        if port in self._descriptions:
            return self._descriptions[port]
        return self._descriptions.get(port.split("?", 1)[0], "")  # sim://coxiris?mute=1

    def _port_text_changed(self, text: str) -> None:
        named = sim_protocol(text)  # a simulated device speaks its own protocol
        index = self.protocol_combo.findText(named) if named else -1
        if index >= 0 and index != self.protocol_combo.currentIndex():
            self.protocol_combo.setCurrentIndex(index)  # protocol_changed: the window adapts
        description = self.port_description(text)
        label = self.description_label
        label.set_full_text(description)
        label.setToolTip(description or self.tr("No description for this port"))

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Enter (Return) in the port field connects, as the Connect button does, when idle."""
        if (
            watched in (self.port_combo, self.port_combo.lineEdit())
            and event.type() == QEvent.Type.KeyPress
            and isinstance(event, QKeyEvent)
            and event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter)
        ):
            if self._state in (DISCONNECTED, ERROR):
                self._connect_clicked()
            return True
        return super().eventFilter(watched, event)

    # -- protocol and baud ---------------------------------------------------------------

    def set_protocols(self, protocols: list[str]) -> None:
        """List the protocol names, keeping the selection if it is still there; emits nothing."""
        current = self.protocol()
        self._quiet = True
        try:
            self.protocol_combo.clear()
            self.protocol_combo.addItems(protocols)
            index = self.protocol_combo.findText(current)
            if index >= 0:
                self.protocol_combo.setCurrentIndex(index)
        finally:
            self._quiet = False

    def protocol(self) -> str:
        """The selected protocol name ("" when none)."""
        return self.protocol_combo.currentText()

    def set_protocol(self, name: str) -> bool:
        """Select a protocol, emitting nothing; False (selection kept) if it is not listed."""
        index = self.protocol_combo.findText(name)
        if index < 0:
            log.warning("unknown protocol %r, keeping %r", name, self.protocol())
            return False
        self._quiet = True
        try:
            self.protocol_combo.setCurrentIndex(index)
        finally:
            self._quiet = False
        return True

    def _protocol_index_changed(self, _index: int) -> None:
        if not self._quiet and self.protocol():
            self.protocol_changed.emit(self.protocol())

    def set_variants(self, variants: list[tuple[str, str]], current: str = "") -> None:
        """List a protocol's wire variants as (name, description); hidden when it has none."""
        self._quiet = True
        try:
            self.variant_combo.clear()
            for name, description in variants:
                self.variant_combo.addItem(name, name)
                self.variant_combo.setItemData(
                    self.variant_combo.count() - 1, description, Qt.ItemDataRole.ToolTipRole
                )
            index = self.variant_combo.findData(current) if current else 0
            self.variant_combo.setCurrentIndex(max(index, 0))
        finally:
            self._quiet = False
        for widget in (self.variant_label, self.variant_combo):
            widget.setVisible(bool(variants))

    def variant(self) -> str:
        """The selected wire variant ("" when the protocol has none)."""
        data = self.variant_combo.currentData()
        return data if isinstance(data, str) else ""

    def _variant_index_changed(self, _index: int) -> None:
        if not self._quiet and self.variant():
            self.variant_changed.emit(self.variant())

    def baud(self) -> int | None:
        """The baud rate, or None when what is typed is not a positive whole number."""
        text = self.baud_combo.currentText().strip()
        return int(text) if text.isdigit() and int(text) > 0 else None

    def set_baud(self, baud: int) -> bool:
        """Show a baud rate (any positive one, not only the common ones); False if not positive."""
        if baud <= 0:
            log.warning("ignoring baud rate %r", baud)
            return False
        self.baud_combo.setCurrentText(str(int(baud)))
        return True

    # -- state ---------------------------------------------------------------------------

    def bridge_mode(self) -> bool:
        """Whether Connect starts a bridge for another program instead of a connection."""
        return self.bridge_check.isChecked()

    def set_bridge_mode(self, on: bool) -> None:
        """Choose bridge mode (or the normal connection)."""
        self.bridge_check.setChecked(on)

    def state(self) -> str:
        """The state: "disconnected", "connecting", "connected" or "error"."""
        return self._state

    def set_state(self, state: str, detail: str = "") -> None:
        """Show the connection state (with an optional detail, e.g. the error message)."""
        if state not in _STATE_STYLE:
            raise ValueError(f"unknown state {state!r}: one of {sorted(_STATE_STYLE)}")
        self._state = state
        name, colour = _STATE_STYLE[state]
        text = self.tr(name)
        full = fill(self.tr("● %1: %2"), text, detail) if detail else f"● {text}"
        self.state_label.setStyleSheet(f"color: {colour}; font-weight: bold;")
        self.state_label.ensurePolished()  # (elided in the bold font)
        self.state_label.set_full_text(full)  # elided, never clipped; the window not widened
        self.state_label.setToolTip(detail or text)
        idle = state in (DISCONNECTED, ERROR)
        for widget in (
            self.port_combo,
            self.protocol_combo,
            self.variant_combo,
            self.baud_combo,
            self.refresh_button,
            self.bridge_check,
        ):
            widget.setEnabled(idle)
        button_text = {CONNECTING: self.tr("Cancel"), CONNECTED: self.tr("Disconnect")}.get(
            state, self.tr("Connect")
        )
        self.connect_button.setText(button_text)
        self.connect_button.setToolTip(
            self.tr("Open the port and talk to the device")
            if idle
            else self.tr("Close the connection")
        )

    def _connect_clicked(self) -> None:
        if self._state in (CONNECTING, CONNECTED):
            self.disconnect_requested.emit()
            return
        port, protocol, baud = self.port(), self.protocol(), self.baud()
        problem = (
            self.tr("choose or type a port") if not port
            else self.tr("choose a protocol") if not protocol
            else self.tr("the baud rate must be a positive whole number") if baud is None
            else ""
        )  # fmt: skip
        if problem:
            self.set_state(ERROR, problem)
            return
        log.debug("connect requested: %s %s %d", port, protocol, baud)
        self.connect_requested.emit(port, protocol, baud)
