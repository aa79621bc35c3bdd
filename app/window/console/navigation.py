"""Where the traffic console's table is: following the tail as lines come (a `paused` label
shows while the user has scrolled up), or on a line chosen, and the search's matches stepped
through."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from PySide6.QtCore import QObject
from PySide6.QtWidgets import QAbstractItemView, QLabel, QWidget

from app.window.console.table import BYTES, TrafficModel, TrafficView


class TrafficNavigator(QObject):
    """The table's place (`view` showing `model`): following the tail or not."""

    def __init__(
        self, parent: QWidget, view: TrafficView, model: TrafficModel, paused_label: QLabel
    ) -> None:
        super().__init__(parent)
        self.view = view
        self.model = model
        self.paused_label = paused_label
        self.following = True
        self._scrolling = False  # the table scrolled by the console, not by the user
        view.verticalScrollBar().valueChanged.connect(self.scrolled)
        view.verticalScrollBar().rangeChanged.connect(self._range_changed)

    def current_line(self) -> int | None:
        """The line of the selected row."""
        index = self.view.currentIndex()
        if not index.isValid() or index.row() >= len(self.model.rows):
            return None
        return int(self.model.rows[index.row()])

    def go_to_row(self, row: int) -> None:
        """Select a row and scroll to it; the tail is followed if it is the last."""
        if row < 0:
            return
        index = self.model.index(row, BYTES)
        self._scrolling = True
        try:
            self.view.setCurrentIndex(index)
            self.view.scrollTo(index, QAbstractItemView.ScrollHint.PositionAtCenter)
        finally:
            self._scrolling = False
        self.set_follow(row == len(self.model.rows) - 1)  # a line chosen stays in view

    def scroll_to_end(self) -> None:
        """Show the last row."""
        self._scrolling = True
        try:
            self.view.scrollToBottom()
        finally:
            self._scrolling = False

    def follow_tail(self) -> None:
        """Rows were added: show the last if following."""
        if self.following:
            self.scroll_to_end()

    def _range_changed(self) -> None:
        if self.following and not self._scrolling:  # (scrolling to the end does it anyway)
            self.scroll_to_end()

    def scrolled(self, value: int) -> None:
        """The scroll bar moved (to `value`): following if at the bottom, unless the console
        scrolled it."""
        if self._scrolling:
            return
        self.set_follow(value >= self.view.verticalScrollBar().maximum())

    def set_follow(self, follow: bool) -> None:
        """Follow the tail, or stay where the view is (`paused` shown)."""
        self.following = follow
        self.paused_label.setVisible(not follow)

    def keep_place(self, drop: Callable[[], None]) -> None:
        """Drop the oldest rows (`drop` does it): a view following the tail keeps following;
        one scrolled up keeps its top line in place (or shows the oldest line kept, if its own
        was dropped)."""
        view, model = self.view, self.model
        top_row = view.rowAt(0)
        top_line = int(model.rows[top_row]) if 0 <= top_row < len(model.rows) else None
        self._scrolling = True  # (Qt's own scrolling as the rows go is not the user's)
        try:
            drop()
            if self.following:
                view.scrollToBottom()
            elif top_line is not None and len(model.rows):
                row = min(model.row_of(top_line), len(model.rows) - 1)
                view.scrollTo(model.index(row, BYTES), QAbstractItemView.ScrollHint.PositionAtTop)
        finally:
            self._scrolling = False

    def next_match(self, forward: bool) -> int | None:
        """The next (or previous) shown line the search matches after the selected one,
        wrapping around; None if none."""
        matches = self.model.matches
        matches = matches[np.isin(matches, self.model.rows)]
        if not len(matches):
            return None
        current = self.current_line()
        if current is None:
            target = matches[0] if forward else matches[-1]
        elif forward:
            after = matches[matches > current]
            target = after[0] if len(after) else matches[0]  # wraps around
        else:
            before = matches[matches < current]
            target = before[-1] if len(before) else matches[-1]
        return int(target)
