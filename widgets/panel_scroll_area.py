"""A scroll area for a dock panel: as big as its panel when there is room, scrolling when not."""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QFrame, QScrollArea, QWidget


class PanelScrollArea(QScrollArea):
    """Asks for its panel's full size and width; scrolls vertically only on a small screen."""

    def __init__(self, panel: QWidget, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName(f"{panel.objectName()}Scroll")
        self.setWidgetResizable(True)
        self.setFrameShape(QFrame.Shape.NoFrame)
        self.setFocusPolicy(Qt.FocusPolicy.NoFocus)  # the arrow keys stay with jogging
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.setWidget(panel)

    def _bar(self) -> int:
        # The style's scroll bar extent, as the vertical bar asks for it: not through QStyle,
        # whose first use in PySide makes its eleven enums (~13 ms before the first paint).
        return self.verticalScrollBar().sizeHint().width()

    def sizeHint(self) -> QSize:
        """The panel's own size hint, with room for a scroll bar."""
        hint = self.widget().sizeHint()
        return QSize(hint.width() + self._bar(), hint.height())

    def minimumSizeHint(self) -> QSize:
        """The panel's full minimum width (never squeezed sideways), and a few rows high."""
        panel = self.widget().minimumSizeHint()
        return QSize(panel.width() + self._bar(), min(panel.height(), 80))
