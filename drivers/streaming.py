"""Streaming a program to a device with a command queue (the laser link): grouped, acknowledged.

Queued instructions go up to `group` a frame (7 on the laser link), each frame sent once the
previous one is acknowledged; a queue-full reply waits and sends again (the client does). The
device's queue depth, asked now and then, tells how many have been executed.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from drivers.client import Client
from drivers.errors import Aborted
from drivers.program import ProgramPoint
from drivers.protocols.laser import GROUP, GetStatus, QueuedGroup, move_instruction

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
        per = self.seconds / self.executed
        return per * (self.total - self.executed)


class Streamer:
    """Sends a program; `pause`, `resume` and `stop` may be called from another thread."""

    def __init__(
        self,
        client: Client,
        points: list[ProgramPoint],
        group: int = GROUP,
        progress: Callable[[StreamProgress], None] | None = None,
    ) -> None:
        self.client = client
        self.points = points
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

    def run(self) -> StreamProgress:
        """Send every point, then wait until the device has executed them; the final progress."""
        retransmissions_before = self.client.retransmissions
        for start in range(0, len(self.points), self.group):
            while not self._running.wait(0.05):
                self._check_status(force=True)
            if self._stopped.is_set():
                break
            chunk = self.points[start : start + self.group]
            instructions = tuple(move_instruction(p.x, p.y, p.z, p.speed) for p in chunk)
            self.state.sent += len(chunk)
            self.client.execute(QueuedGroup(instructions))
            self.state.acknowledged += len(chunk)
            self.state.frames += 1
            self.state.retransmissions = self.client.retransmissions - retransmissions_before
            self._check_status()
            self.progress(self.state)
        while not self._stopped.is_set() and self.state.executed < self.state.acknowledged:
            if self.client.abort.wait(DRAIN_POLL):
                raise Aborted("abandoned: the connection is closing")
            self._check_status(force=True)
            self.progress(self.state)
        self.state.retransmissions = self.client.retransmissions - retransmissions_before
        self.state.finished = not self._stopped.is_set()
        self.progress(self.state)
        return self.state

    def _check_status(self, force: bool = False) -> None:
        now = time.monotonic()
        if not force and now - self._last_status < STATUS_EVERY:
            return
        self._last_status = now
        status = self.client.execute(GetStatus()).value
        depth = int(status["queue"]) if isinstance(status, dict) else 0
        moving = bool(status["moving"]) if isinstance(status, dict) else False
        waiting = depth + (1 if moving and depth == 0 else 0)
        self.state.executed = max(self.state.executed, self.state.acknowledged - waiting)
