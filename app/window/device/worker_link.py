"""One device's serial worker as the window sees it: built late, what is asked of it kept till then,
and the session log handed to it."""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, QSettings

from app.common.session_log import open_session_log
from app.window.preferences import Preferences, poll_rates, session_log_folder
from widgets._i18n import fill

if TYPE_CHECKING:
    from typing import TextIO

    from app.window.device.worker import SerialWorker
    from app.window.device.worker_thread import WorkerThread

log = logging.getLogger(__name__)
translate = QCoreApplication.translate


class WorkerLink(QObject):
    """The serial worker and its thread, built just after the window's first paint (they import
    the jobs, the motion engine, the client and pyserial) or as soon as asked for; what is asked
    of the worker's thread before that (connect, disconnect, travel limits, the session log) is
    kept and done then, in order. `wirers` connect the worker's signals before its thread runs.
    """

    def __init__(
        self, parent: QObject, settings: QSettings, given: WorkerThread | None = None
    ) -> None:
        super().__init__(parent)
        self.thread: WorkerThread | None = None  # None until built
        self._given = given
        self._settings = settings
        self._calls: list[Callable[[WorkerThread], object]] = []  # until it is built
        self.wirers: list[Callable[[SerialWorker], object]] = []
        self.pending_log: TextIO | None = None  # the session log, until the worker has it
        self.closed = False
        self.session_log_path: Path | None = None
        self.log_start: float | None = None  # time.monotonic() the session log counts from

    def get(self) -> WorkerThread:
        """The worker's thread, built now if it is not yet; then what was asked of it before,
        in order. Harmless to call again."""
        if self.thread is not None:
            return self.thread
        from app.window.device.worker_thread import WorkerThread

        thread = self._given
        worker = thread.worker if thread is not None else self._make_worker()
        for wire in self.wirers:  # before its thread starts: it says nothing unheard
            wire(worker)
        if thread is None:
            thread = WorkerThread(worker)
        self.thread, self._given = thread, None
        if self.closed:  # asked for after the window closed: one that has stopped
            thread.stop()
            return thread
        calls, self._calls = self._calls, []
        self.pending_log = None  # handed over by the calls
        for call in calls:
            call(thread)
        return thread

    def _make_worker(self) -> SerialWorker:
        """A worker with the saved polling rates (5-10 Hz while a move is confirmed, 1 s idle)."""
        moving_hz, idle_s = poll_rates(self._settings)
        from app.window.device.worker import SerialWorker

        return SerialWorker(poll_moving_hz=moving_hz, poll_idle_s=idle_s)

    def start(self) -> None:
        """Just after the first paint: the worker, unless the window has closed meanwhile."""
        if not self.closed:
            self.get()

    def to_worker(self, call: Callable[[WorkerThread], object]) -> None:
        """`call(worker_thread)` now, or once the worker is built (in the order asked)."""
        if self.thread is not None:
            call(self.thread)
        else:
            self._calls.append(call)

    def close(self) -> None:
        """The window closes: stop the worker's thread, or forget what was asked of it."""
        self.closed = True
        if self.thread is not None:
            if not self.thread.stop():
                log.error("the serial worker did not stop in time")
            return
        self._calls.clear()  # closed before the worker was built: nothing asked of it is done
        if self.pending_log is not None:
            self.pending_log.close()
            self.pending_log = None

    # -- the session log -------------------------------------------------------------------------
    def start_session_log(self, prefs: Preferences, note: Callable[[str, bool], None]) -> None:
        """Every byte of this session to a file in the log folder (on unless turned off);
        `note(text, warning)` tells the operator."""
        self.session_log_path = None
        if not prefs.session_log:
            return
        try:
            path, stream = open_session_log(session_log_folder(prefs))
        except OSError as exc:
            note(fill(translate("MainWindow", "no session log: %1"), exc), True)
            return
        self.log_start = time.monotonic()
        self.pending_log = stream  # closed here should the window close before the worker is

        def hand_over(thread: WorkerThread) -> None:
            self.log_start = time.monotonic()  # the worker's log counts from about now
            thread.set_session_log(stream)

        self.to_worker(hand_over)
        note(fill(translate("MainWindow", "session log: %1"), path), False)
        self.session_log_path = path

    def restart_session_log(self, prefs: Preferences, note: Callable[[str, bool], None]) -> None:
        """Follow the session-log settings now: a new file in the folder chosen (the worker
        goes on in it, and each file names the other), or no log at all."""
        self.start_session_log(prefs, note)
        if self.session_log_path is None:
            self.to_worker(lambda thread: thread.set_session_log(None))
            note(translate("MainWindow", "no session log from now on"), False)
