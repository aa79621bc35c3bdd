"""The position views as the window's centre: the 3D view and the 2D plots (XY, time) as two
tabs, so that the one shown has the whole central area (issue 28 item 20)."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QSplitter, QTabWidget, QWidget

VIEW_3D, VIEW_2D = 0, 1


def _page(view: QWidget, name: str) -> QSplitter:
    """A page holding `view` alone: a splitter, so that a stand-in view built later
    (widgets/lazy_view.py) is replaced in its place by the real one."""
    page = QSplitter(Qt.Orientation.Horizontal)
    page.setObjectName(name)
    page.setChildrenCollapsible(False)
    page.setHandleWidth(0)
    page.addWidget(view)
    return page


class ViewTabs(QTabWidget):
    """The 3D view and the 2D plots, one tab each; the tab bar never takes the keyboard (the
    arrow keys stay with jogging)."""

    def __init__(self, view3d: QWidget, view2d: QWidget, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("viewTabs")
        self.setDocumentMode(True)  # no frame around the pages: the views take the room
        self.addTab(_page(view3d, "view3dPage"), self.tr("3D"))
        self.addTab(_page(view2d, "view2dPage"), self.tr("XY and time"))
        self.setTabToolTip(VIEW_3D, self.tr("The path in 3D"))
        self.setTabToolTip(VIEW_2D, self.tr("The path seen from above and X, Y, Z against time"))
        self.tabBar().setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.setFocusPolicy(Qt.FocusPolicy.NoFocus)

    def state(self) -> int:
        """The tab shown (kept per layout)."""
        return self.currentIndex()

    def restore(self, state: object) -> None:
        """Show the tab `state` names (as `state()` gave it; anything else: the 3D view)."""
        try:
            index = int(state)  # type: ignore[call-overload]  # (QSettings may give a string)
        except (TypeError, ValueError):
            index = VIEW_3D
        self.setCurrentIndex(index if index in (VIEW_3D, VIEW_2D) else VIEW_3D)
