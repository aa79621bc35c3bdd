"""What stands where the 3D view would be without OpenGL: its words and the placeholder."""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Qt
from PySide6.QtWidgets import QLabel, QWidget

from widgets._axes import Box
from widgets._i18n import fill
from widgets._units import check_units

NOTICE_COLOUR = (97, 97, 97)
NOTICE_STYLE = "color: #616161; border: 1px dashed #9e9e9e;"
NOTICE_TOOLTIP = QT_TRANSLATE_NOOP(
    "PositionView3D", "Needs OpenGL 2.1 or newer (e.g. Mesa) on a display; see the README."
)


def notice_text(reason: str) -> str:
    """The words shown where the 3D view would be, for `reason`."""
    template = QCoreApplication.translate(
        "PositionView3D",
        "3D view unavailable: OpenGL could not be initialised.\n(%1)\n"
        "The 2D view shows the same positions.",
    )
    return fill(template, reason)


class PositionView3DPlaceholder(QLabel):
    """Stands in for the 3D view when OpenGL is unavailable; same API, does nothing."""

    def __init__(self, reason: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("positionView3d")
        self.reason = reason
        self.setText(notice_text(reason))
        self.setToolTip(QCoreApplication.translate("PositionView3D", NOTICE_TOOLTIP))
        self.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.setWordWrap(True)
        self.setStyleSheet(NOTICE_STYLE)

    def refresh(self) -> None:
        """Nothing to draw."""

    def set_target(self, x: object, y: float | None = None, z: float | None = None) -> None:
        """Nothing to draw."""

    def clear_trail(self) -> None:
        """Nothing to draw."""

    def reset_view(self) -> None:
        """Nothing to draw."""

    def set_workspace(self, box: Box | None) -> None:
        """Nothing to draw."""

    def set_preview(self, points: object) -> None:
        """Nothing to draw."""

    def preview(self) -> list[tuple[float, float, float]]:
        """Nothing drawn: []."""
        return []

    def set_program(self, points: np.ndarray | None, rapid: np.ndarray | None = None) -> None:
        """Nothing to draw."""

    def set_program_done(self, row: int) -> None:
        """Nothing to draw."""

    def program(self) -> np.ndarray:
        """Nothing drawn: (0, 3)."""
        return np.zeros((0, 3))

    def grid_spacing(self) -> float:
        """No grid: 0.0."""
        return 0.0

    def set_view_preset(self, name: str) -> None:
        """No camera."""

    def set_follow(self, on: bool) -> None:
        """No camera."""

    def is_following(self) -> bool:
        """Never following."""
        return False

    def set_estimated(self, estimated: bool) -> None:
        """Nothing to draw."""

    def set_units(self, units: str) -> None:
        """Nothing drawn in any units."""
        check_units(units)

    def is_estimated(self) -> bool:
        """Nothing drawn: False."""
        return False
