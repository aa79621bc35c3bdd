"""One connected device: the scripting API, and the set-up every front end shares.

    import drivers

    with drivers.open_device("sim://coxiris", "coxiris") as stage:
        stage.move_to(10, 5)
        print(stage.position())

`open_device` opens the port as the protocol needs it, builds the client and the motion layer,
sets the travel box (every move is checked against it before anything is sent), taps the
traffic (listeners, a log file) and sends the device's start-up commands. The session is closed
when the `with` block ends, an exception included.

Public and stable: `open_device`, `DeviceSession` (the methods and properties without a leading
underscore; `session.parameters` is a `DeviceParameters`, drivers/session/parameters.py, and
`session.tap` a `TrafficTap`, drivers/session/tap.py; `session.where()` a `Whereabouts`,
drivers/device/position_truth.py), `NoStop`, `NoPrograms`, `ProgressListener`.
`DeviceSession.link`, `.client`, `.motion` and `.protocol` are the layers underneath, for front
ends that need more (the panel's worker); they follow the driver layer's own changes. Macros
(app/common/macros.py) are motionctl's command vocabulary and stay on the application side: run
one with `app.common.macros.run_macro(session.motion, macro)`.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from types import TracebackType

from drivers.device import commands as cmd
from drivers.device.capabilities import Capabilities
from drivers.device.client import Client
from drivers.device.events import PositionReport
from drivers.device.motion import Motion
from drivers.device.position_count import resume
from drivers.device.position_truth import PositionTruth, Whereabouts
from drivers.device.travel import TravelLimits
from drivers.errors import BadInput, CommunicationError, MotionError
from drivers.link.transport import Link, TrafficListener
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.session.parameters import DeviceParameters
from drivers.session.setup import LogTarget, make_protocol, open_device_link, travel_limits
from drivers.session.tap import TrafficTap
from drivers.toolpath.loader import from_points
from drivers.toolpath.model import CHORD_TOLERANCE, Toolpath
from drivers.toolpath.point_program import ProgramPoint
from drivers.toolpath.runner import ProgramRunner
from drivers.toolpath.streaming import StreamProgress
from drivers.traffic.log_origin import connection_note
from drivers.traffic.records import TrafficLogWriter

__all__ = [
    "DeviceSession",
    "NoPrograms",
    "NoStop",
    "ProgressListener",
    "Whereabouts",
    "open_device",
]

ProgressListener = Callable[[StreamProgress], None]
"""Told how far a program has got (a StreamProgress) after each frame or move."""


class NoStop(BadInput):
    """The protocol has no stop command: the device finishes what it was sent."""


class NoPrograms(BadInput):
    """Kept for scripts that catch it: every protocol runs programs now (none raises it)."""


class DeviceSession:
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
        self.link = link
        self.protocol = protocol
        self.client = Client(link, protocol, timeout=timeout)
        if abort is not None:
            self.client.abort = abort
        self.motion = Motion(self.client)
        self.motion.travel = travel
        self.truth = PositionTruth(self.motion, after_loss=after_loss)
        """What is known of the position (`where` reads it; the panel's worker feeds it)."""
        self.parameters = DeviceParameters(self.motion, parameters, self._operation)
        """The device's parameters: `all`, `kept()`, `set`, `write`, `write_profile`."""
        self.tap = TrafficTap(link)
        """The traffic tap: listeners, logs (`remove_listener`, `note`)."""
        self._runner: ProgramRunner | None = None
        self._running_in: int | None = None  # the thread an operation runs in (None: idle)

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
            return self.motion.move_to(x, y, z)

    def move_by(
        self, dx: float, dy: float, dz: float = 0.0, kind: str = "linear"
    ) -> PositionReport:
        """Move by (dx, dy, dz): mm, or the protocol's `kind` (rotational, steps); the position."""
        with self._operation():
            return self.motion.move_by(dx, dy, dz, kind)

    def home(self) -> PositionReport:
        """Go to (0, 0, 0) and wait until there; the position then."""
        with self._operation():
            return self.motion.home()

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

    # -- programs ------------------------------------------------------------------------------
    def run_program(
        self,
        program: Toolpath | Iterable[ProgramPoint],
        progress: ProgressListener | None = None,
        group: int | None = None,
        *,
        tolerance: float = CHORD_TOLERANCE,
    ) -> StreamProgress:
        """Run a program and wait until the device has run it: a Toolpath (drivers.toolpath,
        `load_toolpath` reads G-code, DXF, SVG, CSV and JSON) or points. `progress` is told how
        far it got (its `source` names the line under way); arcs are cut into chords within
        `tolerance` mm where the device has no arcs of its own. A program that would leave the
        travel box, or asks a speed the device does not allow, is refused whole before
        anything is sent; `stop` ends it early. Laser-frame streams it to its queue (`group`
        instructions a frame at most), pi-frame gets arcs as arcs, other devices move by move."""
        toolpath = program if isinstance(program, Toolpath) else from_points(list(program))
        runner = ProgramRunner(
            self.motion, toolpath, tolerance=tolerance, progress=progress, group=group
        )
        with self._operation():
            self._runner = runner
            try:
                state = runner.run()
            finally:
                self._runner = None
            if runner.stopped and self.capabilities.stop:
                self.client.execute(cmd.Stop())  # flushes what the device has queued
            self.motion.position()
        return state

    def pause_program(self, paused: bool = True) -> None:
        """Send nothing more of the program under way until resumed (`paused` False); a
        queue on the device goes on with what it has. Any thread; nothing happens without one."""
        runner = self._runner
        if runner is not None:
            if paused:
                runner.pause()
            else:
                runner.resume()

    def stop_program(self) -> bool:
        """End the program under way early (any thread): `run_program` then stops the device
        where it has a stop (flushing its queue); whether a program was under way."""
        runner = self._runner
        if runner is None:
            return False
        runner.stop()
        return True

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
        except CommunicationError:
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
