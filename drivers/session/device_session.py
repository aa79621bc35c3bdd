"""One connected device: the scripting API, and the one API every front end drives a device by.

    from drivers import open_device

    with open_device("sim://coxiris", "coxiris") as stage:
        stage.move_to(10, 5)
        print(stage.position())

`open_device` opens the port as the protocol needs it, builds the client and the motion layer,
sets the travel box (every move, raw bytes included, is checked against it before anything is
sent), taps the traffic (subscriptions, a log file) and sends the device's start-up commands. The
session is closed when the `with` block ends, an exception included.

The stable names are those of `drivers.__all__`; `DeviceSession.link`, `.client`, `.motion` are
the layers underneath and internal (front ends use the session's own methods and `on_...`
subscriptions, drivers/session/subscriptions.py).
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import AbstractContextManager, contextmanager
from types import TracebackType
from typing import TYPE_CHECKING, TypeVar

from drivers.device.client import Client
from drivers.device.guard import ARC_POINTS, RawMove, arc_points
from drivers.device.motion import Motion
from drivers.device.position_count import resume
from drivers.device.position_truth import PositionTruth, Whereabouts
from drivers.device.travel import Point, TravelLimits
from drivers.errors import Aborted, BadInput, CommunicationError, MotionError
from drivers.link.records import TrafficLogWriter
from drivers.link.transport import Link, TrafficListener
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.protocols.base import Protocol, Reply
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.events import PositionReport
from drivers.protocols.parameters import ParameterWritten
from drivers.session.parameters import DeviceParameters
from drivers.session.programs import ProgressListener, SessionPrograms
from drivers.session.setup import LogTarget, make_protocol, open_device_link, travel_limits
from drivers.session.subscriptions import SessionLines, SessionSubscriptions
from drivers.session.tap import TrafficTap
from drivers.traffic.log_origin import connection_note

if TYPE_CHECKING:
    from drivers.toolpath.runner import ProgramRunner

__all__ = [
    "DeviceSession",
    "NoPrograms",
    "NoStop",
    "ProgressListener",
    "Whereabouts",
    "open_device",
]

_R = TypeVar("_R")


class NoStop(BadInput):
    """The protocol has no stop command: the device finishes what it was sent."""


class NoPrograms(BadInput):
    """Kept for scripts that catch it: every protocol runs programs now (none raises it)."""


class DeviceSession(SessionSubscriptions, SessionLines, SessionPrograms):
    """One open device: typed operations, the travel guard, the traffic tap and its log.

    Not thread-safe, like the client under it: one thread drives it; only `stop` may be called
    from another thread (or from a program's progress callback) while an operation runs.
    """

    def __init__(
        self,
        link: Link,
        protocol: Protocol,
        *,
        timeout: float = 2.0,
        travel: TravelLimits | None = None,
        abort: threading.Event | None = None,
        parameters: Mapping[str, float] | None = None,
        after_loss: bool = False,
    ) -> None:
        """A session over an open link (`open_device` opens one); it owns and closes the link.
        `after_loss`: it goes on after a lost link (see `where`)."""
        client = Client(link, protocol, timeout=timeout)
        if abort is not None:
            client.abort = abort
        self._attach(link, protocol, client, Motion(client), parameters, after_loss)
        self.motion.travel = travel

    def _attach(
        self,
        link: Link,
        protocol: Protocol,
        client: Client,
        motion: Motion,
        parameters: Mapping[str, float] | None = None,
        after_loss: bool = False,
    ) -> None:
        """Take on the layers (made by `__init__`, or a front end's own: `_around`)."""
        self.link = link
        self.protocol = protocol
        self.client = client
        self.motion = motion
        self.truth = PositionTruth(self.motion, after_loss=after_loss)
        """What is known of the position (`where` reads it; the panel's worker feeds it)."""
        self.parameters = DeviceParameters(self.motion, parameters, self._operation)
        """The device's parameters: `all`, `kept()`, `set`, `write`, `write_profile`."""
        self.tap = TrafficTap(link)
        """The traffic tap: listeners, logs (`remove_listener`, `note`)."""
        self._move_ended: list[Callable[[PositionReport], None]] = []
        self._runner: ProgramRunner | None = None
        self._running_in: int | None = None  # the thread an operation runs in (None: idle)

    @classmethod
    def _around(cls, motion: Motion) -> DeviceSession:
        """A session over a Motion made elsewhere (for callers that still pass one; internal)."""
        session = cls.__new__(cls)
        session._attach(motion.client.link, motion.client.protocol, motion.client, motion)
        return session

    # -- life cycle ----------------------------------------------------------------------------
    def __enter__(self) -> DeviceSession:
        """The session itself."""
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        value: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        """Close the session, whatever ended the block."""
        self.close()

    def close(self) -> None:
        """Close the port and the log files the session opened (idempotent)."""
        self.link.close()
        self.tap.close()

    @property
    def closed(self) -> bool:
        """Whether the port is closed."""
        return self.link.closed

    def resume_from(self, here: tuple[float, float, float]) -> None:
        """Go on from where a device that cannot be asked was left (kept from an earlier run):
        its next relative move, or a pi-frame's next target, starts there; BadInput where the
        device reports its position (it is asked instead) or cannot be sent from there."""
        if self.capabilities.position_feedback:
            raise BadInput(
                Message("{protocol} reports where it is: it is asked", protocol=self.protocol.name)
            )
        resume(self.protocol, here)
        self.motion.last_position = PositionReport(*here, measured=False)

    def start(self) -> None:
        """Send what the device needs once the port is open (the protocol's start-up commands)."""
        with self._operation():
            self.motion.start()

    # -- what the device is --------------------------------------------------------------------
    @property
    def port(self) -> str:
        """The port as opened (a `sim://` URL with the protocol's variant added)."""
        return self.link.url

    @property
    def capabilities(self) -> Capabilities:
        """What the protocol can do (axes, units, homing, stop, parameters, streaming...)."""
        return self.motion.capabilities

    def identify(self) -> str:
        """The device's identifier (the protocol's name where the device cannot say)."""
        with self._operation():
            return self.motion.identify()

    # -- the travel guard ----------------------------------------------------------------------
    @property
    def travel(self) -> TravelLimits | None:
        """The box every move must stay in (None: anywhere the device accepts)."""
        return self.motion.travel

    @travel.setter
    def travel(self, limits: TravelLimits | str | None) -> None:
        self.motion.travel = travel_limits(limits)

    # -- moves ---------------------------------------------------------------------------------
    def position(self) -> PositionReport:
        """Where the stage is: measured where the device reports it, else as commanded."""
        with self._operation():
            return self.motion.position()

    def where(self) -> Whereabouts:
        """What is known of the position now, without asking the device: the last report
        (live), an estimate during a move, or not known (uncounted, lost with the link, the
        estimate at the loss), with the reason as its `status`."""
        return self.truth.now()

    def move_to(self, x: float, y: float, z: float = 0.0) -> PositionReport:
        """Move to (x, y, z) mm and wait until the move has ended; the position then."""
        with self._operation():
            return self._ended(self.motion.move_to(x, y, z))

    def move_by(
        self,
        dx: float,
        dy: float,
        dz: float = 0.0,
        kind: str = "linear",
        *,
        what: str | None = None,
    ) -> PositionReport:
        """Move by (dx, dy, dz): mm, or the protocol's `kind` (rotational, steps); the position.
        `what`: how an error names the move (default: a jog by the amounts)."""
        with self._operation():
            return self._ended(self.motion.move_by(dx, dy, dz, kind, what=what))

    def home(self) -> PositionReport:
        """Go to (0, 0, 0) and wait until there; the position then."""
        with self._operation():
            return self._ended(self.motion.home())

    def set_home(self) -> None:
        """Make the current position the origin."""
        with self._operation():
            self.motion.set_home()

    def speed(self, value: float | None = None) -> float:
        """Set the speed to `value` (refused outside the device's limits) and return what the
        device reports; without a value, the speed now."""
        with self._operation():
            if value is None:
                return self.motion.speed()
            return self.motion.set_speed(value)

    def speed_limits(self) -> tuple[float, float]:
        """The lowest and highest speed the device allows."""
        with self._operation():
            return self.motion.speed_limits()

    def stop(self) -> None:
        """Stop the move or program under way and flush the device's queue. A program is
        ended on every device (nothing more is sent; the move under way finishes where the
        protocol has no stop); otherwise NoStop where the protocol has no stop command."""
        if self.stop_program():  # run_program sends the device's stop once sending ends
            return
        if self._running_in not in (None, threading.get_ident()) and not self.capabilities.stop:
            self.motion.stop_requested.set()  # a macro or a wait ends at its next step
        if not self.capabilities.stop:
            raise NoStop(
                Message(
                    "{protocol} has no stop command: the device finishes what it was sent",
                    protocol=self.protocol.name,
                )
            )
        if self._running_in not in (None, threading.get_ident()):
            self.motion.stop_requested.set()  # the move being waited on is stopped
            return
        with self._operation():
            self.client.execute(cmd.Stop())

    def request_stop(self) -> None:
        """Ask the operation under way to stop (any thread; nothing is sent from the calling
        one): the move being waited on is stopped by the thread that runs it, where the
        protocol has a stop; a program ends; a macro or a wait ends at its next step."""
        self.motion.stop_requested.set()
        self.stop_program()

    def arc(
        self,
        cx: float,
        cy: float,
        radius: float,
        start: float,
        end: float,
        *,
        ccw: bool = False,
        z: float = 0.0,
    ) -> PositionReport:
        """An arc around (cx, cy) mm from angle `start` to `end` (degrees from +X), clockwise
        unless `ccw`, Z going to `z`; a straight move to its start first where the stage is
        elsewhere; every point is checked against the travel box first. The position then."""
        with self._operation():
            arc = cmd.Arc(cx, cy, radius, start, end, ccw, z)
            if self.capabilities.arcs:  # the whole path first, before a move to its start
                self.motion.guard.path(arc_points(arc, self._here()[2], ARC_POINTS), Message("arc"))
            return self._ended(self.motion.arc(arc))

    def dwell(self, seconds: float) -> None:
        """Pause the device's queue for `seconds` (to the millisecond) and wait it out."""
        with self._operation():
            self.motion.dwell(round(seconds * 1000))

    def wait(self, seconds: float) -> bool:
        """Wait `seconds` reading the port (an error the device reports is raised); True when
        the wait was abandoned (the session's abort)."""
        with self._operation():
            return self.motion.wait(seconds)

    def check(self) -> None:
        """Run the device's diagnostics; DeviceError lists what it reported."""
        with self._operation():
            self.motion.check()

    def check_raw(self, data: bytes, force: bool = False) -> RawMove | None:
        """What the guard makes of raw bytes (as `send_raw` would send them), nothing sent:
        the move checked from where the stage is (None: they move nothing, or go unread);
        BadInput (RawRefused) when they would be refused."""
        with self._operation():
            move = self.motion.guard.read_raw(self.protocol, data, force)
            if move is None:
                return None
            return self._check_move(move, self._here())

    def check_commands(self, commands: Sequence[cmd.Command]) -> Point | None:
        """Check commands with the guard as the device would make them, one after another from
        where the stage is, nothing sent; where the last move ends (None: none moves)."""
        with self._operation():
            start, end = self._here(), None
            for command in commands:
                move = self._move_in(command)
                if move is not None:
                    end = start = self._check_move(move, start).target
            return end

    def send_raw(self, data: bytes, force: bool = False) -> Reply | PositionReport | None:
        """Send bytes as they are, once the guard has read them with the protocol's decoder: a
        move is checked like a typed one and followed to its end (the position then); bytes
        that cannot be read go only where no travel box is set, or with `force`. Else the
        reply (None: none is followed)."""
        with self._operation():
            return self._ended(self.motion.send_raw(data, force))

    def raw(self, text: bytes, force: bool = False) -> Reply | PositionReport | None:
        """Send a command as typed (the protocol adds what ends it, e.g. a line feed), through
        the guard as `send_raw`."""
        with self._operation():
            return self._ended(self.motion.raw(text, force))

    def send(
        self, command: cmd.Command, *, reply: bool = True, timeout: float | None = None
    ) -> Reply | None:
        """Send a typed command of the device's own (a query, a setting, a Firmata step) once
        the guard has checked any move it makes from where the stage is; its reply (None where
        `reply` is False: nothing is waited for). `timeout`: seconds the reply may take."""
        with self._operation():
            move = self._move_in(command)
            if move is not None:
                self._check_move(move, self._here())
            if not reply:
                self.client.send_only(command)
                return None
            return self.client.execute(command, timeout=timeout)

    def set_parameter(self, key: str | int, value: float) -> ParameterWritten:
        """Write one device parameter (by name or id) once the device has confirmed it."""
        with self._operation():
            return self.motion.set_parameter(key, value)

    def configure(self, values: Mapping[str, float]) -> Capabilities:
        """Change the protocol's settings (ticks per mm, steps per revolution...) from now on;
        the capabilities as they are then (BadInput for a value out of range)."""
        self.protocol.configure(dict(values))
        return self.capabilities

    def poll(self) -> None:
        """Read what the device said unasked (the subscribers hear it), waiting for nothing."""
        with self._operation():
            self.client.poll()

    # -- the operation under way ---------------------------------------------------------------
    def operation(self) -> AbstractContextManager[None]:
        """One operation of many steps (a macro): a `stop` from another thread during it is
        kept (`stop_requested`) until it ends, the steps' own operations included."""
        return self._operation()

    @property
    def stop_requested(self) -> bool:
        """Whether a stop was asked during the operation under way."""
        return self.motion.stop_requested.is_set()

    @property
    def last_position(self) -> PositionReport | None:
        """The position last known (read, or where the last move ended), nothing asked."""
        return self.motion.last_position

    @property
    def timeout(self) -> float:
        """Seconds a reply may take (settable: e.g. shorter once interrupted)."""
        return self.client.timeout

    @timeout.setter
    def timeout(self, seconds: float) -> None:
        self.client.timeout = seconds

    @property
    def poll_interval(self) -> float:
        """Seconds between position reads while a move is waited on (settable)."""
        return self.motion.poll_interval

    @poll_interval.setter
    def poll_interval(self, seconds: float) -> None:
        self.motion.poll_interval = seconds

    @property
    def simulator(self) -> object | None:
        """The simulated device behind a `sim://` port (None: a real one)."""
        return getattr(self.link.port, "device", None)

    # -- the traffic tap -----------------------------------------------------------------------
    def add_listener(self, listener: TrafficListener) -> None:
        """Call `listener` with every Traffic record (bytes sent or received) from now on."""
        self.tap.add_listener(listener)

    def log_to(self, target: LogTarget) -> TrafficLogWriter:
        """Write every byte from now on to a log: a path (appended to, closed with the session),
        a stream or a TrafficLogWriter (the caller's). A new log (a path or a stream) starts
        with the note naming the port and protocol, which the log readers parse."""
        writer = self.tap.log_to(target)
        if not isinstance(target, TrafficLogWriter):  # a writer's owner notes its connection
            baud = int(getattr(self.link.port, "baudrate", 0) or 0)
            writer.note(connection_note(self.link.url, self.protocol, baud))
        return writer

    def _ended(self, result: _R) -> _R:
        """Tell the move-ended subscribers where a move ended (a PositionReport result)."""
        if isinstance(result, PositionReport):
            for listener in list(self._move_ended):
                listener(result)
        return result

    def _here(self) -> Point:
        """Where the stage is (asked where it cannot be known otherwise)."""
        here = self.motion.last_position
        if here is None or self.capabilities.position_feedback:
            here = self.motion.position()
        return (here.x, here.y, here.z)

    def _move_in(self, command: cmd.Command) -> cmd.Command | None:
        """The move a typed command makes, as the protocol's decoder reads its bytes (None:
        it moves nothing)."""
        if isinstance(command, cmd.MoveTo | cmd.MoveBy | cmd.Home | cmd.Arc):
            return command
        return self.motion.guard.read_raw(self.protocol, self.protocol.encode(command), True)

    def _check_move(self, move: cmd.Command, start: Point) -> RawMove:
        """A move checked by the guard from `start` (resolution, travel box: never clamped)."""
        resolution = self.capabilities.resolution
        return self.motion.guard.raw_move(self.protocol, move, start, resolution, self.notify)

    # -- helpers -------------------------------------------------------------------------------
    @contextmanager
    def _operation(self) -> Iterator[None]:
        """Mark an operation under way in this thread (`stop` from another one then asks the
        move being waited on to stop); a stop asked before it is not for it."""
        outer = self._running_in is None
        if outer:
            self.motion.stop_requested.clear()
            self._running_in = threading.get_ident()
        try:
            yield
        except (CommunicationError, Aborted):
            self.truth.link_lost()  # a move under way is known only as its estimate now
            raise
        except MotionError:
            self.truth.move_ended()
            raise
        finally:
            if outer:
                self._running_in = None


def open_device(
    port: str,
    protocol: str | Protocol,
    *,
    variant: str | None = None,
    baud: int | None = None,
    timeout: float = 2.0,
    settings: Mapping[str, float] | None = None,
    parameters: Mapping[str, float] | None = None,
    dtr: bool | None = None,
    rts: bool | None = None,
    travel: TravelLimits | str | None = None,
    clamp: bool = False,
    log: LogTarget | None = None,
    listeners: Sequence[TrafficListener] = (),
    start: bool = True,
    abort: threading.Event | None = None,
    position: tuple[float, float, float] | None = None,
    after_loss: bool = False,
) -> DeviceSession:
    """Open a device and return its session (a context manager that closes it).

    `port`: a device path, COM name or pyserial URL (`sim://coxiris`, `rfc2217://host:port`);
    `protocol`: its name (`coxiris`, `visiomex`, `laser-frame`, `pi-frame`, `firmata`) or a
    Protocol made already. `variant`: the wire variant (visiomex: seed, prefixed, board12);
    `baud`: default the protocol's; `timeout`: seconds a reply may take; `settings`: the
    protocol's settings (`ticks_per_mm`...); `parameters`: values written earlier, taken as
    what the device holds; `dtr`/`rts`: the lines when the port opens (default: as the device
    needs); `travel`: the box moves must stay in (a TravelLimits or `X0:X1,Y0:Y1,Z0:Z1` mm),
    `clamp`: beyond it go to its edge instead of refusing; `log`: a file path, stream or
    TrafficLogWriter for a hexdump of the traffic; `listeners`: called with every Traffic
    record; `start`: send the start-up commands now (False: the caller calls `start`);
    `abort`: an Event that, once set from any thread, makes a wait give up (Aborted);
    `position`: where a device that cannot be asked is, as kept from an earlier run (its count,
    or the target it was sent last): the session goes on from there (`resume_from`);
    `after_loss`: the device was lost with its link before (`where` then says `lost`, not
    `uncounted`, for a position it cannot be asked about).
    BadInput or UnknownProtocol for wrong settings, PortError when the port cannot be opened.
    """
    if timeout <= 0:
        raise BadInput(
            Message("timeout {timeout:g} s refused: it must be positive", timeout=timeout)
        )
    made = make_protocol(protocol, variant, settings, parameters)
    limits = travel_limits(travel, clamp)
    link = open_device_link(port, made, baud=baud, dtr=dtr, rts=rts)
    session = DeviceSession(
        link,
        made,
        timeout=timeout,
        travel=limits,
        abort=abort,
        parameters=parameters,
        after_loss=after_loss,
    )
    try:
        if position is not None:
            session.resume_from(position)
        for listener in listeners:
            session.add_listener(listener)
        if log is not None:
            session.log_to(log)
        if start:
            session.start()
    except BaseException:
        session.close()
        raise
    return session
