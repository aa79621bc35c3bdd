"""A dialog to set a device's travel box, and whether moves beyond it are refused or clamped."""

from __future__ import annotations

from PySide6.QtWidgets import (
    QCheckBox,
    QDialog,
    QDialogButtonBox,
    QGridLayout,
    QLabel,
    QRadioButton,
    QVBoxLayout,
    QWidget,
)

from widgets._axes import AXES, Box
from widgets._i18n import fill
from widgets._number_field import NumberSpinBox

SPIN_LIMIT_MM = 99999.0
DEFAULT_BOX: Box = ((-100.0, 100.0), (-100.0, 100.0), (0.0, 50.0))


class TravelLimitsDialog(QDialog):
    """Edit a travel box in mm; `result_limits()` gives (box or None, clamp)."""

    def __init__(
        self, device: str, box: Box | None, clamp: bool, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("travelLimitsDialog")
        self.setWindowTitle(self.tr("Travel limits"))
        intro = QLabel(
            fill(
                self.tr(
                    "Where the stage may go on %1. A jog, go-to or command-line move that "
                    "would leave the box is refused before anything is sent, or clamped to "
                    "its edge."
                ),
                device,
            )
        )
        intro.setWordWrap(True)
        self.enabled_check = QCheckBox(self.tr("Limit moves to this box"))
        self.enabled_check.setObjectName("travelEnabled")
        self.enabled_check.setChecked(box is not None)
        self.enabled_check.toggled.connect(self._sync)

        grid = QGridLayout()
        grid.addWidget(QLabel(self.tr("min")), 0, 1)
        grid.addWidget(QLabel(self.tr("max")), 0, 2)
        self.spins: dict[str, tuple[NumberSpinBox, NumberSpinBox]] = {}
        shown = box or DEFAULT_BOX
        for row, (axis, (low, high)) in enumerate(zip(AXES, shown, strict=True), start=1):
            grid.addWidget(
                QLabel(fill(self.tr("%1:", "an axis field's label"), axis.upper())), row, 0
            )
            name = f"travel{axis.upper()}"
            pair = (self._spin(f"{name}Min", low), self._spin(f"{name}Max", high))
            pair[0].set_what(fill(self.tr("%1 min", "an axis' lower travel limit"), axis.upper()))
            pair[1].set_what(fill(self.tr("%1 max", "an axis' upper travel limit"), axis.upper()))
            grid.addWidget(pair[0], row, 1)
            grid.addWidget(pair[1], row, 2)
            self.spins[axis] = pair

        self.refuse_radio = QRadioButton(self.tr("Refuse a move that would leave the box"))
        self.refuse_radio.setObjectName("travelRefuse")
        self.clamp_radio = QRadioButton(self.tr("Clamp it: go as far as the edge, and say so"))
        self.clamp_radio.setObjectName("travelClamp")
        (self.clamp_radio if clamp else self.refuse_radio).setChecked(True)
        self.problem_label = QLabel()
        self.problem_label.setObjectName("travelProblem")
        self.problem_label.setStyleSheet("color: #c62828;")

        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        for widget in (intro, self.enabled_check):
            layout.addWidget(widget)
        layout.addLayout(grid)
        for widget in (self.refuse_radio, self.clamp_radio, self.problem_label, self.buttons):
            layout.addWidget(widget)
        self._sync()

    def _spin(self, name: str, value: float) -> NumberSpinBox:
        spin = NumberSpinBox()
        spin.setObjectName(name)
        spin.setRange(-SPIN_LIMIT_MM, SPIN_LIMIT_MM)
        spin.setDecimals(2)
        spin.setSuffix(" mm")
        spin.setValue(value)
        spin.valueChanged.connect(self._sync)
        spin.lineEdit().textChanged.connect(self._sync)  # typed text that cannot be used, too
        return spin

    def _sync(self) -> None:
        enabled = self.enabled_check.isChecked()
        for low, high in self.spins.values():
            low.setEnabled(enabled)
            high.setEnabled(enabled)
        self.refuse_radio.setEnabled(enabled)
        self.clamp_radio.setEnabled(enabled)
        problem = self.problem() if enabled else ""
        self.problem_label.setText(problem)
        ok = self.buttons.button(QDialogButtonBox.StandardButton.Ok)
        ok.setEnabled(not problem)

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
