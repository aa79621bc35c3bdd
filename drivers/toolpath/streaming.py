"""Streaming a program to a device with a command queue (the laser link): grouped, acknowledged.

Queued instructions go up to `group` a frame (7 on the laser link), each frame sent once the
previous one is acknowledged; a queue-full reply waits and sends again (the client does). The
device's queue depth, asked now and then, tells how many have been executed.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from drivers.device.client import ABANDONED, Client
from drivers.device.guard import MotionGuard
from drivers.errors import Aborted, DeviceTimeout, Retransmit
from drivers.messages import Message
from drivers.protocols.laser.codec import Instruction
from drivers.protocols.laser.protocol import (
    GROUP,
    GetStatus,
    LaserProtocol,
    QueuedGroup,
    dwell_instruction,
    move_instruction,
)
from drivers.toolpath.point_program import ProgramDwell, ProgramPoint

ROUNDS = 10  # a frame is sent in up to this many rounds of the client's tries before failing
CLEAN_TO_GROW = 8  # frames without a retransmission before the group grows by one
log = logging.getLogger(__name__)

STATUS_EVERY = 0.25  # s between queue-depth questions while sending
DRAIN_POLL = 0.1  # s between questions while the device works its queue down


@dataclass
class StreamProgress:
    """How far a program has got."""

    total: int
    sent: int = 0
    acknowledged: int = 0
    executed: int = 0
    frames: int = 0
    retransmissions: int = 0
    started: float = field(default_factory=time.monotonic)
    finished: bool = False
    paused_s: float = 0.0
    """Seconds spent paused so far (no instruction sent)."""
    source: int | None = None
    """The program's source (drivers/toolpath: its line, entity or element) under way."""
    row: int = 0
    """How far along the program's flattened path the stage has got (a row of its points)."""
    held_s: float = 0.0
    """Seconds the device needs, at most, to run what it holds (acknowledged, not executed)."""

    @property
    def held(self) -> int:
        """Instructions the device holds: acknowledged and not yet executed."""
        return max(self.acknowledged - self.executed, 0)

    @property
    def seconds(self) -> float:
        """Seconds since the start."""
        return time.monotonic() - self.started

    @property
    def rate(self) -> float:
        """Instructions acknowledged a second."""
        return self.acknowledged / self.seconds if self.seconds > 0 else 0.0

    def seconds_left(self) -> float | None:
        """Time to the last execution at the rate so far (None: not known yet)."""
        if not self.executed:
            return None
        per = max(self.seconds - self.paused_s, 0.0) / self.executed
        return per * (self.total - self.executed)


class Streamer:
    """Sends a program; `pause`, `resume` and `stop` may be called from another thread."""

    def __init__(
        self,
        client: Client,
        points: list[ProgramPoint | ProgramDwell],
        group: int = GROUP,
        progress: Callable[[StreamProgress], None] | None = None,
        guard: MotionGuard | None = None,
    ) -> None:
        self.client = client
        self.points = points
        self.guard = guard
        """Checks every point against the travel box before the first is sent."""
        self.group = max(1, min(group, GROUP))
        self.progress = progress or (lambda p: None)
        self.state = StreamProgress(len(points))
        self._running = threading.Event()
        self._running.set()
        self._stopped = threading.Event()
        self._last_status = 0.0

    def pause(self) -> None:
        """Send nothing more until `resume` (what is queued on the device goes on)."""
        self._running.clear()

    def resume(self) -> None:
        """Go on sending."""
        self._running.set()

    def stop(self) -> None:
        """Send nothing more; the caller sends the device's STOP to flush its queue."""
        self._stopped.set()
        self._running.set()

    @property
    def stopped(self) -> bool:
        """Whether `stop` was called."""
        return self._stopped.is_set()

    def run(self) -> StreamProgress:
        """Send every point, then wait until the device has executed them; the final progress.
        A point outside the travel box refuses the whole program before anything is sent."""
        if self.guard is not None:
            self.guard.program(self.points)
        retransmissions_before = self.client.retransmissions
        start = 0
        size, clean = self.group, 0
        while start < len(self.points):
            since = time.monotonic()
            while not self._running.wait(DRAIN_POLL):
                # The device works through its queue meanwhile: the count and the position
                # (the caller's progress reads it) follow it.
                self._check_status(force=True)
                now = time.monotonic()
                self.state.paused_s += now - since
                since = now
                self.progress(self.state)
            if self._stopped.is_set():
                break
            chunk = self.points[start : start + size]
            instructions = tuple(_instruction(p) for p in chunk)
            self.state.sent += len(chunk)
            before = self.client.retransmissions
            self._send(instructions)
            start += len(chunk)
            self.state.acknowledged += len(chunk)
            self.state.frames += 1
            self.state.retransmissions = self.client.retransmissions - retransmissions_before
            # Reliability first: a damaged line gets smaller frames, a clean one larger again.
            if self.client.retransmissions > before:
                size, clean = max(1, size - 1), 0
            else:
                clean += 1
                if clean >= CLEAN_TO_GROW:
                    size, clean = min(self.group, size + 1), 0
            self._check_status()
            self.progress(self.state)
        while not self._stopped.is_set() and self.state.executed < self.state.acknowledged:
            if self.client.abort.wait(DRAIN_POLL):
                raise Aborted(ABANDONED)
            self._check_status(force=True)
            self.progress(self.state)
        self.state.retransmissions = self.client.retransmissions - retransmissions_before
        self.state.finished = not self._stopped.is_set()
        self.progress(self.state)
        return self.state

    def _send(self, instructions: tuple[Instruction, ...]) -> None:
        """One frame, sent again with its number until acknowledged (the device executes a
        frame once, however many copies arrive), for up to ROUNDS rounds of tries."""
        protocol = self.client.protocol
        assert isinstance(protocol, LaserProtocol)
        frame = QueuedGroup(instructions, protocol.next_sequence())
        for round_number in range(1, ROUNDS + 1):
            try:
                self.client.execute(frame)
                return
            except (Retransmit, DeviceTimeout) as exc:
                if round_number == ROUNDS:
                    raise type(exc)(
                        Message(
                            "{error} (after {rounds} rounds; {acknowledged} of {total} "
                            "instructions were acknowledged before it)",
                            error=exc,
                            rounds=ROUNDS,
                            acknowledged=self.state.acknowledged,
                            total=self.state.total,
                        )
                    ) from exc
                self.client.retransmissions += 1

    def _check_status(self, force: bool = False) -> None:
        now = time.monotonic()
        if not force and now - self._last_status < STATUS_EVERY:
            return
        self._last_status = now
        try:
            status = self.client.execute(GetStatus()).value
        except (Retransmit, DeviceTimeout) as exc:
            # The count of executed instructions only informs: asked again a moment later.
            log.info("queue depth not read this time: %s", exc)
            return
        depth = int(status["queue"]) if isinstance(status, dict) else 0
        moving = bool(status["moving"]) if isinstance(status, dict) else False
        waiting = depth + (1 if moving else 0)  # the one under way has left the queue
        self.state.executed = max(self.state.executed, self.state.acknowledged - waiting)
        self.state.held_s = held_seconds(self.points, self.state.executed, self.state.acknowledged)


def held_seconds(points: list[ProgramPoint | ProgramDwell], first: int, end: int) -> float:
    """Seconds that points[first:end] take at their speeds, the one under way counted whole."""
    before: ProgramPoint | None = None  # where the one under way starts (none: no distance)
    for index in range(first - 1, -1, -1):
        found = points[index]
        if isinstance(found, ProgramPoint):
            before = found
            break
    seconds = 0.0
    for point in points[first:end]:
        if isinstance(point, ProgramDwell):
            seconds += point.ms / 1000.0
            continue
        if before is not None and point.speed > 0:
            here, there = (before.x, before.y, before.z), (point.x, point.y, point.z)
            seconds += math.dist(here, there) / point.speed
        before = point
    return seconds


def _instruction(point: ProgramPoint | ProgramDwell) -> Instruction:
    """The queued instruction of a program's point (MOVE_LINEAR) or dwell (DWELL)."""
    if isinstance(point, ProgramDwell):
        return dwell_instruction(point.ms)
    return move_instruction(point.x, point.y, point.z, point.speed)
