"""Type a coordinate and go there; Home, Set Home and Stop."""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterable

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Signal
from PySide6.QtWidgets import (
    QButtonGroup,
    QComboBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QRadioButton,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, Box, decimals_for, normalize_axes
from widgets._buttons import make_button
from widgets._i18n import fill
from widgets._number_field import wheel_needs_focus
from widgets._units import INCH, MM, UnitSpinBox, check_units

log = logging.getLogger(__name__)

UNBOUNDED_MM = 99999.0  # the fields' range where no travel limits are set
ABSOLUTE = "absolute"
RELATIVE = "relative"
MACHINE = "machine"
WORK = "work"
SET_HOME_QUESTION = QT_TRANSLATE_NOOP(
    "CoordinateEntry",
    "Make the current position the new home (0, 0, 0)?\n"
    "All coordinates will be measured from here from now on.",
)  # translated at use


def ask_with_message_box(question: str, parent: QWidget | None = None) -> bool:
    """Ask a yes/no question in a modal QMessageBox; True for Yes."""
    answer = QMessageBox.question(
        parent,
        QCoreApplication.translate("CoordinateEntry", "Motion Panel"),
        question,
        QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
        QMessageBox.StandardButton.No,
    )
    return answer == QMessageBox.StandardButton.Yes


class _AxisSpinBox(UnitSpinBox):
    """A coordinate field: 3 decimals of a mm, value read on Enter or when focus leaves."""

    def __init__(self, axis: str, parent: QWidget | None = None) -> None:
        super().__init__(parent=parent)
        self.setObjectName(f"coord{axis.upper()}")
        self.set_what(axis.upper())
        self.set_mm_decimals(3)
        self.set_single_steps(1.0, 0.1)
        self.setKeyboardTracking(False)
        self.setAccelerated(True)
        self.setMinimumWidth(110)


class CoordinateEntry(QWidget):
    """X/Y/Z fields, absolute or relative, and Go, Home, Set Home, Stop, Use current."""

    go_requested = Signal(str, object)  # mode ("absolute"/"relative"), machine (x, y, z) in mm
    home_requested = Signal()
    set_home_requested = Signal()
    stop_requested = Signal()
    refused = Signal(str)  # why Go (or Enter) sent nothing: a field's text cannot be used

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("coordinateEntry")
        self.confirm: Callable[[str], bool] = lambda q: ask_with_message_box(q, self)
        self._axes = frozenset(AXES)
        self._box: Box | None = None
        self._known: tuple[float, float, float] | None = None
        self._zero: tuple[float, float, float] = (0.0, 0.0, 0.0)
        self._units = MM

        grid = QGridLayout()
        self.fields: dict[str, UnitSpinBox] = {}
        for column, axis in enumerate(AXES):
            label = QLabel(fill(self.tr("&%1:", "an axis field's label; Alt+axis"), axis.upper()))
            field = _AxisSpinBox(axis)
            field.lineEdit().returnPressed.connect(self._go)
            label.setBuddy(field)
            grid.addWidget(label, 0, 2 * column)
            grid.addWidget(field, 0, 2 * column + 1)
            self.fields[axis] = field

        self.absolute_radio = QRadioButton(self.tr("Absolute"))
        self.absolute_radio.setObjectName("modeAbsolute")
        self.relative_radio = QRadioButton(self.tr("Relative"))
        self.relative_radio.setObjectName("modeRelative")
        self._mode_group = QButtonGroup(self)
        self._mode_group.addButton(self.absolute_radio)
        self._mode_group.addButton(self.relative_radio)
        self.absolute_radio.setChecked(True)
        self.relative_radio.toggled.connect(self._mode_toggled)
        self.frame_combo = QComboBox()
        self.frame_combo.setObjectName("coordinateFrame")
        self.frame_combo.addItem(self.tr("Machine"), MACHINE)
        self.frame_combo.addItem(self.tr("Work"), WORK)
        self._unit_tips()
        self.frame_combo.currentIndexChanged.connect(self._frame_changed)
        wheel_needs_focus(self.frame_combo)

        self.go_button = make_button(
            self.tr("Go"), "goButton", self.tr("Start the move (Enter in a field)")
        )
        self.go_button.clicked.connect(self._go)
        self.use_current_button = make_button(
            self.tr("Use current"),
            "useCurrentButton",
            self.tr("Fill the fields with the current position"),
        )
        self.use_current_button.setEnabled(False)
        self.use_current_button.clicked.connect(self._use_current)
        self.home_button = make_button(
            self.tr("Home"), "homeButton", self.tr("Run the homing sequence")
        )
        self.home_button.clicked.connect(self.home_requested)
        self.set_home_button = make_button(
            self.tr("Set Home"),
            "setHomeButton",
            self.tr("Make the current position the origin (asks first)"),
        )
        self.set_home_button.clicked.connect(self._set_home)
        self.stop_button = make_button(self.tr("Stop"), "stopButton", self.tr("Stop the stage now"))
        self.set_stop_mode(True, self.tr("Stop the stage now (Esc)"))
        self.stop_button.clicked.connect(self.stop_requested)

        modes = QHBoxLayout()
        modes.addWidget(self.absolute_radio)
        modes.addWidget(self.relative_radio)
        modes.addWidget(self.frame_combo)
        modes.addStretch(1)
        modes.addWidget(self.use_current_button)
        modes.addWidget(self.go_button)
        actions = QHBoxLayout()
        actions.addWidget(self.home_button)
        actions.addWidget(self.set_home_button)
        actions.addStretch(1)
        actions.addWidget(self.stop_button)

        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addLayout(modes)
        layout.addLayout(actions)
        layout.addStretch(1)  # extra height goes below the panel, not between its rows
        self._apply_range()

    def _unit_tips(self) -> None:
        """The tooltips that name the unit shown."""
        if self._units == INCH:
            absolute = self.tr("Go to the typed coordinates (inches from home)")
            relative = self.tr("Move by the typed distances (inches) from where the stage is")
            frame = self.tr(
                "Which frame the typed coordinates are in: Machine (inches from the device's "
                "home) or Work (inches from the work zero); the device is always sent machine "
                "coordinates, in mm"
            )
        else:
            absolute = self.tr("Go to the typed coordinates (mm from home)")
            relative = self.tr("Move by the typed distances (mm) from where the stage is")
            frame = self.tr(
                "Which frame the typed coordinates are in: Machine (mm from the device's home) "
                "or Work (mm from the work zero); the device is always sent machine coordinates"
            )
        self.absolute_radio.setToolTip(absolute)
        self.relative_radio.setToolTip(relative)
        self.frame_combo.setToolTip(frame)

    # -- units -----------------------------------------------------------------------------

    def set_units(self, units: str) -> None:
        """Show and type coordinates in "mm" or "in" (what is sent stays in mm); the fields
        show the same lengths converted; emits nothing."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        for field in self.fields.values():
            field.set_units(units)
        self._unit_tips()
        self._apply_range()

    def units(self) -> str:
        """The units coordinates are shown and typed in: "mm" or "in"."""
        return self._units

    # -- values ----------------------------------------------------------------------------

    def mode(self) -> str:
        """`"absolute"` or `"relative"`."""
        return RELATIVE if self.relative_radio.isChecked() else ABSOLUTE

    def frame(self) -> str:
        """`"machine"` or `"work"`: the frame absolute coordinates are typed in."""
        return str(self.frame_combo.currentData())

    def set_frame(self, frame: str) -> None:
        """Type absolute coordinates in the machine or the work frame."""
        index = self.frame_combo.findData(frame)
        if index < 0:
            raise ValueError(f"frame must be {MACHINE!r} or {WORK!r}, not {frame!r}")
        self.frame_combo.setCurrentIndex(index)

    def set_work_zero(self, zero: tuple[float, float, float]) -> None:
        """The work zero in machine mm; typed work coordinates are taken from it."""
        moved = zero != self._zero
        self._zero = (float(zero[0]), float(zero[1]), float(zero[2]))
        if moved:
            self._apply_range()

    def _offset(self) -> tuple[float, float, float]:
        """What is added to typed coordinates to make them machine ones."""
        return self._zero if self.frame() == WORK else (0.0, 0.0, 0.0)

    def machine_target(self) -> tuple[float, float, float]:
        """The typed target in machine mm (a relative move's distances as they are)."""
        values = self.values()
        if self.mode() == RELATIVE:
            return values
        offset = self._offset()
        return (values[0] + offset[0], values[1] + offset[1], values[2] + offset[2])

    def _frame_changed(self) -> None:
        self._apply_range()
        if self.mode() == ABSOLUTE and self._known is not None:
            self._fill_known()

    def set_mode(self, mode: str) -> None:
        """Select `"absolute"` or `"relative"` (relative clears the fields to 0)."""
        if mode not in (ABSOLUTE, RELATIVE):
            raise ValueError(f"mode must be {ABSOLUTE!r} or {RELATIVE!r}, not {mode!r}")
        (self.relative_radio if mode == RELATIVE else self.absolute_radio).setChecked(True)

    def problems(self) -> list[str]:
        """Why the typed coordinates cannot be sent, one message a field ([] when they can)."""
        relative = self.mode() == RELATIVE
        return [
            field.problem()
            for axis, field in self.fields.items()
            if field.problem() and not (relative and axis not in self._axes)
        ]

    def values(self) -> tuple[float, float, float]:
        """The typed (x, y, z) in mm; a disabled axis is 0 in relative mode (a field whose
        text cannot be used gives its last usable value: see `problems()`)."""
        relative = self.mode() == RELATIVE
        out = []
        for axis in AXES:
            field = self.fields[axis]
            field.interpretText()
            enabled = axis in self._axes
            out.append(0.0 if relative and not enabled else field.mm_value())
        return (out[0], out[1], out[2])

    def set_values(self, x: float, y: float, z: float) -> None:
        """Fill the fields with mm (clamped to the range); emits nothing."""
        for axis, value in zip(AXES, (x, y, z), strict=True):
            self.fields[axis].set_mm_value(value)

    def set_current(self, x: float, y: float, z: float) -> None:
        """Fill the fields with a machine position, in the frame chosen (and switch to absolute
        mode); emits nothing."""
        self.set_known_position(x, y, z)
        self.set_mode(ABSOLUTE)
        self._fill_known()

    def _fill_known(self) -> None:
        if self._known is None:
            return
        offset = self._offset()
        self.set_values(*(v - o for v, o in zip(self._known, offset, strict=True)))

    def set_known_position(self, x: float, y: float, z: float) -> None:
        """Remember the stage position for "Use current" without touching the fields."""
        self._known = (float(x), float(y), float(z))
        self.use_current_button.setEnabled(True)

    def set_box(self, box: Box | None) -> None:
        """Bound the fields by the travel box in mm (None: no travel limits are known)."""
        self._box = box
        self._apply_range()

    def box(self) -> Box | None:
        """The travel box bounding the fields, or None."""
        return self._box

    def set_resolution(self, resolution: float | None) -> None:
        """Type coordinates to the device's resolution in mm (None: 0.001 mm); in inches, two
        decimals more (at most 4), sent on the device's resolution."""
        decimals = decimals_for(resolution)
        for field in self.fields.values():
            field.set_mm_decimals(decimals)

    def set_home_tips(self, home: str, set_home: str) -> None:
        """Say what Home and Set Home do on this device."""
        self.home_button.setToolTip(home)
        self.set_home_button.setToolTip(set_home)

    def set_stop_mode(self, can_stop: bool, tooltip: str) -> None:
        """A real Stop (red) where the protocol can halt a move; else "Drop queued"."""
        self.stop_button.setText(self.tr("Stop") if can_stop else self.tr("Drop queued"))
        self.stop_button.setToolTip(tooltip)
        colour = "#c62828" if can_stop else "#6d4c41"
        self.stop_button.setStyleSheet(
            f"QPushButton {{ background-color: {colour}; color: white; font-weight: bold;"
            " padding: 4px 10px; } QPushButton:disabled { background-color: #9e9e9e; }"
        )

    def _range(self, index: int) -> tuple[float, float]:
        if self._box is None:
            return (-UNBOUNDED_MM, UNBOUNDED_MM)
        lo, hi = self._box[index]
        if self.mode() == RELATIVE:
            return lo, hi
        offset = self._offset()[index]  # the box is in machine mm
        return lo - offset, hi - offset

    def _range_tip(self, relative: bool) -> str:
        """The field tooltip's template, in the unit shown."""
        if self._units == INCH:
            if relative:
                return self.tr("%1 distance to move, %2 to %3 in (%4)")
            if self.frame() == MACHINE:
                return self.tr("%1 target coordinate, %2 to %3 in (%4)")
            return self.tr("%1 target coordinate in the work frame, %2 to %3 in (%4)")
        if relative:
            return self.tr("%1 distance to move, %2 to %3 mm (%4)")
        if self.frame() == MACHINE:
            return self.tr("%1 target coordinate, %2 to %3 mm (%4)")
        return self.tr("%1 target coordinate in the work frame, %2 to %3 mm (%4)")

    def _apply_range(self) -> None:
        relative = self.mode() == RELATIVE
        tip = self._range_tip(relative)
        for index, (axis, field) in enumerate(self.fields.items()):
            lo, hi = self._range(index)
            if relative:
                lo, hi = -(hi - lo), hi - lo
            field.set_mm_range(lo, hi)
            if self._box is not None:
                limits = self.tr("travel limits")
            else:
                limits = self.tr("no travel limits set")
            state = "" if axis in self._axes else "\n" + self.tr("(this device has no such axis)")
            low, high = field.range_texts()
            field.setToolTip(fill(tip, axis.upper(), low, high, limits) + state)

    def set_axes_enabled(self, axes: Iterable[str]) -> None:
        """Only the fields of `axes` can be edited."""
        self._axes = normalize_axes(axes)
        for axis, field in self.fields.items():
            field.setEnabled(axis in self._axes)
        self._apply_range()

    # -- actions ---------------------------------------------------------------------------

    def _mode_toggled(self, relative: bool) -> None:
        self._apply_range()
        if relative:
            self.set_values(0.0, 0.0, 0.0)  # a relative move must never reuse a coordinate
        else:
            self._fill_known()

    def _use_current(self) -> None:
        if self._known is not None:
            self.set_current(*self._known)

    def _go(self) -> None:
        if not self.isEnabled() or not self.go_button.isEnabled():
            return
        problems = self.problems()
        if problems:
            why = fill(self.tr("%1; nothing sent"), "; ".join(problems))
            log.info("go refused: %s", why)
            self.refused.emit(why)
            return
        mode, target = self.mode(), self.machine_target()
        log.debug("go %s %s (machine)", mode, target)
        self.go_requested.emit(mode, target)

    def _set_home(self) -> None:
        if self.confirm(self.tr(SET_HOME_QUESTION)):
            self.set_home_requested.emit()
