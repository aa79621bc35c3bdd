"""The position on one line ("X 1.00 mm  Y 2.00 mm · estimated"), following a PositionReadout:
the small readout of a layout that has no room for the large one (Traffic)."""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QWidget

from widgets._i18n import fill
from widgets.position_readout import PositionReadout


class CompactReadout(QLabel):
    """One line of what `readout` shows: each axis's machine position, and its status badge."""

    def __init__(self, readout: PositionReadout, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("compactReadout")
        self.readout = readout
        readout.shown_changed.connect(self._follow)
        self._follow()

    def _follow(self) -> None:
        readout = self.readout
        shown = [axis for axis, label in readout.labels.items() if not label.isHidden()]
        text = "  ".join(f"{axis.upper()} {readout.labels[axis].text()}" for axis in shown)
        if text != self.text():
            self.setText(text)
        # The status as the large readout shows it: its colour and slant; its words as the tip.
        colour, italic = readout.value_style(shown[0]) if shown else ("", False)
        style = f"color: {colour}; font-style: {'italic' if italic else 'normal'};"
        if style != self.styleSheet():
            self.setStyleSheet(style)
        badge = readout.status_label.text() if not readout.status_label.isHidden() else ""
        tip = self.tr("Stage position from the device's home")
        tip = (
            fill(self.tr("%1 (%2)", "the position's tip, then its status"), tip, badge)
            if badge
            else tip
        )
        if tip != self.toolTip():
            self.setToolTip(tip)
