"""High-level motion API over a client: moves that return when done, speed with limits."""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import replace
from functools import partial

from drivers.device.client import ABANDONED, Client
from drivers.device.completion import (
    POLL_INTERVAL,
    ReplyEvidence,
    arrival_tolerance,
    as_reported,
    is_at,
    lands_known,
    listen,
    poll_until_at,
    send_move,
)
from drivers.device.guard import MotionGuard, RawMove, arc_point, arc_points
from drivers.device.move_start import MoveStart as MoveStart
from drivers.device.move_start import raw_timing
from drivers.device.speed import Speed
from drivers.device.travel import Point, TravelLimits, check_resolution
from drivers.errors import Aborted, BadInput, DeviceError
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.protocols.base import Reply
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.events import Event, PositionReport
from drivers.protocols.parameters import ParameterWritten

log = logging.getLogger(__name__)

KIND_UNITS = {"linear": "mm", "rotational": "degrees", "steps": "steps"}
"""The unit of a relative move's distances by its kind (MoveBy.kind)."""


class Motion:
    """Operator-level commands for any protocol, adapting to its capabilities."""

    def __init__(self, client: Client, wait: Callable[[float], bool] | None = None) -> None:
        self.client = client
        self.position_listeners: list[Callable[[PositionReport], None]] = []
        self.poll_interval = POLL_INTERVAL
        self.wait = wait or partial(listen, client)
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
        self.speeds = Speed(client, self.set_parameter, self._notify)
        """The speed moves go at, and the device's limits."""
        self.last_position: PositionReport | None = None
        self._known_at = -1  # client.writes when last_position became known (read or arrived)
        self._heard = 0  # unsolicited events so far: a device that spoke unasked may have changed
        self._known_heard = 0  # ... when last_position became known
        self.replies = ReplyEvidence()
        """Whether the device's reply to a move has been seen to mean the move has ended."""
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
    def arrives_on_reply(self) -> bool:
        """Whether this device's reply to a move means the move has ended (`ReplyEvidence`)."""
        return self.replies.arrives_on_reply

    @property
    def capabilities(self) -> Capabilities:
        """The protocol's capabilities as they are now (settings may change them)."""
        return self.client.protocol.capabilities

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
        if inferred is not None and not inferred.measured and not is_at(value, inferred, tolerance):
            self.replies.distrust()  # it was not where it said
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
            self.replies.heard()
        else:
            self._heard += 1  # a restart's banner, a late reply, a line of its own

    def speed(self) -> float:
        """The speed as the device reports it (or as last set, where it cannot be read back)."""
        return self.speeds.read()

    def speed_limits(self) -> tuple[float, float]:
        """The lowest and highest speed the device allows."""
        return self.speeds.limits()

    def set_speed(self, speed: float) -> float:
        """Set the speed, refused outside the device's limits; returns what the device reports."""
        return self.speeds.set(speed)

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
        start = (here.x, here.y, here.z)
        limited, note = self.guard.target(target, what, start)
        if limited != target:
            if command_of is None:
                raise BadInput(
                    Message("{what} refused: home is outside the travel limits", what=what)
                )
            target, command = limited, command_of(here, limited)
        if note is not None:
            self._notify(note)
        return self._run_move(command, start, target)

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
        encoded = None
        if raw is None:
            command = self.speeds.filled_in(command)
            encoded = protocol.encode(command)  # refused before sending; these bytes are sent
            timing = protocol.move_timing(command, start, target)
        else:
            timing = raw[1].timing or raw_timing(protocol, command, start, target)
        if timing is None:
            speed = self.speeds.current()
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
        heard, sent = self._heard, time.monotonic()
        with self.replies.timed() as replies:
            send_move(
                self.client,
                command,
                raw[0] if raw else None,
                completion,
                (start, target),
                (delay, duration),
                self.wait,
                encoded,
            )
        if not self.capabilities.position_feedback:
            confirmed = completion is Completion.FEEDBACK  # the device said the move ended
            known = lands_known(self.capabilities, command, self.last_position)
            self._set_position(
                PositionReport(*target, measured=False, confirmed=confirmed, known=known)
            )
            assert self.last_position is not None
            return self.last_position
        if completion is not Completion.REPLY:
            return self.position()
        undisturbed = heard == self._heard and not self.stop_requested.is_set()
        if self.replies.arrives_on_reply and undisturbed:
            # The reply said the move ended: the stage is at the target (not read back).
            at = as_reported(target, self.capabilities.resolution)
            self._set_position(PositionReport(*at, measured=False, confirmed=True))
            self._known()
            assert self.last_position is not None
            return self.last_position
        report, first_at = self._wait_until_at(target, duration)
        if undisturbed and first_at is not None:
            self.replies.weigh(replies, first_at - sent, duration)
        return report

    def arc(self, arc: cmd.Arc) -> PositionReport:
        """An arc: a straight move to its start point first where the stage is elsewhere."""
        if not self.capabilities.arcs:
            raise BadInput(
                Message("{protocol} has no arc moves", protocol=self.client.protocol.name)
            )
        self.client.protocol.encode(self.speeds.filled_in(arc))  # refused before anything is sent
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
        encoded = self.client.protocol.encode(command)
        self.client.execute(command, encoded=encoded)  # acknowledged where the protocol does
        if self.wait(ms / 1000):
            raise Aborted(ABANDONED)

    def _wait_until_at(self, target: Point, estimate: float) -> tuple[PositionReport, float | None]:
        """After DONE: poll until the position reaches the target (see `poll_until_at`)."""
        return poll_until_at(
            self.client,
            target,
            estimate,
            self.position,
            self.wait,
            self.poll_interval,
            self.stop_requested,
            self._notify,
        )
