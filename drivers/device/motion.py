"""High-level motion API over a client: moves that return when done, speed with limits."""

from __future__ import annotations

import dataclasses
import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace

from drivers.device.client import ABANDONED, Client
from drivers.device.guard import MotionGuard, RawMove, arc_point, arc_points
from drivers.device.travel import Point, TravelLimits, check_resolution
from drivers.errors import Aborted, BadInput, DeviceError, DeviceTimeout
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.protocols.base import Protocol, Reply
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.events import ErrorReport, Event, PositionReport
from drivers.protocols.parameters import ParameterWritten

log = logging.getLogger(__name__)

POSITION_TOLERANCE = 0.011  # positions are printed with two decimals from 32-bit floats
FLOAT_TOLERANCE = 1e-4  # mm: positions reported as 32-bit floats (no resolution declared)
POLL_INTERVAL = 0.1  # seconds between position polls while waiting for a move to end
LISTEN_SLICE = 0.05  # s: a wait on a write-only device's move reads its errors this often
ESTIMATE_MARGIN = 1.5  # a move may take this much longer than distance / speed
KIND_UNITS = {"linear": "mm", "rotational": "degrees", "steps": "steps"}
"""The unit of a relative move's distances by its kind (MoveBy.kind)."""
EVIDENCE_MIN_S = 0.05
"""A move shows whether its device replies once it has ended only if it takes this long (by
distance and speed): a reply at the start then comes clearly before the end."""
LATE_REPLIES = 2
"""Moves whose reply ended a move's time after it began, before that is taken to mean arrival:
a host that stalls between reading the two halves of an early reply looks like it once."""


@dataclass(frozen=True)
class MoveStart:
    """A move has been sent: where from, where to, how fast, and when (time.monotonic())."""

    start: Point
    target: Point
    speed: float
    started: float
    duration: float
    path: Callable[[float], Point] | None = None
    """The point at a fraction 0..1 of the move (an arc); None: a straight line."""
    recomputed: dict[str, float] = field(default_factory=dict)
    """Parameters the device recomputes as it makes this move (Visiomex 15, 16, 19, 20), by
    name: what it holds once the move has run, by its own arithmetic."""

    def estimate(self, now: float) -> Point:
        """Where the stage should be at `now`, moving along its path at `speed`."""
        if self.duration <= 0 or now >= self.started + self.duration:
            return self.target
        f = max(0.0, (now - self.started) / self.duration)
        if self.path is not None:
            return self.path(f)
        x, y, z = (a + (b - a) * f for a, b in zip(self.start, self.target, strict=True))
        return (x, y, z)


def _raw_timing(
    protocol: Protocol, command: cmd.Command, start: Point, target: Point
) -> tuple[float, float] | None:
    """The protocol's timing of a move read from raw bytes (None: distance over speed)."""
    try:
        return protocol.move_timing(command, start, target)
    except BadInput:  # e.g. a pi-frame speed the encoder would write otherwise
        return None


def arrival_tolerance(resolution: float | None) -> float:
    """How near a reported position must be to a target to be at it: a little over the
    device's resolution (COXIRIS's 0.01 mm: 0.011), or the precision of a 32-bit float where
    the device declares none (laser-frame), so a stage still moving is not taken as arrived."""
    return POSITION_TOLERANCE * resolution / 0.01 if resolution else FLOAT_TOLERANCE


def _at(
    report: PositionReport, point: PositionReport | Point, tolerance: float = POSITION_TOLERANCE
) -> bool:
    """Whether a position is `point`, to the precision positions are reported with."""
    if isinstance(point, PositionReport):
        point = (point.x, point.y, point.z)
    here = (report.x, report.y, report.z)
    return all(abs(a - b) <= tolerance for a, b in zip(here, point, strict=True))


class Motion:
    """Operator-level commands for any protocol, adapting to its capabilities."""

    def __init__(self, client: Client, wait: Callable[[float], bool] | None = None) -> None:
        self.client = client
        self.position_listeners: list[Callable[[PositionReport], None]] = []
        self.poll_interval = POLL_INTERVAL
        self.wait = wait or self._listen
        """Waits the given seconds; returns True when the wait was aborted."""
        self.guard = MotionGuard()
        """Checks every move before it is sent (travel box, resolution, raw bytes)."""
        self.move_listeners: list[Callable[[MoveStart], None]] = []
        self.stop_requested = threading.Event()
        """Set from any thread: a move being waited on is stopped (where the device can stop)."""
        self.parameter_listeners: list[Callable[[ParameterWritten], None]] = []
        """Told of every parameter the device confirmed (and what it changed by itself)."""
        self.notice_listeners: list[Callable[[str], None]] = []
        """Told what the user should know, e.g. that a move was clamped to the travel limits."""
        self._speed: float | None = None
        self._limits: tuple[float, float] | None = None
        self.last_position: PositionReport | None = None
        self._known_at = -1  # client.writes when last_position became known (read or arrived)
        self._heard = 0  # unsolicited events so far: a device that spoke unasked may have changed
        self._known_heard = 0  # ... when last_position became known
        self._reply_times: list[float] | None = None  # when a move's reply events came
        self._late_replies = 0  # moves whose reply ended as the move did (see LATE_REPLIES)
        self.arrives_on_reply = False
        """Whether this device's reply to a move has been seen to mean the move has ended
        (Completion.REPLY: COXIRIS's blocking sketch does, its non-blocking one and the laser's
        queue do not), so that the target is where the stage is once the reply has come."""
        client.listeners.append(self._on_event)
        if not self.capabilities.position_feedback:
            # Write-only devices: the position is what was commanded, from where the session
            # began, which is no known place until a Home, a Set Home or an absolute target.
            self.last_position = PositionReport(0.0, 0.0, 0.0, measured=False, known=False)

    @property
    def travel(self) -> TravelLimits | None:
        """Where moves may go (the guard's box); None: anywhere the device accepts."""
        return self.guard.travel

    @travel.setter
    def travel(self, limits: TravelLimits | None) -> None:
        self.guard.travel = limits

    @property
    def capabilities(self) -> Capabilities:
        """The protocol's capabilities as they are now (settings may change them)."""
        return self.client.protocol.capabilities

    def _listen(self, seconds: float) -> bool:
        """Wait while reading the port: an error the device reports meanwhile (Firmata's
        STRING_DATA) ends the wait at once and is raised; True when the wait was abandoned."""
        clock = self.client.clock
        end = clock() + seconds
        while True:
            try:
                events = self.client.listen(min(LISTEN_SLICE, max(end - clock(), 0.0)))
            except Aborted:
                return True
            errors = [e for e in events if isinstance(e, ErrorReport)]
            if errors:
                reported = "; ".join(e.message for e in errors)
                raise DeviceError(Message("the device reported: {reported}", reported=reported))
            if clock() >= end:
                return False

    def start(self) -> None:
        """Send what the device needs once identified (the protocol's startup commands)."""
        for command in self.client.protocol.startup_commands():
            self.client.execute(command)

    def identify(self) -> str:
        """The device's identifier (the protocol's name where the device cannot say)."""
        if not self.capabilities.identity_queryable:
            return Message("{protocol} device", protocol=self.client.protocol.name)
        return str(self.client.execute(cmd.GetId()).value)

    def position(self) -> PositionReport:
        """The current position: measured where the protocol reports it, else the commanded one."""
        if not self.capabilities.position_feedback:
            assert self.last_position is not None
            self._set_position(self.last_position)  # listeners see it like a measured one
            return self.last_position
        inferred = self.last_position if self._fresh() else None
        value = self.client.execute(cmd.GetPosition()).value
        if not isinstance(value, PositionReport):
            raise DeviceError(
                Message("the device did not report a position (it answered {value})", value=value)
            )
        tolerance = arrival_tolerance(self.capabilities.resolution)
        if inferred is not None and not inferred.measured and not _at(value, inferred, tolerance):
            self.arrives_on_reply, self._late_replies = False, 0  # it was not where it said
            for listener in list(self.notice_listeners):
                listener(
                    Message(
                        "the device is at ({x:g}, {y:g}, {z:g}) mm, not where its "
                        "last move ended: its replies are no longer taken as arrival",
                        x=value.x,
                        y=value.y,
                        z=value.z,
                    )
                )
        self._set_position(value)
        self._known()  # nothing has been sent since it was read
        return value

    def _current(self) -> PositionReport:
        """The position, asked only where the last one known may no longer hold.

        A position is known when it was read, or when a move ended that the device said it
        had finished (a reply that means arrival: see `arrives_on_reply`); it stays true until
        anything else is written or the device says something unasked (the stage moves only
        when told to), so a jog right after a jog, or after the idle poll, asks nothing.
        """
        known = self.last_position
        if known is not None and self._fresh():
            return known
        return self.position()

    def _known(self) -> None:
        """The position just given to the listeners holds until something else happens."""
        self._known_at, self._known_heard = self.client.writes, self._heard

    def _fresh(self) -> bool:
        """Whether the position last known still holds: nothing written, nothing unasked."""
        return self._known_at == self.client.writes and self._known_heard == self._heard

    def _on_event(self, event: Event, solicited: bool) -> None:
        if solicited:
            if self._reply_times is not None:
                self._reply_times.append(time.monotonic())
        else:
            self._heard += 1  # a restart's banner, a late reply, a line of its own

    def speed(self) -> float:
        """The speed as the device reports it (or as last set, where it cannot be read back)."""
        if not self.capabilities.speed_readback:
            real = self.client.protocol.moving_speed()  # Visiomex: its step delays' speed
            if real is not None:
                return real
            return self._speed if self._speed is not None else self.capabilities.default_speed
        value = self._number(cmd.GetSpeed())
        self._speed = value
        return value

    def _number(self, command: cmd.Command) -> float:
        """A query's reply value, as a float (float's error where it is not a number)."""
        # Reply.value is an object: which query gets a number is each protocol's to say.
        return float(self.client.execute(command).value)  # type: ignore[arg-type]

    def speed_limits(self) -> tuple[float, float]:
        """The lowest and highest speed the device allows."""
        if self._limits is None:
            if self.capabilities.speed_limits_queryable:
                low = self._number(cmd.GetMinSpeed())
                high = self._number(cmd.GetMaxSpeed())
                self._limits = (low, high)
            elif self.capabilities.speed_range is not None:
                return self.capabilities.speed_range  # not kept: settings may change it
            else:
                raise BadInput(
                    Message(
                        "{protocol} has no speed limits to report",
                        protocol=self.client.protocol.name,
                    )
                )
        return self._limits

    def set_speed(self, speed: float) -> float:
        """Set the speed, refused outside the device's limits; returns what the device reports.

        The limits are asked of the device first where the protocol can (COXIRIS: two queries),
        so an out-of-range speed is refused without SET_SPEED being sent. Where the protocol
        sets the speed as parameters (Visiomex 21 and 22), each is written and reported.
        """
        if not math.isfinite(speed) or speed <= 0:
            raise BadInput(
                Message("speed {speed:g} refused: the speed must be a positive number", speed=speed)
            )
        low, high = self.speed_limits()
        unit = self.capabilities.speed_unit
        if not low <= speed <= high:
            raise BadInput(
                Message(
                    "speed {speed:g} {unit} refused: the device allows {low:g} to {high:g} {unit}",
                    speed=speed,
                    unit=unit,
                    low=low,
                    high=high,
                )
            )
        fixed = self.client.protocol.moving_speed()
        if fixed is not None and math.isclose(speed, fixed):
            return fixed  # the device moves so already (a program's end setting it back)
        # Where the speed goes with every move (pi-frame, Firmata), nothing is sent now.
        speed_in_moves = self.capabilities.speed_in_moves
        parts = [] if speed_in_moves else self.client.protocol.expand(cmd.SetSpeed(speed))
        for part in parts:
            self.client.protocol.encode(part)  # every packet checked before the first is sent
        for part in parts:
            if isinstance(part, cmd.SetParameter):
                self.set_parameter(part.param_id, part.value)
            else:
                self.client.execute(part)
        self._speed = speed
        if fixed is not None:  # Visiomex: 21/22 are written, its step delays time the steps
            real = self.client.protocol.moving_speed()
            assert real is not None
            self._notify(
                Message(
                    "speed {speed:g} {unit} written, but this firmware times its steps from its "
                    "step delays (15, 16) alone: moves go at {real:.3f} {unit}",
                    speed=speed,
                    unit=unit,
                    real=real,
                )
            )
            return real
        if self.capabilities.speed_readback:
            reported = self.speed()
            if reported != speed:
                log.debug(
                    "speed %g %s reads back as %g (the device rounds it)", speed, unit, reported
                )
            return reported
        return speed

    def set_parameter(self, key: str | int, value: float) -> ParameterWritten:
        """Write one device parameter (by name or id) and wait for the device to confirm it."""
        protocol = self.client.protocol
        parameter = protocol.parameter(key)
        command = cmd.SetParameter(parameter.id, value)
        protocol.encode(command)  # refused before sending: range, digits, not a number
        self.client.execute(command)
        written = protocol.parameter_written(command)
        for listener in list(self.parameter_listeners):
            listener(written)
        return written

    def move_to(self, x: float, y: float, z: float = 0.0) -> PositionReport:
        """Absolute move; returns the position once the move has ended.

        Where the device moves only relatively (Visiomex), the distance from the position
        the panel knows is sent.
        """
        check_resolution((x, y, z), ("x", "y", "z"), self.capabilities.resolution)
        what = Message("move to ({x:g}, {y:g}, {z:g}) mm", x=x, y=y, z=z)
        if self.capabilities.absolute_moves:
            return self._move(
                what, lambda here: (x, y, z), lambda here, t: cmd.MoveTo(*t), cmd.MoveTo(x, y, z)
            )
        return self._move(
            what,
            lambda here: (x, y, z),
            lambda here, t: cmd.MoveBy(*self._deltas(here, t)),
            check=cmd.MoveBy(0.0, 0.0, z),
        )

    def move_by(
        self,
        dx: float,
        dy: float,
        dz: float = 0.0,
        kind: str = "linear",
        *,
        what: str | None = None,
    ) -> PositionReport:
        """Relative move (`kind`: linear mm, or the protocol's rotational degrees or steps);
        `what` names it in messages (a Message; default "jog by (dx, dy, dz) unit")."""
        command = cmd.MoveBy(dx, dy, dz, kind)
        if kind == "linear":
            check_resolution((dx, dy, dz), ("dx", "dy", "dz"), self.capabilities.resolution)
        lx, ly, lz = self.client.protocol.kind_to_length(command)
        if what is None:
            what = Message(
                "jog by ({dx:g}, {dy:g}, {dz:g}) {unit}",
                dx=dx,
                dy=dy,
                dz=dz,
                unit=KIND_UNITS.get(kind, kind),
            )
        return self._move(
            what,
            lambda here: (here.x + lx, here.y + ly, here.z + lz),
            lambda here, t: self._relative(command, here, t, (lx, ly, lz)),
            check=command if self.capabilities.relative_moves else cmd.MoveTo(dx, dy, dz),
        )

    def _relative(
        self, command: cmd.MoveBy, here: PositionReport, target: Point, deltas: Point
    ) -> cmd.Command:
        """The command for a relative move: as asked, or (clamped, or for a device that moves
        only to absolute positions) rebuilt for the target."""
        if not self.capabilities.relative_moves:
            return cmd.MoveTo(*target)
        if target == (here.x + deltas[0], here.y + deltas[1], here.z + deltas[2]):
            return command
        return cmd.MoveBy(*self._deltas(here, target))

    def home(self) -> PositionReport:
        """Go to (0, 0, 0); returns the position once there.

        A device with no homing command of its own is moved back by a relative move.
        """
        if not self.capabilities.homing:
            if not self.capabilities.position_feedback:  # the panel knows where (0, 0, 0) is
                report = self.move_to(0.0, 0.0, 0.0)
                if not report.known:  # back where the count began: its origin from now on
                    report = replace(report, known=True)
                    self._set_position(report)
                return report
            raise BadInput(
                Message("{protocol} has no way to go home", protocol=self.client.protocol.name)
            )
        return self._move(Message("go home"), lambda here: (0.0, 0.0, 0.0), None, check=cmd.Home())

    def _as_reported(self, point: Point) -> Point:
        """`point` on the device's resolution, as it reports it (5.1 - 0.2: 4.9, not 4.8999...)."""
        step = self.capabilities.resolution
        if not step:
            return point
        per_unit = round(1 / step)
        if abs(per_unit * step - 1) > 1e-9:
            return point
        x, y, z = (round(v * per_unit) / per_unit for v in point)
        return (x, y, z)

    def _deltas(self, here: PositionReport, target: Point) -> Point:
        """The distances from `here` to `target`, on the device's resolution."""
        step = self.capabilities.resolution or 1e-9
        dx, dy, dz = (
            round((t - h) / step) * step
            for t, h in zip(target, (here.x, here.y, here.z), strict=True)
        )
        return (dx, dy, dz)

    def set_home(self) -> None:
        """Make the current position the origin.

        A commanded-only device with no such command: the panel's own count restarts from here.
        """
        if self.capabilities.set_home:
            self.client.execute(cmd.SetHome())
        elif self.capabilities.position_feedback:
            raise BadInput(
                Message("{protocol} has no set-home command", protocol=self.client.protocol.name)
            )
        self._set_position(PositionReport(0.0, 0.0, 0.0, self.capabilities.position_feedback))

    def _lands_known(self, command: cmd.Command | None) -> bool:
        """Whether a write-only device's move ends at a known place: an absolute target, or a
        home move, where the device takes them; else as known as where it started."""
        caps = self.capabilities
        if isinstance(command, cmd.MoveTo) and caps.absolute_moves:
            return True
        if isinstance(command, cmd.Home) and (caps.homing or caps.absolute_moves):
            return True
        return self.last_position is not None and self.last_position.known

    def _set_position(self, report: PositionReport) -> None:
        self.last_position = report
        for listener in list(self.position_listeners):
            listener(report)

    def check(self) -> None:
        """Run the device's diagnostics; DeviceError lists what it reported."""
        self.client.execute(cmd.CheckErrors())

    def raw(self, data: bytes, force: bool = False) -> Reply | PositionReport | None:
        """Send a raw command (the protocol adds what ends it, e.g. COXIRIS's line feed) through
        the guard, as `send_raw`."""
        return self.send_raw(self.client.protocol.encode(cmd.Raw(data)), force)

    def send_raw(self, data: bytes, force: bool = False) -> Reply | PositionReport | None:
        """Send console bytes as they are, once the guard has read them with the protocol's
        decoder: a move is checked like a typed one and followed like one (its timeout, its
        end, the position after it: returned); bytes that cannot be read go only where no
        travel box is set, or with `force`. Otherwise the reply (None: none is followed)."""
        protocol = self.client.protocol
        protocol.check_raw(data)
        move = self.guard.read_raw(protocol, data, force)
        if move is None:
            return self.client.send_raw(data)
        here = self._current()
        start = (here.x, here.y, here.z)
        planned = self.guard.raw_move(
            protocol, move, start, self.capabilities.resolution, self._notify
        )
        return self._run_move(move, start, planned.target, planned.path, raw=(data, planned))

    def _notify(self, text: str) -> None:
        for listener in list(self.notice_listeners):
            listener(text)

    def _move(
        self,
        what: str,
        target_of: Callable[[PositionReport], Point],
        command_of: Callable[[PositionReport, Point], cmd.Command] | None,
        check: cmd.Command,
    ) -> PositionReport:
        """Move to `target_of(here)` with `command_of(here, target)` (None: `check` as it is)."""
        protocol = self.client.protocol
        protocol.encode(check)  # refuse bad input before any query is sent
        here = self._current()
        target = target_of(here)
        command = command_of(here, target) if command_of is not None else check
        protocol.encode(command)
        start = (here.x, here.y, here.z)
        limited, note = self.guard.target(target, what, start)
        if limited != target:
            if command_of is None:
                raise BadInput(
                    Message("{what} refused: home is outside the travel limits", what=what)
                )
            target, command = limited, command_of(here, limited)
            protocol.encode(command)
        if note is not None:
            self._notify(note)
        return self._run_move(command, start, target)

    def _with_speed(self, command: cmd.Command) -> cmd.Command:
        """Where the speed goes with every move (pi-frame, Firmata): the speed set, filled in."""
        if not self.capabilities.speed_in_moves:
            return command
        if isinstance(command, cmd.MoveTo | cmd.MoveBy | cmd.Arc) and command.speed is None:
            speed = self._speed if self._speed is not None else self.speed()
            return dataclasses.replace(command, speed=speed)
        return command

    def _run_move(
        self,
        command: cmd.Command,
        start: Point,
        target: Point,
        path: Callable[[float], Point] | None = None,
        raw: tuple[bytes, RawMove] | None = None,
    ) -> PositionReport:
        """Send a move whose target is known, wait for its end, and report the position.

        `raw`: the move is console bytes (sent as they are) the guard read as `command`."""
        protocol = self.client.protocol
        if raw is None:
            command = self._with_speed(command)
            protocol.encode(command)
            timing = protocol.move_timing(command, start, target)
        else:
            timing = raw[1].timing or _raw_timing(protocol, command, start, target)
        if timing is None:
            speed = self._speed if self._speed is not None else self.speed()
            delay, duration = 0.0, math.dist(start, target) / max(speed, 1e-9)
        else:
            delay, duration = timing
            speed = math.dist(start, target) / duration if duration > 0 else 0.0
        # Where the device's own arithmetic leaves the stage (Visiomex: whole steps, its Y
        # loop), said before anything is sent where that is not the target asked for.
        outcome = protocol.move_outcome(cmd.Raw(raw[0]) if raw else command, start, target)
        if outcome.warning:
            self._notify(outcome.warning)
        if outcome.end != target and path is None:
            target = outcome.end
        completion = self.capabilities.completion
        started = MoveStart(
            start, target, speed, time.monotonic() + delay, duration, path, outcome.recomputed
        )
        for move_listener in list(self.move_listeners):
            move_listener(started)
        heard, sent, self._reply_times = self._heard, time.monotonic(), []
        try:
            if raw is not None:
                self.client.send_raw(raw[0], extra=(delay + duration) * ESTIMATE_MARGIN)
                protocol.on_sent(command)  # a write-only device's commanded position follows
                if completion is Completion.ESTIMATE and self.wait(delay + duration):
                    raise Aborted(ABANDONED)
            elif completion is Completion.ESTIMATE:
                # The device never says when it is done (drivers/protocols/README.md §4, §5): each
                # part is sent once the previous one should have ended (Firmata splits long moves).
                parts = protocol.expand(command)
                for part in parts:
                    self.client.send_only(part)
                    part_timing = (
                        protocol.move_timing(part, start, target) if len(parts) > 1 else None
                    )
                    if self.wait(sum(part_timing) if part_timing else delay + duration):
                        raise Aborted(ABANDONED)
            else:
                self.client.execute(command, extra=(delay + duration) * ESTIMATE_MARGIN)
        finally:
            replies, self._reply_times = self._reply_times, None
        if not self.capabilities.position_feedback:
            confirmed = completion is Completion.FEEDBACK  # the device said the move ended
            known = self._lands_known(command)
            self._set_position(
                PositionReport(*target, measured=False, confirmed=confirmed, known=known)
            )
            assert self.last_position is not None
            return self.last_position
        if completion is not Completion.REPLY:
            return self.position()
        undisturbed = heard == self._heard and not self.stop_requested.is_set()
        if self.arrives_on_reply and undisturbed:
            # The reply said the move ended: the stage is at the target (not read back).
            at = self._as_reported(target)
            self._set_position(PositionReport(*at, measured=False, confirmed=True))
            self._known()
            assert self.last_position is not None
            return self.last_position
        report, first_at = self._wait_until_at(target, duration)
        if undisturbed and first_at is not None and duration >= EVIDENCE_MIN_S:
            # The first poll found the stage at the target. The reply meant arrival if the
            # stage got there in under half the time the move takes (it had no time to move
            # after an early reply), or if the reply ended a move's time after it began (a
            # firmware busy while it moves), seen LATE_REPLIES times.
            answering = replies[-1] - replies[0] if replies else 0.0
            if answering >= 0.9 * duration:
                self._late_replies += 1
            if first_at - sent < 0.5 * duration or self._late_replies >= LATE_REPLIES:
                self.arrives_on_reply = True
                log.debug("the device replies to a move once it has ended")
        return report

    def arc(self, arc: cmd.Arc) -> PositionReport:
        """An arc: a straight move to its start point first where the stage is elsewhere."""
        if not self.capabilities.arcs:
            raise BadInput(
                Message("{protocol} has no arc moves", protocol=self.client.protocol.name)
            )
        self.client.protocol.encode(self._with_speed(arc))  # refused before anything is sent
        here = self.position()
        sx, sy = arc.point(arc.start)
        if math.dist((here.x, here.y), (sx, sy)) > (self.capabilities.resolution or 1e-6):
            here = self.move_to(sx, sy, here.z)
        ex, ey = arc.point(arc.end)
        target = (ex, ey, arc.z)
        self.guard.path(arc_points(arc, here.z, 72), Message("arc"))  # never clamped
        z0 = here.z
        return self._run_move(
            arc, (here.x, here.y, here.z), target, lambda f: arc_point(arc, z0, f)
        )

    def dwell(self, ms: int) -> None:
        """Wait on the device (its queue pauses) for `ms` milliseconds."""
        if not self.capabilities.dwell:
            raise BadInput(Message("{protocol} has no dwell", protocol=self.client.protocol.name))
        command = cmd.Dwell(ms)
        self.client.protocol.encode(command)
        self.client.execute(command)  # acknowledged where the protocol acknowledges (laser)
        if self.wait(ms / 1000):
            raise Aborted(ABANDONED)

    def _wait_until_at(
        self, target: tuple[float, float, float], estimate: float
    ) -> tuple[PositionReport, float | None]:
        """After DONE: poll until the position reaches the target (non-blocking firmware style).

        Returns the position, and when the first poll answered if it found the target already.
        """
        allowed = estimate * ESTIMATE_MARGIN + self.client.timeout
        deadline = time.monotonic() + allowed
        previous: PositionReport | None = None
        while True:
            if self.stop_requested.is_set() and self.capabilities.stop:
                self.stop_requested.clear()
                self.client.execute(cmd.Stop())  # halts the move under way and flushes the queue
                stopped = self.position()
                for listener in list(self.notice_listeners):
                    listener(
                        Message(
                            "stopped at ({x:g}, {y:g}, {z:g}) mm",
                            x=stopped.x,
                            y=stopped.y,
                            z=stopped.z,
                        )
                    )
                return stopped, None
            now = self.position()
            if _at(now, target, arrival_tolerance(self.capabilities.resolution)):
                return now, (time.monotonic() if previous is None else None)
            if previous == now:
                log.warning("the stage stopped at %s short of the target %s", now, target)
                return now, None
            if time.monotonic() > deadline:
                raise DeviceTimeout(
                    Message(
                        "the move to {target} did not end within {seconds:.1f} s",
                        target=target,
                        seconds=allowed,
                    )
                )
            previous = now
            if self.wait(self.poll_interval):
                raise Aborted(ABANDONED)
