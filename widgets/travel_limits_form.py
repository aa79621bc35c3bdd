"""A device's travel box and whether moves beyond it are refused or clamped: the form that the
Travel limits dialog and the Set up layout's Travel limits dock both show."""

from __future__ import annotations

from PySide6.QtCore import Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QRadioButton,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, Box
from widgets._buttons import make_button
from widgets._i18n import fill
from widgets._number_field import NumberSpinBox

SPIN_LIMIT_MM = 99999.0
DEFAULT_BOX: Box = ((-100.0, 100.0), (-100.0, 100.0), (0.0, 50.0))
PROBLEM_STYLE = "color: #c62828;"


class TravelLimitsForm(QWidget):
    """Edit a travel box in mm; `result_limits()` gives (box or None, clamp); `changed` on every
    edit (`problem()` says why the box cannot be used, "" when it can)."""

    changed = Signal()

    def __init__(
        self,
        device: str = "",
        box: Box | None = None,
        clamp: bool = False,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("travelLimitsForm")
        self.intro = QLabel()
        self.intro.setObjectName("travelIntro")
        self.intro.setWordWrap(True)
        self.enabled_check = QCheckBox(self.tr("Limit moves to this box"))
        self.enabled_check.setObjectName("travelEnabled")
        self.enabled_check.toggled.connect(self._sync)

        grid = QGridLayout()
        grid.addWidget(QLabel(self.tr("min")), 0, 1)
        grid.addWidget(QLabel(self.tr("max")), 0, 2)
        self.spins: dict[str, tuple[NumberSpinBox, NumberSpinBox]] = {}
        for row, axis in enumerate(AXES, start=1):
            grid.addWidget(
                QLabel(fill(self.tr("%1:", "an axis field's label"), axis.upper())), row, 0
            )
            name = f"travel{axis.upper()}"
            pair = (self._spin(f"{name}Min"), self._spin(f"{name}Max"))
            pair[0].set_what(fill(self.tr("%1 min", "an axis' lower travel limit"), axis.upper()))
            pair[1].set_what(fill(self.tr("%1 max", "an axis' upper travel limit"), axis.upper()))
            grid.addWidget(pair[0], row, 1)
            grid.addWidget(pair[1], row, 2)
            self.spins[axis] = pair

        self.refuse_radio = QRadioButton(self.tr("Refuse a move that would leave the box"))
        self.refuse_radio.setObjectName("travelRefuse")
        self.clamp_radio = QRadioButton(self.tr("Clamp it: go as far as the edge, and say so"))
        self.clamp_radio.setObjectName("travelClamp")
        self.clamp_radio.toggled.connect(self._sync)
        self.problem_label = QLabel()
        self.problem_label.setObjectName("travelProblem")
        self.problem_label.setStyleSheet(PROBLEM_STYLE)
        self.problem_label.setWordWrap(True)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.intro)
        layout.addWidget(self.enabled_check)
        layout.addLayout(grid)
        for part in (self.refuse_radio, self.clamp_radio, self.problem_label):
            layout.addWidget(part)
        self.set_device(device)
        self.set_limits(box, clamp)

    def _spin(self, name: str) -> NumberSpinBox:
        spin = NumberSpinBox()
        spin.setObjectName(name)
        spin.setRange(-SPIN_LIMIT_MM, SPIN_LIMIT_MM)
        spin.setDecimals(2)
        spin.setSuffix(" mm")
        spin.valueChanged.connect(self._sync)
        spin.lineEdit().textChanged.connect(self._sync)  # typed text that cannot be used, too
        return spin

    def set_device(self, device: str) -> None:
        """Name the device the box is for ("" : no device, the form says so)."""
        if device:
            text = fill(
                self.tr(
                    "Where the stage may go on %1. A jog, go-to or command-line move that "
                    "would leave the box is refused before anything is sent, or clamped to "
                    "its edge."
                ),
                device,
            )
        else:
            text = self.tr("Connect a device to set where its stage may go.")
        self.intro.setText(text)

    def set_limits(self, box: Box | None, clamp: bool) -> None:
        """Show `box` (None: no limits; the spin boxes show a default box) and the choice."""
        self.blockSignals(True)  # one `changed` for the whole change
        try:
            self.enabled_check.setChecked(box is not None)
            for (low, high), (low_spin, high_spin) in zip(
                box or DEFAULT_BOX, self.spins.values(), strict=True
            ):
                low_spin.setValue(low)
                high_spin.setValue(high)
            (self.clamp_radio if clamp else self.refuse_radio).setChecked(True)
        finally:
            self.blockSignals(False)
        self._sync()

    def _sync(self) -> None:
        enabled = self.enabled_check.isChecked()
        for low, high in self.spins.values():
            low.setEnabled(enabled)
            high.setEnabled(enabled)
        self.refuse_radio.setEnabled(enabled)
        self.clamp_radio.setEnabled(enabled)
        problem = self.problem() if enabled else ""
        if problem != self.problem_label.text():
            self.problem_label.setText(problem)
        self.problem_label.setVisible(bool(problem))
        self.changed.emit()

    def problem(self) -> str:
        """Why the box cannot be used ("" when it can)."""
        typed = [spin.problem() for pair in self.spins.values() for spin in pair if spin.problem()]
        if typed:
            return "\n".join(typed)
        for axis, (low, high) in self.spins.items():
            if low.value() >= high.value():
                why = self.tr("%1: the minimum must be below the maximum")
                return fill(why, axis.upper())
        return ""

    def result_limits(self) -> tuple[Box | None, bool]:
        """The box in mm (None: no limits) and whether to clamp."""
        if not self.enabled_check.isChecked():
            return None, self.clamp_radio.isChecked()
        x, y, z = ((low.value(), high.value()) for low, high in self.spins.values())
        return (x, y, z), self.clamp_radio.isChecked()


class TravelLimitsPanel(QWidget):
    """The form in a dock: Apply sends `apply_requested(box or None, clamp)`; Revert shows the
    limits in use again. Apply is on while the form differs from them and can be used."""

    apply_requested = Signal(object, bool)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("travelLimits")
        self._applied: tuple[Box | None, bool] = (None, False)
        self._connected = False
        self.form = TravelLimitsForm(parent=self)
        self.apply_button = make_button(
            self.tr("Apply"),
            "travelApplyButton",
            self.tr("Use these limits for this device from now on (kept for it)"),
        )
        self.revert_button = make_button(
            self.tr("Revert"), "travelRevertButton", self.tr("Show the limits in use again")
        )
        self.apply_button.clicked.connect(self._apply)
        self.revert_button.clicked.connect(self.revert)
        self.form.changed.connect(self._sync)
        buttons = QHBoxLayout()
        buttons.addStretch(1)
        buttons.addWidget(self.revert_button)
        buttons.addWidget(self.apply_button)
        layout = QVBoxLayout(self)
        layout.addWidget(self.form)
        layout.addLayout(buttons)
        layout.addStretch(1)
        self.set_device("", None, False)

    def set_device(self, device: str, box: Box | None, clamp: bool) -> None:
        """The device connected (described; "": none, the form is off) and its limits."""
        self._connected = bool(device)
        self.form.set_device(device)
        self.form.setEnabled(self._connected)
        self.show_limits(box, clamp)

    def show_limits(self, box: Box | None, clamp: bool) -> None:
        """The limits in use now (set here, from the menu's dialog, or at connection)."""
        self._applied = (box, clamp)
        self.form.set_limits(box, clamp)

    def revert(self) -> None:
        """Show the limits in use again, dropping the edits."""
        self.form.set_limits(*self._applied)

    def _apply(self) -> None:
        if self._connected and not self.form.problem():
            box, clamp = self.form.result_limits()
            self.apply_requested.emit(box, clamp)

    def _sync(self) -> None:
        box, clamp = self.form.result_limits()
        applied_box, applied_clamp = self._applied
        same = box == applied_box and (box is None or clamp == applied_clamp)
        self.apply_button.setEnabled(self._connected and not same and not self.form.problem())
        self.revert_button.setEnabled(self._connected and not same)
