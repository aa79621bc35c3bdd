"""How the end of a move becomes known: by its time, by the device's reply, by polling."""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from drivers.device.client import ABANDONED, Client
from drivers.errors import Aborted, DeviceError, DeviceTimeout
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.protocols.base import Point
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.events import ErrorReport, PositionReport

log = logging.getLogger(__name__)

POSITION_TOLERANCE = 0.011  # positions are printed with two decimals from 32-bit floats
FLOAT_TOLERANCE = 1e-4  # mm: positions reported as 32-bit floats (no resolution declared)
POLL_INTERVAL = 0.1  # seconds between position polls while waiting for a move to end
LISTEN_SLICE = 0.05  # s: a wait on a write-only device's move reads its errors this often
ESTIMATE_MARGIN = 1.5  # a move may take this much longer than distance / speed
EVIDENCE_MIN_S = 0.05
"""A move shows whether its device replies once it has ended only if it takes this long (by
distance and speed): a reply at the start then comes clearly before the end."""
LATE_REPLIES = 2
"""Moves whose reply ended a move's time after it began, before that is taken to mean arrival:
a host that stalls between reading the two halves of an early reply looks like it once."""


def arrival_tolerance(resolution: float | None) -> float:
    """How near a reported position must be to a target to be at it: a little over the
    device's resolution (COXIRIS's 0.01 mm: 0.011), or the precision of a 32-bit float where
    the device declares none (laser-frame), so a stage still moving is not taken as arrived."""
    return POSITION_TOLERANCE * resolution / 0.01 if resolution else FLOAT_TOLERANCE


def is_at(
    report: PositionReport, point: PositionReport | Point, tolerance: float = POSITION_TOLERANCE
) -> bool:
    """Whether a position is `point`, to the precision positions are reported with."""
    if isinstance(point, PositionReport):
        point = (point.x, point.y, point.z)
    here = (report.x, report.y, report.z)
    return all(abs(a - b) <= tolerance for a, b in zip(here, point, strict=True))


def as_reported(point: Point, resolution: float | None) -> Point:
    """`point` on the device's resolution, as it reports it (5.1 - 0.2: 4.9, not 4.8999...)."""
    if not resolution:
        return point
    per_unit = round(1 / resolution)
    if abs(per_unit * resolution - 1) > 1e-9:
        return point
    x, y, z = (round(v * per_unit) / per_unit for v in point)
    return (x, y, z)


def listen(client: Client, seconds: float) -> bool:
    """Wait while reading the port: an error the device reports meanwhile (Firmata's
    STRING_DATA) ends the wait at once and is raised; True when the wait was abandoned."""
    clock = client.clock
    end = clock() + seconds
    while True:
        try:
            events = client.listen(min(LISTEN_SLICE, max(end - clock(), 0.0)))
        except Aborted:
            return True
        errors = [e for e in events if isinstance(e, ErrorReport)]
        if errors:
            reported = "; ".join(e.message for e in errors)
            raise DeviceError(Message("the device reported: {reported}", reported=reported))
        if clock() >= end:
            return False


def send_move(
    client: Client,
    command: cmd.Command,
    raw: bytes | None,
    completion: Completion,
    span: tuple[Point, Point],
    timing: tuple[float, float],
    wait: Callable[[float], bool],
    encoded: bytes | None = None,
) -> None:
    """Send a move (`raw`: as these console bytes), waiting out its time where the device
    never says it is done (ESTIMATE), else for its reply; `timing`: its delay and duration;
    `encoded`: the command's bytes, made once already."""
    protocol = client.protocol
    delay, duration = timing
    if raw is not None:
        client.send_raw(raw, extra=(delay + duration) * ESTIMATE_MARGIN)
        protocol.on_sent(command)  # a write-only device's commanded position follows
        if completion is Completion.ESTIMATE and wait(delay + duration):
            raise Aborted(ABANDONED)
    elif completion is Completion.ESTIMATE:
        # The device never says when it is done (drivers/protocols/README.md §4, §5): each
        # part is sent once the previous one should have ended (Firmata splits long moves).
        parts = protocol.expand(command)
        for part in parts:
            client.send_only(part)
            part_timing = protocol.move_timing(part, *span) if len(parts) > 1 else None
            if wait(sum(part_timing) if part_timing else delay + duration):
                raise Aborted(ABANDONED)
    else:
        client.execute(command, extra=(delay + duration) * ESTIMATE_MARGIN, encoded=encoded)


def lands_known(
    caps: Capabilities, command: cmd.Command | None, last: PositionReport | None
) -> bool:
    """Whether a write-only device's move ends at a known place: an absolute target, or a
    home move, where the device takes them; else as known as where it started (`last`)."""
    if isinstance(command, cmd.MoveTo) and caps.absolute_moves:
        return True
    if isinstance(command, cmd.Home) and (caps.homing or caps.absolute_moves):
        return True
    return last is not None and last.known


def poll_until_at(
    client: Client,
    target: Point,
    estimate: float,
    position: Callable[[], PositionReport],
    wait: Callable[[float], bool],
    interval: float,
    stop_requested: threading.Event,
    notify: Callable[[str], None],
) -> tuple[PositionReport, float | None]:
    """After DONE: poll until the position reaches the target (non-blocking firmware style).

    Returns the position, and when the first poll answered if it found the target already.
    """
    allowed = estimate * ESTIMATE_MARGIN + client.timeout
    deadline = time.monotonic() + allowed
    previous: PositionReport | None = None
    while True:
        if stop_requested.is_set() and client.protocol.capabilities.stop:
            stop_requested.clear()
            client.execute(cmd.Stop())  # halts the move under way and flushes the queue
            stopped = position()
            notify(
                Message(
                    "stopped at ({x:g}, {y:g}, {z:g}) mm", x=stopped.x, y=stopped.y, z=stopped.z
                )
            )
            return stopped, None
        now = position()
        if is_at(now, target, arrival_tolerance(client.protocol.capabilities.resolution)):
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
        if wait(interval):
            raise Aborted(ABANDONED)


class ReplyEvidence:
    """What a device's replies to moves have shown: whether one comes once the move has ended."""

    def __init__(self) -> None:
        self.arrives_on_reply = False
        """Whether this device's reply to a move has been seen to mean the move has ended
        (Completion.REPLY: COXIRIS's blocking sketch does, its non-blocking one and the laser's
        queue do not), so that the target is where the stage is once the reply has come."""
        self.late_replies = 0  # moves whose reply ended as the move did (see LATE_REPLIES)
        self._times: list[float] | None = None  # when a move's reply events came

    def heard(self) -> None:
        """A reply event came: its time is noted while a move is being sent."""
        if self._times is not None:
            self._times.append(time.monotonic())

    @contextmanager
    def timed(self) -> Iterator[list[float]]:
        """While the block runs (a move being sent), the times replies come, in the list."""
        times: list[float] = []
        self._times = times
        try:
            yield times
        finally:
            self._times = None

    def distrust(self) -> None:
        """The device was not where its reply put it: its replies no longer mean arrival."""
        self.arrives_on_reply, self.late_replies = False, 0

    def weigh(self, replies: list[float], reached: float, duration: float) -> None:
        """The first poll found the stage at its target `reached` s after the move was sent."""
        if duration < EVIDENCE_MIN_S:
            return
        # The reply meant arrival if the stage got there in under half the time the move
        # takes (it had no time to move after an early reply), or if the reply ended a move's
        # time after it began (a firmware busy while it moves), seen LATE_REPLIES times.
        answering = replies[-1] - replies[0] if replies else 0.0
        if answering >= 0.9 * duration:
            self.late_replies += 1
        if reached < 0.5 * duration or self.late_replies >= LATE_REPLIES:
            self.arrives_on_reply = True
            log.debug("the device replies to a move once it has ended")
