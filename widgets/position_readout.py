"""Large X/Y/Z position labels, and whether the position is measured or only commanded."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from PySide6.QtCore import QT_TRANSLATE_NOOP, QLocale, Qt, Signal
from PySide6.QtGui import QColor, QFont, QFontDatabase, QPalette
from PySide6.QtWidgets import (
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QSizePolicy,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, decimals_for, normalize_axes
from widgets._i18n import fill, number_text
from widgets._units import INCH, MM, MM_PER_INCH, check_units

UNKNOWN = "—"
# Translated at use, in the PositionReadout context.
NOT_MEASURED_TEXT = QT_TRANSLATE_NOOP("PositionReadout", "commanded, not measured")
CONFIRMED_TEXT = QT_TRANSLATE_NOOP("PositionReadout", "commanded, move confirmed")
COMMANDED_TIP = QT_TRANSLATE_NOOP(
    "PositionReadout",
    "This device does not report its position: the numbers are where it was told to go.",
)
CONFIRMED_TIP = QT_TRANSLATE_NOOP(
    "PositionReadout",
    "Where the device was told to go, and its reply said the move ended there; not read back "
    "(a device that can report its position is asked again when idle).",
)
LIVE, ESTIMATED, STALE, LOST = "live", "estimated", "stale", "lost"
LOST_MOVING = "lost-moving"  # the link went during a move: the estimate at that moment
UNCOUNTED = "uncounted"  # a fresh connection to a device that cannot be asked: nothing counted
# Bridging: the panel asks nothing; what another program's traffic with the device told.
BRIDGED = "bridged"  # nothing told yet
OBSERVED = "observed"  # the device's reply to the other program reported it
OBSERVED_TARGET = "observed-target"  # the target of a move the other program sent
_OBSERVED_STYLE = "color: #1b5e20; background: #e8f5e9; border: 1px solid #a5d6a7;"
_STATUS = {
    UNCOUNTED: (
        QT_TRANSLATE_NOOP(
            "PositionReadout",
            "position unknown: the device cannot be asked; Home or Set Home to start counting",
        ),
        "color: #b71c1c; background: #ffebee; border: 1px solid #ef9a9a;",
        ("#9e9e9e", False),
    ),
    LOST: (
        QT_TRANSLATE_NOOP(
            "PositionReadout",
            "position unknown: the link failed or the device restarted, and it cannot report "
            "where it is; home it or set home",
        ),
        "color: #b71c1c; background: #ffebee; border: 1px solid #ef9a9a;",
        ("#9e9e9e", False),
    ),
    ESTIMATED: (
        QT_TRANSLATE_NOOP(
            "PositionReadout", "estimated from the speed: the device cannot be asked while it moves"
        ),
        "color: #0d47a1; background: #e3f2fd; border: 1px solid #90caf9;",
        ("#1565c0", True),
    ),
    LOST_MOVING: (
        QT_TRANSLATE_NOOP(
            "PositionReadout",
            "estimated when the link was lost, during a move: somewhere between its start and "
            "its target; not connected",
        ),
        "color: #0d47a1; background: #eeeeee; border: 1px solid #90caf9;",
        ("#5c7fa3", True),
    ),
    BRIDGED: (
        QT_TRANSLATE_NOOP(
            "PositionReadout",
            "bridging: no position seen in the bridged traffic yet (the panel asks nothing)",
        ),
        _OBSERVED_STYLE,
        ("#9e9e9e", False),
    ),
    OBSERVED: (
        QT_TRANSLATE_NOOP(
            "PositionReadout",
            "observed in the bridged traffic: the device reported this position to the other "
            "program",
        ),
        _OBSERVED_STYLE,
        ("#2e7d32", False),
    ),
    OBSERVED_TARGET: (
        QT_TRANSLATE_NOOP(
            "PositionReadout",
            "observed in the bridged traffic: the target of a move the other program sent, "
            "not confirmed by the device",
        ),
        _OBSERVED_STYLE,
        ("#2e7d32", True),
    ),
    STALE: (
        QT_TRANSLATE_NOOP("PositionReadout", "last known position: not connected"),
        "color: #616161; background: #eeeeee; border: 1px solid #bdbdbd;",
        ("#9e9e9e", False),
    ),
}


class PositionReadout(QWidget):
    """Shows the stage position as "12.34 mm" per axis, in a large fixed-width font: in machine
    coordinates (from the device's home) and in work coordinates (from the panel's work zero),
    with a Zero button per axis; `zero_requested(axes)`, `clear_zero_requested()`."""

    zero_requested = Signal(str)  # "x", "y", "z" or "xyz"
    clear_zero_requested = Signal()
    shown_changed = Signal()  # the position, units or status shown changed

    def __init__(self, parent: QWidget | None = None, decimals: int = 2) -> None:
        super().__init__(parent)
        self.setObjectName("positionReadout")
        self._decimals = decimals
        self._axes = frozenset(AXES)
        self._position: tuple[float, float, float] | None = None
        self._zero: tuple[float, float, float] = (0.0, 0.0, 0.0)
        self._units = MM
        self._fixed_decimals = -1
        self._resolution: float | None = None
        self._status = LIVE
        self._measured = True

        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        font.setPointSizeF(max(font.pointSizeF(), 9.0) * 2.0)
        font.setWeight(QFont.Weight.Bold)
        name_font = QFont(font)
        name_font.setWeight(QFont.Weight.Normal)

        work_font = QFont(font)
        work_font.setPointSizeF(font.pointSizeF() * 0.7)
        grid = QGridLayout()
        grid.setHorizontalSpacing(12)
        self.machine_header = QLabel(self.tr("Machine"))
        self.machine_header.setObjectName("machineFrameHeader")
        self.machine_header.setToolTip(self.tr("Distances from the device's home (its origin)"))
        self.work_header = QLabel(self.tr("Work"))
        self.work_header.setObjectName("workFrameHeader")
        self.work_header.setToolTip(
            self.tr("Distances from the work zero the panel keeps (the device is not told)")
        )
        for header in (self.machine_header, self.work_header):
            header.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignBottom)
        grid.addWidget(self.machine_header, 0, 1)
        grid.addWidget(self.work_header, 0, 2)
        self.labels: dict[str, QLabel] = {}
        self.work_labels: dict[str, QLabel] = {}
        self.names: dict[str, QLabel] = {}
        self.zero_buttons: dict[str, QToolButton] = {}
        for row, axis in enumerate(AXES, start=1):
            name = QLabel(f"{axis.upper()}")
            name.setFont(name_font)
            value = self._value_label(f"position{axis.upper()}", font)
            work = self._value_label(f"work{axis.upper()}", work_font)
            zero = QToolButton()
            zero.setText(self.tr("Zero %1").replace("%1", axis.upper()))
            zero.setObjectName(f"zero{axis.upper()}")
            zero.setToolTip(
                self.tr(
                    "Make the current %1 the work zero (0 mm in the work frame); the device "
                    "is not told, and its home stays where it is"
                ).replace("%1", axis.upper())
            )
            zero.clicked.connect(self._zero_clicked)
            zero.setProperty("axis", axis)
            grid.addWidget(name, row, 0)
            grid.addWidget(value, row, 1)
            grid.addWidget(work, row, 2)
            self.labels[axis] = value
            self.work_labels[axis] = work
            self.names[axis] = name
            self.zero_buttons[axis] = zero
        grid.setColumnStretch(1, 1)
        grid.setColumnStretch(2, 1)
        self.zero_all_button = QToolButton()
        self.zero_all_button.setText(self.tr("Zero all"))
        self.zero_all_button.setObjectName("zeroAll")
        self.zero_all_button.setToolTip(self.tr("Make the current position the work zero"))
        self.zero_all_button.clicked.connect(self._zero_all_clicked)
        self.clear_zero_button = QToolButton()
        self.clear_zero_button.setText(self.tr("Clear zero"))
        self.clear_zero_button.setObjectName("clearWorkZero")
        self.clear_zero_button.setToolTip(
            self.tr("Put the work zero back at the device's home (work = machine)")
        )
        self.clear_zero_button.clicked.connect(self.clear_zero_requested)
        self.zero_label = QLabel()
        self.zero_label.setObjectName("workZeroText")
        # Under the numbers, so the panel is no wider for them: Zero X, Y, Z, all, clear.
        zeros = QHBoxLayout()
        for axis in AXES:
            zeros.addWidget(self.zero_buttons[axis])
        zeros.addWidget(self.zero_all_button)
        zeros.addWidget(self.clear_zero_button)
        zeros.addStretch(1)
        self.set_zero_enabled(False)

        self.measured_label = QLabel(self.tr(NOT_MEASURED_TEXT))
        self.measured_label.setObjectName("positionNotMeasured")
        self.measured_label.setToolTip(self.tr(COMMANDED_TIP))
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

        self.outside_label = QLabel()
        self.outside_label.setObjectName("positionOutsideTravel")
        self.outside_label.setWordWrap(True)
        self.outside_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.outside_label.setStyleSheet(
            "color: #b71c1c; background: #fff3e0; border: 1px solid #ef6c00;"
            " border-radius: 3px; padding: 2px 6px;"
        )
        self.outside_label.setToolTip(
            self.tr(
                "The stage is outside the travel limits set for this device: only moves that "
                "bring it closer to them are sent, until it is back inside"
            )
        )
        self.outside_label.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Maximum)
        self.outside_label.setVisible(False)
        self._outside: list[tuple[str, float, float, float]] = []

        layout = QVBoxLayout(self)
        layout.addWidget(self.outside_label)  # first: seen even where the panel scrolls
        layout.addLayout(grid)
        layout.addWidget(self.zero_label)
        layout.addLayout(zeros)
        # One place for the badges, as tall as the tallest shown so far: a move's estimate
        # replacing "commanded" does not make the panel jump (nor grow a scrollbar).
        self.badges = QWidget()
        self.badges.setObjectName("positionBadges")
        badges = QVBoxLayout(self.badges)
        badges.setContentsMargins(0, 0, 0, 0)
        badges.addWidget(self.measured_label)
        badges.addWidget(self.status_label)
        layout.addWidget(self.badges)
        layout.addStretch(1)  # a taller dock: the room goes under the badges, not between rows
        self._render_status()
        self._render()

    def _value_label(self, name: str, font: QFont) -> QLabel:
        value = QLabel()
        value.setObjectName(name)
        value.setFont(font)
        value.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        value.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        value.setMinimumWidth(value.fontMetrics().horizontalAdvance("-0000.000 mm"))
        return value

    def number_text(self, value: float) -> str:
        """A length in mm as shown here: in the units and decimals shown, in the interface's
        locale (12,34 in French), no thousands separator, no unit."""
        return self._number(value)

    def _number(self, value: float) -> str:
        """A value with the decimals shown, in the interface's locale (12,34 in French), no
        thousands separator."""
        if self._units == INCH:
            value = value / MM_PER_INCH
        return number_text(value, self._decimals, trim=False)

    def set_work_zero(self, zero: tuple[float, float, float]) -> None:
        """The work zero in machine mm ((0, 0, 0): the work frame is the machine frame)."""
        self._zero = (float(zero[0]), float(zero[1]), float(zero[2]))
        self._render()

    def work_zero(self) -> tuple[float, float, float]:
        """The work zero shown, in machine mm."""
        return self._zero

    def set_zero_enabled(self, enabled: bool) -> None:
        """Zero buttons on (a position is known) or off."""
        for axis, button in self.zero_buttons.items():
            button.setEnabled(enabled and axis in self._axes)
        self.zero_all_button.setEnabled(enabled)

    def work_text(self, axis: str) -> str:
        """The work-frame text shown for one axis, e.g. "2.34 mm"."""
        return self.work_labels[axis.lower()].text()

    def _zero_clicked(self) -> None:
        button = self.sender()
        if button is not None:
            self.zero_requested.emit(str(button.property("axis")))

    def _zero_all_clicked(self) -> None:
        self.zero_requested.emit("".join(a for a in AXES if a in self._axes))

    def set_status(self, status: str) -> None:
        """`"live"` (measured or commanded), `"estimated"` (moving), `"stale"` (last known),
        `"lost-moving"` (estimated when the link went mid-move), `"lost"`, `"uncounted"`, or
        while bridging `"bridged"` (nothing seen yet), `"observed"` (a reply reported it) or
        `"observed-target"` (a move sent)."""
        if status not in _STATUS and status != LIVE:
            raise ValueError(
                f"status must be {LIVE} or one of {', '.join(_STATUS)}, not {status!r}"
            )
        if status != self._status:
            self._status = status
            self._render_status()

    def status(self) -> str:
        """The status shown (see `set_status`)."""
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

    def show_outside(self, outside: Sequence[tuple[str, float, float, float]]) -> None:
        """Say the stage is outside its travel limits: (axis, value, low, high) per axis
        outside, in mm; empty: inside (or no limits), the line is hidden."""
        self._outside = list(outside)
        self._render_outside()

    def outside_text(self) -> str:
        """The outside-the-travel-limits line ("" when hidden)."""
        return self.outside_label.text() if self._outside else ""

    def _render_outside(self) -> None:
        parts = [
            f"{axis.upper()} {self._number(value)} {self._units} "
            f"({self._number(low)}..{self._number(high)})"
            for axis, value, low, high in self._outside
        ]
        text = fill(self.tr("outside the travel limits: %1"), ", ".join(parts)) if parts else ""
        if text != self.outside_label.text():
            self.outside_label.setText(text)
        self.outside_label.setVisible(bool(parts))

    def set_measured(self, measured: bool, confirmed: bool | None = None) -> None:
        """False: the position is only commanded; say so visibly, and whether the device
        confirmed reaching it (`confirmed`: None where the device never says); not shown
        beside an estimate, which says more."""
        self._measured = measured
        self._show_measured()
        if confirmed:
            text, tip = self.tr(CONFIRMED_TEXT), self.tr(CONFIRMED_TIP)
        else:
            text, tip = self.tr(NOT_MEASURED_TEXT), self.tr(COMMANDED_TIP)
        if self.measured_label.text() != text:
            self.measured_label.setText(text)
            self.measured_label.setToolTip(tip)

    def is_measured(self) -> bool:
        """Whether the position is shown as measured."""
        return self._measured

    def _show_measured(self) -> None:
        # Not beside an estimate or an unknown position, which say more, nor while bridging: the
        # panel measures nothing (one badge fewer: the position panel fits a 640 px screen).
        quiet = self._status in (ESTIMATED, BRIDGED, OBSERVED, OBSERVED_TARGET, UNCOUNTED, LOST)
        self.measured_label.setVisible(not self._measured and not quiet)
        self._keep_badge_height()

    def _keep_badge_height(self) -> None:
        """The badges' place grows to the tallest shown, and never shrinks back."""
        height = self.badges.sizeHint().height()
        if height > self.badges.minimumHeight():
            self.badges.setMinimumHeight(height)

    def set_resolution(self, resolution: float | None) -> None:
        """Show as many decimals as the device resolves (0.01 mm: 2; 1 µm: 3; 1 mm: 0)."""
        self._resolution = resolution
        self._set_decimals()

    def set_display(self, units: str, decimals: int = -1) -> None:
        """Show positions in "mm" or "in" (the device is always sent mm), with `decimals`
        decimals (-1: as many as the device resolves, in those units)."""
        check_units(units)
        self._units, self._fixed_decimals = units, decimals
        self._set_decimals()
        self._render()

    def units(self) -> str:
        """The units positions are shown in: "mm" or "in"."""
        return self._units

    def _set_decimals(self) -> None:
        if self._fixed_decimals >= 0:
            decimals = self._fixed_decimals
        elif self._resolution is None:
            decimals = 2 if self._units == MM else 3
        else:
            decimals = decimals_for(self._resolution)
            if self._units == INCH:  # enough to tell one device step from the next
                inches = self._resolution / MM_PER_INCH
                decimals = max(0, min(5, math.ceil(-math.log10(inches) - 1e-9)))
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
        """The badge, and the values' colour and slant: by palette and font, not style sheets,
        which re-polish each label (some 8 ms at every move's start and end)."""
        text, badge, (colour, italic) = _STATUS.get(self._status, ("", "", (None, False)))
        self.status_label.setText(self.tr(text) if text else "")
        self.status_label.setStyleSheet(f"{badge} border-radius: 3px; padding: 2px 6px;")
        self.status_label.setVisible(bool(text))
        self._show_measured()
        for label in (*self.labels.values(), *self.work_labels.values()):
            palette = QPalette(self.palette())  # the theme's, with the status colour on top
            if colour is not None:
                palette.setColor(QPalette.ColorRole.WindowText, QColor(colour))
            label.setPalette(palette)
            font = label.font()
            if font.italic() != italic:
                font.setItalic(italic)
                label.setFont(font)
        self.shown_changed.emit()

    def value_style(self, axis: str) -> tuple[str, bool]:
        """The colour (#rrggbb) and slant of an axis's machine value, as shown."""
        label = self.labels[axis.lower()]
        return label.palette().color(QPalette.ColorRole.WindowText).name(), label.font().italic()

    def _render(self) -> None:
        unit = self.tr("millimetres") if self._units == MM else self.tr("inches")
        tip = fill(
            self.tr("Stage position in %1: from the device's home, and from the work zero"), unit
        )
        if tip != self.toolTip():
            self.setToolTip(tip)
        for index, axis in enumerate(AXES):
            label, work = self.labels[axis], self.work_labels[axis]
            enabled = axis in self._axes
            for widget in (label, work, self.names[axis], self.zero_buttons[axis]):
                widget.setVisible(enabled)  # a device without the axis: its row is not shown
            label.setEnabled(enabled)
            if not enabled:
                label.setText(f"{UNKNOWN} {self._units}")
                work.setText(f"{UNKNOWN} {self._units}")
                label.setToolTip(self.tr("This device has no %1 axis").replace("%1", axis.upper()))
            elif self._position is None:
                label.setText(f"{UNKNOWN} {self._units}")
                work.setText(f"{UNKNOWN} {self._units}")
                label.setToolTip(self.tr("Position unknown"))
            else:
                machine = self._position[index]
                label.setText(f"{self._number(machine)} {self._units}")
                work.setText(f"{self._number(machine - self._zero[index])} {self._units}")
                label.setToolTip(
                    fill(self.tr("%1 position in %2 from the device's home"), axis.upper(), unit)
                )
                work.setToolTip(
                    fill(self.tr("%1 position in %2 from the work zero"), axis.upper(), unit)
                )
        at_home = self._zero == (0.0, 0.0, 0.0)
        comma = QLocale().decimalPoint() == ","
        shown = ("; " if comma else ", ").join(self._number(v) for v in self._zero)
        self.zero_label.setText(
            self.tr("work zero: home")
            if at_home
            else fill(self.tr("work zero at (%1) %2 (machine)"), shown, self._units)
        )
        self.clear_zero_button.setEnabled(not at_home)
        self.shown_changed.emit()
        if self._outside:
            self._render_outside()  # in the units and decimals shown
