"""A dialog to set a device's travel box, and whether moves beyond it are refused or clamped."""

from __future__ import annotations

from PySide6.QtWidgets import QDialog, QDialogButtonBox, QVBoxLayout, QWidget

from widgets._axes import Box
from widgets.travel_limits_form import TravelLimitsForm


class TravelLimitsDialog(QDialog):
    """Edit a travel box in mm (TravelLimitsForm); `result_limits()` gives (box or None, clamp)."""

    def __init__(
        self, device: str, box: Box | None, clamp: bool, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("travelLimitsDialog")
        self.setWindowTitle(self.tr("Travel limits"))
        self.form = TravelLimitsForm(device, box, clamp, self)
        # The form's parts, as the dialog's own (tests and callers reach them here).
        self.enabled_check = self.form.enabled_check
        self.spins = self.form.spins
        self.refuse_radio = self.form.refuse_radio
        self.clamp_radio = self.form.clamp_radio
        self.problem_label = self.form.problem_label
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(self.form)
        layout.addWidget(self.buttons)
        self.form.changed.connect(self._sync)
        self._sync()

    def _sync(self) -> None:
        ok = self.buttons.button(QDialogButtonBox.StandardButton.Ok)
        ok.setEnabled(not self.problem())

    def problem(self) -> str:
        """Why the box cannot be used ("" when it can)."""
        return self.form.problem() if self.enabled_check.isChecked() else ""

    def result_limits(self) -> tuple[Box | None, bool]:
        """The box in mm (None: no limits) and whether to clamp."""
        return self.form.result_limits()
