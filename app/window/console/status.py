"""The traffic console's status line: lines kept and shown, older ones in the session log,
polls hidden, errors, search matches; in a flood, updated at most 4 times a second. The strings
are in the console's translation context (RawConsole)."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import NamedTuple

from PySide6.QtCore import QCoreApplication, QObject, QTimer
from PySide6.QtWidgets import QLabel, QSizePolicy, QWidget

from widgets._i18n import fill

STATUS_INTERVAL_S = 0.25  # the status line's counts follow a flood at most 4 times a second


class StatusFigures(NamedTuple):
    """What the status line says."""

    kept: int  # lines in the console
    shown: int  # lines through the filters
    older: int  # lines dropped by the line limit (the session log has them)
    poll_hidden: int  # poll lines hidden by the filters
    errors: int
    matches: int | None  # shown lines the search matches (None: no search)
    limit: int  # the console's line limit (0: none)
    matches_hidden: int = 0  # lines the search matches that the filters hide


class ConsoleStatus(QObject):
    """The status line (`label`, laid out by the console, `parent`), its figures read from
    `figures` when it is updated."""

    def __init__(self, parent: QWidget, figures: Callable[[], StatusFigures]) -> None:
        super().__init__(parent)
        self._figures = figures
        self._at = 0.0  # perf_counter of the last update
        self.label = QLabel()
        self.label.setObjectName("consoleStatus")
        self.label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.label.setMinimumWidth(0)
        self.label.setToolTip(
            QCoreApplication.translate(
                "RawConsole", "Lines in the session, shown, hidden polls, errors, matches"
            )
        )
        self.timer = QTimer(self)
        self.timer.setObjectName("consoleStatusTimer")
        self.timer.setSingleShot(True)
        self.timer.setInterval(int(STATUS_INTERVAL_S * 1000))
        self.timer.timeout.connect(self.refresh)

    def refresh(self) -> None:
        """Show the figures now."""
        self.timer.stop()
        self._at = time.perf_counter()
        figures = self._figures()
        lines = (
            QCoreApplication.translate("RawConsole", "%1 line")
            if figures.kept == 1
            else QCoreApplication.translate("RawConsole", "%1 lines")
        )
        parts = [
            fill(lines, f"{figures.kept:,}"),
            fill(QCoreApplication.translate("RawConsole", "%1 shown"), f"{figures.shown:,}"),
        ]
        if figures.older:
            older = QCoreApplication.translate("RawConsole", "%1 older in the session log")
            parts.append(fill(older, f"{figures.older:,}"))
        if figures.poll_hidden:
            hidden = QCoreApplication.translate("RawConsole", "%1 poll hidden")
            parts.append(fill(hidden, f"{figures.poll_hidden:,}"))
        if figures.errors:
            errors = (
                QCoreApplication.translate("RawConsole", "%1 error")
                if figures.errors == 1
                else QCoreApplication.translate("RawConsole", "%1 errors")
            )
            parts.append(fill(errors, f"{figures.errors:,}"))
        if figures.matches is not None:
            matches = (
                QCoreApplication.translate("RawConsole", "%1 match")
                if figures.matches == 1
                else QCoreApplication.translate("RawConsole", "%1 matches")
            )
            parts.append(fill(matches, f"{figures.matches:,}"))
            if figures.matches_hidden:  # found, but not in the view: Enter cannot go there
                hidden = QCoreApplication.translate("RawConsole", "%1 more hidden by the filters")
                parts.append(fill(hidden, f"{figures.matches_hidden:,}"))
        self.label.setText(" · ".join(parts))
        tip = parts
        if figures.limit:
            limit = QCoreApplication.translate(
                "RawConsole",
                "The console keeps the newest %1 lines (Settings): older lines are dropped from"
                " it, the session log on disk keeps every line",
            )
            tip = [*parts, fill(limit, f"{figures.limit:,}")]
        self.label.setToolTip("\n".join(tip))

    def refresh_soon(self, now: float) -> None:
        """The figures changed (at `now`, perf_counter): shown now if the last update was
        STATUS_INTERVAL_S ago, else when that time has passed."""
        if now - self._at >= STATUS_INTERVAL_S:
            self.refresh()
        elif not self.timer.isActive():
            self.timer.start()

    def text(self) -> str:
        """The figures as the status line says them (up to date)."""
        if self.timer.isActive():  # a flood's counts are shown a few times a second
            self.refresh()
        return self.label.text()
