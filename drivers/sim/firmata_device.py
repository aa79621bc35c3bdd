"""A FirmataPlus board (Arduino) driving one stepper, as PyMata sees it (drivers/protocols/README.md
§5)."""

from __future__ import annotations

import logging
from dataclasses import dataclass

from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice

log = logging.getLogger(__name__)

START_SYSEX = 0xF0
END_SYSEX = 0xF7
REPORT_VERSION = 0xF9
SYSTEM_RESET = 0xFF
STRING_DATA = 0x71
STEPPER_DATA = 0x72
REPORT_FIRMWARE = 0x79
CAPABILITY_QUERY = 0x6B
CAPABILITY_RESPONSE = 0x6C
ANALOG_MAPPING_QUERY = 0x69
ANALOG_MAPPING_RESPONSE = 0x6A
STEPPER_CONFIGURE, STEPPER_STEP, STEPPER_LIBRARY_VERSION = 0x00, 0x01, 0x02

FIRMATA_VERSION = (2, 5)
FIRMWARE_NAME = "FirmataPlus.ino"
STEPPER_LIBRARY = 5
RESET_DELAY = 2.0  # seconds the bootloader holds the board after the port opens
MAX_SYSEX = 64  # Firmata's MAX_DATA_BYTES: a longer SysEx is dropped
DIGITAL_PINS, ANALOG_PINS = 14, 6
PWM_PINS = frozenset({3, 5, 6, 9, 10, 11})
INPUT, OUTPUT, ANALOG, PWM = 0x00, 0x01, 0x02, 0x03

CONFIG_ERROR = "STEPPER CONFIG Error: Wrong Number of arguments"
NOT_CONFIGURED_ERROR = "STEPPER Error: not configured"
SPEED_ERROR = "STEPPER Error: speed must be positive"

# Data bytes that follow a channel or system command (Firmata's parser; others take none).
_DATA_BYTES = {0x90: 2, 0xE0: 2, 0xF4: 2, 0xF5: 2, 0xC0: 1, 0xD0: 1}


def two_byte_text(text: str) -> bytes:
    """Firmata's 7-bit encoding of text: each character as (c & 0x7F, c >> 7)."""
    out = bytearray()
    for char in text:
        code = ord(char)
        out += bytes((code & 0x7F, (code >> 7) & 0x7F))
    return bytes(out)


def string_data(text: str) -> bytes:
    """A STRING_DATA SysEx, as Firmata.sendString() sends it."""
    return bytes((START_SYSEX, STRING_DATA)) + two_byte_text(text) + bytes((END_SYSEX,))


def version_report() -> bytes:
    """`F9 02 05`."""
    return bytes((REPORT_VERSION, *FIRMATA_VERSION))


def firmware_report() -> bytes:
    """`F0 79 02 05 <name> F7`."""
    head = bytes((START_SYSEX, REPORT_FIRMWARE, *FIRMATA_VERSION))
    return head + two_byte_text(FIRMWARE_NAME) + bytes((END_SYSEX,))


def capability_response() -> bytes:
    """`F0 6C`, (mode, resolution) pairs then `7F` for each pin, `F7`."""
    out = bytearray((START_SYSEX, CAPABILITY_RESPONSE))
    for pin in range(DIGITAL_PINS + ANALOG_PINS):
        out += bytes((INPUT, 1, OUTPUT, 1))
        if pin in PWM_PINS:
            out += bytes((PWM, 8))
        if pin >= DIGITAL_PINS:
            out += bytes((ANALOG, 10))
        out.append(0x7F)
    out.append(END_SYSEX)
    return bytes(out)


def analog_mapping_response() -> bytes:
    """`F0 6A`, 7F for each digital pin, the analog channel of each analog pin, `F7`."""
    channels = bytes([0x7F] * DIGITAL_PINS + list(range(ANALOG_PINS)))
    return bytes((START_SYSEX, ANALOG_MAPPING_RESPONSE)) + channels + bytes((END_SYSEX,))


@dataclass
class _Move:
    """A blocking Stepper.step(): from `start` to `end` steps between `t0` and `t0 + duration`."""

    t0: float = 0.0
    duration: float = 0.0
    start: int = 0
    end: int = 0


class FirmataDevice(SimulatedDevice):
    """FirmataPlus on an Uno with one stepper; Stepper.step() blocks the whole sketch.

    `boot()` is the reset when the port opens: for `reset_delay` seconds bytes are lost, then the
    board announces itself. `instant` makes steps take no time; `mute` is a port with no board.
    Asserting DTR again (off, then on) resets the board the same way, through the Uno's
    auto-reset capacitor: the banner comes again and the stepper must be configured again; a
    step under way stops where the motor is. (Opening the port always resets it: the kernel
    asserts DTR when a tty opens, whatever DTR was asked for.)
    """

    protocol = "firmata"
    default_baud = 57600
    resets_on_open = True

    def __init__(
        self,
        clock: Clock = monotonic,
        baud: int | None = None,
        *,
        instant: bool = False,
        mute: bool = False,
        reset_delay: float = RESET_DELAY,
    ) -> None:
        super().__init__(clock, baud)
        self.instant = instant
        self.mute = mute
        self.reset_delay = reset_delay
        self.steps_per_revolution: int | None = None
        self.pins: tuple[int, ...] = ()
        self.ignored_messages = 0
        self._ready_at = 0.0
        self._sysex: bytearray | None = None
        self._waiting = 0
        self._move = _Move()
        self._step_end: float | None = None

    # -- accessors -------------------------------------------------------------------------
    @property
    def configured(self) -> bool:
        """Whether a stepper is configured (with a non-zero number of steps per revolution)."""
        return bool(self.steps_per_revolution)

    def steps(self, t: float | None = None) -> float:
        """The motor position in steps at `t` (default: now), linear in time during a move."""
        self._process(self.clock())
        return self._steps_at(self.clock() if t is None else t)

    def _steps_at(self, now: float) -> float:
        move = self._move
        if move.duration <= 0 or now >= move.t0 + move.duration:
            return float(move.end) if now >= move.t0 else float(move.start)
        if now <= move.t0:
            return float(move.start)
        return move.start + (move.end - move.start) * (now - move.t0) / move.duration

    # -- serial ----------------------------------------------------------------------------
    def wake_at(self) -> float | None:
        """The end of the step under way, so a server sees when the motor stops."""
        return self._step_end

    def tick(self, now: float) -> None:
        """Stepper.step() has returned."""
        self._step_end = None

    def power_cycle(self) -> None:
        """The port opened again: the Arduino resets and forgets its stepper."""
        self.steps_per_revolution = None
        self.pins = ()
        self._sysex = None
        self._waiting = 0
        self._step_end = None
        super().power_cycle()

    def dtr_reset(self, now: float) -> None:
        """DTR asserted: the Arduino resets; a step under way stops where the motor is."""
        here = round(self._steps_at(now))
        self._move = _Move(now, 0.0, here, here)
        super().dtr_reset(now)

    def boot(self) -> None:
        """The port opened: the Arduino resets, then Firmata.begin() reports version and name."""
        self._ready_at = self.clock() + self.reset_delay
        self.emit(version_report() + firmware_report(), self._ready_at)

    def emit(self, data: bytes, at: float) -> None:
        """Send `data` at `at`, unless there is no board."""
        if not self.mute:
            super().emit(data, at)

    def handle_byte(self, byte: int, t: float) -> None:
        """Firmata's parser: SysEx up to F7, commands with their data bytes, stray data skipped."""
        if self.mute or t < self._ready_at:
            return  # no board, or the bootloader is running: the byte is lost
        if self._sysex is not None:
            if byte == END_SYSEX:
                payload, self._sysex = bytes(self._sysex), None
                self._on_sysex(payload, t)
            else:
                self._sysex.append(byte)  # as in Firmata, even a status byte is stored
            return
        if byte < 0x80:
            if self._waiting:
                self._waiting -= 1  # pin and analog messages: no effect on the stepper
            else:
                self.ignored_messages += 1
            return
        self._waiting = 0
        if byte == START_SYSEX:
            self._sysex = bytearray()
        elif byte == REPORT_VERSION:
            self.emit(version_report(), t)
        elif byte == SYSTEM_RESET:
            log.debug("firmata: system reset (the stepper stays configured)")
        else:
            command = byte & 0xF0 if byte < 0xF0 else byte
            self._waiting = _DATA_BYTES.get(command, 0)

    # -- SysEx -----------------------------------------------------------------------------
    def _on_sysex(self, payload: bytes, t: float) -> None:
        if not payload or len(payload) > MAX_SYSEX:
            self.ignored_messages += 1
            return
        command, args = payload[0], payload[1:]
        if command == REPORT_FIRMWARE:
            self.emit(firmware_report(), t)
        elif command == CAPABILITY_QUERY:
            self.emit(capability_response(), t)
        elif command == ANALOG_MAPPING_QUERY:
            self.emit(analog_mapping_response(), t)
        elif command == STEPPER_DATA and args:
            self._stepper(args[0], args[1:], t)
        else:
            self.ignored_messages += 1
            log.debug("firmata: SysEx %s ignored", payload.hex(" "))

    def _stepper(self, sub: int, args: bytes, t: float) -> None:
        if sub == STEPPER_CONFIGURE:
            pins = args[2:]
            if len(args) < 2 or len(pins) not in (2, 4):
                self.emit(string_data(CONFIG_ERROR), t)
                return
            self.steps_per_revolution = args[0] | args[1] << 7
            self.pins = tuple(pins)
            log.debug("firmata: stepper %d steps/rev on pins %s", self.steps_per_revolution, pins)
        elif sub == STEPPER_STEP:
            if len(args) != 6:
                self.ignored_messages += 1
                return
            speed = args[0] | args[1] << 7 | args[2] << 14
            count = args[3] | args[4] << 7
            self._step(speed, count if args[5] else -count, t)
        elif sub == STEPPER_LIBRARY_VERSION:
            self.emit(bytes((START_SYSEX, STEPPER_DATA, STEPPER_LIBRARY, 0, END_SYSEX)), t)
        else:
            self.ignored_messages += 1

    def _step(self, speed: int, count: int, t: float) -> None:
        """Stepper.setSpeed(speed); Stepper.step(count): blocks until the last step."""
        if not self.steps_per_revolution:
            self.emit(string_data(NOT_CONFIGURED_ERROR), t)
            return
        if speed <= 0:
            self.emit(string_data(SPEED_ERROR), t)
            return
        start = self._move.end  # the previous step() has returned: it ended there
        duration = 0.0 if self.instant else abs(count) * 60 / (speed * self.steps_per_revolution)
        self._move = _Move(t, duration, start, start + count)
        self.busy_until = t + duration
        self._step_end = t + duration if duration > 0 else None
