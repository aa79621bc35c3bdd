"""What bridged traffic says about where the stage is: a reply that reports the position, or
the target of a move the other program sent.

The bridge forwards another program's bytes; nothing in the panel asks the device anything.
`BridgeWatch` reads the traffic with the protocol's own decoders and reply trackers (the ones
the driver uses): a request the protocol would send as `GetPosition` is followed by its
exchange, and its answer is a position the device reported; a frame that moves the stage
(`sent_command`) gives the position commanded (absolute targets as they are; relative moves,
Home and arcs from the position last observed). Neither is a measurement by the panel.
"""

from __future__ import annotations

import logging
from collections import deque
from dataclasses import dataclass

from drivers.errors import MotionError
from drivers.link.records import TX, Traffic
from drivers.protocols.base import Exchange, MoveSequence, Point, Protocol
from drivers.protocols.commands import Arc, Command, GetPosition, Home, MoveBy, MoveTo
from drivers.protocols.events import PositionReport
from drivers.traffic.decoding import DecodedFrame, StreamDecoder

log = logging.getLogger(__name__)

REPORTED = "reported"  # the device answered a position request of the other program's
COMMANDED = "commanded"  # the target of a move the other program sent
MAX_WAITING = 8  # position requests followed at once (the oldest is dropped)
WAIT_S = 10.0  # seconds a position request waits for its answer


@dataclass(frozen=True, slots=True)
class Observed:
    """A position the traffic told, in mm: `source` REPORTED or COMMANDED, `time` monotonic."""

    x: float
    y: float
    z: float
    source: str
    time: float

    @property
    def point(self) -> Point:
        """The position as (x, y, z)."""
        return (self.x, self.y, self.z)


class BridgeWatch:
    """Follows one bridge's traffic, record by record, for the positions it tells."""

    def __init__(self, protocol: Protocol) -> None:
        self.protocol = protocol
        self.position: Point | None = None  # the last one observed
        self._decoder = StreamDecoder(protocol)
        self._request = _position_request(protocol)
        self._waiting: deque[tuple[float, Exchange]] = deque()

    def feed(self, record: Traffic) -> list[Observed]:
        """The positions that the frames `record` completes tell, in order."""
        found: list[Observed] = []
        frames = self._decoder.feed_bytes(record.direction, record.data, record.time)
        for frame in frames:
            if record.direction == TX:
                point, source = self._sent(frame), COMMANDED
            else:
                point, source = self._received(frame), REPORTED
            if point is not None:
                self.position = point
                found.append(Observed(*point, source, record.time))
        return found

    def _sent(self, frame: DecodedFrame) -> Point | None:
        if self._request is not None and frame.data == self._request:
            self._follow(frame.time)
            return None
        try:
            command = self.protocol.sent_command(frame.data)
        except MotionError:  # not readable as the device reads it: it tells nothing
            return None
        return self._target(command, self.position) if command is not None else None

    def _follow(self, time: float) -> None:
        """A position request went to the device: its answer is awaited with its tracker."""
        waiting = self._waiting
        while waiting and (len(waiting) >= MAX_WAITING or time - waiting[0][0] > WAIT_S):
            waiting.popleft()
        try:
            waiting.append((time, self.protocol.exchange(GetPosition())))
        except MotionError:
            log.debug("no tracker for %s's position request", self.protocol.name)

    def _received(self, frame: DecodedFrame) -> Point | None:
        point = None
        for event in frame.events:
            for entry in list(self._waiting):
                exchange = entry[1]
                if not exchange.on_event(event):
                    continue
                if exchange.finished:
                    self._waiting.remove(entry)
                    if exchange.error is None and isinstance(exchange.value, PositionReport):
                        value = exchange.value
                        point = (value.x, value.y, value.z)
                break
        return point

    def _target(self, command: Command, start: Point | None) -> Point | None:
        """Where `command` sends the stage from `start` (None: not known from the traffic)."""
        if isinstance(command, MoveTo):
            return (command.x, command.y, command.z)
        if isinstance(command, Home):
            return (0.0, 0.0, 0.0)
        if isinstance(command, MoveBy):
            if start is None or command.kind != "linear":
                return None
            return (start[0] + command.dx, start[1] + command.dy, start[2] + command.dz)
        if isinstance(command, Arc):
            x, y = command.point(command.end)
            return (x, y, command.z)
        if isinstance(command, MoveSequence):
            here = start
            for move in command.moves:
                here = self._target(move, here)
            return here
        return None


def _position_request(protocol: Protocol) -> bytes | None:
    """The frame the protocol sends to ask the position, as its TX framer gives it (None: none)."""
    try:
        data = protocol.encode(GetPosition())
    except MotionError:
        return None
    framer = protocol.new_tx_framer()
    if framer is None:
        return data
    frames, rest = framer.split(data)
    return frames[0] if len(frames) == 1 and not rest else None
