"""Running a toolpath on a device, the way each protocol can take it.

- A device with a command queue (laser-frame) is streamed the flattened path, grouped and
  acknowledged (drivers/toolpath/streaming.py), dwells queued as DWELL.
- A device with arc moves (pi-frame) gets each arc as its own arc command (a Circular frame)
  and each straight move as a move; dwells go to the device.
- Any other device (COXIRIS, Visiomex, Firmata) runs the flattened path as a sequence of moves,
  each waited for as a typed move is; dwells are waited on the host.

Everything is checked before the first byte: the travel box (arcs' widest points included), the
speeds against the device's range, every command against the protocol's encoder. Coordinates
are rounded to the device's resolution. A speed of None runs at the speed set on the panel,
which is set back once the program ends.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable, Iterator

from drivers.device.motion import Motion
from drivers.errors import Aborted, BadInput
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.toolpath.geometry import FlatPath, check_fits, check_speeds, flatten
from drivers.toolpath.model import CHORD_TOLERANCE, ArcTo, Dwell, Toolpath, arc_angles
from drivers.toolpath.point_program import ProgramDwell, ProgramPoint
from drivers.toolpath.streaming import Streamer, StreamProgress

log = logging.getLogger(__name__)

DWELL_MS_MAX = 32767  # a device dwell longer than this goes as several
Progress = Callable[[StreamProgress], None]


class ProgramRunner:
    """Runs one toolpath; `pause`, `resume` and `stop` may be called from another thread."""

    def __init__(
        self,
        motion: Motion,
        toolpath: Toolpath,
        *,
        tolerance: float = CHORD_TOLERANCE,
        progress: Progress | None = None,
        group: int | None = None,
    ) -> None:
        self.motion = motion
        self.toolpath = toolpath
        self.tolerance = tolerance
        self.flat: FlatPath = flatten(toolpath, tolerance)
        self.progress = progress or (lambda state: None)
        self.group = group
        self._running = threading.Event()
        self._running.set()
        self._stopped = threading.Event()
        self._streamer: Streamer | None = None
        self._set_speed: float | None = None  # the speed last set (the panel's at the start)
        caps = motion.capabilities
        self.mode = "stream" if caps.streaming else "arcs" if caps.arcs else "moves"
        self.state = StreamProgress(self._count())

    # -- any thread ----------------------------------------------------------------------------
    def pause(self) -> None:
        """Send nothing more until `resume`."""
        self._running.clear()
        if self._streamer is not None:
            self._streamer.pause()

    def resume(self) -> None:
        """Go on."""
        self._running.set()
        if self._streamer is not None:
            self._streamer.resume()

    def stop(self) -> None:
        """Send nothing more; the move under way is stopped where the device can stop."""
        self._stopped.set()
        self._running.set()
        if self._streamer is not None:
            self._streamer.stop()
        self.motion.stop_requested.set()

    @property
    def stopped(self) -> bool:
        """Whether `stop` was called."""
        return self._stopped.is_set()

    # -- the run -------------------------------------------------------------------------------
    def check(self) -> float | None:
        """Refuse the program before anything is sent: the device's axes, the travel box, the
        speeds (the panel's for the moves without one), and every command it would send, read
        by the protocol's encoder. Returns the panel's speed, read once the box has passed."""
        caps = self.motion.capabilities
        check_fits(self.toolpath, self.flat, caps.axes, self.motion.guard.travel)
        moving = [s for s in self.toolpath.steps if not isinstance(s, Dwell)]
        if any(s.speed is not None for s in moving) and caps.speed:
            low, high = self.motion.speed_limits()
            check_speeds(self.toolpath, low, high, caps.speed_decimals)
        panel_speed = self._panel_speed()
        own = [s.speed is not None for s in moving]
        if panel_speed is not None and any(own) and not all(own) and self.mode != "stream":
            # Moves without a speed go at the panel's, set again after those with one.
            low, high = self.motion.speed_limits()
            if not low <= panel_speed <= high:
                raise BadInput(
                    Message(
                        "the program's moves without a speed would go at the device's speed, "
                        "{speed:g} mm/s, outside the {low:g} to {high:g} mm/s it allows: set "
                        "the speed first; nothing was sent",
                        speed=panel_speed,
                        low=low,
                        high=high,
                    )
                )
        if self.mode == "stream":
            return panel_speed  # the laser's fields are float32 and its speeds checked above
        protocol = self.motion.client.protocol
        for source, command in self._commands(panel_speed):
            try:
                protocol.encode(command)
            except BadInput as exc:
                raise BadInput(
                    Message(
                        "{where}: {error}; nothing was sent",
                        where=self.toolpath.where(source),
                        error=exc,
                    )
                ) from None
        return panel_speed

    def _commands(self, panel_speed: float | None) -> Iterator[tuple[int, cmd.Command]]:
        """Every command the run will send, with the source it comes from."""
        if self.mode != "arcs":
            for row in range(1, len(self.flat.points)):
                yield int(self.flat.source[row]), self._move_command(row, panel_speed)
            return
        for index, step in enumerate(self.toolpath.steps):
            if isinstance(step, Dwell):
                yield from ((step.source, cmd.Dwell(ms)) for ms in _dwell_parts(step.seconds))
                continue
            first = int(self.flat.step_end[index - 1]) if index else 0
            start = tuple(float(v) for v in self.flat.points[first])
            here = (start[0], start[1], start[2])
            if isinstance(step, ArcTo) and self._arc_worth_it(here, step):
                speed = self._wanted(step.speed, panel_speed)
                yield step.source, self._arc_command(here, step, speed)
                continue
            for row in range(first + 1, int(self.flat.step_end[index]) + 1):
                yield step.source, self._move_command(row, panel_speed)

    def _move_command(self, row: int, panel_speed: float | None) -> cmd.Command:
        """The move to a row of the flat path, as the device is sent it."""
        caps = self.motion.capabilities
        speed = self._wanted(_speed_or_none(float(self.flat.speed[row])), panel_speed)
        moved = speed if caps.speed_in_moves else None
        target = self._point(row)
        if caps.absolute_moves:
            return cmd.MoveTo(*target, speed=moved)
        here = self._point(row - 1)
        dx, dy, dz = (b - a for a, b in zip(here, target, strict=True))
        return cmd.MoveBy(dx, dy, dz, speed=moved)

    def _point(self, row: int) -> tuple[float, float, float]:
        """A row of the flat path on the device's grid."""
        resolution = self.motion.capabilities.resolution
        x, y, z = (_rounded(float(v), resolution) for v in self.flat.points[row])
        return (x, y, z)

    def _arc_command(
        self, here: tuple[float, float, float], step: ArcTo, speed: float | None
    ) -> cmd.Arc:
        """The device's arc for `step` from `here` (its centre and radius on its grid)."""
        resolution = self.motion.capabilities.resolution
        radius, a0, a1 = arc_angles(here, step)
        return cmd.Arc(
            _rounded(step.centre[0], resolution),
            _rounded(step.centre[1], resolution),
            _rounded(radius, resolution),
            math.degrees(a0),
            math.degrees(a1),
            step.ccw,
            _rounded(step.end[2], resolution),
            speed,
        )

    def _wanted(self, speed: float | None, panel_speed: float | None) -> float | None:
        """The speed a move runs at: its own, else the panel's."""
        return panel_speed if speed is None else self._speed_of(speed)

    def run(self) -> StreamProgress:
        """Check the program, then run it to its end (or to `stop`); the final progress."""
        panel_speed = self.check()
        if self.mode == "stream":
            return self._stream(panel_speed)
        self._set_speed = panel_speed
        try:
            if self.mode == "arcs":
                self._run_steps(panel_speed)
            else:
                self._run_rows(panel_speed)
        finally:
            self.motion.stop_requested.clear()
        self.state.finished = not self.stopped
        if self.motion.capabilities.speed and panel_speed is not None and not self.stopped:
            self._speed(None, panel_speed)
        self.progress(self.state)
        return self.state

    # -- streaming (laser-frame) ---------------------------------------------------------------
    def _stream(self, panel_speed: float | None) -> StreamProgress:
        panel = panel_speed or self.motion.capabilities.default_speed
        items: list[ProgramPoint | ProgramDwell] = []
        rows: list[int] = []
        points, speeds = self.flat.points, self.flat.speed
        dwells = self._dwells_at()
        for row in range(1, len(points)):
            for seconds in dwells.get(row - 1, ()):
                for ms in _dwell_parts(seconds):
                    items.append(ProgramDwell(ms))
                    rows.append(row - 1)
            x, y, z = (float(v) for v in points[row])
            speed = float(speeds[row])
            items.append(ProgramPoint(x, y, z, panel if math.isnan(speed) else speed))
            rows.append(row)
        for seconds in dwells.get(len(points) - 1, ()):
            for ms in _dwell_parts(seconds):
                items.append(ProgramDwell(ms))
                rows.append(len(points) - 1)

        def progress(state: StreamProgress) -> None:
            if state.executed:
                row = rows[min(state.executed, len(rows)) - 1]
                state.row = row
                state.source = int(self.flat.source[row])
            self.progress(state)

        streamer = Streamer(self.motion.client, items, progress=progress, guard=self.motion.guard)
        if self.group is not None:
            streamer.group = max(1, min(self.group, streamer.group))
        self._streamer = streamer
        if self.stopped:
            streamer.stop()
        try:
            self.state = streamer.run()
        finally:
            self._streamer = None
        return self.state

    # -- step by step (pi-frame) ---------------------------------------------------------------
    def _run_steps(self, panel_speed: float | None) -> None:
        here = self.toolpath.start
        for index, step in enumerate(self.toolpath.steps):
            if not self._go_on():
                return
            end_row = int(self.flat.step_end[index])
            self.state.source = step.source
            if type(step) is Dwell:
                for ms in _dwell_parts(step.seconds):
                    self.motion.dwell(ms)
            elif type(step) is ArcTo and self._arc_worth_it(here, step):
                self._speed(step.speed, panel_speed)
                self.motion.arc(self._arc_command(here, step, None))
            else:
                start_row = int(self.flat.step_end[index - 1]) if index else 0
                for row in range(start_row + 1, end_row + 1):
                    self._move_row(row, panel_speed)
            if not isinstance(step, Dwell):
                here = step.end
            self._advance(end_row, index + 1)

    def _arc_worth_it(self, here: tuple[float, float, float], arc: ArcTo) -> bool:
        """Whether the device can draw this arc as one (its radius above its resolution)."""
        radius = arc_angles(here, arc)[0]
        return radius > (self.motion.capabilities.resolution or 0.0) * 2

    # -- move by move (COXIRIS, Visiomex, Firmata) ---------------------------------------------
    def _run_rows(self, panel_speed: float | None) -> None:
        dwells = self._dwells_at()
        done = 0
        for row in range(len(self.flat.points)):
            if row:
                if not self._go_on():
                    return
                self.state.source = int(self.flat.source[row])
                self._move_row(row, panel_speed)
                done += 1
                self._advance(row, done)
            for seconds in dwells.get(row, ()):
                if not self._go_on():
                    return
                if self.motion.wait(seconds):
                    raise Aborted(Message("the program was abandoned during a dwell"))
                done += 1
                self._advance(row, done)

    def _move_row(self, row: int, panel_speed: float | None) -> None:
        speed = float(self.flat.speed[row])
        self._speed(None if math.isnan(speed) else speed, panel_speed)
        resolution = self.motion.capabilities.resolution
        x, y, z = (_rounded(float(v), resolution) for v in self.flat.points[row])
        self.motion.move_to(x, y, z)

    # -- helpers -------------------------------------------------------------------------------
    def _count(self) -> int:
        dwells = sum(1 for s in self.toolpath.steps if type(s) is Dwell)
        if self.mode == "arcs":
            return len(self.toolpath.steps)
        return len(self.flat.points) - 1 + dwells

    def _dwells_at(self) -> dict[int, list[float]]:
        """The dwells after each row of the flat path."""
        at: dict[int, list[float]] = {}
        for index, step in enumerate(self.toolpath.steps):
            if type(step) is Dwell:
                at.setdefault(int(self.flat.step_end[index]), []).append(step.seconds)
        return at

    def _go_on(self) -> bool:
        """Wait while paused; whether to go on (False once stopped)."""
        since = time.monotonic()
        while not self._running.wait(0.1):
            now = time.monotonic()
            self.state.paused_s += now - since
            since = now
            self.progress(self.state)
        return not self.stopped

    def _advance(self, row: int, done: int) -> None:
        self.state.row = row
        self.state.sent = self.state.acknowledged = self.state.executed = done
        self.progress(self.state)

    def _panel_speed(self) -> float | None:
        """The speed set on the panel now (None: the device has no speed)."""
        if not self.motion.capabilities.speed:
            return None
        return self.motion.speed()

    def _speed_of(self, speed: float) -> float:
        """A program's speed as the device takes it (Visiomex: whole mm/s)."""
        return round(speed, self.motion.capabilities.speed_decimals)

    def _speed(self, speed: float | None, panel_speed: float | None) -> None:
        """Set the speed a move needs, where it differs from the one set."""
        if not self.motion.capabilities.speed:
            return
        wanted = panel_speed if speed is None else self._speed_of(speed)
        if wanted is None or wanted == self._set_speed:
            return
        self.motion.set_speed(wanted)
        self._set_speed = wanted


def _speed_or_none(speed: float) -> float | None:
    """A flat path's speed (NaN: the panel's) as a step's."""
    return None if math.isnan(speed) else speed


def _rounded(value: float, resolution: float | None) -> float:
    """`value` on the device's grid (so that a flattened arc's points are sent as they can be)."""
    if not resolution:
        return value
    steps = round(value / resolution)
    decimals = max(0, -math.floor(math.log10(resolution)) + 1)
    return round(steps * resolution, decimals)


def _dwell_parts(seconds: float) -> list[int]:
    """A dwell as device dwells of at most DWELL_MS_MAX ms each."""
    total = max(0, round(seconds * 1000))
    parts = [DWELL_MS_MAX] * (total // DWELL_MS_MAX)
    if total % DWELL_MS_MAX or not parts:
        parts.append(total % DWELL_MS_MAX)
    return parts
