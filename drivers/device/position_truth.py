"""What is known of where a device's stage is, kept by its session for every front end.

The session's motion layer reports positions (measured, or counted / commanded from a known
place, each report saying whether it is known) and the moves it starts. From those, and from
whether the link was lost, one `Whereabouts` says what a front end may show: the position, or
an estimate during a move, or that it is not known, and why. The panel, motionctl and scripts
read it here, so they cannot disagree.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, replace

from drivers.device.motion import Motion, MoveStart
from drivers.protocols.base import Point
from drivers.protocols.events import PositionReport

LIVE = "live"  # the device's report: measured, or counted / commanded from a known place
ESTIMATED = "estimated"  # a move under way, interpolated from its start, target and speed
UNCOUNTED = "uncounted"  # a device that cannot be asked, with no known place reached yet
LOST = "lost"  # such a device after its link was lost: what it counted is not trusted
LOST_MOVING = "lost-moving"  # the link went during a move: the estimate at the loss
STALE = "stale"  # the link went while the stage stood: the last position, no longer live
UNREAD = "unread"  # a device that reports where it is, not asked yet

UNKNOWN = frozenset({UNCOUNTED, LOST})  # a device that cannot be asked: Home or Set Home


@dataclass(frozen=True)
class Whereabouts:
    """What is known of the stage's position: a `status` (one of the names above), the point
    to show (None: none at all) and the last report it comes from."""

    status: str
    point: Point | None
    report: PositionReport | None = None

    @property
    def known(self) -> bool:
        """Whether the point is where the stage is (live), or on its way there (estimated)."""
        return self.status in (LIVE, ESTIMATED) and self.point is not None


class PositionTruth:
    """Follows one session's motion layer; `now()` is what is known at this instant.

    Fed from the thread that drives the session; `now()` may be read from any thread (each
    attribute is replaced whole).
    """

    def __init__(
        self,
        motion: Motion,
        *,
        after_loss: bool = False,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        """Follow `motion`; `after_loss`: the session goes on after a lost link (a position a
        device cannot be asked about is then lost, not merely not counted yet)."""
        self.clock = clock
        self.after_loss = after_loss
        self._motion = motion
        self._move: MoveStart | None = None
        self._lost_at: float | None = None
        motion.position_listeners.append(self._reported)
        motion.move_listeners.append(self._moving)

    def _reported(self, report: PositionReport) -> None:
        self._move = None

    def _moving(self, move: MoveStart) -> None:
        if self._lost_at is None:
            self._move = move

    def move_ended(self) -> None:
        """The move under way ended with no position reported (failed, stopped): the last
        report stands."""
        self._move = None

    def found_again(self) -> None:
        """The device answers again after a loss (or a restart) on this link: a position it
        cannot be asked about is not known until a Home, a Set Home or an absolute target."""
        self._lost_at, self._move, self.after_loss = None, None, True
        motion = self._motion
        report = motion.last_position
        if report is not None and not motion.capabilities.position_feedback:
            motion.last_position = replace(report, known=False)

    def link_lost(self) -> None:
        """The link went: a move under way is known only as its estimate at this instant."""
        if self._lost_at is None:
            self._lost_at = self.clock()

    def now(self) -> Whereabouts:
        """What is known of the position at this instant."""
        report, move = self._motion.last_position, self._move
        point = (report.x, report.y, report.z) if report is not None else None
        known = report is not None and report.known
        if self._lost_at is not None:
            if not known:  # not known before the link went: no estimate makes it known
                return Whereabouts(LOST, point, report)
            if move is not None:
                return Whereabouts(LOST_MOVING, move.estimate(self._lost_at), report)
            return Whereabouts(STALE, point, report)
        if report is None and self._motion.capabilities.position_feedback:
            return Whereabouts(UNREAD, None)
        if not known:
            return Whereabouts(LOST if self.after_loss else UNCOUNTED, point, report)
        if move is not None:
            return Whereabouts(ESTIMATED, move.estimate(self.clock()), report)
        return Whereabouts(LIVE, point, report)
