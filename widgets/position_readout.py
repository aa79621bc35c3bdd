"""Large X/Y/Z position labels, and whether the position is measured or only commanded."""

from __future__ import annotations

from collections.abc import Iterable

from PySide6.QtCore import Qt
from PySide6.QtGui import QFont, QFontDatabase
from PySide6.QtWidgets import QGridLayout, QLabel, QSizePolicy, QVBoxLayout, QWidget

from widgets._axes import AXES, decimals_for, normalize_axes

UNKNOWN = "—"
NOT_MEASURED_TEXT = "commanded, not measured"
CONFIRMED_TEXT = "commanded, move confirmed"
COMMANDED_TIP = "This device does not report its position: the numbers are where it was told to go."
CONFIRMED_TIP = (
    "Where the device was told to go, and its reply said the move ended there; not read back "
    "(a device that can report its position is asked again when idle)."
)
LIVE, ESTIMATED, STALE, LOST = "live", "estimated", "stale", "lost"
_STATUS = {
    LOST: (
        "position unknown: the link failed or the device restarted, and it cannot report "
        "where it is; home it or set home",
        "color: #b71c1c; background: #ffebee; border: 1px solid #ef9a9a;",
        "color: #9e9e9e;",
    ),
    ESTIMATED: (
        "estimated from the speed: the device cannot be asked while it moves",
        "color: #0d47a1; background: #e3f2fd; border: 1px solid #90caf9;",
        "color: #1565c0; font-style: italic;",
    ),
    STALE: (
        "last known position: not connected",
        "color: #616161; background: #eeeeee; border: 1px solid #bdbdbd;",
        "color: #9e9e9e;",
    ),
}


class PositionReadout(QWidget):
    """Shows the stage position as "12.34 mm" per axis, in a large fixed-width font."""

    def __init__(self, parent: QWidget | None = None, decimals: int = 2) -> None:
        super().__init__(parent)
        self.setObjectName("positionReadout")
        self.setToolTip("Stage position in mm from home")
        self._decimals = decimals
        self._axes = frozenset(AXES)
        self._position: tuple[float, float, float] | None = None
        self._status = LIVE

        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        font.setPointSizeF(max(font.pointSizeF(), 9.0) * 2.0)
        font.setWeight(QFont.Weight.Bold)
        name_font = QFont(font)
        name_font.setWeight(QFont.Weight.Normal)

        grid = QGridLayout()
        grid.setHorizontalSpacing(12)
        self.labels: dict[str, QLabel] = {}
        self.names: dict[str, QLabel] = {}
        for row, axis in enumerate(AXES):
            name = QLabel(f"{axis.upper()}")
            name.setFont(name_font)
            value = QLabel()
            value.setObjectName(f"position{axis.upper()}")
            value.setFont(font)
            value.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            value.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
            value.setMinimumWidth(value.fontMetrics().horizontalAdvance("-0000.000 mm"))
            grid.addWidget(name, row, 0)
            grid.addWidget(value, row, 1)
            self.labels[axis] = value
            self.names[axis] = name
        grid.setColumnStretch(1, 1)

        self.measured_label = QLabel(NOT_MEASURED_TEXT)
        self.measured_label.setObjectName("positionNotMeasured")
        self.measured_label.setToolTip(COMMANDED_TIP)
        self.measured_label.setStyleSheet(
            "color: #8a4b00; background: #fff3cd; border: 1px solid #e0b44c;"
            " border-radius: 3px; padding: 2px 6px;"
        )
        self.measured_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.measured_label.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Maximum)
        self.measured_label.setVisible(False)

        self.status_label = QLabel()
        self.status_label.setObjectName("positionStatus")
        self.status_label.setWordWrap(True)
        self.status_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.status_label.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Maximum)
        self.status_label.setVisible(False)

        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addWidget(self.measured_label)
        layout.addWidget(self.status_label)
        self._render_status()
        self._render()

    def set_status(self, status: str) -> None:
        """`"live"` (measured or commanded), `"estimated"` (moving) or `"stale"` (last known)."""
        if status not in _STATUS and status != LIVE:
            raise ValueError(f"status must be live, estimated, stale or lost, not {status!r}")
        if status != self._status:
            self._status = status
            self._render_status()

    def status(self) -> str:
        """The status shown: live, estimated, stale or lost."""
        return self._status

    def set_position(self, x: float, y: float, z: float) -> None:
        """Show a position in mm."""
        self._position = (float(x), float(y), float(z))
        self._render()

    def clear(self) -> None:
        """Show no position (unknown, e.g. disconnected)."""
        self._position = None
        self._render()

    def position(self) -> tuple[float, float, float] | None:
        """The position last shown, or None."""
        return self._position

    def set_measured(self, measured: bool, confirmed: bool | None = None) -> None:
        """False: the position is only commanded; say so visibly, and whether the device
        confirmed reaching it (`confirmed`: None where the device never says)."""
        self.measured_label.setVisible(not measured)
        if confirmed:
            text, tip = CONFIRMED_TEXT, CONFIRMED_TIP
        else:
            text, tip = NOT_MEASURED_TEXT, COMMANDED_TIP
        if self.measured_label.text() != text:
            self.measured_label.setText(text)
            self.measured_label.setToolTip(tip)

    def is_measured(self) -> bool:
        """Whether the position is shown as measured."""
        return self.measured_label.isHidden()

    def set_resolution(self, resolution: float | None) -> None:
        """Show as many decimals as the device resolves (0.01 mm: 2; 1 µm: 3; 1 mm: 0)."""
        decimals = 2 if resolution is None else decimals_for(resolution)
        if decimals != self._decimals:
            self._decimals = decimals
            self._render()

    def set_axes_enabled(self, axes: Iterable[str]) -> None:
        """Grey out the axes the device lacks."""
        self._axes = normalize_axes(axes)
        self._render()

    def text(self, axis: str) -> str:
        """The text shown for one axis, e.g. "12.34 mm"."""
        return self.labels[axis.lower()].text()

    def _render_status(self) -> None:
        """The badge and the values' style (style sheets are costly: only when it changes)."""
        text, badge, value_style = _STATUS.get(self._status, ("", "", ""))
        self.status_label.setText(text)
        self.status_label.setStyleSheet(f"{badge} border-radius: 3px; padding: 2px 6px;")
        self.status_label.setVisible(bool(text))
        for label in self.labels.values():
            label.setStyleSheet(value_style)

    def _render(self) -> None:
        for index, axis in enumerate(AXES):
            label = self.labels[axis]
            enabled = axis in self._axes
            label.setEnabled(enabled)
            label.setVisible(enabled)  # a device without the axis: its row is not shown
            self.names[axis].setVisible(enabled)
            if not enabled:
                label.setText(f"{UNKNOWN} mm")
                label.setToolTip(f"This device has no {axis.upper()} axis")
            elif self._position is None:
                label.setText(f"{UNKNOWN} mm")
                label.setToolTip("Position unknown")
            else:
                label.setText(f"{self._position[index]:.{self._decimals}f} mm")
                label.setToolTip(f"{axis.upper()} position in mm from home")
