"""The status bar's contents: the machine state once, and the last message once."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, Qt
from PySide6.QtWidgets import QHBoxLayout, QLabel, QSizePolicy, QWidget

DISCONNECTED, CONNECTING, IDLE, MOVING, BUSY, PAUSED, ERROR = (
    "disconnected",
    "connecting",
    "idle",
    "moving",
    "busy",
    "paused",
    "error",
)
_STATES = {  # text and tooltip translated at use, in the StatusLine context
    DISCONNECTED: (
        QT_TRANSLATE_NOOP("StatusLine", "Disconnected"),
        "#616161",
        QT_TRANSLATE_NOOP("StatusLine", "No device is connected"),
    ),
    CONNECTING: (
        QT_TRANSLATE_NOOP("StatusLine", "Connecting…"),
        "#ef6c00",
        QT_TRANSLATE_NOOP("StatusLine", "Opening the port and asking the device who it is"),
    ),
    IDLE: (
        QT_TRANSLATE_NOOP("StatusLine", "Idle"),
        "#2e7d32",
        QT_TRANSLATE_NOOP("StatusLine", "Connected and not moving"),
    ),
    MOVING: (
        QT_TRANSLATE_NOOP("StatusLine", "Moving"),
        "#1565c0",
        QT_TRANSLATE_NOOP("StatusLine", "A move is under way"),
    ),
    BUSY: (
        QT_TRANSLATE_NOOP("StatusLine", "Busy"),
        "#6a1b9a",
        QT_TRANSLATE_NOOP("StatusLine", "A command is under way"),
    ),
    PAUSED: (
        QT_TRANSLATE_NOOP("StatusLine", "Paused"),
        "#8d6e63",
        QT_TRANSLATE_NOOP(
            "StatusLine", "A program is paused: nothing more of it is sent until Resume"
        ),
    ),
    ERROR: (
        QT_TRANSLATE_NOOP("StatusLine", "Error"),
        "#c62828",
        QT_TRANSLATE_NOOP("StatusLine", "The last command failed, or the connection did"),
    ),
}
INFO, WARNING, FAILURE = "info", "warning", "error"
# An information message in the theme's own text colour (dark #212121 was unreadable on dark).
_MESSAGE_COLOURS = {INFO: "palette(window-text)", WARNING: "#8a4b00", FAILURE: "#c62828"}


class StatusLine(QWidget):
    """A coloured machine-state badge and one message label; nothing overlaps, nothing repeats."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("statusLine")
        self.state_label = QLabel()
        self.state_label.setObjectName("machineState")
        self.state_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.state_label.setMinimumWidth(
            self.fontMetrics().horizontalAdvance("● " + self.tr("Connecting…")) + 24
        )
        self.message_label = QLabel()
        self.message_label.setObjectName("statusMessage")
        self.message_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.message_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(2, 0, 2, 0)
        layout.addWidget(self.state_label)
        layout.addWidget(self.message_label, 1)
        self._state = ""
        self._message = ""
        self._kind = INFO
        self.set_state(DISCONNECTED)

    def set_state(self, state: str, detail: str = "") -> None:
        """Show the machine state (disconnected, connecting, idle, moving, busy, paused or
        error)."""
        if state not in _STATES:
            raise ValueError(f"unknown machine state {state!r}: one of {sorted(_STATES)}")
        text, colour, tip = _STATES[state]
        self.state_label.setToolTip(detail or self.tr(tip))
        if state == self._state:
            return  # style sheets are costly: restyle only on a change
        self._state = state
        self.state_label.setText(f"● {self.tr(text)}")
        self.state_label.setStyleSheet(
            f"color: white; background: {colour}; border-radius: 3px; padding: 1px 8px;"
            " font-weight: bold;"
        )

    def state(self) -> str:
        """The machine state shown."""
        return self._state

    def show_message(self, text: str, kind: str = INFO) -> None:
        """Replace the message (info, warning or error); the full text is in the tooltip."""
        if kind not in _MESSAGE_COLOURS:
            raise ValueError(f"unknown message kind {kind!r}")
        restyle = kind != self._kind or not self.message_label.styleSheet()
        self._message, self._kind = text, kind
        metrics = self.message_label.fontMetrics()
        width = max(self.message_label.width(), 200)
        self.message_label.setText(metrics.elidedText(text, Qt.TextElideMode.ElideRight, width))
        self.message_label.setToolTip(text)
        if restyle:  # style sheets are costly: only when the kind changes
            weight = "bold" if kind == FAILURE else "normal"
            colour = _MESSAGE_COLOURS[kind]
            self.message_label.setStyleSheet(f"color: {colour}; font-weight: {weight};")

    def clear_error(self) -> None:
        """Clear the message if it is an error (the next command succeeded)."""
        if self._kind == FAILURE:
            self.show_message("")

    def message(self) -> str:
        """The whole message shown (not elided)."""
        return self._message

    def message_kind(self) -> str:
        """info, warning or error."""
        return self._kind

    def resizeEvent(self, event: object) -> None:  # type: ignore[override]
        """Elide the message again to the new width."""
        super().resizeEvent(event)  # type: ignore[arg-type]
        self.show_message(self._message, self._kind)
