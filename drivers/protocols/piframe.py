"""The Raspberry Pi motion frame (drivers/protocols/README.md §4): 25 bytes, big-endian, write-only.

`7B 7D`, action (0 Dwell, 1 Linear, 2 Circular, 3 SetHome), ten 16-bit fields X, Y, Z, speed X,
Y, Z, radius, angular speed, start angle, end angle, direction (1 byte), `2A`. X/Y/Z are signed
ticks from (0, 0, 0); speeds and the radius unsigned; angles in 0.01° (0..35999); angular speed in
0.01°/s; direction 0 CW, 1 CCW. Circular: X, Y the centre, Z the final Z. Dwell: ms in X.
The device answers nothing: positions are commanded, completion is estimated.
"""

from __future__ import annotations

import dataclasses
import math
import struct

from drivers.errors import BadInput, FrameError
from drivers.framers.fixed import FixedFramer
from drivers.messages import Message
from drivers.protocols.base import Exchange, Point, Protocol, Setting
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.commands import Arc, Command, Dwell, Home, MoveTo, Raw, SetHome
from drivers.protocols.events import Event, Feedback

HEADER = b"\x7b\x7d"
END = b"\x2a"
DWELL, LINEAR, CIRCULAR, SET_HOME = 0, 1, 2, 3
INT16 = (-32768, 32767)
UINT16 = (0, 65535)
ACTION_NAMES = {DWELL: "Dwell", LINEAR: "Linear", CIRCULAR: "Circular", SET_HOME: "SetHome"}
TICKS_PER_MM = Setting(
    "ticks_per_mm", "ticks/mm", 100.0, 0.001, 100000.0, Message("Encoder ticks per millimetre")
)
DEFAULT_SPEED = 10.0  # mm/s until the operator sets one

CAPABILITIES = Capabilities(
    axes=("x", "y", "z"),
    default_baud=115200,
    relative_moves=False,
    homing=False,
    speed_readback=False,
    default_speed=DEFAULT_SPEED,
    identity_queryable=False,
    position_feedback=False,
    completion=Completion.ESTIMATE,
    raw_text=False,
    raw_line_end="",
    speed_in_moves=True,
    dtr=True,  # the seed's set-up: "cocher la case DTR"
    arcs=True,
    dwell=True,
    home_note=Message("Moves back to (0, 0, 0) with a Linear frame: the device has no homing"),
    notes=(
        Message(
            "write-only: positions are commanded, completion estimated from distance and speed"
        ),
    ),
)

# The fields a refusal names, made once: every move checks its fields.
_SPEEDS = {axis: Message("speed {axis}", axis=axis) for axis in "XYZ"}
_CENTRE = {axis: Message("centre {axis}", axis=axis) for axis in "XY"}
_RADIUS = Message("radius")
_ANGULAR_SPEED = Message("angular speed")
_DWELL = Message("dwell")


class NoReply(Exchange):
    """The device answers nothing: the exchange is over once the frame is written."""

    def __init__(self, command: Command) -> None:
        super().__init__(command)
        self.finish()

    def handle(self, event: Event) -> bool:
        """Nothing belongs to it."""
        return False


def _field(value: float, name: str, bounds: tuple[int, int], unit: str) -> int:
    """A 16-bit field, never wrapped: BadInput naming the field and what fits."""
    number = round(value)
    if not bounds[0] <= number <= bounds[1]:
        raise BadInput(
            Message(
                "{field} {value:g} {unit} refused: a pi-frame field holds {low} to {high}",
                field=name,
                value=value,
                unit=unit,
                low=bounds[0],
                high=bounds[1],
            )
        )
    return number


class PiFrameProtocol(Protocol):
    """Writes 25-byte frames; keeps the commanded position in ticks."""

    name = "pi-frame"
    capabilities = CAPABILITIES
    settings = (TICKS_PER_MM,)

    def __init__(self, variant: str | None = None) -> None:
        super().__init__(variant)
        self.commanded = (0, 0, 0)
        """The position in ticks the last frame sent leads to."""
        self.configured()

    @property
    def ticks_per_mm(self) -> float:
        """The ticks-per-mm setting."""
        return self.values[TICKS_PER_MM.name]

    def configured(self) -> None:
        """Resolution, travel box and speed range follow the ticks per mm."""
        tpm = self.ticks_per_mm
        box = (INT16[0] / tpm, INT16[1] / tpm)
        self.capabilities = dataclasses.replace(
            CAPABILITIES,
            resolution=1 / tpm,
            travel=(box, box, box),
            speed_range=(1 / tpm, UINT16[1] / tpm),
        )

    def new_framer(self) -> FixedFramer:
        """25-byte frames (the device sends none; an echo would be framed like ours)."""
        return FixedFramer(HEADER, 22, END)

    def _ticks(self, mm: float, name: str) -> int:
        ticks = mm * self.ticks_per_mm
        if abs(ticks - round(ticks)) > 1e-6 * max(1.0, abs(ticks)):
            raise BadInput(
                Message(
                    "{field} {distance:g} mm refused: the device moves in ticks of {tick:g} mm "
                    "({per_mm:g} ticks/mm)",
                    field=name,
                    distance=mm,
                    tick=1 / self.ticks_per_mm,
                    per_mm=self.ticks_per_mm,
                )
            )
        if not INT16[0] <= round(ticks) <= INT16[1]:
            raise BadInput(
                Message(
                    "{field} {distance:g} mm refused: {ticks} ticks do not fit 16 bits "
                    "({low:g} to {high:g} mm at {per_mm:g} ticks/mm)",
                    field=name,
                    distance=mm,
                    ticks=round(ticks),
                    low=INT16[0] / self.ticks_per_mm,
                    high=INT16[1] / self.ticks_per_mm,
                    per_mm=self.ticks_per_mm,
                )
            )
        return round(ticks)

    def _linear_speeds(self, target: tuple[int, int, int], speed: float) -> tuple[int, ...]:
        """Per-axis speeds so that every axis arrives together at `speed` mm/s."""
        deltas = [t - c for t, c in zip(target, self.commanded, strict=True)]
        length = math.sqrt(sum(d * d for d in deltas))
        if length == 0:
            return (0, 0, 0)
        speeds = []
        for axis, delta in zip("XYZ", deltas, strict=True):
            wanted = speed * self.ticks_per_mm * abs(delta) / length
            value = max(1, math.ceil(wanted - 1e-9)) if delta else 0
            speeds.append(_field(value, _SPEEDS[axis], UINT16, "ticks/s"))
        return tuple(speeds)

    def frame(self, command: Command) -> bytes:
        """The 25 bytes for a typed command; BadInput for any field that does not fit."""
        fields = [0] * 10
        direction = 0
        if isinstance(command, MoveTo):
            action = LINEAR
            target = (
                self._ticks(command.x, "X"),
                self._ticks(command.y, "Y"),
                self._ticks(command.z, "Z"),
            )
            fields[0:3] = target
            fields[3:6] = self._linear_speeds(target, command.speed or DEFAULT_SPEED)
        elif isinstance(command, Home):
            return self.frame(MoveTo(0.0, 0.0, 0.0))
        elif isinstance(command, Arc):
            action, direction = CIRCULAR, 1 if command.ccw else 0
            fields[0] = self._ticks(command.cx, _CENTRE["X"])
            fields[1] = self._ticks(command.cy, _CENTRE["Y"])
            fields[2] = self._ticks(command.z, "Z")
            fields[6] = _field(command.radius * self.ticks_per_mm, _RADIUS, (1, UINT16[1]), "ticks")
            speed = command.speed or DEFAULT_SPEED
            angular = math.degrees(speed / command.radius) * 100
            fields[7] = _field(max(1, angular), _ANGULAR_SPEED, UINT16, "0.01°/s")
            seconds = command.sweep() / (fields[7] / 100)
            fields[5] = _field(
                abs(fields[2] - self.commanded[2]) / seconds, _SPEEDS["Z"], UINT16, "ticks/s"
            )
            fields[8] = round(command.start * 100) % 36000
            fields[9] = round(command.end * 100) % 36000
        elif isinstance(command, Dwell):
            action = DWELL
            fields[0] = _field(command.ms, _DWELL, UINT16, "ms")
        elif isinstance(command, SetHome):
            action = SET_HOME
        elif isinstance(command, Raw):
            return command.data
        else:
            raise BadInput(
                Message("pi-frame has no frame for {command}", command=type(command).__name__)
            )
        body = struct.pack(">B3h7HB", action, *fields, direction)
        return HEADER + body + END

    def encode(self, command: Command) -> bytes:
        """The frame's bytes."""
        return self.frame(command)

    def decode(self, frame: bytes) -> list[Event]:
        """The device sends nothing; a frame seen on the line (an echo) is named, not obeyed."""
        action = frame[2] if len(frame) > 2 else -1
        name = ACTION_NAMES.get(action) or Message("action {number}", number=action)
        return [Feedback("frame", frame, name)]

    def describe_sent(self, frame: bytes) -> str:
        """A frame's action and fields, e.g. `Linear X=100 Y=50 Z=0 ticks at 9/5/0 ticks/s`."""
        if len(frame) != 25:
            return Message("a {length}-byte frame", length=len(frame))
        action, x, y, z, sx, sy, sz, radius, angular, a0, a1, direction = struct.unpack(
            ">B3h7HB", frame[2:-1]
        )
        if action == LINEAR:
            return Message(
                "Linear X={x} Y={y} Z={z} ticks at {sx}/{sy}/{sz} ticks/s",
                x=x,
                y=y,
                z=z,
                sx=sx,
                sy=sy,
                sz=sz,
            )
        if action == CIRCULAR:
            return Message(
                "Circular centre ({x}, {y}) radius {radius} ticks, {start:g}° to {end:g}° "
                "{turn} at {speed:g}°/s, Z to {z}",
                x=x,
                y=y,
                radius=radius,
                start=a0 / 100,
                end=a1 / 100,
                turn="CCW" if direction else "CW",
                speed=angular / 100,
                z=z,
            )
        if action == DWELL:
            return Message("Dwell {ms} ms", ms=x & 0xFFFF)
        if action == SET_HOME:
            return "SetHome"
        return Message("action {number}", number=action)

    def sent_command(self, frame: bytes) -> Command | None:
        """Linear and Circular frames move, in mm at the ticks per mm set; Dwell and SetHome
        move nothing; any other action cannot be read."""
        if len(frame) != 25 or frame[:2] != HEADER or frame[-1:] != END:
            raise FrameError(Message("a {length}-byte frame", length=len(frame)))
        action, x, y, z, sx, sy, sz, radius, angular, a0, a1, direction = struct.unpack(
            ">B3h7HB", frame[2:-1]
        )
        tpm = self.ticks_per_mm
        if action == LINEAR:
            speed = math.sqrt(sx * sx + sy * sy + sz * sz) / tpm
            return MoveTo(x / tpm, y / tpm, z / tpm, speed or None)
        if action == CIRCULAR:
            return Arc(
                x / tpm,
                y / tpm,
                radius / tpm,
                a0 / 100,
                a1 / 100,
                bool(direction),
                z / tpm,
                math.radians(angular / 100) * radius / tpm or None,
            )
        if action in (DWELL, SET_HOME):
            return None
        raise FrameError(Message("action {number}", number=action))

    def sent_kind(self, frame: bytes) -> str:
        """Every action moves (or waits) but SetHome, a setting."""
        return "setting" if len(frame) == 25 and frame[2] == SET_HOME else "motion"

    def expects_reply(self, frame: bytes) -> bool:
        """The board answers nothing."""
        return False

    def exchange(self, command: Command) -> NoReply:
        """No reply ever comes."""
        return NoReply(command)

    def on_sent(self, command: Command) -> None:
        """Follow the commanded position."""
        if isinstance(command, (MoveTo, Home)):
            x, y, z = (
                (0.0, 0.0, 0.0) if isinstance(command, Home) else (command.x, command.y, command.z)
            )
            self.commanded = (self._ticks(x, "X"), self._ticks(y, "Y"), self._ticks(z, "Z"))
        elif isinstance(command, Arc):
            ex, ey = command.point(command.end)
            tpm = self.ticks_per_mm
            self.commanded = (round(ex * tpm), round(ey * tpm), self._ticks(command.z, "Z"))
        elif isinstance(command, SetHome):
            self.commanded = (0, 0, 0)

    def move_timing(self, command: Command, start: Point, target: Point) -> tuple[float, float]:
        """Linear: the slowest axis at its field speed; arcs: the sweep at the angular speed."""
        if isinstance(command, Home):
            command = MoveTo(0.0, 0.0, 0.0, getattr(command, "speed", None))
        if isinstance(command, MoveTo):
            fields = struct.unpack(">B3h7HB", self.frame(command)[2:-1])
            deltas = [t - c for t, c in zip(fields[1:4], self.commanded, strict=True)]
            speeds = fields[4:7]
            times = [abs(d) / s for d, s in zip(deltas, speeds, strict=True) if d]
            return 0.0, max(times, default=0.0)
        if isinstance(command, Arc):
            fields = struct.unpack(">B3h7HB", self.frame(command)[2:-1])
            return 0.0, command.sweep() / (fields[8] / 100)
        if isinstance(command, Dwell):
            return 0.0, command.ms / 1000
        return 0.0, 0.0
