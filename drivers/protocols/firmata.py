"""Firmata with the FirmataPlus stepper extension (drivers/protocols/README.md §5), one motor as the
X axis.

Stepper messages are SysEx `F0 72 <sub> ... F7` with 7-bit data: config (steps per revolution,
2 or 4 pins), step (speed in rpm on 21 bits, steps on 14 bits, direction), library version. The
firmware sends no completion: a move is estimated from speed and steps, and a move longer than
16383 steps is split into messages, each sent once the previous one should have ended.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from drivers.errors import BadInput, DeviceError, FrameError
from drivers.framers.sysex import SysexFramer
from drivers.messages import Message
from drivers.protocols.base import Exchange, Point, Protocol, Setting
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.commands import Command, GetId, MoveBy, Raw
from drivers.protocols.events import ErrorReport, Event, Feedback, TextLine
from drivers.protocols.piframe import NoReply

START, END = 0xF0, 0xF7
REPORT_VERSION = 0xF9
REPORT_FIRMWARE = 0x79
STRING_DATA = 0x71
STEPPER_DATA = 0x72
CAPABILITY_RESPONSE, ANALOG_MAPPING_RESPONSE = 0x6C, 0x6A
CONFIGURE, STEP, LIBRARY_VERSION = 0x00, 0x01, 0x02
MAX_STEPS = 16383  # 14 bits: PyMata masks more (a bug); the driver splits instead
MAX_RPM = 2**21 - 1
USEFUL_RPM = 1000  # the speed control's top: Arduino's Stepper.step cannot go much faster
STEPS_PER_REV = Setting(
    "steps_per_rev", "steps/rev", 200, 1, MAX_STEPS, Message("Motor steps per turn")
)
STEPS_PER_MM = Setting(
    "steps_per_mm", "steps/mm", 80, 0.001, 1e6, Message("Motor steps per millimetre")
)
PINS = tuple(
    Setting(f"pin{i}", "", -1, -1, 127, Message("Motor control pin {pin} (-1: none)", pin=i))
    for i in range(1, 5)
)
IDENTIFY_TIMEOUT = 3.0  # s for the version and firmware name, after the board's reset

CAPABILITIES = Capabilities(
    axes=("x",),
    default_baud=57600,
    absolute_moves=False,
    homing=False,
    set_home=False,
    speed_readback=False,
    position_feedback=False,
    completion=Completion.ESTIMATE,
    raw_text=False,
    raw_line_end="",
    speed_in_moves=True,
    startup_wait=2.5,  # an Arduino resets when the port opens; its bootloader runs up to ~2 s
    home_note=Message("Moves back to 0 by a relative move: the board has no homing"),
    notes=(Message("no completion message: moves are estimated from speed and steps"),),
)


@dataclass(frozen=True)
class StepperConfig(Command):
    """Configure the motor: steps per revolution and its 2 or 4 control pins."""

    steps_per_rev: int
    pins: tuple[int, ...]


@dataclass(frozen=True)
class StepperStep(Command):
    """Step the motor: speed in rpm, steps signed (negative: reverse)."""

    rpm: int
    steps: int


@dataclass(frozen=True)
class StepperVersion(Command):
    """Ask the stepper library's version."""


_COMMAND_NAMES: dict[type[Command], str] = {
    GetId: Message("the version and firmware name (is a Firmata board on this port?)"),
    StepperConfig: "STEPPER_CONFIGURE",
    StepperVersion: "STEPPER_LIBRARY_VERSION",
    StepperStep: "STEPPER_STEP",
}


def step_parts(rpm: int, steps: int) -> list[StepperStep]:
    """Step messages of at most 16383 steps each, summing to `steps` (never masked)."""
    sign = 1 if steps >= 0 else -1
    parts = []
    left = abs(steps)
    while left > 0:
        chunk = min(left, MAX_STEPS)
        parts.append(StepperStep(rpm, sign * chunk))
        left -= chunk
    return parts


def seven_bit_pairs(text: bytes) -> bytes:
    """Firmata's string encoding: every byte as its low 7 bits, then its high bit."""
    return bytes(b for c in text for b in (c & 0x7F, c >> 7))


def from_pairs(data: bytes) -> str:
    """Bytes sent as 7-bit pairs, back to text."""
    chars = bytes((data[i] | (data[i + 1] << 7)) & 0xFF for i in range(0, len(data) - 1, 2))
    return chars.decode("latin-1")


# What a checked number is (made once: a step message is checked at every move).
_RPM = Message("speed (rpm)")
_STEPS_PER_REV = Message("steps per revolution")
_PIN = Message("pin")
_STEPS = Message("steps")
_SYSEX_NAMES = {
    CAPABILITY_RESPONSE: Message("capability response"),
    ANALOG_MAPPING_RESPONSE: Message("analog mapping"),
}
_VERSION_REQUEST = Message("version request")
_FIRMWARE_REQUEST = Message("firmware name request")
_LIBRARY_VERSION_REQUEST = Message("STEPPER_LIBRARY_VERSION request")


def _check(value: int, low: int, high: int, what: str) -> int:
    if not isinstance(value, int) or not low <= value <= high:
        raise BadInput(
            Message(
                "{what} {value} refused: the stepper takes {low} to {high}",
                what=what,
                value=value,
                low=low,
                high=high,
            )
        )
    return value


class HostFramer(SysexFramer):
    """What a host sends: as the board reads it, where `F9` alone asks the version."""

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """A lone `F9` is a whole message from the host."""
        if buffer[:1] == bytes((REPORT_VERSION,)):
            return 1, buffer[:1]
        return super().decode(buffer)


class _Reply(Exchange):
    """Waits for one kind of message: the firmware name (identity) or the library version."""

    def __init__(self, command: Command, code: str, timeout: float | None = None) -> None:
        super().__init__(command)
        self.code = code
        self.timeout = timeout
        self.version = ""

    def handle(self, event: Event) -> bool:
        """The wanted message ends it; a STRING_DATA error fails it."""
        if isinstance(event, ErrorReport):
            self.fail(DeviceError(Message("the board answered: {error}", error=event.message)))
            return True
        if isinstance(event, Feedback) and event.code == "version":
            report = event.value
            if isinstance(report, bytes | bytearray) and len(report) >= 3:
                self.version = f"{report[1]}.{report[2]}"  # the report's bytes
            return self.code == "version"
        if isinstance(event, Feedback) and event.code == self.code:
            self.finish(event.meaning)
            return True
        return False


class FirmataProtocol(Protocol):
    """PyMata-compatible stepper messages, plus what the base protocol sends."""

    name = "firmata"
    capabilities = CAPABILITIES
    settings = (STEPS_PER_REV, STEPS_PER_MM, *PINS)

    def __init__(self, variant: str | None = None) -> None:
        super().__init__(variant)
        self.configured()

    def configured(self) -> None:
        """Resolution and speed range follow steps per mm and per revolution."""
        per_rpm = self.values["steps_per_rev"] / 60 / self.values["steps_per_mm"]  # mm/s per rpm
        self.capabilities = dataclasses.replace(
            CAPABILITIES,
            resolution=1 / self.values["steps_per_mm"],
            speed_range=(per_rpm, USEFUL_RPM * per_rpm),
        )

    def pins(self) -> tuple[int, ...]:
        """The motor's control pins as configured (empty: not configured)."""
        return tuple(int(self.values[p.name]) for p in PINS if self.values[p.name] >= 0)

    def startup_commands(self) -> list[Command]:
        """The saved stepper config, sent again after the board's reset, then confirmed."""
        pins = self.pins()
        if len(pins) not in (2, 4):
            return []
        return [StepperConfig(int(self.values["steps_per_rev"]), pins), StepperVersion()]

    def new_framer(self) -> SysexFramer:
        """SysEx and the base protocol's short messages."""
        return SysexFramer()

    def rpm(self, speed: float) -> int:
        """The motor speed in rpm for `speed` mm/s."""
        steps_per_s = speed * self.values["steps_per_mm"]
        return _check(
            max(1, round(steps_per_s * 60 / self.values["steps_per_rev"])),
            1,
            MAX_RPM,
            _RPM,
        )

    def steps(self, mm: float) -> int:
        """Whole steps for a distance; BadInput where it is finer than one step."""
        steps = mm * self.values["steps_per_mm"]
        if abs(steps - round(steps)) > 1e-6 * max(1.0, abs(steps)):
            per_mm = self.values["steps_per_mm"]
            raise BadInput(
                Message(
                    "{distance:g} mm refused: the motor moves in steps of {step:g} mm "
                    "({per_mm:g} steps/mm)",
                    distance=mm,
                    step=1 / per_mm,
                    per_mm=per_mm,
                )
            )
        return round(steps)

    def expand(self, command: Command) -> list[Command]:
        """A move as step messages of at most 16383 steps; a speed is kept, not sent."""
        if isinstance(command, MoveBy):
            if command.dy or command.dz:
                raise BadInput(Message("the Firmata stepper is one axis (X): Y and Z must be 0"))
            rpm = self.rpm(command.speed or self.capabilities.default_speed)
            return list(step_parts(rpm, self.steps(command.dx)))
        return [command]

    def encode(self, command: Command) -> bytes:
        """The bytes of a command (a move: all its step messages)."""
        if isinstance(command, GetId):
            return bytes((REPORT_VERSION, START, REPORT_FIRMWARE, END))
        if isinstance(command, StepperConfig):
            _check(command.steps_per_rev, 1, MAX_STEPS, _STEPS_PER_REV)
            if len(command.pins) not in (2, 4):
                raise BadInput(
                    Message(
                        "{count} pins refused: a stepper has 2 or 4 pins", count=len(command.pins)
                    )
                )
            for pin in command.pins:
                _check(pin, 0, 127, _PIN)
            spr = command.steps_per_rev
            return bytes((START, STEPPER_DATA, CONFIGURE, spr & 0x7F, spr >> 7, *command.pins, END))
        if isinstance(command, StepperStep):
            rpm = _check(command.rpm, 1, MAX_RPM, _RPM)
            steps = _check(abs(command.steps), 0, MAX_STEPS, _STEPS)
            direction = 1 if command.steps >= 0 else 0
            speed = (rpm & 0x7F, (rpm >> 7) & 0x7F, rpm >> 14)
            return bytes(
                (START, STEPPER_DATA, STEP, *speed, steps & 0x7F, steps >> 7, direction, END)
            )
        if isinstance(command, StepperVersion):
            return bytes((START, STEPPER_DATA, LIBRARY_VERSION, END))
        if isinstance(command, MoveBy):
            return b"".join(self.encode(part) for part in self.expand(command))
        if isinstance(command, Raw):
            return command.data
        raise BadInput(
            Message("Firmata has no message for {command}", command=type(command).__name__)
        )

    def decode(self, frame: bytes) -> list[Event]:
        """Every Firmata message named; STRING_DATA as the board's own words."""
        if not frame:
            raise FrameError(Message("an empty Firmata message"))
        status = frame[0]
        if status == REPORT_VERSION and len(frame) == 3:
            version = Message("Firmata protocol {major}.{minor}", major=frame[1], minor=frame[2])
            return [Feedback("version", frame, version)]
        if 0xE0 <= status <= 0xEF and len(frame) == 3:
            value = frame[1] | frame[2] << 7
            meaning = Message("analog pin {pin}: {value}", pin=status & 0x0F, value=value)
            return [Feedback("analog", frame, meaning)]
        if 0x90 <= status <= 0x9F and len(frame) == 3:
            bits = frame[1] | frame[2] << 7
            meaning = Message("digital port {port}: {bits:08b}", port=status & 0x0F, bits=bits)
            return [Feedback("digital", frame, meaning)]
        if status != START or len(frame) < 3:
            meaning = Message("message {bytes}", bytes=frame.hex(" ").upper())
            return [Feedback("firmata", frame, meaning)]
        command, data = frame[1], frame[2:-1]
        if command == STRING_DATA:
            text = from_pairs(data)
            return [ErrorReport(text, "STRING_DATA") if "error" in text.lower() else TextLine(text)]
        if command == REPORT_FIRMWARE and len(data) >= 2:
            name = from_pairs(data[2:])
            return [Feedback("firmware", frame, f"{name} {data[0]}.{data[1]}")]
        if command == STEPPER_DATA and len(data) == 2:
            return [Feedback("stepper_version", frame, str(data[0] | data[1] << 7))]
        name = _SYSEX_NAMES.get(command) or Message("SysEx {command:#04x}", command=command)
        return [Feedback("sysex", frame, name)]

    def is_restart(self, event: Event, waiting: Command | None = None) -> bool:
        """`Firmata.begin()` reports the protocol version unasked at every boot (identifying
        asks for it too)."""
        return (
            isinstance(event, Feedback)
            and event.code == "version"
            and not isinstance(waiting, GetId)
        )

    def new_tx_framer(self) -> HostFramer:
        """The host's messages, `F9` alone included."""
        return HostFramer()

    def describe_sent(self, frame: bytes) -> str:
        """What the host asked the board, e.g. `STEPPER_STEP 300 rpm, 500 steps forward`."""
        if frame == bytes((REPORT_VERSION,)):
            return _VERSION_REQUEST
        if frame[:2] == bytes((START, REPORT_FIRMWARE)):
            return _FIRMWARE_REQUEST
        if frame[:2] == bytes((START, STEPPER_DATA)) and len(frame) >= 4:
            sub, data = frame[2], frame[3:-1]
            if sub == CONFIGURE and len(data) >= 2:
                pins = " ".join(str(p) for p in data[2:])
                return Message(
                    "STEPPER_CONFIGURE {steps} steps/rev, pins {pins}",
                    steps=data[0] | data[1] << 7,
                    pins=pins,
                )
            if sub == STEP and len(data) == 6:
                rpm = data[0] | data[1] << 7 | data[2] << 14
                steps = data[3] | data[4] << 7
                if data[5]:
                    return Message(
                        "STEPPER_STEP {rpm} rpm, {steps} steps forward", rpm=rpm, steps=steps
                    )
                return Message(
                    "STEPPER_STEP {rpm} rpm, {steps} steps reverse", rpm=rpm, steps=steps
                )
            if sub == LIBRARY_VERSION:
                return _LIBRARY_VERSION_REQUEST
        return super().describe_sent(frame)

    def sent_command(self, frame: bytes) -> Command | None:
        """STEPPER_STEP moves X by its steps (at the steps per mm set); the rest moves nothing."""
        if frame[:3] != bytes((START, STEPPER_DATA, STEP)):
            return None
        data = frame[3:-1]
        if len(data) != 6 or frame[-1] != END:
            raise FrameError(
                Message("a STEPPER_STEP of {count} data bytes, not 6", count=len(data))
            )
        rpm = data[0] | data[1] << 7 | data[2] << 14
        steps = (data[3] | data[4] << 7) * (1 if data[5] else -1)
        per_mm = self.values["steps_per_mm"]
        speed = rpm * self.values["steps_per_rev"] / 60 / per_mm
        return MoveBy(steps / per_mm, 0.0, 0.0, speed=speed or None)

    def sent_kind(self, frame: bytes) -> str:
        """STEPPER_STEP is motion, STEPPER_CONFIGURE a setting, the requests queries."""
        if frame[:2] == bytes((START, STEPPER_DATA)) and len(frame) >= 3:
            return {STEP: "motion", CONFIGURE: "setting"}.get(frame[2], "query")
        return "query"

    def expects_reply(self, frame: bytes) -> bool:
        """Only the version, firmware-name and library-version requests are answered."""
        return self.sent_kind(frame) == "query"

    def exchange(self, command: Command) -> Exchange:
        """Identity: the firmware name; config and version: the library version reply."""
        if isinstance(command, GetId):
            return _Reply(command, "firmware", IDENTIFY_TIMEOUT)
        if isinstance(command, StepperVersion):
            return _Reply(command, "stepper_version")
        return NoReply(command)

    def command_name(self, command: Command) -> str:
        """What the board was asked, in Firmata's words."""
        return _COMMAND_NAMES.get(type(command), type(command).__name__)

    def move_timing(
        self, command: Command, start: Point, target: Point
    ) -> tuple[float, float] | None:
        """Steps at rpm × steps per revolution / 60 steps a second."""
        parts = self.expand(command) if isinstance(command, MoveBy) else [command]
        steps = [p for p in parts if isinstance(p, StepperStep)]
        if len(steps) < len(parts):
            return None
        spr = self.values["steps_per_rev"]
        return 0.0, sum(abs(p.steps) * 60 / (p.rpm * spr) for p in steps)
