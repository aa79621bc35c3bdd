"""The motion guard: the one place where what would move the stage is checked before it is sent.

Typed moves (jog, go-to, home, arc), raw bytes (the console, `motionctl raw`, macro steps) and
program points all pass it. Raw bytes are read with the protocol's own decoder
(`Protocol.sent_commands`): a frame read as a move is checked like a typed one (travel box,
resolution); bytes that cannot be read go only where no travel box is set, or when forced.
"""

from __future__ import annotations

import itertools
import logging
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from drivers.device.program_steps import ProgramDwell, ProgramPoint
from drivers.device.travel import Point, TravelLimits, check_resolution
from drivers.errors import BadInput, FrameError
from drivers.messages import Message, message_of
from drivers.protocols import commands as cmd
from drivers.protocols.base import MoveSequence, Protocol

log = logging.getLogger(__name__)

ARC_POINTS = 72  # points along an arc checked against the box


class RawRefused(BadInput):
    """Raw bytes the protocol cannot read while a travel box is set, sent without force."""


@dataclass(frozen=True)
class RawMove:
    """A move raw bytes make: the command read, where it goes, and how long it should take."""

    command: cmd.Command
    target: Point
    path: Callable[[float], Point] | None = None
    """The point at a fraction 0..1 of the move (None: a straight line)."""
    timing: tuple[float, float] | None = None
    """Seconds before it starts and how long it runs (None: as the protocol says)."""


def _polyline(points: Sequence[Point]) -> Callable[[float], Point]:
    """The point a fraction 0..1 along straight segments through `points` (by length)."""
    lengths = [math.dist(a, b) for a, b in itertools.pairwise(points)]
    total = sum(lengths)

    def at(fraction: float) -> Point:
        left = max(0.0, min(1.0, fraction)) * total
        for (a, b), length in zip(itertools.pairwise(points), lengths, strict=True):
            if left <= length and length > 0:
                f = left / length
                x, y, z = (u + (v - u) * f for u, v in zip(a, b, strict=True))
                return (x, y, z)
            left -= length
        return points[-1]

    return at


def arc_point(arc: cmd.Arc, z0: float, fraction: float) -> Point:
    """The point a fraction 0..1 along an arc, Z going linearly from `z0` to the arc's Z."""
    sweep = arc.sweep() if arc.ccw else -arc.sweep()
    x, y = arc.point(arc.start + sweep * fraction)
    return (x, y, z0 + (arc.z - z0) * fraction)


def arc_points(arc: cmd.Arc, z0: float, count: int) -> list[Point]:
    """`count` + 1 points along an arc, its ends included."""
    return [arc_point(arc, z0, i / count) for i in range(count + 1)]


def unreadable(protocol: Protocol | None, data: bytes) -> str | None:
    """Why the protocol cannot read bytes the host would send (None: it reads them)."""
    if protocol is None:
        return Message("no protocol to read them with")
    try:
        protocol.sent_commands(data)
    except FrameError as exc:
        return message_of(exc) or str(exc)
    return None


class MotionGuard:
    """Checks every move against the travel box (None: none) and the device's resolution."""

    def __init__(self, travel: TravelLimits | None = None) -> None:
        self.travel = travel

    def target(
        self, target: Point, what: str, here: Point | None = None
    ) -> tuple[Point, str | None]:
        """The target to send (clamped where the box says so) and a note for the operator;
        BadInput when refused. From `here` outside the box, a move back towards it goes."""
        if self.travel is None:
            return target, None
        return self.travel.apply(target, what, here)

    def exact(self, target: Point, what: str, here: Point | None = None) -> str | None:
        """Check a target that cannot be changed (raw bytes, a program): never clamped."""
        if self.travel is None:
            return None
        strict = TravelLimits(self.travel.box)
        return strict.apply(target, what, here)[1]

    def path(self, points: Sequence[Point], what: str) -> None:
        """Refuse a path (an arc) any point of which is outside the box."""
        for point in points:
            self.exact(point, what)

    def program(self, points: Sequence[ProgramPoint | ProgramDwell]) -> None:
        """Refuse a program any point of which is outside the box, before anything is sent."""
        if self.travel is None:
            return
        for number, p in enumerate(points, start=1):
            if isinstance(p, ProgramPoint) and not self.travel.contains((p.x, p.y, p.z)):
                self.exact((p.x, p.y, p.z), Message("program point {number}", number=number))

    def read_raw(self, protocol: Protocol, data: bytes, force: bool = False) -> cmd.Command | None:
        """The move raw bytes make, read with the protocol's decoder (None: they move nothing,
        or cannot be read and may go as they are); RawRefused or BadInput when refused."""
        try:
            commands = protocol.sent_commands(data)
        except FrameError as exc:
            reason = message_of(exc) or str(exc)
            if self.travel is not None and not force:
                raise RawRefused(
                    Message(
                        "raw bytes refused: {protocol} cannot read them as a command ({reason}), "
                        "so they cannot be checked against the travel limits ({box}); send "
                        "them with force to send them anyway",
                        protocol=protocol.name,
                        reason=reason,
                        box=self.travel.describe(),
                    )
                ) from None
            log.info("raw bytes sent unread (%s): %r", reason, data)
            return None
        moves = [c for c in commands if c is not None]
        if not moves:
            return None
        if len(commands) > 1:
            raise BadInput(
                Message(
                    "raw bytes refused: they hold {count} commands, {moves} of them moves; "
                    "send a move alone, so that it is checked and followed to its end",
                    count=len(commands),
                    moves=len(moves),
                )
            )
        return moves[0]

    def raw_move(
        self,
        protocol: Protocol,
        command: cmd.Command,
        here: Point,
        resolution: float | None,
        notify: Callable[[str], None],
    ) -> RawMove:
        """Check a move read from raw bytes like a typed one: resolution, then the box (never
        clamped: the bytes go as typed); where it goes. BadInput when refused."""
        what = Message("raw move {command}", command=_shown(command))
        if isinstance(command, MoveSequence):
            points, start, seconds = [here], here, 0.0
            for part in command.moves:
                end = self._checked(protocol, part, start, resolution, what, notify)
                speed = getattr(part, "speed", None)
                seconds += math.dist(start, end) / speed if speed else 0.0
                points.append(end)
                start = end
            return RawMove(command, start, _polyline(points), (0.0, seconds) if seconds else None)
        target = self._checked(protocol, command, here, resolution, what, notify)
        if isinstance(command, cmd.Arc):
            z0 = here[2]
            return RawMove(command, target, lambda f: arc_point(command, z0, f))
        return RawMove(command, target)

    def _checked(
        self,
        protocol: Protocol,
        command: cmd.Command,
        here: Point,
        resolution: float | None,
        what: str,
        notify: Callable[[str], None],
    ) -> Point:
        """The end of one decoded move from `here`, checked."""
        if isinstance(command, cmd.MoveTo):
            target = (command.x, command.y, command.z)
            check_resolution(target, ("x", "y", "z"), resolution)
        elif isinstance(command, cmd.MoveBy):
            if command.kind == "linear":
                deltas = (command.dx, command.dy, command.dz)
                check_resolution(deltas, ("dx", "dy", "dz"), resolution)
            lx, ly, lz = protocol.kind_to_length(command)
            target = (here[0] + lx, here[1] + ly, here[2] + lz)
        elif isinstance(command, cmd.Home):
            target = (0.0, 0.0, 0.0)
        elif isinstance(command, cmd.Arc):
            self.path(arc_points(command, here[2], ARC_POINTS), what)
            ex, ey = command.point(command.end)
            return (ex, ey, command.z)
        else:
            raise BadInput(
                Message("{what}: not a move the panel can check", what=what)
            )  # a protocol that reads a move the guard does not know: never sent unchecked
        note = self.exact(target, what, here)
        if note is not None:
            notify(note)
        return target


def _shown(command: cmd.Command) -> str:
    """A decoded move for people, e.g. `MoveTo(x=100.0, y=0.0, z=0.0)`."""
    return repr(command).replace(", speed=None", "")
