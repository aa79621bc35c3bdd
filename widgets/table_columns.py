"""A table's columns sized to their text, one of them taking the width left: every header border
can be dragged (no Stretch section pins the others), and a column the operator dragged keeps
the width given, until the table is shown anew."""

from __future__ import annotations

from collections.abc import Iterable

from PySide6.QtCore import QEvent, QObject, Qt, QTimer
from PySide6.QtWidgets import QApplication, QHeaderView, QTableView


class FittedColumns(QObject):
    """Sizes `view`'s columns: those of `to_text` as wide as their header and the rows on screen
    need (never narrower than they are), the `fillers` share the width left in the viewport
    (each its share of it, at least `least` px: below that the table scrolls sideways, and a
    cut cell is elided, its tooltip whole). A column whose border the operator drags keeps
    the width given."""

    def __init__(
        self,
        view: QTableView,
        to_text: Iterable[int],
        fillers: dict[int, float],
        least: int,
    ) -> None:
        super().__init__(view)
        self.view = view
        self.to_text = tuple(to_text)
        self.fillers = dict(fillers)
        self.least = least
        self.dragged: set[int] = set()  # columns whose border the operator moved
        header = view.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        header.sectionResized.connect(self._resized)
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(0)
        self._timer.timeout.connect(self.fit)
        model = view.model()
        for signal in (model.modelReset, model.layoutChanged):
            signal.connect(self._timer.start)
        if self.to_text:  # (their text can change with any cell)
            model.dataChanged.connect(self._timer.start)
        view.viewport().installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """The viewport resized or shown: fit again."""
        if event.type() in (QEvent.Type.Resize, QEvent.Type.Show):
            self._timer.start()
        return False

    def _resized(self, column: int, _old: int, _new: int) -> None:
        # Only a drag of the header's border has the mouse button down: not the code's resizes.
        if QApplication.mouseButtons() & Qt.MouseButton.LeftButton:
            self.dragged.add(column)

    def fit(self) -> None:
        """Size the columns now (those the operator dragged keep their width)."""
        view = self.view
        header = view.horizontalHeader()
        header.setStretchLastSection(False)  # the fillers take the width, not the last column
        for column in self.to_text:
            if column not in self.dragged and not view.isColumnHidden(column):
                needed = max(view.sizeHintForColumn(column), header.sectionSizeHint(column))
                if needed > view.columnWidth(column):
                    view.setColumnWidth(column, needed)
        fillers = {
            column: share
            for column, share in self.fillers.items()
            if column not in self.dragged and not view.isColumnHidden(column)
        }
        others = sum(
            view.columnWidth(column)
            for column in range(view.model().columnCount())
            if column not in fillers and not view.isColumnHidden(column)
        )
        left = view.viewport().width() - others
        total = sum(fillers.values()) or 1.0
        for column, share in fillers.items():
            view.setColumnWidth(column, max(self.least, int(left * share / total)))
