"""A serial worker's connection life cycle: the session opened and identified, subscribed to,
lost (the port gone, the device silent or restarted), watched for, found again and closed; and
what the session tells, turned into the worker's signals."""

from __future__ import annotations

import logging
import time

from app.common.messages import localized
from app.common.position_messages import Lengths, position_localized
from app.window.device import jobs
from app.window.device.connect_options import ConnectOptions, DeviceInfo
from app.window.device.port_watch import PortWatch, watchable
from drivers.device.motion import MoveStart
from drivers.errors import CommunicationError, DeviceError, DeviceRestarted, MotionError, PortError
from drivers.link.records import RX, Traffic
from drivers.messages import Message
from drivers.protocols.events import ErrorReport, Event, TextLine, Undecodable
from drivers.protocols.sniff import looks_like
from drivers.session.device_session import DeviceSession, open_device

log = logging.getLogger(__name__)

RECOVER_S = 1.0  # s between attempts to talk again to a device that stopped answering


class WorkerConnection:
    """The connection half of SerialWorker (a mixin: it uses the worker's state and signals)."""

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
                url, protocol_name, variant=options.variant or None, baud=baud,
                settings=options.settings, parameters=options.parameters,
                dtr=options.dtr, rts=options.rts, travel=self._travel,
                start=False,  # the handshake identifies the device first
                abort=self._abort, position=options.position, after_loss=options.after_loss,
            )  # fmt: skip
        except MotionError as exc:
            failed: object = exc
            if self._watch is not None:  # back, but not usable yet (busy, permissions)
                failed = Message("{error}; waiting for {url}", error=exc, url=url)
            self.state_changed.emit("error", localized(failed))
            return
        self._unsubscribe = [
            session.on_traffic(self.batch.add),
            session.on_link_note(self._on_link_note),
        ]
        self._log.attach(session)
        shown = f"{protocol_name} {options.variant}" if options.variant else protocol_name
        self._log.note(f"connected to {url} ({shown}, {baud} baud)")
        for text in session.opening_notes:  # e.g. an RFC 2217 server that left DTR unconfirmed
            self._on_link_note(text)
        self._unsubscribe += [
            session.on_wait(self.batch.flush_if_due),
            session.on_event(self._on_event),
            session.on_position(self.position_changed.emit),
            session.on_move_started(self._on_move_started),
            session.on_notice(self._on_motion_notice),
            session.on_parameter(self.parameter_written.emit),
        ]
        session.poll_interval = 1.0 / self.poll_moving_hz
        self.session = session
        self._connection = (url, protocol_name, options)
        self._recovering = ""
        self._lines.forget()
        self._received.clear()
        keeping = session.on_traffic(self._keep_received)
        try:
            self._lines.report(session, note=True)
            self._handshake()
        except MotionError as exc:
            self._fail_connection(exc)
        finally:
            keeping()

    def _keep_received(self, record: Traffic) -> None:
        """Keep what the device sends while it is identified (bounded)."""
        if record.direction == RX and len(self._received) < 4096:
            self._received += record.data

    def _handshake(self) -> None:
        """Identify the device, send the saved setup, read its state; then report it ready."""
        session, connection = self.session, self._connection
        assert session is not None and connection is not None
        url, protocol_name, _ = connection
        protocol = session.protocol
        identity = session.identify()
        try:
            session.start()
        except DeviceError as exc:  # a saved setup the device refuses: say so, stay connected
            self.notice.emit(localized(Message("the saved setup was refused: {error}", error=exc)))
        self.refresh()
        self.batch.flush()
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
                session.where(),
            )
        )
        self._restart.forget()
        self._next_poll = time.monotonic() + self.poll_idle_s
        self._ready_once = True
        self._watch = None
        self._lines.report(session, force=True)  # again: the window enables the lines now

    def _close_link(self) -> None:
        if self.session is None:
            return
        self.batch.flush()
        self._log.note(f"disconnected from {self.session.port}")  # the log keeps English
        self._tell_lost()  # a move under way when the operator disconnected: its estimate
        self._end_session()
        self.state_changed.emit("disconnected", "")

    def _tell_lost(self) -> None:
        """The link went: the session's account of the position then (the estimate at the
        loss during a move), for the window."""
        if self.session is not None:
            self.session.truth.link_lost()
            self.whereabouts_changed.emit(self.session.where())

    def _end_session(self) -> None:
        """Close the session (its port) and forget it."""
        for unsubscribe in self._unsubscribe:
            unsubscribe()
        self._unsubscribe = []
        self._log.attach(None)
        if self.session is not None:
            self.session.close()
        self.session = None

    def _lose_device(self, exc: CommunicationError) -> None:
        """The device stopped making sense: drop the queue, say so, then talk to it again."""
        dropped = self.cancel_pending()
        self._restart.forget()
        self._tell_lost()
        self.target_changed.emit(None)
        self._recovering = str(exc)
        restarted = isinstance(exc, DeviceRestarted)
        self._next_recover = time.monotonic() + (0.0 if restarted else RECOVER_S)
        lost = Message("{error}; talking to it again", error=exc)
        if dropped:
            lost = Message(
                "{error}; not sent: {jobs}; talking to it again",
                error=exc,
                jobs=_described(dropped),
            )
        self.state_changed.emit("error", localized(lost))

    def _recover(self, session: DeviceSession) -> None:
        """Refuse what was queued meanwhile; when due, identify and re-read the device."""
        for job in self.cancel_pending():
            self.job_failed.emit(
                job, localized(Message("not sent: the device is being reconnected"))
            )
        if time.monotonic() < self._next_recover:
            return
        self._next_recover = time.monotonic() + RECOVER_S
        session.truth.found_again()  # what it counted before is not trusted
        try:
            self._handshake()
        except PortError:
            raise
        except MotionError as exc:
            log.info("the device does not answer yet: %s", exc)
            return
        self._recovering = ""

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
        self.batch.flush()
        self._tell_lost()
        self._end_session()
        if self._ready_once and url and watchable(url):
            if self._watch is None:
                now = time.monotonic()
                self._watch = PortWatch.lost(url, protocol_name, self._baud, options, now)
            error = Message("{error}; connecting again when {url} is back", error=error, url=url)
        self.target_changed.emit(None)
        self.state_changed.emit("error", localized(error))

    def _reopen(self, watch: PortWatch) -> None:
        """The lost port's path is back: connect again as before."""
        log.info("%s is back: connecting again", watch.url)
        self.notice.emit(localized(Message("{url} is back: connecting again", url=watch.url)))
        self._open(watch.url, watch.protocol, watch.baud, watch.options)

    # -- listeners (worker thread) -----------------------------------------------------------
    def _on_motion_notice(self, text: str) -> None:
        """A notice of the session (e.g. a move clamped), in the interface's language, the
        positions it states in the operator's units to the device's resolution."""
        resolution = self.session.capabilities.resolution if self.session is not None else None
        self.notice.emit(position_localized(text, Lengths(self.units, resolution)))

    def _on_move_started(self, start: MoveStart) -> None:
        self.target_changed.emit(start.target)  # the target as sent, after any clamping
        self.move_started.emit(start)

    def _on_event(self, event: Event, solicited: bool) -> None:
        # Unsolicited text lines are in the console's RX already (as text): not repeated, except
        # for a binary protocol, whose console shows hex (Firmata's STRING_DATA).
        if solicited or self.session is None:
            return
        if isinstance(event, ErrorReport):
            self.device_error.emit(event.message)
        elif isinstance(event, Undecodable):
            self.device_note.emit(localized(str(event)))
        elif isinstance(event, TextLine) and not self.session.capabilities.raw_text:
            self.device_note.emit(localized(Message("the device says: {text}", text=event.text)))


def _described(dropped: list[jobs.Job]) -> str:
    """`jog by (1, 0, 0) mm, go home` for the queued jobs dropped (each described in the
    interface's language)."""
    return ", ".join(job.describe() for job in dropped)
