"""The serial worker: one QObject on a QThread owns the device's session; the GUI talks to it by
signals. Jobs (job_dispatch.py), the port watch, the traffic batches, the restart watch, the modem
lines and the session log each live in their own module; this one holds the connection's life
cycle and the loop."""

from __future__ import annotations

import logging
import queue
import threading
import time
from collections.abc import Callable
from typing import TextIO

from PySide6.QtCore import QCoreApplication, QObject, QThread, QTimer, Signal, Slot

from app.common.macros import MacroStopped
from app.common.messages import localized
from app.window.device import jobs
from app.window.device.connect_options import ConnectOptions, DeviceInfo
from app.window.device.job_dispatch import dispatch
from app.window.device.line_watch import LineWatch
from app.window.device.port_watch import PortWatch
from app.window.device.restart_watch import RestartWatch
from app.window.device.session_log_switch import SessionLog
from app.window.device.traffic_batch import TrafficBatch
from app.window.device.worker_connection import WorkerConnection
from drivers.device.travel import TravelLimits
from drivers.errors import (
    Aborted,
    CommunicationError,
    DeviceTimeout,
    MotionError,
    NoControlLines,
    PortError,
)
from drivers.messages import Message, message_of
from drivers.session.device_session import DeviceSession
from drivers.session.subscriptions import Unsubscribe

__all__ = ["ConnectOptions", "DeviceInfo", "SerialWorker", "failure_text"]

log = logging.getLogger(__name__)

TICK_MS = 20  # the worker's loop period: queue, unsolicited input, polling


class SerialWorker(WorkerConnection, QObject):
    """Owns the session; runs jobs from a queue; polls the position; reports by signals.

    Only `submit`, `cancel_pending`, `abort`, `stop_now`, `stream_pause`, `stream_stop` and
    `note_now` may be called from another thread; everything else runs in the worker's thread
    via queued signals.
    """

    state_changed = Signal(str, str)  # connecting | connected | disconnected | error; detail
    device_ready = Signal(object)  # DeviceInfo
    traffic = Signal(list)  # list[Traffic], batched
    position_changed = Signal(object)  # PositionReport
    whereabouts_changed = Signal(object)  # Whereabouts: the session's, when its link is lost
    target_changed = Signal(object)  # (x, y, z) or None
    speed_changed = Signal(float)
    speed_limits_changed = Signal(float, float)
    busy_changed = Signal(bool)
    job_finished = Signal(object, object)  # Job, result
    job_failed = Signal(object, str)  # Job, message
    job_stopped = Signal(object, str)  # Job, message: the operator's stop ended it (not a failure)
    program_paused = Signal(bool)  # Pause (True) or Resume (False) of the program under way
    move_started = Signal(object)  # MoveStart: from, to, speed, when
    notice = Signal(str)  # something the operator should know, e.g. a move clamped to the limits
    device_error = Signal(str)  # an error the device reported unasked (e.g. to a console line)
    device_note = Signal(str)  # an unsolicited frame that could not be decoded
    parameter_written = Signal(object)  # ParameterWritten: the device confirmed a parameter
    job_timed_out = Signal(object)  # Job: the device did not answer it (before job_failed)
    capabilities_changed = Signal(object)  # Capabilities, after new protocol settings
    stream_progress = Signal(object)  # StreamProgress (a copy), while a program streams
    macro_step = Signal(str, int, int, str)  # macro name, step number, step count, step text
    control_lines_changed = Signal(object)  # ControlLines: after connecting, a change, an input
    control_note = Signal(str)  # a line change or a break, for the console: "DTR off", "CTS on"

    def __init__(self, poll_moving_hz: float = 10.0, poll_idle_s: float = 1.0) -> None:
        super().__init__()
        self.poll_moving_hz = poll_moving_hz
        self.poll_idle_s = poll_idle_s
        self._jobs: queue.Queue[tuple[int, jobs.Job]] = queue.Queue()
        self._submit_lock = threading.Lock()
        self._submitted = 0  # jobs submitted so far (each numbered in turn)
        self._stop_covers = 0  # the jobs numbered up to this were submitted before a stop
        self.session: DeviceSession | None = None  # None: not connected
        self._unsubscribe: list[Unsubscribe] = []
        self.units = "mm"  # the operator's, for the positions its notices state (set by the window)
        self._timer: QTimer | None = None
        self.batch = TrafficBatch(self.traffic.emit)
        self._next_poll = 0.0
        self._abort = threading.Event()
        self._travel: TravelLimits | None = None
        self._log = SessionLog()
        self._recovering = ""  # why the device is being talked to again ("": it answers)
        self._next_recover = 0.0
        self._connection: tuple[str, str, ConnectOptions] | None = None
        self._restart = RestartWatch()
        self._lines = LineWatch(self.control_lines_changed.emit, self._on_link_note, self._log.note)
        self._baud = 0  # of the connection asked for
        self._ready_once = False  # the connection asked for reached the device at least once
        self._watch: PortWatch | None = None  # a lost port, watched for its return
        self._received = bytearray()  # what came while identifying (to name another protocol)

    # -- thread-safe API ---------------------------------------------------------------------
    def submit(self, job: jobs.Job) -> None:
        """Queue a job (any thread)."""
        with self._submit_lock:
            self._submitted += 1
            self._jobs.put((self._submitted, job))

    def cancel_pending(self) -> list[jobs.Job]:
        """Drop every queued job that has not started; return them (any thread)."""
        dropped = []
        while True:
            try:
                dropped.append(self._jobs.get_nowait()[1])
            except queue.Empty:
                return dropped

    def abort(self) -> None:
        """Make a wait in progress give up at once (any thread)."""
        self._abort.set()

    def stream_pause(self, paused: bool) -> None:
        """Pause or resume the program under way (any thread)."""
        session = self.session
        if session is not None:
            session.pause_program(paused)
            self.program_paused.emit(paused)

    def stop_now(self) -> None:
        """Stop the move or program under way, where the device has a stop (any thread); a
        move submitted before the stop and not yet started is not sent."""
        with self._submit_lock:
            self._stop_covers = self._submitted
        session = self.session
        if session is not None:
            session.request_stop()

    def stream_stop(self) -> None:
        """Stop the program under way; the device's queue is flushed (any thread)."""
        session = self.session
        if session is not None:
            session.stop_program()

    def abort_clear(self) -> None:
        """Allow waits again (before a new connection)."""
        self._abort.clear()

    def note_now(self, text: str) -> None:
        """A note into the session log at once, while a job runs too (any thread)."""
        self._log.note(text)

    # -- worker-thread slots -----------------------------------------------------------------
    @Slot(object)
    def set_travel(self, limits: TravelLimits | None) -> None:
        """Use these travel limits for every move from now on (None: no limits)."""
        self._travel = limits
        if self.session is not None:
            self.session.travel = limits

    @Slot(object)
    def set_session_log(self, stream: TextIO | None) -> None:
        """Write every byte of every connection to `stream` from now on (None: stop)."""
        self._log.switch(stream)

    @Slot()
    def start(self) -> None:
        """Create the loop timer in the worker's thread."""
        self._timer = QTimer(self)
        self._timer.setInterval(TICK_MS)
        self._timer.timeout.connect(self._tick)
        self._timer.start()

    @Slot(str, str, int, object)
    def open_port(
        self, url: str, protocol_name: str, baud: int, options: ConnectOptions | None = None
    ) -> None:
        """Open the port, identify the device and read its state."""
        self.close_port()
        self._ready_once = False
        self._open(url, protocol_name, baud, options or ConnectOptions())

    @Slot(float, float)
    def set_poll_rates(self, moving_hz: float, idle_s: float) -> None:
        """Read the position `moving_hz` times a second while a move is waited on, and every
        `idle_s` seconds otherwise (from the next poll on)."""
        self.poll_moving_hz, self.poll_idle_s = moving_hz, idle_s
        if self.session is not None:
            self.session.poll_interval = 1.0 / moving_hz
        self._next_poll = min(self._next_poll, time.monotonic() + idle_s)

    @Slot(str, bool)
    def set_control_line(self, name: str, on: bool) -> None:
        """Drive DTR or RTS (`name`: "dtr" or "rts"); then report the lines as they are (a port
        without modem lines: a notice saying why, and the lines as unknown)."""
        if self.session is None:
            unchanged = Message("{line} not changed: not connected", line=name.upper())
            self.notice.emit(localized(unchanged))
            return
        self._on_lines(lambda session: session.set_control(name, on), MotionError)

    @Slot()
    def send_break(self) -> None:
        """Send a break (250 ms: the worker waits it out); a notice if it cannot."""
        if self.session is None:
            self.notice.emit(localized(Message("no break sent: not connected")))
            return
        self.batch.flush()  # the console shows what went before the break, before it
        self._on_lines(lambda session: session.send_break(), NoControlLines)

    def _on_lines(
        self, change: Callable[[DeviceSession], object], refused: type[MotionError]
    ) -> None:
        """Make a line change; report the lines after it even unchanged (a refused toggle must
        show its line as it is); a lost port ends the connection."""
        assert self.session is not None
        try:
            change(self.session)
        except PortError as exc:
            self._fail_connection(exc)
            return
        except refused as exc:  # NoControlLines, or a line that is not DTR or RTS
            self.notice.emit(localized(exc))
        try:
            self._lines.report(self.session, force=True)
        except PortError as exc:
            self._fail_connection(exc)
        self.batch.flush()

    @Slot(str)
    def add_note(self, text: str) -> None:
        """Write what the operator did (a program loaded) into the session log, in order with
        the traffic."""
        self.batch.flush()
        self._log.note(text)

    def _on_link_note(self, text: str) -> None:
        """A control-line change or break: to the session log and the console, in order with
        the traffic."""
        self.batch.flush()
        self._log.note(str(text))  # the session log keeps English
        self.control_note.emit(localized(text))

    @Slot()
    def close_port(self) -> None:
        """Close the port if open; a lost port is no longer watched for."""
        self._watch = None
        self._close_link()

    @Slot()
    def shutdown(self) -> None:
        """Stop the loop, close the port and end the worker's thread."""
        if self._timer is not None:
            self._timer.stop()
        self.cancel_pending()
        self.close_port()
        self._log.end("Motion Panel quit; the session log ends here")
        # Hand the worker (and its timer) back to the main thread, so that it can be deleted
        # there once this thread has ended.
        app = QCoreApplication.instance()
        if app is not None:
            self.moveToThread(app.thread())
        QThread.currentThread().quit()

    # -- the loop ----------------------------------------------------------------------------
    def _tick(self) -> None:
        session = self.session
        if session is None:
            if self._watch is not None and self._watch.back(time.monotonic()):
                self._reopen(self._watch)
            return
        try:
            if self._lines.due():
                self._lines.report(session)
            if self._recovering:
                self._recover(session)
            else:
                try:
                    number, job = self._jobs.get_nowait()
                except queue.Empty:
                    job = None
                if job is not None:
                    self._restart.forget()
                    self._run(session, job, number)
                    self._rest_after(session, job)
                else:
                    session.poll()
                    if time.monotonic() >= self._next_poll:
                        self._poll_idle(session)
        except Aborted:
            self.cancel_pending()
            self.close_port()  # the user disconnected (or the window closed) mid-command
        except PortError as exc:
            self._fail_connection(exc)
        except CommunicationError as exc:  # no answer, a garbled or wrong one, a restart
            self._lose_device(exc)
        except MotionError as exc:
            # "device: " marks the detail for the window (which compares it): kept as is.
            self.state_changed.emit("connected", "device: " + localized(exc))
        self.batch.flush()

    def _poll_idle(self, session: DeviceSession) -> None:
        """Read the position, which shows a restart of a device with no boot banner."""
        self._next_poll = time.monotonic() + self.poll_idle_s
        if session.capabilities.position_feedback:
            report = session.position()
            self._restart.reading((report.x, report.y, report.z))

    def _rest_after(self, session: DeviceSession, job: jobs.Job) -> None:
        """Where the device rests after `job`, as its last position; unknown after console
        bytes (a move they started may still run)."""
        known = session.last_position
        raw = isinstance(job, jobs.RawJob) or (
            isinstance(job, jobs.MacroJob) and any(s.startswith("raw") for s in job.macro.steps)
        )
        if known is not None and not raw:
            self._restart.rest_at((known.x, known.y, known.z))

    def _run(self, session: DeviceSession, job: jobs.Job, number: int) -> None:
        if number <= self._stop_covers and job.moves:
            # Queued when a stop was asked (a held jog let go during a step): not sent.
            stopped = localized(Message("stopped before it was sent"))
            if isinstance(job, jobs.StreamJob):  # the Program dock follows its end as a failure
                self.job_failed.emit(job, stopped)
            else:
                self.job_stopped.emit(job, stopped)
            return
        self.busy_changed.emit(True)
        try:
            with session.operation():  # a stop asked before this job is not for it
                result = dispatch(self, session, job)
        except PortError:
            self.batch.flush()
            self.job_failed.emit(job, localized(Message("the connection was lost")))
            raise
        except CommunicationError as exc:  # the tick talks to the device again
            self.batch.flush()
            if isinstance(exc, DeviceTimeout):
                self.job_timed_out.emit(job)
            self.job_failed.emit(job, localized(exc))
            raise
        except Aborted:
            self.batch.flush()
            abandoned = Message("abandoned: disconnected while it was under way")
            self.job_failed.emit(job, localized(abandoned))
            raise
        except MacroStopped as exc:  # the operator's stop, between two steps
            self.batch.flush()
            self.job_stopped.emit(job, localized(exc))
        except MotionError as exc:
            self.batch.flush()  # the console shows the traffic before the failure
            self.job_failed.emit(job, failure_text(job, exc))
        else:
            self.batch.flush()
            self.job_finished.emit(job, result)
        finally:
            if job.moves and number <= self._stop_covers:
                self.target_changed.emit(None)  # stopped short of it: no target any more
            self.busy_changed.emit(False)
            self._next_poll = time.monotonic() + self.poll_idle_s

    def refresh(self) -> None:
        """Read the position, and the speed and its limits where the device has them."""
        session = self.session
        assert session is not None
        session.position()
        caps = session.capabilities
        if caps.speed:
            if caps.speed_limits_queryable or caps.speed_range is not None:
                low, high = session.speed_limits()
                self.speed_limits_changed.emit(low, high)
            self.speed_changed.emit(session.speed())


def failure_text(job: jobs.Job, error: BaseException) -> str:
    """Why `job` failed, for the operator; where the error names the move itself ({what}), it
    is named as the window names the job, so that the window says it once, not twice."""
    said = message_of(error)
    if said is None or "what" not in said.values:
        return localized(error)
    values = {**said.values, "what": job.describe()}
    return localized(Message(said.template, **values))
