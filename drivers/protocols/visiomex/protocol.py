"""Visiomex VMR2P0R0001 packets (drivers/protocols/README.md §2): `S` sets, `M` moves,
`FS`/`FP`/`FA`/`E` lines.

Packets have no terminator: the firmware ends one after 1 s of silence (`Serial.readString()`),
so a reply comes about 1 s after the last byte and two packets within 1 s merge. The client keeps
one packet in flight and never writes within `write_gap` of the last one unless it was answered.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from drivers.errors import BadInput, FrameError
from drivers.framers.lines import LineFramer
from drivers.messages import Message
from drivers.protocols.base import Point, Protocol, Variant
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.commands import Command, Home, MoveBy, MoveTo, Raw, SetParameter, SetSpeed
from drivers.protocols.events import ErrorReport, Event, Feedback, TextLine
from drivers.protocols.move_outcome import MoveOutcome
from drivers.protocols.parameters import ParameterWritten
from drivers.protocols.visiomex import advice as visiomex_advice
from drivers.protocols.visiomex.estimate import move_seconds
from drivers.protocols.visiomex.model import (
    BOOT_ONLY,
    FULLCYCLE,
    MICROSTEP,
    NEVER_READ,
    OVERWRITTEN_AFTER_SET,
    OVERWRITTEN_AT_MOVE,
    SILENCE,
    FirmwareState,
    parse_atof,
)
from drivers.protocols.visiomex.move_digits import firmware_move_mm
from drivers.protocols.visiomex.params import (
    BY_ID,
    DEFAULTS,
    DRIVING_MECHANISM_ID,
    PARAMETERS,
    SPEED_IDS,
)
from drivers.protocols.visiomex.replies import (
    CODE,
    ERRORS,
    UNLISTED_ERROR,
    VisiomexExchange,
    code_meaning,
)
from drivers.protocols.visiomex.where import firmware_move, move_warning, stepping_speeds

PAD = "N"
MOVE_TYPES = {"linear": "L", "rotational": "R", "steps": "S"}
_UNITS = {"linear": "mm", "rotational": "°", "steps": Message("steps")}
_GO_HOME = Message("go home")
BOOT_BANNER = "Checkpoint 2"  # setup() prints it at every boot


@dataclass(frozen=True)
class PacketFormat:
    """The shape of one wire variant's packets."""

    length: int
    digits: int  # digits per move axis
    per_mm: int  # wire units per mm of a linear move (µm: 1000, mm: 1)
    prefix: str  # what starts a feedback line ('>' in later firmware)
    home: bool  # has the `D` go-home packet


FORMATS = {
    "seed": PacketFormat(18, 7, 1000, "", False),
    "prefixed": PacketFormat(18, 7, 1000, ">", False),
    "board12": PacketFormat(12, 4, 1, "", True),
}

CAPABILITIES = Capabilities(
    axes=("x", "y"),
    default_baud=9600,
    absolute_moves=False,
    homing=False,
    set_home=False,
    speed_range=(1.0, 50.0),
    speed_readback=False,
    speed_decimals=0,
    identity_queryable=False,
    position_feedback=False,
    completion=Completion.FEEDBACK,
    parameters=True,
    resolution=0.001,  # µm on the wire
    raw_line_end="",  # a packet has no terminator: the silence after it ends it
    move_kinds=tuple(MOVE_TYPES),
    speed_note=Message(
        "The speed cannot be set here: this firmware revision times its steps from "
        "step_delay_instantaneous (15, 16) alone, not from input_speed_steady (21, 22). "
        '"device:" is the speed X steps at (15 high plus 16 low a step); change 15 and 16 '
        "in the parameter table to change it."
    ),
    speed_fixed=True,
    home_note=Message(
        "Visiomex has no homing at this revision: Home moves back to (0, 0) by a relative move "
        "from the position the panel counted"
    ),
    notes=(
        Message("no read-back: the panel keeps what was last written"),
        Message("positions are commanded, and confirmed by FA0001 when the move ends"),
        Message("a reply comes 1 s after a packet: the firmware waits for 1 s of silence"),
    ),
)


class VisiomexProtocol(Protocol):
    """The Visiomex VMR2P0R0001 motor controller's packet protocol."""

    name = "visiomex"
    capabilities = CAPABILITIES
    write_gap = SILENCE + 0.05
    variants = (
        Variant("seed", Message("18-character packets at 9600 baud, as the seed documents"), 9600),
        Variant("prefixed", Message("the seed's packets; feedback lines start with '>'"), 9600),
        Variant(
            "board12",
            Message("12-character packets at 115200 baud, moves in mm, D goes home"),
            115200,
        ),
    )
    parameters = PARAMETERS

    def __init__(self, variant: str | None = None) -> None:
        super().__init__(variant)
        assert self.variant is not None
        self.format = FORMATS[self.variant.name]
        if self.format.home:
            self.capabilities = dataclasses.replace(
                CAPABILITIES, default_baud=115200, resolution=1.0, homing=True, home_note=""
            )
        self.known: dict[int, float] = dict(DEFAULTS)
        """What the device holds, as far as the panel knows: boot defaults and confirmed sets."""
        self.firmware = FirmwareState.boot()
        """The firmware's own state (drivers/protocols/README.md §2b): every confirmed set and every
        move sent advance it, so estimates follow what the device computes."""

    def assume_parameters(self, values: dict[str, float]) -> None:
        """Take values written earlier (saved by the panel) as what the device holds."""
        for name, value in values.items():
            try:
                parameter = self.parameter(name)
                wire = parameter.to_wire(value)
            except BadInput:
                continue  # a name from an older version of the panel, or a value out of range
            self.known[parameter.id] = value
            self.firmware.set(parameter.id, wire)

    # -- encoding ----------------------------------------------------------------------------
    def new_framer(self) -> LineFramer:
        """Replies are CR LF lines."""
        return LineFramer(b"\n")

    def packet(self, command: Command) -> str:
        """The packet text for a typed command; BadInput before anything is sent."""
        length = self.format.length
        if isinstance(command, SetParameter):
            parameter = self.parameter(command.param_id)
            wire = parameter.to_wire(command.value)
            return f"S{parameter.id:02d}{wire:06d}".ljust(length, PAD)
        if isinstance(command, MoveBy):
            return self._move_packet(command)
        if isinstance(command, Home) and self.format.home:
            return "D".ljust(length, PAD)
        if isinstance(command, Raw):
            return self._raw_text(command.data)
        if isinstance(command, MoveTo):
            raise BadInput(
                Message("Visiomex moves are relative: the panel sends the distance to go")
            )
        if isinstance(command, SetSpeed):
            raise BadInput(Message("the speed is parameters 21 and 22: it is sent as two sets"))
        raise BadInput(
            Message("Visiomex has no packet for {command}", command=type(command).__name__)
        )

    def _move_packet(self, command: MoveBy) -> str:
        kind = command.kind
        if kind not in MOVE_TYPES:
            kinds = ", ".join(MOVE_TYPES)
            raise BadInput(
                Message(
                    "move kind {kind!r} refused: Visiomex moves are {kinds}", kind=kind, kinds=kinds
                )
            )
        if command.dz != 0:
            raise BadInput(
                Message(
                    "Z {distance:g} mm refused: the Visiomex controller has X and Y only",
                    distance=command.dz,
                )
            )
        digits, per_unit = self.format.digits, self.format.per_mm if kind == "linear" else 1
        unit = _UNITS[kind]
        fields = []
        for axis, value in (("X", command.dx), ("Y", command.dy)):
            scaled = value * per_unit
            wire = round(scaled)
            if abs(scaled - wire) > 1e-6 * max(1.0, abs(scaled)):
                if per_unit == 1000:
                    refusal = Message(
                        "{axis} {value:g} {unit} refused: this device moves in 1 µm",
                        axis=axis,
                        value=value,
                        unit=unit,
                    )
                else:
                    refusal = Message(
                        "{axis} {value:g} {unit} refused: this device moves in whole {unit}",
                        axis=axis,
                        value=value,
                        unit=unit,
                    )
                raise BadInput(refusal)
            if abs(wire) > 10**digits - 1:
                most = f"{(10**digits - 1) / per_unit:.{len(str(per_unit)) - 1}f}"
                raise BadInput(
                    Message(
                        "{axis} {value:g} {unit} refused: one move goes at most {most} {unit} "
                        "per axis ({digits} digits)",
                        axis=axis,
                        value=value,
                        unit=unit,
                        most=most,
                        digits=digits,
                    )
                )
            fields.append(("N" if wire < 0 else "P") + f"{abs(wire):0{digits}d}")
        return f"M{MOVE_TYPES[kind]}{fields[0]}{fields[1]}"

    def _raw_text(self, data: bytes) -> str:
        if not data.isascii():
            raise BadInput(Message("packet refused: Visiomex takes ASCII characters only"))
        if not data:
            raise BadInput(Message("packet refused: it is empty"))
        if len(data) > self.format.length:
            raise BadInput(
                Message(
                    "packet refused: {length} characters, a Visiomex packet has {most} "
                    "(a line ending counts too)",
                    length=len(data),
                    most=self.format.length,
                )
            )
        return data.decode("ascii")

    def encode(self, command: Command) -> bytes:
        """The packet's bytes, with no terminator."""
        return self.packet(command).encode("ascii")

    def expand(self, command: Command) -> list[Command]:
        """A speed is two sets: input_speed_steady_x and _y."""
        if isinstance(command, SetSpeed):
            return [SetParameter(i, command.speed) for i in SPEED_IDS]
        return [command]

    # -- decoding ----------------------------------------------------------------------------
    def decode(self, frame: bytes) -> list[Event]:
        """A feedback or error code to a typed event; any other line is the device's own text."""
        try:
            text = frame.decode("ascii").rstrip("\r\n")
        except UnicodeDecodeError as exc:
            shown = frame.hex(" ").upper()
            raise FrameError(
                Message("non-ASCII bytes in a Visiomex line: {bytes}", bytes=shown)
            ) from exc
        prefix = self.format.prefix
        if prefix and not text.startswith(prefix):
            return [TextLine(text)]
        code = text[len(prefix) :]
        if not CODE.fullmatch(code):
            return [TextLine(text)]
        if code.startswith("E"):
            meaning = ERRORS.get(code, UNLISTED_ERROR)
            return [ErrorReport(meaning, code)]
        return [Feedback(code, meaning=code_meaning(code))]

    def is_restart(self, event: Event, waiting: Command | None = None) -> bool:
        """The sketch's `setup()` prints `Checkpoint 2` at every boot."""
        # A reset cuts the line the firmware was printing: its banner then ends that line
        # ("FP0001Checkpoint 2" when the board restarted between FP0001 and its CR LF).
        return isinstance(event, TextLine) and event.text.strip().endswith(BOOT_BANNER)

    # -- replies -----------------------------------------------------------------------------
    def exchange(self, command: Command) -> VisiomexExchange:
        """What answers the packet: `FSnnnn` for a set, `FP0001` then `FA0001` for a move."""
        what = self.command_name(command)
        if isinstance(command, SetParameter):
            return VisiomexExchange(command, what, f"FS{self.parameter(command.param_id).id:04d}")
        if isinstance(command, (MoveBy, Home)):
            return VisiomexExchange(command, what, None)
        if isinstance(command, Raw):
            exchange = self.raw_exchange(command.data)
            if exchange is None:
                raise BadInput(
                    Message("that packet gets no reply: send it from the console instead")
                )
            return exchange
        raise BadInput(
            Message("Visiomex has no packet for {command}", command=type(command).__name__)
        )

    def raw_exchange(self, data: bytes) -> VisiomexExchange | None:
        """A console packet followed by its first letter; `G` gets no reply at all."""
        text = self._raw_text(data)
        first = text[0]
        what = Message("packet {packet}", packet=text)
        if first == "S":
            return VisiomexExchange(Raw(data), what, "")
        if first == "M" or (first == "D" and self.format.home):
            return VisiomexExchange(Raw(data), what, None, extra=self._raw_move_seconds(text))
        if first == "G":
            return None  # the firmware answers G with nothing (drivers/protocols/README.md §2)
        return VisiomexExchange(Raw(data), what, "FS")

    def _raw_move_seconds(self, text: str) -> float:
        """Time a console move packet takes: its distances read as the firmware reads them."""
        return (self.move_packet_seconds(text) - SILENCE) * 1.5

    def move_packet_seconds(self, text: str) -> float:
        """Seconds from a move packet's last byte to the end of its `FA0001`, as the firmware
        will take them from the state it is in now (drivers/protocols/README.md §2b)."""
        return move_seconds(self.firmware, *self._firmware_reads(text))

    def _firmware_reads(self, text: str) -> tuple[float, float, int]:
        """A move packet as this firmware reads it: X and Y in µm (`atof`, whatever the type
        letter), and how many direction letters it answers EP0003 for."""
        d = self.format.digits
        x_um, y_um = (
            parse_atof(text[start : start + d]) * 1000 / self.format.per_mm for start in (3, 4 + d)
        )
        bad = sum(1 for i in (2, 3 + d) if text[i : i + 1] not in ("P", "N"))
        return x_um, y_um, bad

    def new_tx_framer(self) -> None:
        """A packet has no terminator: each write is one packet."""
        return None

    def describe_sent(self, frame: bytes) -> str:
        """A set or a move in words, e.g. `set pulley_diameter_x = 38.2 mm`."""
        text = frame.decode("latin-1")
        if text.startswith("S") and text[1:3].isdecimal() and text[3:9].isdecimal():
            number = int(text[1:3])
            if number in BY_ID:
                parameter = BY_ID[number]
                value = parameter.from_wire(int(text[3:9]))
                return Message(
                    "set {parameter} = {value}",
                    parameter=parameter.name,
                    value=parameter.with_unit(value),
                )
        if text.startswith("M") and len(text) >= 2 + 2 * (self.format.digits + 1):
            d = self.format.digits
            x, y = text[2 : 3 + d], text[3 + d : 4 + 2 * d]
            if text[1] == "L":
                return Message("move linear X {x} Y {y}", x=x, y=y)
            if text[1] == "R":
                return Message("move rotational X {x} Y {y}", x=x, y=y)
            if text[1] == "S":
                return Message("move steps X {x} Y {y}", x=x, y=y)
            return Message("move {kind} X {x} Y {y}", kind=text[1], x=x, y=y)
        if text.startswith("D") and self.format.home:
            return _GO_HOME
        return Message("packet {packet!r}", packet=text)

    def sent_command(self, frame: bytes) -> Command | None:
        """`M` packets move by their distances and `D` goes home (board12); a move packet not
        exactly as documented cannot be read (the seed's firmware runs some of those anyway)."""
        if frame[:1] == b"D" and self.format.home:
            return Home()
        if frame[:1] != b"M":
            return None  # sets, `G`, and what the firmware answers EP0002
        text = frame.decode("latin-1")
        d = self.format.digits
        kinds = {letter: kind for kind, letter in MOVE_TYPES.items()}
        x, y = text[3 : 3 + d], text[4 + d : 4 + 2 * d]
        if (
            len(text) != self.format.length
            or text[1:2] not in kinds
            or text[2:3] not in ("P", "N")
            or text[3 + d : 4 + d] not in ("P", "N")
            or not (x.isascii() and x.isdecimal() and y.isascii() and y.isdecimal())
        ):
            raise FrameError(
                Message("move packet {packet!r} is not as the protocol documents", packet=text)
            )
        kind = kinds[text[1]]
        per = self.format.per_mm if kind == "linear" else 1
        dx = (-1 if text[2] == "N" else 1) * int(x) / per
        dy = (-1 if text[3 + d] == "N" else 1) * int(y) / per
        return MoveBy(dx, dy, 0.0, kind)

    def sent_kind(self, frame: bytes) -> str:
        """`M…` moves and `D` (home) are motion, `S…` sets a parameter; the rest queries."""
        head = frame[:1]
        if head == b"M" or (head == b"D" and self.format.home):
            return "motion"
        return "setting" if head == b"S" else "query"

    def check_raw(self, data: bytes) -> None:
        """Refuse what the firmware cannot take as one packet."""
        self._raw_text(data)

    def command_name(self, command: Command) -> str:
        """The packet and what it does, e.g. `S03000382NNNNNNNNN (set pulley_diameter_x)`."""
        try:
            packet = self.packet(command)
        except BadInput:
            return type(command).__name__
        if isinstance(command, SetParameter):
            return Message(
                "{packet} (set {parameter})",
                packet=packet,
                parameter=self.parameter(command.param_id).name,
            )
        return packet

    # -- what the panel knows of the device ---------------------------------------------------
    def parameter_written(self, command: SetParameter) -> ParameterWritten:
        """Keep the value and recompute as the firmware does (drivers/protocols/README.md §2b): it
        forces driving_mechanism to 1 and overwrites its outputs after every set."""
        parameter = self.parameter(command.param_id)
        self.known[parameter.id] = command.value
        self.firmware.set(parameter.id, parameter.to_wire(command.value))
        notes = []
        forced: dict[str, float] = {}
        if self.known[DRIVING_MECHANISM_ID] != 1:
            notes.append(Message("the firmware forces driving_mechanism to 1 after every set"))
        self.known[DRIVING_MECHANISM_ID] = 1
        forced[BY_ID[DRIVING_MECHANISM_ID].name] = 1.0
        for output in sorted(OVERWRITTEN_AFTER_SET - {parameter.id}):
            now = BY_ID[output].from_wire(self.firmware.values[output])
            if self.known.get(output) != now:  # e.g. a set of 21 recomputes 25
                self.known[output] = now
                forced[BY_ID[output].name] = now
        if parameter.id in OVERWRITTEN_AFTER_SET:
            held = parameter.from_wire(self.firmware.values[parameter.id])
            self.known[parameter.id] = held
            forced[parameter.name] = held
            notes.append(
                Message(
                    "the firmware recomputes {parameter} after every set: this value will not "
                    "stay (it holds {held:g})",
                    parameter=parameter.name,
                    held=held,
                )
            )
        elif parameter.id in OVERWRITTEN_AT_MOVE:
            notes.append(
                Message(
                    "the firmware recomputes {parameter} at every move: this value will not stay",
                    parameter=parameter.name,
                )
            )
        elif parameter.id in BOOT_ONLY:
            notes.append(
                Message(
                    "this firmware revision reads {parameter} only at boot: moves do not "
                    "change until the device restarts",
                    parameter=parameter.name,
                )
            )
        elif parameter.id in NEVER_READ - {DRIVING_MECHANISM_ID}:
            notes.append(
                Message(
                    "this firmware revision never reads {parameter}: moves do not change",
                    parameter=parameter.name,
                )
            )
        return ParameterWritten(parameter, command.value, forced, tuple(notes))

    def on_sent(self, command: Command) -> None:
        """A move went out: the firmware recomputes 19/20 and its ramps leave 15/16 changed."""
        reads = self._move_reads(command)
        if reads is not None:
            self.firmware.move(reads[0], reads[1])

    def _move_reads(self, command: Command) -> tuple[float, float, int] | None:
        """What the firmware reads from a move command's packet (None: not a move packet)."""
        text = self._move_text(command)
        return None if text is None else self._firmware_reads(text)

    def _move_text(self, command: Command) -> str | None:
        """A move command's packet text (None: not a move packet)."""
        if isinstance(command, Raw):
            text = command.data.decode("latin-1")
        elif isinstance(command, (MoveBy, Home)):
            try:
                text = self.packet(command)
            except BadInput:
                return None
        else:
            return None
        return text if text.startswith("M") else None

    def move_outcome(self, command: Command, start: Point, target: Point) -> MoveOutcome:
        """Where the packet leaves the stage by the firmware's arithmetic (truncated step
        counts, the Y loop's ramp count), what to say when that is not `target`, and what the
        move leaves in 15, 16, 19 and 20 (visiomex_where)."""
        text = self._move_text(command)
        if text is None:  # `D` (board12) goes back by the firmware's own count
            return MoveOutcome(target)
        x_um, y_um, _ = self._firmware_reads(text)
        d = self.format.digits
        signs = (-1 if text[2:3] == "N" else 1, -1 if text[3 + d : 4 + d] == "N" else 1)
        move = firmware_move(self.firmware, x_um, y_um, signs)
        end = (start[0] + move.moved[0], start[1] + move.moved[1], start[2])
        left = {BY_ID[i].name: BY_ID[i].from_wire(value) for i, value in move.left.items()}
        return MoveOutcome(end, move_warning(move), left)

    def moving_speed(self) -> float | None:
        """X's stepping speed now (15 high plus 16 low a step): the firmware times its steps
        from the step delays alone, whatever 21/22 say."""
        return stepping_speeds(self.firmware)[0]

    def move_timing(self, command: Command, start: Point, target: Point) -> tuple[float, float]:
        """Until stepping starts (the packet, 1 s of silence, the debug lines going out), then
        until `FA0001` has come: from the firmware's state, as it stands before this move."""
        transmit = self.format.length * 10 / (self.variant_baud() or 9600)
        reads = self._move_reads(command)
        if reads is None:  # `D` (board12) or a command without a packet: the distance given
            dx, dy = target[0] - start[0], target[1] - start[1]
            reads = (abs(dx) * 1000, abs(dy) * 1000, 0)
        total = move_seconds(self.firmware, *reads)
        stepping = min(self.firmware.copy().move(reads[0], reads[1]).seconds, total - SILENCE)
        return transmit + total - stepping, stepping

    def derived_values(self, values: dict[str, float]) -> list[tuple[str, str]]:
        """What the firmware will do with these values (by name): visiomex_advice."""
        return visiomex_advice.derived_values(
            {self.parameter(name).id: value for name, value in values.items()}
        )

    def write_warning(self, param_id: int) -> str:
        """What writing this parameter will not do on this firmware (visiomex_advice)."""
        return visiomex_advice.write_warning(param_id)

    def variant_baud(self) -> int:
        """The line rate of the chosen variant."""
        return type(self).default_baud(self.variant.name if self.variant else None)

    def kind_to_length(self, command: MoveBy) -> Point:
        """Degrees and steps to mm: as the firmware reads the packet (the seed firmware takes
        the digits as µm whatever the type letter), else by the cycle length and steps per turn."""
        if command.kind == "linear":
            return (command.dx, command.dy, command.dz)
        moved = firmware_move_mm(self, self.encode(command))
        if moved is not None:
            return moved
        values = []
        firmware = self.firmware.values
        for axis, value in enumerate((command.dx, command.dy)):
            cycle = self.firmware.cycle[axis]  # the firmware's boot-time cycle
            if command.kind == "rotational":
                values.append(value / 360 * cycle)
            else:
                per_turn = int(firmware[FULLCYCLE[axis]]) * int(firmware[MICROSTEP[axis]])
                values.append(value / max(per_turn, 1) * cycle)
        return (values[0], values[1], 0.0)
