"""The Raspberry Pi motion-frame device (drivers/protocols/README.md §4): write-only, 25-byte binary
frames."""

from __future__ import annotations

import bisect
import logging
import math
import struct
from collections import deque
from dataclasses import dataclass

from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice

log = logging.getLogger(__name__)

HEADER = b"\x7b\x7d"
TRAILER = 0x2A
FRAME_LENGTH = 25
DWELL, LINEAR, CIRCULAR, SET_HOME = 0, 1, 2, 3
CW, CCW = 0, 1
DEFAULT_SPEED = 1000.0  # ticks/s, for an axis that moves with speed 0
DEFAULT_ANGULAR = 9000  # 0.01°/s (90°/s), for an angular speed of 0
FULL_TURN = 36000  # 0.01°
ARC_START_TOLERANCE = 1.0  # ticks: closer than this to the arc's start, no approach move
MAX_PIECES = 10000  # path pieces kept for position(t) in the past
_FIELDS = struct.Struct(">BhhhHHHHHHHB")  # action, X Y Z, speeds, radius, angular, angles, dir

Frame = tuple[int, tuple[int, ...]]
Point = tuple[float, float, float]


@dataclass(frozen=True)
class Line:
    """A straight move from `start` to `end`, all axes ending together (a hold if they match)."""

    t0: float
    duration: float
    start: Point
    end: Point

    def at(self, t: float) -> Point:
        """The position at time `t` (clamped to the piece)."""
        if self.duration <= 0 or t >= self.t0 + self.duration:
            return self.end
        f = max(0.0, (t - self.t0) / self.duration)
        x0, y0, z0 = self.start
        x1, y1, z1 = self.end
        return (x0 + (x1 - x0) * f, y0 + (y1 - y0) * f, z0 + (z1 - z0) * f)


@dataclass(frozen=True)
class Arc:
    """A move along a circle around (cx, cy), from angle `a0` through `sweep` (radians, signed:
    positive is counter-clockwise), Z going linearly from `z0` to `z1`."""

    t0: float
    duration: float
    cx: float
    cy: float
    radius: float
    a0: float
    sweep: float
    z0: float
    z1: float

    def at(self, t: float) -> Point:
        """The position at time `t` (clamped to the piece)."""
        if self.duration <= 0 or t >= self.t0 + self.duration:
            f = 1.0
        else:
            f = max(0.0, (t - self.t0) / self.duration)
        angle = self.a0 + self.sweep * f
        return (
            self.cx + self.radius * math.cos(angle),
            self.cy + self.radius * math.sin(angle),
            self.z0 + (self.z1 - self.z0) * f,
        )

    @property
    def end(self) -> Point:
        """Where the arc ends."""
        return self.at(self.t0 + self.duration)


Piece = Line | Arc


@dataclass
class _Planned:
    """A received frame with its place on the timeline."""

    frame: Frame
    start: float
    end: float
    started: bool = False


def decode_frame(frame: bytes) -> Frame:
    """(action, (X, Y, Z, speedX, speedY, speedZ, radius, angular, start, end, direction))."""
    action, *fields = _FIELDS.unpack(frame[2:24])
    return action, tuple(fields)


class PiFrameDevice(SimulatedDevice):
    """The Pi-driven stage: frames are queued and executed in order; it never answers.

    Every frame is planned when it arrives (it starts when the previous one ends), so `position`
    can be asked for any time. `instant` makes moves and dwells take no time; `mute` is accepted
    for a uniform interface and changes nothing (the device is silent anyway).

    DTR gates reception: the seed's set-up ticks the DTR box, and the panel takes DTR as the line
    that powers the frame's serial interface, so while DTR is off every byte is lost (counted in
    `ignored_bytes`) and a frame cut by DTR going off is dropped whole. Frames received before
    keep running: the Pi executes its queue on its own.
    """

    protocol = "pi-frame"
    default_baud = 115200

    def __init__(
        self,
        clock: Clock = monotonic,
        baud: int | None = None,
        *,
        instant: bool = False,
        mute: bool = False,
    ) -> None:
        super().__init__(clock, baud)
        self.instant = instant
        self.mute = mute
        self.frames_ok = 0
        self.frames_bad = 0
        self.garbage_bytes = 0
        self.ignored_bytes = 0  # bytes lost while DTR was off
        self.history: list[Frame] = []
        self._buffer = bytearray()
        self._planned: deque[_Planned] = deque()
        self._pieces: deque[Piece] = deque(maxlen=MAX_PIECES)
        self._plan_end = 0.0
        self._plan_position: Point = (0.0, 0.0, 0.0)

    # -- accessors -------------------------------------------------------------------------
    def position(self, t: float | None = None) -> tuple[float, float, float]:
        """Where the stage is at `t` (ticks; default: now), frames received so far included."""
        self._process(self.clock())
        now = self.clock() if t is None else t
        starts = [piece.t0 for piece in self._pieces]
        index = bisect.bisect_right(starts, now) - 1
        if index < 0:
            return self._pieces[0].at(now) if self._pieces else (0.0, 0.0, 0.0)
        return self._pieces[index].at(now)

    def queue_length(self) -> int:
        """Frames received and not started yet."""
        self._process(self.clock())
        return sum(1 for planned in self._planned if not planned.started)

    # -- the frame parser ----------------------------------------------------------------------
    def set_lines(self, dtr: bool, rts: bool) -> None:
        """DTR going off drops a frame half received (see the class)."""
        super().set_lines(dtr, rts)
        if not self.dtr:
            self._buffer.clear()

    def handle_byte(self, byte: int, t: float) -> None:
        """Look for `7B 7D`, take 25 bytes, check the end byte; skip anything else. Nothing is
        read while DTR is off."""
        if not self.dtr:
            self.ignored_bytes += 1
            return
        self._buffer.append(byte)
        buf = self._buffer
        while buf:
            if buf[0] != HEADER[0] or (len(buf) >= 2 and buf[1] != HEADER[1]):
                skip = 1 + next((i for i, b in enumerate(buf[1:]) if b == HEADER[0]), len(buf) - 1)
                self.garbage_bytes += skip
                del buf[:skip]
                continue
            if len(buf) < FRAME_LENGTH:
                return
            frame = bytes(buf[:FRAME_LENGTH])
            if frame[-1] != TRAILER or frame[2] > SET_HOME:
                # Not a frame after all: resynchronise at the next header, inside it or later.
                self.frames_bad += 1
                log.debug("pi-frame: bad frame %s skipped", frame.hex(" "))
                del buf[: len(HEADER)]
                continue
            del buf[:FRAME_LENGTH]
            self.frames_ok += 1
            self._accept(decode_frame(frame), t)

    # -- the queue -------------------------------------------------------------------------
    def wake_at(self) -> float | None:
        """The start of the next queued frame, or the end of the running one."""
        if not self._planned:
            return None
        first = self._planned[0]
        return first.end if first.started else first.start

    def tick(self, now: float) -> None:
        """Frames end and start at `now`."""
        self._sync(now)

    def _sync(self, now: float) -> None:
        while self._planned:
            first = self._planned[0]
            if not first.started:
                if first.start > now:
                    return
                first.started = True
                self.history.append(first.frame)
                log.debug("pi-frame: executing %s at %.3f", first.frame, first.start)
            if first.end > now:
                return
            self._planned.popleft()

    def _accept(self, frame: Frame, t: float) -> None:
        start = max(t, self._plan_end)
        end = self._plan(frame, start)
        self._planned.append(_Planned(frame, start, end))
        self._plan_end = end
        self._sync(t)

    # -- motion planning -----------------------------------------------------------------------
    def _plan(self, frame: Frame, t: float) -> float:
        """Add the frame's path pieces from `t`; return when it ends."""
        action, fields = frame
        x, y, z, sx, sy, sz = fields[:6]
        here = self._plan_position
        if action == DWELL:
            duration = 0.0 if self.instant else (x & 0xFFFF) / 1000  # X read as unsigned here
            return self._add(Line(t, duration, here, here))
        if action == SET_HOME:
            self._plan_position = (0.0, 0.0, 0.0)
            return self._add(Line(t, 0.0, self._plan_position, self._plan_position))
        if action == LINEAR:
            return self._line_to((float(x), float(y), float(z)), (sx, sy, sz), t)
        return self._arc(fields, t)

    def _add(self, piece: Piece) -> float:
        self._pieces.append(piece)
        self._plan_position = piece.end
        return piece.t0 + piece.duration

    def _line_to(self, target: Point, speeds: tuple[int, ...], t: float) -> float:
        here = self._plan_position
        duration = 0.0
        if not self.instant:
            for a, b, speed in zip(here, target, speeds, strict=True):
                if a != b:
                    duration = max(duration, abs(b - a) / (speed or DEFAULT_SPEED))
        return self._add(Line(t, duration, here, target))

    def _arc(self, fields: tuple[int, ...], t: float) -> float:
        cx, cy, z, _, _, _, radius, angular, a0, a1, direction = fields
        a0, a1 = a0 % FULL_TURN, a1 % FULL_TURN  # the host never sends more than 35999
        if direction:  # any non-zero direction byte counts as CCW
            sweep = (a1 - a0) % FULL_TURN or FULL_TURN
        else:
            sweep = -((a0 - a1) % FULL_TURN or FULL_TURN)
        start_angle = math.radians(a0 / 100)
        x0, y0, z0 = self._plan_position
        sx = cx + radius * math.cos(start_angle)
        sy = cy + radius * math.sin(start_angle)
        if math.dist((x0, y0), (sx, sy)) > ARC_START_TOLERANCE:
            t = self._line_to((sx, sy, z0), (0, 0, 0), t)
        duration = 0.0 if self.instant else abs(sweep) / (angular or DEFAULT_ANGULAR)
        arc = Arc(t, duration, cx, cy, radius, start_angle, math.radians(sweep / 100), z0, z)
        return self._add(arc)
