"""The echo-stage line protocol: `MOVE x y` -> `OK x y` once there, `POS?` -> `POS x y z`,
anything else -> `ERR text`. Lines end in LF; numbers are plain decimals."""

from __future__ import annotations

import re

from drivers.errors import BadInput, DeviceError, FrameError
from drivers.framers.lines import LineFramer
from drivers.protocols.base import Exchange, Protocol
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.commands import Command, GetPosition, MoveTo
from drivers.protocols.events import Done, ErrorReport, Event, PositionReport, TextLine

NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)"
MOVE = re.compile(rf"MOVE ({NUMBER}) ({NUMBER})\Z")
POSITION = re.compile(rf"POS ({NUMBER}) ({NUMBER}) ({NUMBER})\Z")
OK = re.compile(rf"OK ({NUMBER}) ({NUMBER})\Z")


class EchoStageExchange(Exchange):
    """Waits for the one line that answers a command: `OK`, `POS` or `ERR`."""

    def handle(self, event: Event) -> bool:
        """Take the reply line of our command; an `ERR` line fails it."""
        if isinstance(event, ErrorReport):
            self.fail(DeviceError(f"the stage refused the command: {event.message}"))
            return True
        if isinstance(self.command, GetPosition) and isinstance(event, PositionReport):
            self.finish(event)
            return True
        if isinstance(self.command, MoveTo) and isinstance(event, Done):
            self.finish(event.data)
            return True
        return False


class EchoStageProtocol(Protocol):
    """A two-axis stage that echoes each move once it is there."""

    name = "echo-stage"
    capabilities = Capabilities(
        axes=("x", "y"),
        default_baud=115200,
        relative_moves=False,
        homing=False,
        set_home=False,
        speed=False,
        speed_readback=False,  # the speed is fixed: moves are timed at default_speed
        default_speed=20.0,
        identity_queryable=False,
        completion=Completion.REPLY,
        resolution=0.001,  # three decimals on the wire
    )

    def new_framer(self) -> LineFramer:
        """Lines ended by LF (a CR before it is dropped)."""
        return LineFramer(b"\n", max_length=256)

    def encode(self, command: Command) -> bytes:
        """`MOVE x y` or `POS?`; BadInput for anything the stage has no command for."""
        if isinstance(command, MoveTo):
            if command.z:
                raise BadInput("echo-stage has no Z axis")
            return f"MOVE {command.x:.3f} {command.y:.3f}\n".encode("ascii")
        if isinstance(command, GetPosition):
            return b"POS?\n"
        raise BadInput(f"echo-stage has no command for {type(command).__name__}")

    def decode(self, frame: bytes) -> list[Event]:
        """One reply line to one event."""
        try:
            text = frame.decode("ascii").strip()
        except UnicodeDecodeError as exc:
            raise FrameError(f"non-ASCII bytes in an echo-stage line: {frame.hex(' ')}") from exc
        if match := POSITION.match(text):
            x, y, z = (float(v) for v in match.groups())
            return [PositionReport(x, y, z)]
        if match := OK.match(text):
            return [Done("MOVE", f"{match[1]} {match[2]}")]
        if text.startswith("ERR"):
            return [ErrorReport(text[3:].strip())]
        return [TextLine(text)]

    def exchange(self, command: Command) -> EchoStageExchange:
        """A tracker for the one reply line."""
        return EchoStageExchange(command)

    def describe_sent(self, frame: bytes) -> str:
        """The line as sent."""
        return frame.decode("latin-1").strip()

    def sent_kind(self, frame: bytes) -> str:
        """MOVE is motion, POS? the poll."""
        return "motion" if frame.startswith(b"MOVE") else "poll"

    def sent_command(self, frame: bytes) -> Command | None:
        """The move a sent line makes (None for POS?); FrameError for a MOVE without 2 numbers."""
        text = frame.decode("latin-1").strip()
        if not text.startswith("MOVE"):
            return None
        match = MOVE.match(text)
        if match is None:
            raise FrameError(f"{text!r} is not MOVE x y")
        return MoveTo(float(match[1]), float(match[2]))
