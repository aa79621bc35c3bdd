"""COXIRIS ASCII protocol (drivers/protocols/README.md §1): `CMD args\\n` -> `ACK CMD` ...
`DONE CMD[: data]`."""

from __future__ import annotations

import re

from drivers.errors import BadInput, DeviceError, FrameError, GarbledReply
from drivers.framers.lines import LineFramer
from drivers.messages import Message
from drivers.protocols.base import Exchange, Protocol
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.commands import (
    CheckErrors,
    Command,
    GetId,
    GetMaxSpeed,
    GetMinSpeed,
    GetPosition,
    GetSpeed,
    Help,
    Home,
    MoveBy,
    MoveTo,
    Raw,
    SetHome,
    SetSpeed,
)
from drivers.protocols.events import Ack, Done, ErrorReport, Event, PositionReport, TextLine
from drivers.protocols.numbers import format_number

MAX_COMMAND_LENGTH = 63  # the firmware's 64-byte buffer keeps 63 characters and a NUL
HELP_LINE_COUNT = 12
UNKNOWN_COMMAND = "Unknown command - "
LINE_ENDS = b"\r\n"  # only CR or LF ends a line (a NUL cuts the command: parsed_part)
NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)")  # what the firmware takes as a number
MOVES = ("ABSOLUTE_MOVE", "DELTA_MOVE")
TOO_LONG = "Command too long"
# What a number is, for format_number's and parse_reply_number's refusals: made once, so that
# encoding a move builds no message unless it is refused.
_COORDINATES = tuple(Message("{axis} coordinate", axis=a) for a in "xyz")
_DISTANCES = tuple(Message("{axis} distance", axis=a) for a in ("dx", "dy", "dz"))
_SPEED = Message("speed")
_A_COORDINATE = Message("a coordinate")
_THE_SPEED = Message("the speed")

_SIMPLE: dict[type[Command], str] = {
    Help: "HELP",
    SetHome: "SET_HOME",
    Home: "GO_HOME",
    GetPosition: "GET_POSITION",
    GetSpeed: "GET_SPEED",
    GetMinSpeed: "GET_MIN_SPEED",
    GetMaxSpeed: "GET_MAX_SPEED",
    GetId: "GET_ID",
    CheckErrors: "CHECK_ERRORS",
}


def command_line(command: Command) -> str:
    """The text line (without terminator) for a typed command; BadInput if it cannot be sent."""
    if type(command) in _SIMPLE:
        line = _SIMPLE[type(command)]
    elif isinstance(command, MoveTo):
        parts = [
            format_number(v, what)
            for what, v in zip(_COORDINATES, (command.x, command.y, command.z), strict=True)
        ]
        line = "ABSOLUTE_MOVE " + " ".join(parts)
    elif isinstance(command, MoveBy):
        deltas = (command.dx, command.dy, command.dz)
        parts = [format_number(v, what) for what, v in zip(_DISTANCES, deltas, strict=True)]
        line = "DELTA_MOVE " + " ".join(parts)
    elif isinstance(command, SetSpeed):
        if not command.speed > 0:
            raise BadInput(
                Message(
                    "speed {speed:g} mm/s refused: the speed must be positive", speed=command.speed
                )
            )
        line = "SET_SPEED " + format_number(command.speed, _SPEED)
    elif isinstance(command, Raw):
        try:
            line = command.data.decode("ascii")
        except UnicodeDecodeError as exc:
            raise BadInput(Message("raw command refused: COXIRIS takes ASCII text only")) from exc
        if any(c in line for c in "\r\n"):
            raise BadInput(
                Message("raw command refused: one line at a time (it contains a line break)")
            )
        if not line.strip():
            raise BadInput(
                Message("raw command refused: it is empty, and the device ignores blank lines")
            )
    else:
        raise BadInput(
            Message("COXIRIS has no command for {command}", command=type(command).__name__)
        )
    if len(line) > MAX_COMMAND_LENGTH:
        raise BadInput(
            Message(
                "command refused: {length} characters, the device takes at most {most} "
                "({start}...)",
                length=len(line),
                most=MAX_COMMAND_LENGTH,
                start=line[:24],
            )
        )
    return line


def parsed_part(line: bytes) -> bytes:
    """What the firmware parses of a line: the bytes before its first NUL.

    A NUL does not end a line and still counts toward the 63 characters, but the parser reads
    the line as a C string, so the rest of it is ignored (drivers/protocols/README.md §1,
    coxiris-nul.json)."""
    return line.split(b"\0", 1)[0]


def expected_name(line: str) -> str:
    """The command name the device will echo in ACK/DONE: the first token, upper-cased."""
    return line.strip().upper().split(" ")[0]


def parse_reply_number(text: str, what: str) -> float:
    """A number printed by the firmware; `ovf`, `nan` and `inf` are reported as unreadable.
    `what` (a Message, e.g. "a coordinate") names it in the refusal."""
    try:
        value = float(text)
    except ValueError as exc:
        raise GarbledReply(
            Message(
                "the device reported {what} as {text!r}, which is not a number",
                what=what,
                text=text,
            )
        ) from exc
    if text.strip().lower() in ("nan", "inf", "-inf", "ovf"):
        raise GarbledReply(Message("the device reported {what} as {text!r}", what=what, text=text))
    return value


class CoxirisExchange(Exchange):
    """Follows `ACK CMD`, error and text lines, then `DONE CMD`; and the ACK-less error replies."""

    linger = 2.0  # the help text after an unknown command: about 0.8 kB, 70 ms at 115200 baud

    def __init__(self, command: Command, name: str) -> None:
        super().__init__(command)
        self.name = name
        self.acked = False
        self.errors: list[str] = []
        self.lines: list[str] = []
        self._trailing_lines = 0
        self._unknown_pending = False

    @property
    def wants_more(self) -> bool:
        """True while the echo and help text of an unknown-command reply are still to come."""
        return self._trailing_lines > 0

    def handle_trailing(self, event: Event) -> bool:
        """Swallow the echo and the help lines that follow `ERROR: Unknown command`."""
        if self._trailing_lines > 0 and isinstance(event, TextLine):
            self._trailing_lines -= 1
            self.lines.append(event.text)
            return True
        return False

    def handle(self, event: Event) -> bool:
        """Track one event of the reply."""
        if self._unknown_pending:
            # drivers/protocols/README.md §1: the line after `ERROR: Unknown command - ` echoes the
            # command name; an echo of another name is the tail of an earlier reply, not ours.
            self._unknown_pending = False
            if isinstance(event, TextLine) and event.text == self.name:
                self._trailing_lines = 1 + HELP_LINE_COUNT  # "Available commands:" and the help
                self.lines.append(event.text)
                self.fail(
                    DeviceError(
                        Message("the device does not know the command {name!r}", name=self.name)
                    )
                )
                return True
            return False
        if not self.acked:
            if isinstance(event, Ack) and event.command == self.name:
                self.acked = True
                return True
            if isinstance(event, Done) and event.command == self.name:
                self.acked = True  # its ACK was lost on the line (noise glued to it): DONE says it
                return self.handle(event)
            if isinstance(event, ErrorReport):
                # Unknown and too-long commands get an ERROR line with no ACK and no DONE.
                if event.message.startswith(UNKNOWN_COMMAND.rstrip()):
                    self._unknown_pending = True
                    return True
                self.fail(
                    DeviceError(
                        Message("the device refused the command: {error}", error=event.message)
                    )
                )
                return True
            return False
        if isinstance(event, ErrorReport):
            self.errors.append(event.message)
            return True
        if isinstance(event, TextLine):
            self.lines.append(event.text)
            return True
        if isinstance(event, Done) and event.command == self.name:
            if self.errors:
                self.fail(DeviceError("; ".join(self.errors)))
            else:
                self._complete(event)
            return True
        if isinstance(event, (Ack, Done)):
            self.fail(
                GarbledReply(
                    Message(
                        "expected DONE {command}, got {event}", command=self.name, event=str(event)
                    )
                )
            )
            return True
        return False

    def _complete(self, done: Done) -> None:
        command = self.command
        data = done.data
        try:
            if isinstance(command, GetPosition):
                fields = (data or "").split()
                if len(fields) != 3:
                    raise GarbledReply(
                        Message("position reply {data!r} does not hold three numbers", data=data)
                    )
                x, y, z = (parse_reply_number(f, _A_COORDINATE) for f in fields)
                self.finish(PositionReport(x, y, z))
            elif isinstance(command, (GetSpeed, GetMinSpeed, GetMaxSpeed)):
                self.finish(parse_reply_number(data or "", _THE_SPEED))
            elif isinstance(command, GetId):
                self.finish((data or "").strip())
            elif isinstance(command, Help):
                self.finish(list(self.lines))
            else:
                self.finish(data)
        except GarbledReply as exc:
            self.fail(exc)


class CoxirisProtocol(Protocol):
    """The COXIRIS positioning system's line protocol."""

    name = "coxiris"
    capabilities = Capabilities(
        axes=("x", "y", "z"),
        default_baud=115200,
        speed_limits_queryable=True,
        completion=Completion.REPLY,
        resolution=0.01,  # positions are printed with two decimals
        # a blocking move callback delays every reply (drivers/protocols/README.md §1)
        busy_silent=True,
        notes=(
            Message("speeds are reported rounded to whole mm/s"),
            Message("positions are reported to 0.01 mm"),
        ),
    )

    def new_framer(self) -> LineFramer:
        """Lines ended by CR LF."""
        return LineFramer(b"\n")

    def encode(self, command: Command) -> bytes:
        """`CMD args\\n`, refused if longer than the firmware's 63 characters."""
        return command_line(command).encode("ascii") + b"\n"

    def decode(self, frame: bytes) -> list[Event]:
        """One reply line to one event."""
        try:
            text = frame.decode("ascii")
        except UnicodeDecodeError as exc:
            raise FrameError(
                Message("non-ASCII bytes in a COXIRIS line: {bytes}", bytes=frame.hex(" ").upper())
            ) from exc
        if text.startswith("ACK "):
            return [Ack(text[4:].strip())]
        if text.startswith("DONE "):
            name, sep, data = text[5:].partition(":")
            return [Done(name.strip(), data.strip() if sep else None)]
        if text.startswith("ERROR:"):
            return [ErrorReport(text[6:].lstrip(" "))]
        return [TextLine(text)]

    def describe_sent(self, frame: bytes) -> str:
        """The command line as sent."""
        return frame.decode("latin-1").strip()

    def sent_kind(self, frame: bytes) -> str:
        """Moves and homing are motion, GET_POSITION the poll, SET_* settings, the rest queries."""
        name = parsed_part(frame).decode("latin-1").strip().split(" ", 1)[0].upper()
        if name in ("ABSOLUTE_MOVE", "DELTA_MOVE", "GO_HOME"):
            return "motion"
        if name == "GET_POSITION":
            return "poll"
        return "setting" if name.startswith("SET_") else "query"

    def check_raw(self, data: bytes) -> None:
        """Refuse any line over 63 characters: the firmware would overflow its buffer."""
        for line in data.replace(b"\r", b"\n").split(b"\n"):
            if len(line) > MAX_COMMAND_LENGTH:
                raise BadInput(
                    Message(
                        "line refused: {length} characters, the device takes at most {most}",
                        length=len(line),
                        most=MAX_COMMAND_LENGTH,
                    )
                )

    def raw_exchange(self, data: bytes) -> CoxirisExchange | None:
        """One console line (one trailing CR, LF or CR LF) is followed like a typed command."""
        line = data
        for ending in (b"\r\n", b"\n", b"\r"):
            if line.endswith(ending):
                line = line[: -len(ending)]
                break
        else:
            return None  # not ended: the device waits for more, nothing to follow yet
        if b"\r" in line or b"\n" in line:
            return None
        parsed = parsed_part(line)
        if not parsed.strip() or not parsed.isascii():
            return None  # nothing before a NUL is a blank line: no reply at all
        return CoxirisExchange(Raw(line), expected_name(parsed.decode("ascii")))

    def sent_commands(self, data: bytes) -> list[Command | None]:
        """Every line in console bytes as the firmware reads them: CR or LF ends a line, and
        a line's command is what precedes its first NUL."""
        lines = data.replace(b"\r", b"\n").split(b"\n")
        if lines[-1]:
            raise FrameError(
                Message(
                    "{line!r} has no line end: the device would wait for the rest",
                    line=lines[-1].decode("latin-1"),
                )
            )
        commands = [self.sent_command(line) for line in lines[:-1] if parsed_part(line).strip()]
        if not commands:
            raise FrameError(Message("an empty line: the device ignores it"))
        return commands

    def sent_command(self, frame: bytes) -> Command | None:
        """`ABSOLUTE_MOVE x y z`, `DELTA_MOVE dx dy dz` and `GO_HOME` move (any case, as the
        firmware upper-cases the line; what follows a NUL is not read); a move without exactly
        three numbers cannot be read."""
        try:
            line = parsed_part(frame).decode("ascii").strip(" \t\r\n\v\f").upper()
        except UnicodeDecodeError as exc:
            raise FrameError(Message("non-ASCII bytes: COXIRIS takes ASCII text only")) from exc
        name, _, rest = line.partition(" ")
        params = [p for p in rest.split(" ") if p]
        if name == "GO_HOME":
            return Home()
        if name not in MOVES:
            return None
        if len(params) != 3 or not all(NUMBER.fullmatch(p) for p in params):
            raise FrameError(
                Message(
                    "{name} {params!r} is not three numbers as the firmware reads them",
                    name=name,
                    params=rest.strip(),
                )
            )
        x, y, z = (float(p) for p in params)
        return MoveTo(x, y, z) if name == "ABSOLUTE_MOVE" else MoveBy(x, y, z)

    def command_name(self, command: Command) -> str:
        """The name the device echoes in ACK/DONE, e.g. `GET_POSITION`."""
        try:
            return expected_name(command_line(command))
        except BadInput:
            return type(command).__name__

    def exchange(self, command: Command) -> CoxirisExchange:
        """Track the reply by the command name the device will echo."""
        return CoxirisExchange(command, expected_name(command_line(command)))
