"""A move as it starts: where from and to, when, how long it takes, where the stage is meanwhile."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from drivers.errors import BadInput
from drivers.protocols import commands as cmd
from drivers.protocols.base import Point, Protocol


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


def raw_timing(
    protocol: Protocol, command: cmd.Command, start: Point, target: Point
) -> tuple[float, float] | None:
    """The protocol's timing of a move read from raw bytes (None: distance over speed)."""
    try:
        return protocol.move_timing(command, start, target)
    except BadInput:  # e.g. a pi-frame speed the encoder would write otherwise
        return None
