"""A kinematic stage: straight-line moves at a set speed, position computed when asked."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass
class _Segment:
    start: tuple[float, ...]
    end: tuple[float, ...]
    t0: float
    duration: float


class Stage:
    """Axes that move together along a straight line at `speed` units per second."""

    def __init__(self, axes: int = 3, speed: float = 10.0, instant: bool = False) -> None:
        self.axes = axes
        self.speed = speed
        self.instant = instant
        self._segment = _Segment((0.0,) * axes, (0.0,) * axes, 0.0, 0.0)

    def position(self, now: float) -> tuple[float, ...]:
        """Where the stage is at time `now`."""
        seg = self._segment
        if seg.duration <= 0 or now >= seg.t0 + seg.duration:
            return seg.end
        if now <= seg.t0:
            return seg.start
        f = (now - seg.t0) / seg.duration
        return tuple(a + (b - a) * f for a, b in zip(seg.start, seg.end, strict=True))

    def target(self) -> tuple[float, ...]:
        """Where the current (or last) move ends."""
        return self._segment.end

    def is_moving(self, now: float) -> bool:
        """Whether a move is under way at `now`."""
        seg = self._segment
        return seg.duration > 0 and seg.t0 <= now < seg.t0 + seg.duration

    def move_to(self, target: tuple[float, ...], now: float) -> float:
        """Start a move from wherever the stage is now; return its duration in seconds."""
        start = self.position(now)
        distance = math.dist(start, target)
        duration = 0.0 if self.instant or self.speed <= 0 else distance / self.speed
        self._segment = _Segment(start, tuple(target), now, duration)
        return duration

    def duration_to(self, target: tuple[float, ...], now: float) -> float:
        """How long a move to `target` would take from the position at `now`."""
        if self.instant or self.speed <= 0:
            return 0.0
        return math.dist(self.position(now), target) / self.speed

    def stop(self, now: float) -> None:
        """Stop where the stage is."""
        here = self.position(now)
        self._segment = _Segment(here, here, now, 0.0)

    def set_position(self, position: tuple[float, ...], now: float) -> None:
        """Redefine the current position (stops any move)."""
        self._segment = _Segment(tuple(position), tuple(position), now, 0.0)
