"""The serial worker: one QObject on a QThread owns the port; the GUI talks to it by signals."""

from __future__ import annotations

import dataclasses
import logging
import os
import queue
import threading
import time
from dataclasses import dataclass, field, replace
from typing import TextIO

from PySide6.QtCore import QCoreApplication, QObject, QThread, QTimer, Signal, Slot

from app.common.macros import Macro, MacroStopped, run_macro
from app.common.messages import localized
from app.common.position_messages import Lengths, position_localized
from app.window.device import jobs
from drivers.device.motion import KIND_UNITS, Motion, MoveStart
from drivers.device.position_truth import Whereabouts
from drivers.device.travel import TravelLimits
from drivers.errors import (
    Aborted,
    CommunicationError,
    DeviceError,
    DeviceRestarted,
    DeviceTimeout,
    MotionError,
    NoControlLines,
    PortError,
)
from drivers.link.control_lines import BREAK_S, ControlLines
from drivers.link.records import RX, Traffic, TrafficLogWriter
from drivers.link.transport import Link
from drivers.messages import Message, message_of
from drivers.protocols.base import Reply, Setting
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.events import ErrorReport, Event, TextLine, Undecodable
from drivers.protocols.firmata import StepperVersion, configure_stepper
from drivers.protocols.parameters import Parameter
from drivers.protocols.sniff import looks_like
from drivers.session.device_session import DeviceSession, open_device
from drivers.toolpath.streaming import StreamProgress

log = logging.getLogger(__name__)

STREAM_POSITION_S = 0.2  # s between position reads while a program streams
STREAM_PROGRESS_S = 0.05  # s between progress reports to the window (it draws at 10 Hz)
TICK_MS = 20  # the worker's loop period: queue, unsolicited input, polling
TRAFFIC_BATCH_S = 0.05  # traffic is handed to the GUI at most this often (20 Hz)
RECOVER_S = 1.0  # s between attempts to talk again to a device that stopped answering
POSITION_TOLERANCE = 1e-6  # mm: readings closer than this are the same position
CONTROL_POLL_S = 0.25  # s between reads of the modem lines (CTS, DSR, CD, RI) while idle
PORT_WATCH_S = 0.5  # s between looks for a lost port's path coming back
PORT_RETRY_S = 5.0  # s after which a lost port's path that never went away is tried again


@dataclass(frozen=True)
class DeviceInfo:
    """What the window needs to adapt to a connected device."""

    port: str
    protocol: str
    identity: str
    capabilities: Capabilities
    variant: str = ""
    parameters: tuple[Parameter, ...] = ()
    settings: tuple[Setting, ...] = ()
    """The protocol's settings (ticks per mm...), with their values at connection."""
    values: dict[str, float] = field(default_factory=dict)
    whereabouts: Whereabouts | None = None
    """What the session knows of the position once the device is ready."""


@dataclass(frozen=True)
class ConnectOptions:
    """How to talk to the device beyond port, protocol and baud."""

    variant: str = ""  # the protocol's wire variant ("": its default)
    settings: dict[str, float] = field(default_factory=dict)
    """The protocol's settings kept by the panel (ticks per mm...)."""
    parameters: dict[str, float] = field(default_factory=dict)
    """Values written earlier and kept by the panel (the device may have no read-back)."""
    dtr: bool | None = None  # DTR when the port opens (None: the protocol's default)
    rts: bool | None = None  # RTS when the port opens (None: as the port opens it, asserted)
    position: tuple[float, float, float] | None = None
    """Where a device that cannot be asked was left, as kept (None: not known)."""
    after_loss: bool = False  # the device was lost with its link before (the session knows)


@dataclass
class _PortWatch:
    """A lost port's path, watched for its return (a USB adapter plugged in again, a
    `motionsim --link` started again) to connect again as before."""

    url: str
    protocol: str
    baud: int
    options: ConnectOptions
    node: tuple[int, int] | None  # the device file when the port was lost (None: gone)
    gone: bool = False  # the path was seen missing since
    next_look: float = 0.0
    retry_at: float = 0.0  # the same device file is tried again from then on


def _device_node(path: str) -> tuple[int, int] | None:
    """(device number, inode) of the file `path` names, a symlink followed; None if missing."""
    try:
        info = os.stat(path)
    except OSError:
        return None
    return info.st_rdev, info.st_ino


def _watchable(url: str) -> bool:
    """Whether a lost port is watched for its return: a file path (a device, a link to one),
    not a pyserial URL, nor a pseudo-terminal's own /dev/pts/N, whose number the system gives
    the next pty opened by any program (`motionsim --link` gives a pty a name that lasts)."""
    return "://" not in url and not url.startswith("/dev/pts/")


class SerialWorker(QObject):
    """Owns the link; runs jobs from a queue; polls the position; reports by signals.

    Only `submit`, `cancel_pending` and `abort` may be called from another thread (they touch
    thread-safe structures); everything else runs in the worker's thread via queued signals.
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
        self._session: DeviceSession | None = None
        self._link: Link | None = None  # the session's (None: not connected)
        self._motion: Motion | None = None  # the session's
        self.units = "mm"  # the operator's, for the positions its notices state (set by the window)
        self._timer: QTimer | None = None
        self._batch: list[Traffic] = []
        self._batch_sent = 0.0
        self._next_poll = 0.0
        self._abort = threading.Event()
        self._travel: TravelLimits | None = None
        self._session_log: TrafficLogWriter | None = None
        self._last_stream_position = 0.0
        self._recovering = ""  # why the device is being talked to again ("": it answers)
        self._next_recover = 0.0
        self._connection: tuple[str, str, ConnectOptions] | None = None
        self._idle_position: tuple[float, float, float] | None = None
        self._idle_stable: tuple[float, float, float] | None = None  # the reading before
        self._lines: ControlLines | None = None  # as last reported
        self._next_lines_poll = 0.0
        self._baud = 0  # of the connection asked for
        self._ready_once = False  # the connection asked for reached the device at least once
        self._watch: _PortWatch | None = None  # a lost port, watched for its return
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
        session = self._session
        if session is not None:
            session.pause_program(paused)
            self.program_paused.emit(paused)

    def stop_now(self) -> None:
        """Stop the move or program under way, where the device has a stop (any thread); a
        move submitted before the stop and not yet started is not sent."""
        with self._submit_lock:
            self._stop_covers = self._submitted
        motion = self._motion
        if motion is not None:
            motion.stop_requested.set()
        self.stream_stop()

    def stream_stop(self) -> None:
        """Stop the program under way; the device's queue is flushed (any thread)."""
        session = self._session
        if session is not None:
            session.stop_program()

    def abort_clear(self) -> None:
        """Allow waits again (before a new connection)."""
        self._abort.clear()

    def note_now(self, text: str) -> None:
        """A note into the session log at once, while a job runs too (any thread)."""
        writer = self._session_log
        if writer is not None:
            writer.note(text)

    # -- worker-thread slots -----------------------------------------------------------------
    @Slot(object)
    def set_travel(self, limits: TravelLimits | None) -> None:
        """Use these travel limits for every move from now on (None: no limits)."""
        self._travel = limits
        if self._motion is not None:
            self._motion.travel = limits

    @Slot(object)
    def set_session_log(self, stream: TextIO | None) -> None:
        """Write every byte of every connection to `stream` from now on (None: stop); the
        connection open now, if any, goes on in the new one, and each file says where the
        other is."""
        before = self._session_log
        self._session_log = TrafficLogWriter(stream) if stream is not None else None
        link = self._link
        if link is not None:
            if before is not None and before in link.listeners:
                link.listeners.remove(before)
            if self._session_log is not None:
                link.listeners.append(self._session_log)
        if before is not None:
            if self._session_log is not None:
                self._log_note(f"continued from {_file_name(before.stream)}")
                before.note(f"the session log goes on in {_file_name(self._session_log.stream)}")
            else:
                before.note("the session log was turned off")
            before.stream.close()

    def _log_note(self, text: str) -> None:
        if self._session_log is not None:
            self._session_log.note(text)

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

    def _open(self, url: str, protocol_name: str, baud: int, options: ConnectOptions) -> None:
        """Open the port and talk to the device (asked for, or a lost port come back)."""
        self._close_link()
        self._baud = baud
        connecting = Message(
            "{url} ({protocol}, {baud} baud)", url=url, protocol=protocol_name, baud=baud
        )
        self.state_changed.emit("connecting", localized(connecting))
        try:
            session = open_device(
                url,
                protocol_name,
                variant=options.variant or None,
                baud=baud,
                settings=options.settings,
                parameters=options.parameters,
                dtr=options.dtr,
                rts=options.rts,
                travel=self._travel,
                start=False,  # the handshake identifies the device first
                abort=self._abort,
                position=options.position,
                after_loss=options.after_loss,
            )
        except MotionError as exc:
            failed: object = exc
            if self._watch is not None:  # back, but not usable yet (busy, permissions)
                failed = Message("{error}; waiting for {url}", error=exc, url=url)
            self.state_changed.emit("error", localized(failed))
            return
        link = session.link
        session.add_listener(self._on_traffic)
        link.note_listeners.append(self._on_link_note)
        if self._session_log is not None:
            session.add_listener(self._session_log)  # set_session_log may change it later
            shown = f"{protocol_name} {options.variant}" if options.variant else protocol_name
            self._log_note(f"connected to {url} ({shown}, {baud} baud)")
        for text in link.opening_notes:  # e.g. an RFC 2217 server that left DTR unconfirmed
            self._on_link_note(text)
        session.client.wait_hooks.append(self._flush_traffic_if_due)
        session.client.listeners.append(self._on_event)
        self._session = session
        self._link = link
        self._motion = session.motion
        self._motion.poll_interval = 1.0 / self.poll_moving_hz
        self._motion.position_listeners.append(self.position_changed.emit)
        self._motion.move_listeners.append(self._on_move_started)
        self._motion.notice_listeners.append(self._on_motion_notice)
        self._motion.parameter_listeners.append(self.parameter_written.emit)
        self._connection = (url, protocol_name, options)
        self._recovering = ""
        self._lines = None
        self._received.clear()
        link.listeners.append(self._keep_received)
        try:
            self._report_lines(note=True)
            self._handshake()
        except MotionError as exc:
            self._fail_connection(exc)
        finally:
            if self._keep_received in link.listeners:
                link.listeners.remove(self._keep_received)

    def _keep_received(self, record: Traffic) -> None:
        """Keep what the device sends while it is identified (bounded)."""
        if record.direction == RX and len(self._received) < 4096:
            self._received += record.data

    def _handshake(self) -> None:
        """Identify the device, send the saved setup, read its state; then report it ready."""
        motion, connection = self._motion, self._connection
        assert motion is not None and connection is not None
        url, protocol_name, _ = connection
        protocol = motion.client.protocol
        identity = motion.identify()
        try:
            motion.start()
        except DeviceError as exc:  # a saved setup the device refuses: say so, stay connected
            self.notice.emit(localized(Message("the saved setup was refused: {error}", error=exc)))
        self._refresh()
        self._flush_traffic()
        connected = Message("{identity} on {url}", identity=identity, url=url)
        self.state_changed.emit("connected", localized(connected))
        variant = protocol.variant.name if protocol.variant else ""
        self.device_ready.emit(
            DeviceInfo(
                url,
                protocol_name,
                identity,
                protocol.capabilities,
                variant,
                protocol.parameters,
                protocol.settings,
                dict(protocol.values),
                self._session.where() if self._session is not None else None,
            )
        )
        self._idle_position = self._idle_stable = None
        self._next_poll = time.monotonic() + self.poll_idle_s
        self._ready_once = True
        self._watch = None
        self._report_lines(force=True)  # again: the window enables the lines once connected

    @Slot(float, float)
    def set_poll_rates(self, moving_hz: float, idle_s: float) -> None:
        """Read the position `moving_hz` times a second while a move is waited on, and every
        `idle_s` seconds otherwise (from the next poll on)."""
        self.poll_moving_hz, self.poll_idle_s = moving_hz, idle_s
        if self._motion is not None:
            self._motion.poll_interval = 1.0 / moving_hz
        self._next_poll = min(self._next_poll, time.monotonic() + idle_s)

    @Slot(str, bool)
    def set_control_line(self, name: str, on: bool) -> None:
        """Drive DTR or RTS (`name`: "dtr" or "rts"); then report the lines as they are (a port
        without modem lines: a notice saying why, and the lines as unknown)."""
        link = self._link
        if link is None:
            unchanged = Message("{line} not changed: not connected", line=name.upper())
            self.notice.emit(localized(unchanged))
            return
        try:
            link.set_control(name, on)
        except PortError as exc:
            self._fail_connection(exc)
            return
        except MotionError as exc:  # NoControlLines, or a line that is not DTR or RTS
            self.notice.emit(localized(exc))
        self._after_line_change()

    @Slot()
    def send_break(self) -> None:
        """Send a break (BREAK_S, 250 ms: the worker waits it out); a notice if it cannot."""
        link = self._link
        if link is None:
            self.notice.emit(localized(Message("no break sent: not connected")))
            return
        self._flush_traffic()  # the console shows what went before the break, before it
        try:
            link.send_break(BREAK_S)
        except PortError as exc:
            self._fail_connection(exc)
            return
        except NoControlLines as exc:
            self.notice.emit(localized(exc))
        self._after_line_change()

    def _after_line_change(self) -> None:
        """Report the lines after a change asked for, even unchanged (a refused toggle must
        show its line as it is); a lost port ends the connection."""
        try:
            self._report_lines(force=True)
        except PortError as exc:
            self._fail_connection(exc)
        self._flush_traffic()

    def _report_lines(self, force: bool = False, note: bool = False) -> None:
        """Read the lines; emit them if they changed (or `force`), noting the inputs that
        changed by themselves; `note`: write them all to the session log (at connection)."""
        link = self._link
        if link is None:
            return
        self._next_lines_poll = time.monotonic() + CONTROL_POLL_S
        lines = link.control_lines()
        before, self._lines = self._lines, lines
        if note:
            self._log_note(f"control lines: {lines.describe()}")
        elif before is not None and not force:
            for change in lines.changes(before):
                self._on_link_note(change)
        if force or lines != before:
            self.control_lines_changed.emit(lines)

    @Slot(str)
    def add_note(self, text: str) -> None:
        """Write what the operator did (a program loaded) into the session log, in order with
        the traffic."""
        self._flush_traffic()
        self._log_note(text)

    def _on_link_note(self, text: str) -> None:
        """A control-line change or break: to the session log and the console, in order with
        the traffic."""
        self._flush_traffic()
        self._log_note(str(text))  # the session log keeps English
        self.control_note.emit(localized(text))

    @Slot()
    def close_port(self) -> None:
        """Close the port if open; a lost port is no longer watched for."""
        self._watch = None
        self._close_link()

    def _close_link(self) -> None:
        if self._link is None:
            return
        self._flush_traffic()
        self._log_note(f"disconnected from {self._link.url}")  # the session log keeps English
        self._tell_lost()  # a move under way when the operator disconnected: its estimate
        self._end_session()
        self.state_changed.emit("disconnected", "")

    def _tell_lost(self) -> None:
        """The link went: the session's account of the position then (the estimate at the
        loss during a move), for the window."""
        if self._session is not None:
            self._session.truth.link_lost()
            self.whereabouts_changed.emit(self._session.where())

    def _end_session(self) -> None:
        """Close the session (its port) and forget it."""
        if self._session is not None:
            self._session.close()
        self._session = None
        self._link = None
        self._motion = None

    @Slot()
    def shutdown(self) -> None:
        """Stop the loop, close the port and end the worker's thread."""
        if self._timer is not None:
            self._timer.stop()
        self.cancel_pending()
        self.close_port()
        ending, self._session_log = self._session_log, None
        if ending is not None:  # a quit, not the log turned off in Settings
            ending.note("Motion Panel quit; the session log ends here")
            ending.stream.close()
        # Hand the worker (and its timer) back to the main thread, so that it can be deleted
        # there once this thread has ended.
        app = QCoreApplication.instance()
        if app is not None:
            self.moveToThread(app.thread())
        QThread.currentThread().quit()

    # -- the loop ----------------------------------------------------------------------------
    def _tick(self) -> None:
        if self._motion is None:
            self._watch_port()
            return
        try:
            if time.monotonic() >= self._next_lines_poll:
                self._report_lines()
            if self._recovering:
                self._recover()
            else:
                try:
                    number, job = self._jobs.get_nowait()
                except queue.Empty:
                    job = None
                if job is not None:
                    self._idle_position = self._idle_stable = None
                    self._run(job, number)
                    self._rest_after(job)
                else:
                    self._motion.client.poll()
                    if time.monotonic() >= self._next_poll:
                        self._poll_idle(self._motion)
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
        self._flush_traffic()

    def _poll_idle(self, motion: Motion) -> None:
        """Read the position. A device with no boot banner shows a restart only so: it stood
        still (where the last job left it, or for two readings), nothing was sent meanwhile,
        and now it is at the power-on origin."""
        self._next_poll = time.monotonic() + self.poll_idle_s
        if not motion.capabilities.position_feedback:
            return
        report = motion.position()
        here = (report.x, report.y, report.z)
        before, self._idle_position = self._idle_position, here
        if before is None or self._idle_stable is None:
            self._idle_stable = before
            return
        stood_still = _same(before, self._idle_stable)
        self._idle_stable = before
        if stood_still and not _same(here, before) and _same(here, (0.0, 0.0, 0.0)):
            shown = ", ".join(f"{v:g}" for v in before)
            raise DeviceRestarted(
                Message(
                    "the position went from ({position}) to (0, 0, 0) mm while nothing was sent: "
                    "the device restarted",
                    position=shown,
                )
            )

    def _rest_after(self, job: jobs.Job) -> None:
        """Where the device rests after `job`, as its last position; unknown after console
        bytes (a move they started may still run)."""
        known = self._motion.last_position if self._motion is not None else None
        raw = isinstance(job, jobs.RawJob) or (
            isinstance(job, jobs.MacroJob) and any(s.startswith("raw") for s in job.macro.steps)
        )
        if known is not None and not raw:
            self._idle_position = self._idle_stable = (known.x, known.y, known.z)

    def _lose_device(self, exc: CommunicationError) -> None:
        """The device stopped making sense: drop the queue, say so, then talk to it again."""
        dropped = self.cancel_pending()
        self._idle_position = self._idle_stable = None
        self._tell_lost()
        self.target_changed.emit(None)
        self._recovering = str(exc)
        self._next_recover = time.monotonic() + (
            0.0 if isinstance(exc, DeviceRestarted) else RECOVER_S
        )
        if dropped:
            lost = Message(
                "{error}; not sent: {jobs}; talking to it again",
                error=exc,
                jobs=_described(dropped),
            )
        else:
            lost = Message("{error}; talking to it again", error=exc)
        self.state_changed.emit("error", localized(lost))

    def _recover(self) -> None:
        """Refuse what was queued meanwhile; when due, identify and re-read the device."""
        for job in self.cancel_pending():
            self.job_failed.emit(
                job, localized(Message("not sent: the device is being reconnected"))
            )
        if time.monotonic() < self._next_recover:
            return
        motion = self._motion
        assert motion is not None
        self._next_recover = time.monotonic() + RECOVER_S
        if self._session is not None:
            self._session.truth.found_again()  # what it counted before is not trusted
        try:
            self._handshake()
        except PortError:
            raise
        except MotionError as exc:
            log.info("the device does not answer yet: %s", exc)
            return
        self._recovering = ""

    def _run(self, job: jobs.Job, number: int) -> None:
        motion = self._motion
        assert motion is not None
        if number <= self._stop_covers and job.moves:
            # Queued when a stop was asked (a held jog let go during a step): not sent.
            motion.stop_requested.clear()
            stopped = localized(Message("stopped before it was sent"))
            if isinstance(job, jobs.StreamJob):  # the Program dock follows its end as a failure
                self.job_failed.emit(job, stopped)
            else:
                self.job_stopped.emit(job, stopped)
            return
        motion.stop_requested.clear()  # a stop asked before this job is not for it
        self.busy_changed.emit(True)
        try:
            result = self._dispatch(motion, job)
        except PortError:
            self._flush_traffic()
            self.job_failed.emit(job, localized(Message("the connection was lost")))
            raise
        except CommunicationError as exc:  # the tick talks to the device again
            self._flush_traffic()
            if isinstance(exc, DeviceTimeout):
                self.job_timed_out.emit(job)
            self.job_failed.emit(job, localized(exc))
            raise
        except Aborted:
            self._flush_traffic()
            abandoned = Message("abandoned: disconnected while it was under way")
            self.job_failed.emit(job, localized(abandoned))
            raise
        except MacroStopped as exc:  # the operator's stop, between two steps
            self._flush_traffic()
            self._move_ended()
            self.job_stopped.emit(job, localized(exc))
        except MotionError as exc:
            self._flush_traffic()  # the console shows the traffic before the failure
            self._move_ended()
            self.job_failed.emit(job, failure_text(job, exc))
        else:
            self._flush_traffic()
            self.job_finished.emit(job, result)
        finally:
            if job.moves and number <= self._stop_covers:
                self.target_changed.emit(None)  # stopped short of it: no target any more
            self.busy_changed.emit(False)
            self._next_poll = time.monotonic() + self.poll_idle_s

    def _move_ended(self) -> None:
        """A job failed or was stopped short: the session's last report stands."""
        if self._session is not None:
            self._session.truth.move_ended()

    def _dispatch(self, motion: Motion, job: jobs.Job) -> object:
        if isinstance(job, jobs.MoveToJob):
            return motion.move_to(job.x, job.y, job.z)
        if isinstance(job, jobs.MoveByJob):
            what = None
            if not job.jog:  # a relative Go to: not a "jog" in its messages
                what = Message(
                    "relative move by ({dx:g}, {dy:g}, {dz:g}) {unit}",
                    dx=job.dx,
                    dy=job.dy,
                    dz=job.dz,
                    unit=KIND_UNITS.get(job.kind, job.kind),
                )
            return motion.move_by(job.dx, job.dy, job.dz, job.kind, what=what)
        if isinstance(job, jobs.HomeJob):
            return motion.home()
        if isinstance(job, jobs.SetHomeJob):
            motion.set_home()
            return None
        if isinstance(job, jobs.SetSpeedJob):
            speed = motion.set_speed(job.speed)
            self.speed_changed.emit(speed)
            return speed
        if isinstance(job, jobs.RawJob):
            # Through the motion guard: a move is checked and followed like a typed one.
            reply = motion.send_raw(job.data, job.force)
            return reply.value if isinstance(reply, Reply) else reply
        if isinstance(job, jobs.SetParameterJob):
            return motion.set_parameter(job.param_id, job.value)
        if isinstance(job, jobs.ArcJob):
            return motion.arc(job.arc)
        if isinstance(job, jobs.DwellJob):
            motion.dwell(job.ms)
            return None
        if isinstance(job, jobs.SettingsJob):
            motion.client.protocol.configure(job.values)
            self.capabilities_changed.emit(motion.capabilities)
            return None
        if isinstance(job, jobs.StreamJob):
            return self._stream(motion, job)
        if isinstance(job, jobs.StepperConfigJob):
            return configure_stepper(motion.client, job.steps_per_rev, job.pins)
        if isinstance(job, jobs.StepperVersionJob):
            return int(str(motion.client.execute(StepperVersion()).value))
        if isinstance(job, jobs.RefreshJob):
            self._refresh()
            return None
        if isinstance(job, jobs.MacroJob):
            return self._macro(motion, job.macro)
        raise MotionError(Message("unknown job {job!r}", job=job))

    def _macro(self, motion: Motion, macro: Macro) -> list[dict[str, object]]:
        """Run a macro, telling each step before it starts; the traffic goes out as it runs."""
        count = len(macro.steps)

        def step(number: int, text: str) -> None:
            self._flush_traffic()
            self.macro_step.emit(macro.name, number, count, text)

        return run_macro(motion, macro, step)

    def _stream(self, motion: Motion, job: jobs.StreamJob) -> StreamProgress:
        last_emit = 0.0
        queued = motion.capabilities.streaming  # moves run elsewhere report their own position

        def progress(state: StreamProgress) -> None:
            nonlocal last_emit
            now = time.monotonic()
            if now - last_emit >= STREAM_PROGRESS_S or state.finished:
                last_emit = now  # the final state comes with job_finished anyway
                self.stream_progress.emit(dataclasses.replace(state))
            if queued and now - self._last_stream_position >= STREAM_POSITION_S:
                self._last_stream_position = now
                motion.position()  # the live position moves along the program
            self._flush_traffic_if_due()

        assert self._session is not None
        # Stopped early, the device is stopped (its queue flushed); the position is read at
        # the end.
        return self._session.run_program(job.toolpath, progress, tolerance=job.tolerance)

    def _refresh(self) -> None:
        motion = self._motion
        assert motion is not None
        motion.position()
        caps = motion.capabilities
        if caps.speed:
            if caps.speed_limits_queryable or caps.speed_range is not None:
                low, high = motion.speed_limits()
                self.speed_limits_changed.emit(low, high)
            self.speed_changed.emit(motion.speed())

    def _fail_connection(self, exc: Exception) -> None:
        """The port failed (or the device was never reached): close it, say why; a port lost
        after the device was reached is watched for its return."""
        dropped = self.cancel_pending()
        error: object = exc
        url, protocol_name, options = self._connection or ("", "", ConnectOptions())
        if not self._ready_once:  # never reached: does it speak another protocol?
            hint = looks_like(bytes(self._received), protocol_name)
            if hint is not None:
                error = Message("{hint} ({error})", hint=hint, error=exc)
        if dropped:
            error = Message("{error}; not sent: {jobs}", error=error, jobs=_described(dropped))
        self._recovering = ""
        self._flush_traffic()
        self._tell_lost()
        self._end_session()
        if self._ready_once and url and _watchable(url):
            if self._watch is None:
                now = time.monotonic()
                lost = replace(options, position=None, after_loss=True)  # not known now
                self._watch = _PortWatch(
                    url, protocol_name, self._baud, lost, _device_node(url),
                    next_look=now + PORT_WATCH_S, retry_at=now + PORT_RETRY_S,
                )  # fmt: skip
            error = Message("{error}; connecting again when {url} is back", error=error, url=url)
        self.target_changed.emit(None)
        self.state_changed.emit("error", localized(error))

    def _watch_port(self) -> None:
        """Every PORT_WATCH_S: if the lost port's path is back (it went away and came again,
        names another device file, or PORT_RETRY_S passed), connect again as before."""
        watch, now = self._watch, time.monotonic()
        if watch is None or now < watch.next_look:
            return
        watch.next_look = now + PORT_WATCH_S
        node = _device_node(watch.url)
        if node is None:
            watch.gone = True
            return
        if not (watch.gone or node != watch.node or now >= watch.retry_at):
            return
        watch.gone, watch.node, watch.retry_at = False, node, now + PORT_RETRY_S
        log.info("%s is back: connecting again", watch.url)
        self.notice.emit(localized(Message("{url} is back: connecting again", url=watch.url)))
        self._open(watch.url, watch.protocol, watch.baud, watch.options)

    # -- listeners (worker thread) -----------------------------------------------------------
    def _on_traffic(self, record: Traffic) -> None:
        self._batch.append(record)
        if record.time - self._batch_sent >= TRAFFIC_BATCH_S:
            self._flush_traffic()

    def _flush_traffic_if_due(self) -> None:
        if self._batch and time.monotonic() - self._batch_sent >= TRAFFIC_BATCH_S:
            self._flush_traffic()

    def _flush_traffic(self) -> None:
        if self._batch:
            batch, self._batch = self._batch, []
            self.traffic.emit(batch)
        self._batch_sent = time.monotonic()

    def _on_motion_notice(self, text: str) -> None:
        """A notice of the Motion (e.g. a move clamped), in the interface's language, the
        positions it states in the operator's units to the device's resolution."""
        motion = self._motion
        resolution = motion.capabilities.resolution if motion is not None else None
        self.notice.emit(position_localized(text, Lengths(self.units, resolution)))

    def _on_move_started(self, start: MoveStart) -> None:
        self.target_changed.emit(start.target)  # the target as sent, after any clamping
        self.move_started.emit(start)

    def _on_event(self, event: Event, solicited: bool) -> None:
        # Unsolicited text lines are in the console's RX already (as text): not repeated, except
        # for a binary protocol, whose console shows hex (Firmata's STRING_DATA).
        if solicited or self._motion is None:
            return
        if isinstance(event, ErrorReport):
            self.device_error.emit(event.message)
        elif isinstance(event, Undecodable):
            self.device_note.emit(localized(str(event)))
        elif isinstance(event, TextLine) and not self._motion.capabilities.raw_text:
            self.device_note.emit(localized(Message("the device says: {text}", text=event.text)))


def _file_name(stream: TextIO) -> str:
    """The path of a log's file, as far as the stream knows it."""
    return str(getattr(stream, "name", "another file"))


def failure_text(job: jobs.Job, error: BaseException) -> str:
    """Why `job` failed, for the operator; where the error names the move itself ({what}), it
    is named as the window names the job, so that the window says it once, not twice."""
    said = message_of(error)
    if said is None or "what" not in said.values:
        return localized(error)
    values = {**said.values, "what": job.describe()}
    return localized(Message(said.template, **values))


def _described(dropped: list[jobs.Job]) -> str:
    """`jog by (1, 0, 0) mm, go home` for the queued jobs dropped (each described in the
    interface's language)."""
    return ", ".join(job.describe() for job in dropped)


def _same(a: tuple[float, float, float], b: tuple[float, float, float]) -> bool:
    return all(abs(p - q) <= POSITION_TOLERANCE for p, q in zip(a, b, strict=True))
