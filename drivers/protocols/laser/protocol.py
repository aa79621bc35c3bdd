"""The laser-processing robot link (drivers/protocols/README.md §3): stuffed frames, acknowledged,
retransmitted.

Immediate instructions (GET_POSITION 0x10, GET_STATUS 0x11, SET_HOME 0x12, STOP 0x13, GET_ID 0x14)
go alone and are answered with their command word (and data). Queued ones (MOVE_LINEAR 0x01,
DWELL 0x02, GO_HOME 0x03) go up to 7 a frame behind a SEQUENCE instruction (0x20, a 16-bit frame
number): the device acknowledges the frame with the SEQUENCE word and number, and a frame whose
number it accepted last is acknowledged again but not executed again (exactly once, a project
decision). An error reply (0x7F) for a damaged frame, or no reply in time, sends the kept copy
again (3 tries); a queue-full reply waits and sends again.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

from drivers.errors import BadInput, DeviceError, FrameError, QueueFull, Retransmit
from drivers.framers.splitter import FrameSplitter
from drivers.framers.stuffed import StuffedFramer
from drivers.messages import Message, message_of
from drivers.protocols.base import Exchange, MoveSequence, Protocol, Setting
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.commands import (
    Command,
    Dwell,
    GetId,
    GetPosition,
    Home,
    MoveTo,
    Raw,
    SetHome,
    Stop,
)
from drivers.protocols.events import Event, PositionReport, Undecodable
from drivers.protocols.laser.codec import (
    CHAR,
    FLOAT,
    INT16,
    UINT8,
    Field,
    Instruction,
    as_int16,
    crc16,
    decode_instructions,
)

MOVE_LINEAR, DWELL, GO_HOME = 0x01, 0x02, 0x03
GET_POSITION, GET_STATUS, SET_HOME, STOP, GET_ID = 0x10, 0x11, 0x12, 0x13, 0x14
SEQUENCE, ERROR = 0x20, 0x7F
QUEUED = (MOVE_LINEAR, DWELL, GO_HOME)
GROUP = 7  # queued instructions per frame at most (the article)
REPLY_TIMEOUT = 0.25  # s: a reply is a few ms away at 115200 baud
WORD_NAMES = {
    MOVE_LINEAR: "MOVE_LINEAR", DWELL: "DWELL", GO_HOME: "GO_HOME", GET_POSITION: "GET_POSITION",
    GET_STATUS: "GET_STATUS", SET_HOME: "SET_HOME", STOP: "STOP", GET_ID: "GET_ID",
    SEQUENCE: "SEQUENCE", ERROR: "ERROR",
}  # fmt: skip
ERROR_CODES = {
    1: Message("framing"),
    2: Message("checksum"),
    3: Message("unknown command"),
    4: Message("bad arguments"),
    5: Message("queue full"),
}
_UNDOCUMENTED = Message("undocumented")


@dataclass(frozen=True)
class GetStatus(Command):
    """Ask the queue depth and the state (0 idle, 1 moving)."""


@dataclass(frozen=True)
class QueuedGroup(Command):
    """Up to 7 queued instructions in one frame (program streaming); `sequence` fixes the frame
    number, so that the same frame can be sent again later (None: the protocol's next)."""

    instructions: tuple[Instruction, ...]
    sequence: int | None = None


@dataclass(frozen=True)
class LaserReply(Event):
    """A reply frame: its instructions; for an error reply, the failed word and the code."""

    instructions: tuple[Instruction, ...]

    @property
    def word(self) -> int:
        """The command word it answers."""
        return self.instructions[0].word if self.instructions else 0

    @property
    def error(self) -> tuple[int, int] | None:
        """(failed command word, code) for an error reply."""
        if self.word != ERROR:
            return None
        values = self.instructions[0].values(UINT8)
        return (int(values[0]), int(values[1])) if len(values) == 2 else (0, 0)

    def __str__(self) -> str:
        if self.error is not None:
            failed, code = self.error
            return Message(
                "error {code} ({meaning}) for {command}",
                code=code,
                meaning=ERROR_CODES.get(code, _UNDOCUMENTED),
                command=WORD_NAMES.get(failed, f"{failed:#04x}"),
            )
        return " ".join(
            WORD_NAMES.get(i.word, f"{i.word:#04x}")
            + "".join(f" {list(f.values)}" for f in i.fields)
            for i in self.instructions
        )


def dwell_instruction(ms: int) -> Instruction:
    """DWELL for `ms` milliseconds (an int16 field: 0 to 32767)."""
    if not 0 <= ms <= 32767:
        raise BadInput(Message("dwell {ms} ms refused: the field is an int16 (0 to 32767)", ms=ms))
    return Instruction(DWELL, (Field(INT16, (ms,)),))


def move_instruction(x: float, y: float, z: float, speed: float) -> Instruction:
    """MOVE_LINEAR to (x, y, z) mm at `speed` mm/s."""
    if not speed > 0:
        raise BadInput(Message("speed {speed:g} mm/s refused: it must be above 0", speed=speed))
    return Instruction(MOVE_LINEAR, (Field(FLOAT, (x, y, z, speed)),))


def reply_value(command: Command, reply: LaserReply) -> object:
    """What a reply means for its command: a position, an id, a status, or the reply itself."""
    first = reply.instructions[0]
    if isinstance(command, GetPosition):
        values = first.values(FLOAT)
        if len(values) != 3:
            raise DeviceError(
                Message("the position reply holds {count} numbers, not 3", count=len(values))
            )
        x, y, z = (float(v) for v in values)
        return PositionReport(x, y, z)
    if isinstance(command, GetId):
        return "".join(str(c) for c in first.values(CHAR))
    if isinstance(command, GetStatus):
        values = first.values(UINT8)
        if len(values) != 2:
            raise DeviceError(
                Message("the status reply holds {count} numbers, not 2", count=len(values))
            )
        return {"queue": int(values[0]), "moving": bool(values[1])}
    return reply


class LaserExchange(Exchange):
    """Waits for the reply with the first instruction's command word (and frame number)."""

    timeout = REPLY_TIMEOUT

    def __init__(self, command: Command, word: int, sequence: int | None, what: str) -> None:
        super().__init__(command)
        self.word = word
        self.sequence = sequence
        self.what = what

    def handle(self, event: Event) -> bool:
        """Errors for this frame fail it (retransmit, back-pressure or refusal); a reply with
        another word or frame number is a late answer to an earlier frame, and is ignored."""
        if not isinstance(event, LaserReply):
            return False
        if event.error is not None:
            failed, code = event.error
            if failed not in (self.word, 0):
                return False  # a late error reply to another frame
            meaning = ERROR_CODES.get(code) or Message("undocumented code {code}", code=code)
            message = Message(
                "{command}: the device answered error {code} ({meaning})",
                command=self.what,
                code=code,
                meaning=meaning,
            )
            # A queued frame the driver built cannot be malformed unless damaged on the way past
            # the one-byte sum (its header, so that the CRC is not even read): sent again too.
            if code in (1, 2) or (code in (3, 4) and self.sequence is not None):
                self.fail(Retransmit(message))
            elif code == 5:
                self.fail(QueueFull(message))
            else:
                self.fail(DeviceError(message))
            return True
        if event.word != self.word:
            return False
        if self.sequence is not None and event.instructions[0].values(INT16)[:1] != (
            self.sequence,
        ):
            return False  # the acknowledgement of another frame
        try:
            self.finish(reply_value(self.command, event))
        except DeviceError as exc:
            self.fail(exc)
        return True


class LaserProtocol(Protocol):
    """The laser robot's framed binary link."""

    name = "laser-frame"
    capabilities = Capabilities(
        axes=("x", "y", "z"),
        default_baud=115200,
        relative_moves=False,
        speed_range=(0.1, 1000.0),
        speed_readback=False,
        completion=Completion.REPLY,
        stop=True,
        raw_text=False,
        raw_line_end="",
        speed_in_moves=True,
        dwell=True,
        streaming=True,
        notes=(
            Message("moves are queued on the device; the position is read back while they run"),
        ),
    )
    attempts = 3
    settings = (
        Setting(
            "next_sequence",
            "",
            0,
            0,
            32767,
            Message("The next queued frame's number (0: random)"),
        ),
    )

    def __init__(self, variant: str | None = None) -> None:
        super().__init__(variant)
        self.sequence = random.randint(1, 32767)
        """The number the next queued frame gets (1..32767, wrapping). A session starts where
        the last one left off (`configure`) or, with nothing kept, at a random number: a first
        frame numbered like the device's last accepted one would be taken for its copy."""

    def configured(self) -> None:
        """A kept frame number continues the numbering of the last session."""
        kept = int(self.values.get("next_sequence", 0))
        if kept:
            self.sequence = kept

    def new_framer(self) -> StuffedFramer:
        """`EB 90 82 F0`, stuffed data, `90 82`, checksum."""
        return StuffedFramer()

    def instructions(self, command: Command) -> list[Instruction]:
        """The instructions of a typed command (a queued one behind its SEQUENCE)."""
        immediate = {GetPosition: GET_POSITION, GetStatus: GET_STATUS, SetHome: SET_HOME,
                     Stop: STOP, GetId: GET_ID}  # fmt: skip
        if type(command) in immediate:
            return [Instruction(immediate[type(command)])]
        if isinstance(command, MoveTo):
            queued = [move_instruction(command.x, command.y, command.z, command.speed or 10.0)]
        elif isinstance(command, Home):
            queued = [Instruction(GO_HOME)]
        elif isinstance(command, Dwell):
            queued = [dwell_instruction(command.ms)]
        elif isinstance(command, QueuedGroup):
            queued = list(command.instructions)
            if not 1 <= len(queued) <= GROUP or any(i.word not in QUEUED for i in queued):
                raise BadInput(
                    Message("a queued frame holds 1 to {most} queued instructions", most=GROUP)
                )
        else:
            raise BadInput(
                Message(
                    "the laser link has no instruction for {command}",
                    command=type(command).__name__,
                )
            )
        number = getattr(command, "sequence", None) or self.sequence
        # The frame's own CRC-16 beside its number: the link's one-byte sum misses two errors
        # that cancel out, and a queued move must not run with damaged coordinates.
        check = as_int16(crc16(b"".join(i.encode() for i in queued)))
        return [Instruction(SEQUENCE, (Field(INT16, (number, check)),)), *queued]

    def encode(self, command: Command) -> bytes:
        """The frame's bytes (raw console bytes go as they are)."""
        if isinstance(command, Raw):
            return command.data
        data = b"".join(i.encode() for i in self.instructions(command))
        return self.new_framer().encode(data)

    def decode(self, frame: bytes) -> list[Event]:
        """A reply frame's instructions."""
        try:
            return [LaserReply(tuple(decode_instructions(frame)))]
        except FrameError as exc:
            return [Undecodable(frame, message_of(exc) or str(exc))]

    def exchange(self, command: Command) -> LaserExchange:
        """The reply carries the first instruction's word (and, queued, the frame number)."""
        first = self.instructions(command)[0]
        sequence = int(first.values(INT16)[0]) if first.word == SEQUENCE else None
        return LaserExchange(command, first.word, sequence, self.command_name(command))

    def sent_kind(self, frame: bytes) -> str:
        """Queued instructions and STOP are motion, GET_POSITION the poll, SET_HOME a setting."""
        try:
            words = {i.word for i in decode_instructions(frame)}
        except FrameError:
            return "query"
        if words & {*QUEUED, STOP}:
            return "motion"
        if SET_HOME in words:
            return "setting"
        return "poll" if words == {GET_POSITION} else "query"

    def sent_command(self, frame: bytes) -> Command | None:
        """A frame's MOVE_LINEAR and GO_HOME instructions, in order (several: a
        MoveSequence); None where it holds none (queries, SET_HOME, STOP, DWELL)."""
        moves: list[Command] = []
        for instruction in decode_instructions(frame):
            if instruction.word == GO_HOME:
                moves.append(Home())
            elif instruction.word == MOVE_LINEAR:
                values = instruction.values(FLOAT)
                if len(values) != 4:
                    raise FrameError(
                        Message(
                            "MOVE_LINEAR with {count} float values, not x, y, z and speed",
                            count=len(values),
                        )
                    )
                x, y, z, speed = (float(v) for v in values)
                moves.append(MoveTo(x, y, z, speed))
        if not moves:
            return None
        return moves[0] if len(moves) == 1 else MoveSequence(tuple(moves))

    def raw_exchange(self, data: bytes) -> LaserExchange | None:
        """A whole frame is followed by its first instruction's word (and frame number)."""
        frames, rest = FrameSplitter(self.new_framer()).whole(data)
        if len(frames) != 1 or rest:
            return None
        try:
            instructions = decode_instructions(frames[0])
        except FrameError:
            return None
        if not instructions:
            return None
        first = instructions[0]
        sequence = int(first.values(INT16)[0]) if first.word == SEQUENCE else None
        name = WORD_NAMES.get(first.word) or Message("word {word:#04x}", word=first.word)
        return LaserExchange(Raw(data), first.word, sequence, name)

    def on_sent(self, command: Command) -> None:
        """A queued frame went out: the next one gets the next number."""
        if isinstance(command, QueuedGroup) and command.sequence is not None:
            return  # numbered by its sender
        if isinstance(command, (MoveTo, Home, Dwell, QueuedGroup)):
            self.next_sequence()

    def next_sequence(self) -> int:
        """Take a frame number (for a frame its sender may have to send again)."""
        number = self.sequence
        self.sequence = self.sequence % 32767 + 1
        return number

    def command_name(self, command: Command) -> str:
        """E.g. `GET_POSITION`, or `frame 12 (MOVE_LINEAR ×7)`."""
        try:
            instructions = self.instructions(command)
        except BadInput:
            return type(command).__name__
        if instructions[0].word != SEQUENCE:
            return WORD_NAMES.get(instructions[0].word, f"{instructions[0].word:#04x}")
        words = [WORD_NAMES.get(i.word, "?") for i in instructions[1:]]
        shown = words[0] if len(set(words)) == 1 else "+".join(words)
        number = instructions[0].values(INT16)[0]
        if len(words) > 1:
            return Message(
                "frame {number} ({words} ×{count})", number=number, words=shown, count=len(words)
            )
        return Message("frame {number} ({words})", number=number, words=shown)
