"""Waiting for a worker's signal from the GUI thread, as the window receives it.

pytest-qt's waitSignal connects a plain function, which Qt calls in the emitter's thread: for a
signal of the serial worker that stops the blocker's timer from the worker's thread (a Qt
warning, and a race). A relay QObject living in the GUI thread receives it queued instead.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from PySide6.QtCore import QObject, Signal


class GuiRelay(QObject):
    """Re-emits `signal`'s arguments as one list, in the thread this relay lives in."""

    fired = Signal(list)

    def __init__(self, signal: Any) -> None:
        super().__init__()
        signal.connect(self._forward)

    def _forward(self, *args: object) -> None:
        self.fired.emit(list(args))


class Received:
    """The arguments the signal was emitted with, once it has been (`args`)."""

    def __init__(self, blocker: Any) -> None:
        self._blocker = blocker

    @property
    def args(self) -> list[object]:
        """The signal's arguments."""
        return self._blocker.args[0] if self._blocker.args else []


@contextmanager
def wait_in_gui(qtbot: Any, signal: Any, timeout: int = 5000) -> Iterator[Received]:
    """Like `qtbot.waitSignal(signal)`, with the signal received in the GUI thread."""
    relay = GuiRelay(signal)
    with qtbot.waitSignal(relay.fired, timeout=timeout) as blocker:
        yield Received(blocker)
    relay.deleteLater()
