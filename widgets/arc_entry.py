"""Type an arc in the XY plane (centre, radius, angles, direction, final Z) and run it."""

from __future__ import annotations

import itertools
import logging
import math

from PySide6.QtCore import Signal
from PySide6.QtWidgets import (
    QButtonGroup,
    QCheckBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QRadioButton,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import Box, decimals_for
from widgets._buttons import make_button
from widgets._i18n import fill, number_text
from widgets._number_field import NumberSpinBox, label_name
from widgets._units import INCH, MM, UnitSpinBox, check_units

log = logging.getLogger(__name__)

UNBOUNDED_MM = 99999.0  # the fields' range: the travel box is checked on the whole arc instead
MAX_POINTS = 720
POINTS_PER_DEGREE = 2
TOLERANCE_MM = 1e-6
ARC_KEYS = ("cx", "cy", "radius", "start", "end", "ccw", "z")

Point = tuple[float, float, float]


def arc_sweep(start: float, end: float, ccw: bool) -> float:
    """Degrees swept from `start` to `end` (0 < sweep <= 360); end == start is a full circle."""
    sweep = ((end - start) if ccw else (start - end)) % 360.0
    return 360.0 if sweep < 1e-9 or sweep > 360.0 - 1e-9 else sweep


def arc_path(
    cx: float,
    cy: float,
    radius: float,
    start: float,
    end: float,
    ccw: bool,
    z_start: float,
    z_end: float,
) -> list[Point]:
    """Points (x, y, z) in mm from the start to the end angle, angles in degrees from +X.

    CCW means increasing angle (counter-clockwise seen from above). At least 2 points per degree
    swept, at most 720; Z goes linearly from `z_start` to `z_end`. Empty when radius <= 0.
    """
    if not radius > 0 or not all(map(math.isfinite, (cx, cy, radius, start, end))):
        return []
    sweep = arc_sweep(start, end, ccw)
    count = max(2, min(MAX_POINTS, math.ceil(POINTS_PER_DEGREE * sweep) + 1))
    sign = 1.0 if ccw else -1.0
    points = []
    for i in range(count):
        share = i / (count - 1)
        angle = math.radians(start + sign * sweep * share)
        points.append(
            (
                cx + radius * math.cos(angle),
                cy + radius * math.sin(angle),
                z_start + (z_end - z_start) * share,
            )
        )
    return points


def arc_extent(
    cx: float, cy: float, radius: float, start: float, end: float, ccw: bool
) -> tuple[tuple[float, float], tuple[float, float]]:
    """The exact XY bounding box ((x_min, x_max), (y_min, y_max)) of the arc, in mm."""
    sweep = arc_sweep(start, end, ccw)
    angles = [start, start + (sweep if ccw else -sweep)]
    for quarter in (0.0, 90.0, 180.0, 270.0):  # where the circle reaches its extremes
        offset = ((quarter - start) if ccw else (start - quarter)) % 360.0
        if offset <= sweep:
            angles.append(quarter)
    xs = [cx + radius * math.cos(math.radians(a)) for a in angles]
    ys = [cy + radius * math.sin(math.radians(a)) for a in angles]
    return (min(xs), max(xs)), (min(ys), max(ys))


def _spin(name: str, suffix: str, low: float, high: float, decimals: int) -> NumberSpinBox:
    """A field with its unit; the value is taken on Enter, arrow steps or when focus leaves."""
    field = NumberSpinBox()
    field.setObjectName(name)
    field.setDecimals(decimals)
    field.setRange(low, high)
    field.setSuffix(suffix)
    field.setKeyboardTracking(False)
    field.setAccelerated(True)
    field.setMinimumWidth(100)
    return field


def _length(name: str, low: float, high: float) -> UnitSpinBox:
    """A length field in mm or inches (set and read in mm), 3 decimals of a mm."""
    field = UnitSpinBox()
    field.setObjectName(name)
    field.set_mm_decimals(3)
    field.set_mm_range(low, high)
    field.set_single_steps(1.0, 0.1)
    field.setKeyboardTracking(False)
    field.setAccelerated(True)
    field.setMinimumWidth(100)
    return field


FIELDS_PER_ROW = 2  # two columns: the panel fits the left column of a 1024-pixel window


class ArcEntry(QWidget):
    """Centre, radius, start and end angle, direction and final Z of an arc; Preview; Run arc.

    `preview_changed` carries the arc's points (or [] when Preview is off or the arc is invalid)
    whenever a value changes; `arc_requested` carries `values()` when Run arc is pressed.
    """

    preview_changed = Signal(object)  # list of (x, y, z) mm, [] for no preview
    arc_requested = Signal(object)  # {"cx", "cy", "radius", "start", "end", "ccw", "z"}

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("arcEntry")
        self._start_z = 0.0
        self._box: Box | None = None
        self._points: list[Point] = []
        self._units = MM

        self.cx_field = _length("arcCentreX", -UNBOUNDED_MM, UNBOUNDED_MM)
        self.cy_field = _length("arcCentreY", -UNBOUNDED_MM, UNBOUNDED_MM)
        self.radius_field = _length("arcRadius", 0.001, UNBOUNDED_MM)
        self.radius_field.set_mm_value(10.0)
        self.start_field = _spin("arcStart", " °", 0.0, 360.0, 1)
        self.start_field.setWrapping(True)
        self.start_field.setSingleStep(15.0)
        self.start_field.setToolTip(
            self.tr(
                "Angle of the start point, 0 to 360°, counter-clockwise from +X seen from above"
            )
        )
        self.end_field = _spin("arcEnd", " °", 0.0, 360.0, 1)
        self.end_field.setWrapping(True)
        self.end_field.setSingleStep(15.0)
        self.end_field.setValue(90.0)
        self.end_field.setToolTip(
            self.tr(
                "Angle of the end point, 0 to 360°, counter-clockwise from +X seen from above;"
                "\nthe same as the start angle: a full circle"
            )
        )
        self.z_field = _length("arcFinalZ", -UNBOUNDED_MM, UNBOUNDED_MM)
        self.lengths: tuple[UnitSpinBox, ...] = (
            self.cx_field,
            self.cy_field,
            self.radius_field,
            self.z_field,
        )
        self.labels: dict[NumberSpinBox, QLabel] = {}  # each field's label, by field
        self._unit_tips()
        self.fields: dict[str, NumberSpinBox] = {
            "cx": self.cx_field,
            "cy": self.cy_field,
            "radius": self.radius_field,
            "start": self.start_field,
            "end": self.end_field,
            "z": self.z_field,
        }

        grid = QGridLayout()
        labels = (
            (self.tr("Centre X:"), self.cx_field),
            (self.tr("Centre Y:"), self.cy_field),
            (self.tr("Radius:"), self.radius_field),
            (self.tr("Start:"), self.start_field),
            (self.tr("End:"), self.end_field),
            (self.tr("Final Z:"), self.z_field),
        )
        for index, (text, field) in enumerate(labels):
            label = QLabel(text)
            field.set_what(label_name(text))
            label.setBuddy(field)
            label.setToolTip(field.toolTip())
            self.labels[field] = label
            row, column = divmod(index, FIELDS_PER_ROW)
            grid.addWidget(label, row, 2 * column)
            grid.addWidget(field, row, 2 * column + 1)
            grid.setColumnStretch(2 * column + 1, 1)

        self.cw_radio = QRadioButton(self.tr("CW"))
        self.cw_radio.setObjectName("arcCw")
        self.cw_radio.setToolTip(self.tr("Clockwise seen from above: the angle decreases"))
        self.ccw_radio = QRadioButton(self.tr("CCW"))
        self.ccw_radio.setObjectName("arcCcw")
        self.ccw_radio.setToolTip(self.tr("Counter-clockwise seen from above: the angle increases"))
        self._direction = QButtonGroup(self)
        self._direction.addButton(self.cw_radio)
        self._direction.addButton(self.ccw_radio)
        self.ccw_radio.setChecked(True)

        self.preview_check = QCheckBox(self.tr("Preview"))
        self.preview_check.setObjectName("arcPreview")
        self.preview_check.setToolTip(self.tr("Draw the arc, dashed, in the position views"))
        self.preview_check.setChecked(True)

        self.run_button = make_button(
            self.tr("Run arc"),
            "runArcButton",
            self.tr("Move along the arc, from its start point to its end point"),
        )
        self.run_button.clicked.connect(self._run)

        self.problem_label = QLabel()
        self.problem_label.setObjectName("arcProblem")
        self.problem_label.setWordWrap(True)
        self.problem_label.setStyleSheet("color: #c62828;")
        self.problem_label.setToolTip(self.tr("Why the arc cannot run"))
        self.problem_label.setVisible(False)

        actions = QHBoxLayout()
        actions.addWidget(self.cw_radio)
        actions.addWidget(self.ccw_radio)
        actions.addSpacing(12)
        actions.addWidget(self.preview_check)
        actions.addStretch(1)
        actions.addWidget(self.run_button)
        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addLayout(actions)
        layout.addWidget(self.problem_label)
        layout.addStretch(1)

        order = [
            *self.fields.values(),
            self.cw_radio,
            self.ccw_radio,
            self.preview_check,
            self.run_button,
        ]
        for first, second in itertools.pairwise(order):
            QWidget.setTabOrder(first, second)

        for field in self.fields.values():
            field.valueChanged.connect(self._changed)
            field.lineEdit().textChanged.connect(self._check)  # a typed value out of range
        self.ccw_radio.toggled.connect(self._changed)
        self.preview_check.toggled.connect(self._changed)
        self._changed()

    def _unit_tips(self) -> None:
        """The length fields' tooltips, naming the unit shown (and their labels')."""
        if self._units == INCH:
            tips = (
                self.tr("X of the arc's centre, in inches from home"),
                self.tr("Y of the arc's centre, in inches from home"),
                self.tr("Radius of the arc, in inches (more than 0)"),
                self.tr(
                    "Z at the end of the arc, in inches; Z moves evenly from the current Z along "
                    "the arc\n(a helix when it differs)"
                ),
            )
        else:
            tips = (
                self.tr("X of the arc's centre, in mm from home"),
                self.tr("Y of the arc's centre, in mm from home"),
                self.tr("Radius of the arc, in mm (more than 0)"),
                self.tr(
                    "Z at the end of the arc, in mm; Z moves evenly from the current Z along the "
                    "arc\n(a helix when it differs)"
                ),
            )
        for field, tip in zip(self.lengths, tips, strict=True):
            field.setToolTip(tip)
            label = self.labels.get(field)
            if label is not None:
                label.setToolTip(tip)

    # -- units -----------------------------------------------------------------------------

    def set_units(self, units: str) -> None:
        """Show and type lengths in "mm" or "in" (values, the preview and what is sent stay in
        mm); the fields show the same lengths converted. Emits nothing."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        for field in self.lengths:
            field.set_units(units)
        self._unit_tips()
        self._check()

    def units(self) -> str:
        """The units lengths are shown and typed in: "mm" or "in"."""
        return self._units

    # -- values ----------------------------------------------------------------------------

    def values(self) -> dict:
        """{"cx", "cy", "radius", "start", "end", "z"} as floats (mm, degrees), "ccw" a bool."""
        for field in self.fields.values():
            field.interpretText()  # the typed text, if it can be used
        return self._taken()

    def _taken(self) -> dict:
        """The values the fields hold, without taking what is being typed."""
        out: dict = {}
        for key, field in self.fields.items():
            if isinstance(field, UnitSpinBox):
                out[key] = field.mm_value()
            else:
                out[key] = float(field.value())
        out["ccw"] = self.ccw_radio.isChecked()
        return {key: out[key] for key in ARC_KEYS}

    def set_values(self, **values: float | bool) -> None:
        """Set some of cx, cy, radius, start, end, z (clamped to the fields) and ccw.

        Emits `preview_changed` once afterwards.
        """
        unknown = set(values) - set(ARC_KEYS)
        if unknown:
            raise TypeError(f"unknown arc values {sorted(unknown)}; known: {ARC_KEYS}")
        widgets = [*self.fields.values(), self.ccw_radio, self.cw_radio]
        for widget in widgets:
            widget.blockSignals(True)
        try:
            for key, value in values.items():
                field = self.fields.get(key)
                if key == "ccw":
                    (self.ccw_radio if value else self.cw_radio).setChecked(True)
                elif isinstance(field, UnitSpinBox):
                    field.set_mm_value(float(value))  # lengths are given in mm
                elif field is not None:
                    field.setValue(float(value))
        finally:
            for widget in widgets:
                widget.blockSignals(False)
        self._changed()

    def set_start_z(self, z: float | None) -> None:
        """The Z the arc starts at (the current Z), in mm; None: 0. Updates the preview."""
        self._start_z = 0.0 if z is None else float(z)
        self._changed()

    def start_z(self) -> float:
        """The Z the arc starts at, in mm."""
        return self._start_z

    def set_box(self, box: Box | None) -> None:
        """Check the arc against the travel box in mm (None: no travel limits are known)."""
        self._box = None if box is None else tuple(tuple(map(float, pair)) for pair in box)
        self._check()

    def box(self) -> Box | None:
        """The travel box the arc is checked against, or None."""
        return self._box

    def set_resolution(self, resolution: float | None) -> None:
        """Type lengths to the device's resolution in mm (None: 0.001 mm); in inches, two
        decimals more (at most 4), sent on the device's resolution."""
        decimals = decimals_for(resolution)
        for field in self.lengths:
            field.blockSignals(True)
        try:
            for field in self.lengths:
                field.set_mm_decimals(decimals)
            self.radius_field.set_mm_range(10.0**-decimals, UNBOUNDED_MM)
        finally:
            for field in self.lengths:
                field.blockSignals(False)
        self._changed()

    def arc_points(self) -> list[Point]:
        """The arc's points (x, y, z) in mm, whether or not Preview is on; [] if invalid."""
        return list(self._points)

    def problem(self) -> str:
        """Why the arc cannot run, or ""."""
        return self.problem_label.text()

    # -- updates -----------------------------------------------------------------------------

    def _changed(self, *_: object) -> None:
        v = self.values()
        self._points = arc_path(
            v["cx"], v["cy"], v["radius"], v["start"], v["end"], v["ccw"], self._start_z, v["z"]
        )
        self._check()
        shown = self._points if self.preview_check.isChecked() else []
        self.preview_changed.emit(list(shown))

    def _check(self, *_: object) -> None:
        typed = [field.problem() for field in self.fields.values() if field.problem()]
        problem = "; ".join(typed) if typed else self._find_problem()
        self.problem_label.setText(problem)
        self.problem_label.setVisible(bool(problem))
        self.run_button.setEnabled(not problem)
        tip = self.tr("Move along the arc, from its start point to its end point")
        self.run_button.setToolTip(f"{tip}\n{problem}" if problem else tip)

    def _find_problem(self) -> str:
        v = self._taken()
        inch = self._units == INCH
        if not v["radius"] > 0:
            if inch:
                return self.tr("The radius must be more than 0 in.")
            return self.tr("The radius must be more than 0 mm.")
        if self._box is None:
            return ""
        xs, ys = arc_extent(v["cx"], v["cy"], v["radius"], v["start"], v["end"], v["ccw"])
        zs = (min(self._start_z, v["z"]), max(self._start_z, v["z"]))
        outside = []
        if inch:
            span = self.tr("%1 %2 to %3 in (travel %4 to %5 in)")
            point = self.tr("%1 %2 in (travel %3 to %4 in)")
        else:
            span = self.tr("%1 %2 to %3 mm (travel %4 to %5 mm)")
            point = self.tr("%1 %2 mm (travel %3 to %4 mm)")
        factor = self.cx_field.factor()
        decimals = self.cx_field.decimals()  # the arc's reach: as typed; the travel: trimmed
        travel_decimals = decimals if inch else 6

        def shown(mm: float) -> str:
            return number_text(mm / factor, decimals, trim=False)

        for name, (low, high), (lo, hi) in zip("XYZ", (xs, ys, zs), self._box, strict=True):
            if low < lo - TOLERANCE_MM or high > hi + TOLERANCE_MM:
                travel = tuple(number_text(v / factor, travel_decimals) for v in (lo, hi))
                outside.append(
                    fill(span, name, shown(low), shown(high), *travel)
                    if low != high
                    else fill(point, name, shown(low), *travel)
                )
        if not outside:
            return ""
        return fill(self.tr("The arc leaves the travel limits: %1."), "; ".join(outside))

    def _run(self) -> None:
        values = self.values()  # takes a half-typed field first, which rechecks the arc
        if not self.isEnabled() or not self.run_button.isEnabled():
            return
        log.debug("arc requested: %s", values)
        self.arc_requested.emit(values)
