"""Start-up marks for bench/startup.py: with MOTIONPANEL_STARTUP_MARKS=PATH set, the panel writes
the system's monotonic time of its window's first paint, of its views being built and of the
device shown connected to PATH (one JSON object), then quits."""

from __future__ import annotations

import json
import os
import time

from PySide6.QtCore import QEvent, QObject, QTimer

ENV = "MOTIONPANEL_STARTUP_MARKS"


class StartupMarks(QObject):
    """Notes the marks as they happen; writes them and closes the window once all are in."""

    def __init__(self, window: QObject, path: str) -> None:
        super().__init__(window)
        self._window = window
        self._path = path
        self.marks: dict[str, float] = {}
        window.installEventFilter(self)
        window.views.ready.connect(lambda: self._mark("ready"))  # type: ignore[attr-defined]
        window.connection.device_shown.connect(  # type: ignore[attr-defined]
            lambda: self._mark("connected")
        )

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """The window's first paint."""
        if event.type() == QEvent.Type.Paint and "painted" not in self.marks:
            self._mark("painted")
        return False

    def _mark(self, name: str) -> None:
        self.marks.setdefault(name, time.monotonic())
        if {"painted", "ready", "connected"} <= self.marks.keys():
            with open(self._path, "w", encoding="utf-8") as out:
                json.dump(self.marks, out)
            QTimer.singleShot(0, self._window.close)  # type: ignore[attr-defined]


def watch_startup(window: QObject) -> StartupMarks | None:
    """Start-up marks for `window` when MOTIONPANEL_STARTUP_MARKS names a file (else None)."""
    path = os.environ.get(ENV)
    return StartupMarks(window, path) if path else None
