"""The laser-processing robot (drivers/protocols/README.md §3): stuffed frames in, one reply frame
per frame out.

Queued instructions (MOVE_LINEAR, DWELL, GO_HOME) run in order on a 3-axis stage; immediate ones
are answered at once. Line faults can be injected (seeded), for exercising the host's retransmits.
"""

from __future__ import annotations

import logging
import random
import struct
from collections import deque

from drivers.framers.stuffed import HEADER, StuffedFramer
from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice
from drivers.sim.laser_wire import (
    CHAR,
    CHECKSUM,
    DWELL,
    FLOAT,
    FRAMING,
    GET_ID,
    GET_POSITION,
    GET_STATUS,
    GO_HOME,
    INT16,
    MOVE_LINEAR,
    QUEUE_FULL,
    SEQUENCE,
    SET_HOME,
    STOP,
    UINT8,
    Parsed,
    Refused,
    Values,
    error_reply,
    field,
    parse,
)
from drivers.sim.stage import Stage

log = logging.getLogger(__name__)

DEVICE_ID = "LZR-SIM-01"
DEFAULT_SPEED = 10.0  # mm/s for a GO_HOME before any MOVE_LINEAR
REPLY_DELAY = 0.5  # s, the `delay_reply` fault
FRAME_TIMEOUT = 0.05  # s of line silence that ends an incomplete frame or a run of junk
MAX_DATA = 512  # data bytes without a tail before the receiver gives up on a frame
# Noise bytes never include the header's first byte, so a burst cannot fake a reply's start.
_NOISE = bytes(b for b in range(256) if b != HEADER[0])

Point = tuple[float, float, float]


class LaserDevice(SimulatedDevice):
    """The robot controller's serial task and its command queue, on a simulated line.

    `executed` lists (command word, values) of queued instructions as they start, `executed_at`
    their start times. `instant` makes moves and dwells take no time; `mute` never answers.
    Fault rates (0..1, drawn from `random.Random(seed)`): `corrupt` flips received bytes, `drop`
    loses whole received frames, `drop_reply` loses replies, `delay_reply` sends them 0.5 s late,
    `garbage` sends 1-16 noise bytes before a reply. `queue` is the queue depth in instructions.
    """

    protocol = "laser-frame"
    default_baud = 115200

    def __init__(
        self,
        clock: Clock = monotonic,
        baud: int | None = None,
        *,
        instant: bool = False,
        mute: bool = False,
        corrupt: float = 0.0,
        drop: float = 0.0,
        drop_reply: float = 0.0,
        delay_reply: float = 0.0,
        garbage: float = 0.0,
        seed: int = 0,
        queue: int = 32,
    ) -> None:
        super().__init__(clock, baud)
        for name, rate in (
            ("corrupt", corrupt),
            ("drop", drop),
            ("drop_reply", drop_reply),
            ("delay_reply", delay_reply),
            ("garbage", garbage),
        ):
            if not 0.0 <= rate <= 1.0:
                raise ValueError(f"{name}={rate}: a probability is between 0 and 1")
        if queue < 1:
            raise ValueError(f"queue={queue}: the queue holds at least one instruction")
        self.instant = instant
        self.mute = mute
        self.corrupt = corrupt
        self.drop = drop
        self.drop_reply = drop_reply
        self.delay_reply = delay_reply
        self.garbage = garbage
        self.queue_depth = queue
        self.rng = random.Random(seed)
        self.framer = StuffedFramer(max_length=MAX_DATA)
        self.stage = Stage(3, speed=DEFAULT_SPEED, instant=instant)
        self.executed: list[tuple[int, Values]] = []
        self.executed_at: list[float] = []
        self.frames_ok = 0
        self.frames_bad = 0
        self.frames_dropped = 0
        self.replies_dropped = 0
        self.duplicates = 0
        self.last_sequence: int | None = None
        self._queue: deque[tuple[int, Values]] = deque()
        self._running: tuple[int, Values] | None = None
        self._running_end = 0.0
        self._speed = DEFAULT_SPEED
        self._buffer = bytearray()
        self._last_rx = 0.0
        self._junk = False  # bytes skipped since the last frame, not yet answered
        self._swallow = False  # the rest of a frame already answered with an error

    # -- accessors -------------------------------------------------------------------------
    def position(self, t: float | None = None) -> Point:
        """Where the stage is at `t` (default: now; a time within the current move or later)."""
        now = self.clock()
        self._process(now)
        x, y, z = self.stage.position(now if t is None else t)
        return (x, y, z)

    def queue_length(self) -> int:
        """Queued instructions not started yet."""
        self._process(self.clock())
        return len(self._queue)

    def is_running(self) -> bool:
        """Whether a queued instruction is executing (a move or a dwell)."""
        self._process(self.clock())
        return self._running is not None

    # -- the receiver ----------------------------------------------------------------------
    def handle_byte(self, byte: int, t: float) -> None:
        """The serial task reads one byte; a complete frame is answered at once."""
        if self.mute:
            return
        if self.corrupt and self.rng.random() < self.corrupt:
            byte ^= self.rng.randrange(1, 256)
        self._buffer.append(byte)
        self._last_rx = t
        self._scan(t)

    def _scan(self, t: float) -> None:
        while self._buffer:
            buffer = bytes(self._buffer)
            self.framer.last_error = None
            used, data = self.framer.decode(buffer)
            if used == 0:
                return
            del self._buffer[:used]
            if data is not None:
                self._swallow = self._junk = False
                self._frame(data, t)
            elif self.framer.last_error is not None:
                code = CHECKSUM if self.framer.last_error.startswith("checksum") else FRAMING
                log.debug("laser-frame: %s", self.framer.last_error)
                self._junk = False
                self._bad(_first_data_byte(buffer[:used]), code, t)
                # What follows of this frame is junk the host knows about: no second reply.
                self._swallow = True
            elif not self._swallow:
                self._junk = True

    def _frame_timeout(self, now: float) -> None:
        """Line silence: an incomplete frame or stray bytes get a framing error, once."""
        pending, swallow = bytes(self._buffer), self._swallow
        answer = self._junk or (bool(pending) and not swallow)
        self._buffer.clear()
        self._junk = self._swallow = False
        if answer:
            # The article's "no header" case: the robot reports what is not a frame.
            failed = _first_data_byte(pending) if pending.startswith(HEADER) else 0
            log.debug("laser-frame: %d stray bytes at a pause", len(pending))
            self._bad(failed, FRAMING, now)

    def _dropped(self) -> bool:
        if self.drop and self.rng.random() < self.drop:
            self.frames_dropped += 1
            return True
        return False

    def _bad(self, failed: int, code: int, t: float) -> None:
        if self._dropped():
            return
        self.frames_bad += 1
        self._reply(error_reply(failed, code), t)

    def _frame(self, data: bytes, t: float) -> None:
        if self._dropped():
            return
        self.frames_ok += 1
        self._sync(t)
        try:
            parsed = parse(data)
        except Refused as refused:
            log.debug("laser-frame: %s refused: %s", data.hex(" "), refused)
            self._reply(error_reply(refused.word, refused.code), t)
            return
        if parsed.immediate:
            word, _ = parsed.instructions[0]
            self._reply(self._immediate(word, t), t)
        else:
            self._reply(self._enqueue(parsed, t), t)

    def _reply(self, payload: bytes, t: float) -> None:
        if self.drop_reply and self.rng.random() < self.drop_reply:
            self.replies_dropped += 1
            return
        at = t
        if self.delay_reply and self.rng.random() < self.delay_reply:
            at += REPLY_DELAY
        noise = b""
        if self.garbage and self.rng.random() < self.garbage:
            noise = bytes(self.rng.choice(_NOISE) for _ in range(self.rng.randint(1, 16)))
        self.emit(noise + self.framer.encode(payload), at)

    # -- instructions ----------------------------------------------------------------------
    def _immediate(self, word: int, t: float) -> bytes:
        if word == GET_POSITION:
            return bytes((word,)) + field(FLOAT, self.stage.position(t))
        if word == GET_STATUS:
            state = 0 if self._running is None else 1
            return bytes((word,)) + field(UINT8, (min(len(self._queue), 255), state))
        if word == SET_HOME:
            self._set_home(t)
        elif word == STOP:
            self.stage.stop(t)
            self._queue.clear()
            self._running = None
        elif word == GET_ID:
            return bytes((word,)) + field(CHAR, tuple(DEVICE_ID))
        return bytes((word,))

    def _set_home(self, t: float) -> None:
        """The current position becomes (0, 0, 0); a move under way goes on to the same place."""
        here = self.stage.position(t)
        target = self.stage.target()
        self.stage.set_position((0.0, 0.0, 0.0), t)
        if self._running is not None and self._running[0] != DWELL:
            shifted = tuple(b - a for a, b in zip(here, target, strict=True))
            self._running_end = t + self.stage.move_to(shifted, t)

    def _enqueue(self, parsed: Parsed, t: float) -> bytes:
        if parsed.sequence is not None:
            ack = bytes((SEQUENCE,)) + struct.pack("<BBH", INT16, 1, parsed.sequence)
            if parsed.sequence == self.last_sequence:
                # The first copy arrived and its reply was lost: acknowledge, do not run again.
                self.duplicates += 1
                log.debug("laser-frame: frame %d again, not executed", parsed.sequence)
                return ack
            failed = SEQUENCE
        else:
            failed = parsed.instructions[0][0]
            ack = bytes((failed,))
        if len(self._queue) + len(parsed.instructions) > self.queue_depth:
            return error_reply(failed, QUEUE_FULL)
        if parsed.sequence is not None:
            self.last_sequence = parsed.sequence
        self._queue.extend(parsed.instructions)
        self._start_next(t)
        return ack

    # -- execution -------------------------------------------------------------------------
    def wake_at(self) -> float | None:
        """The end of the running instruction, or the pause that ends a pending frame."""
        times: list[float] = []
        if self._running is not None:
            times.append(self._running_end)
        if self._buffer or self._junk or self._swallow:
            times.append(self._last_rx + FRAME_TIMEOUT)
        return min(times) if times else None

    def tick(self, now: float) -> None:
        """Instructions end and start; a pause ends a pending frame."""
        self._sync(now)
        if (self._buffer or self._junk or self._swallow) and self._last_rx + FRAME_TIMEOUT <= now:
            self._frame_timeout(now)

    def _sync(self, now: float) -> None:
        while self._running is not None and self._running_end <= now:
            self._running = None
            self._start_next(self._running_end)

    def _start_next(self, t: float) -> None:
        while self._running is None and self._queue:
            word, values = self._queue.popleft()
            self.executed.append((word, values))
            self.executed_at.append(t)
            log.debug("laser-frame: executing %#04x %s at %.3f", word, values, t)
            duration = self._begin(word, values, t)
            if duration > 0:
                self._running = (word, values)
                self._running_end = t + duration

    def _begin(self, word: int, values: Values, t: float) -> float:
        """Start one queued instruction at `t`; return how long it takes."""
        if word == MOVE_LINEAR:
            x, y, z, speed = (float(v) for v in values)
            self._speed = self.stage.speed = speed
            return self.stage.move_to((x, y, z), t)
        if word == GO_HOME:
            self.stage.speed = self._speed
            return self.stage.move_to((0.0, 0.0, 0.0), t)
        if word == DWELL:
            return 0.0 if self.instant else int(values[0]) / 1000
        return 0.0


def _first_data_byte(frame: bytes) -> int:
    """The first unstuffed data byte of a (damaged) frame, or 0 if it has none."""
    start = len(HEADER) + 1
    if len(frame) <= start:
        return 0
    byte = frame[start]
    if byte != 0x90:
        return byte
    # `90 90` is a stuffed data byte; `90 82` (or a lone 90) means no data.
    return 0x90 if frame[start + 1 : start + 2] == b"\x90" else 0
