"""What a program's Pause really does on the device connected, said when it is pressed: nothing
more is sent, how many moves the device still holds and when it will stand still. Said on the
status line and in the console, and written into the session log at once (in English), though the
worker is busy with the program."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Protocol

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject

from widgets import status_line as status
from widgets._i18n import fill

if TYPE_CHECKING:
    from app.window.device.worker import SerialWorker
    from drivers.toolpath.streaming import StreamProgress

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"

NO_FEED_HOLD = QT_TRANSLATE_NOOP(
    "MainWindow",
    "paused: nothing more is sent; the move under way finishes (this device has no feed hold)",
)
RESUMED = QT_TRANSLATE_NOOP("MainWindow", "resumed: sending the program again")
HOLDS = QT_TRANSLATE_NOOP(
    "MainWindow",
    "paused: nothing more is sent; the device still holds %1 move(s) and runs them (its "
    "protocol has no feed hold): it stands still in about %2 s; Stop flushes them now",
)
STANDS_STILL = QT_TRANSLATE_NOOP(
    "MainWindow", "paused: the device has run what it held; the stage stands still"
)


class PausedMachine(Protocol):
    """What the pause needs of the machine state (app/window/device/machine_state.py, which builds
    it: named here by shape, so the two modules do not import each other)."""

    info: Any
    busy_job: Any
    window: Any

    def show_status(self, connection: str = "", detail: str = "") -> None: ...


class ProgramPause(QObject):
    """Follows Pause and Resume and the program's progress; tells the operator what goes on."""

    def __init__(self, machine: PausedMachine) -> None:
        super().__init__(machine)  # (a QObject: the machine state)
        self.machine = machine
        self.paused = False
        self._said_held = False  # the device's queue at the pause, said once
        self._said_still = False  # its end, said once
        self._worker: SerialWorker | None = None  # writes the session log

    def wire(self, w: SerialWorker) -> None:
        """Pause and progress reports of the worker, to bound methods (queued to the GUI)."""
        self._worker = w
        w.program_paused.connect(self._on_paused)
        w.stream_progress.connect(self._on_progress)

    def _queued(self) -> bool:
        info = self.machine.info
        return info is not None and info.capabilities.streaming

    def _on_paused(self, paused: bool) -> None:
        if paused == self.paused or (paused and self.machine.busy_job is None):
            return
        self.paused = paused
        self._said_held = self._said_still = False
        if paused and not self._queued():
            self._say(NO_FEED_HOLD, status.INFO)
        elif not paused:
            self._say(RESUMED, status.INFO)
        self.machine.show_status()

    def ended(self) -> None:
        """The program ended: nothing is paused any more."""
        self.paused = False

    def _on_progress(self, progress: StreamProgress) -> None:
        if not self.paused or not self._queued():
            return
        held = progress.held
        if not self._said_held and held:
            self._said_held = True
            self._say(HOLDS, status.WARNING, held, f"{math.ceil(progress.held_s):d}")
        elif held == 0 and not self._said_still:
            self._said_held = self._said_still = True
            self._say(STANDS_STILL, status.INFO)

    def _say(self, english: str, kind: str, *values: object) -> None:
        """Tell the operator, and write it into the session log now, in English: the worker
        is busy with the program, so a note queued to it would come after the program."""
        self.machine.window.tell(fill(translate("MainWindow", english), *values), kind)
        if self._worker is not None:
            self._worker.note_now(fill(english, *values))
