"""motionctl's command vocabulary, shared with macros: each command checked before the port is
opened, and carried out on a Motion."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from app.cli.devices import DEVICE_COMMANDS, check_device_offline, run_device
from app.cli.log import USAGE as LOG_USAGE
from app.cli.log import check_log_offline
from app.cli.params import check_param_offline, run_param
from app.cli.run_program import check_run_offline
from drivers.device import commands as cmd
from drivers.device.events import PositionReport
from drivers.device.guard import MotionGuard
from drivers.device.motion import KIND_UNITS, Motion
from drivers.device.position_count import firmware_move_mm, kind_note, no_identity
from drivers.device.travel import TravelLimits, check_resolution
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.numbers import parse_number
from drivers.protocols.registry import protocol_names
from drivers.traffic.records import RX, Traffic

PROTOCOL_CHOICES = tuple(protocol_names())  # the built-in protocols and the installed plugins'
COMMANDS = (
    "id", "position", "home", "set-home", "move", "jog", "speed", "limits", "check", "raw", "param",
    *DEVICE_COMMANDS, "log", "macro",
)  # fmt: skip
_ARITY = {
    "id": (0, 0), "position": (0, 0), "home": (0, 0), "set-home": (0, 0), "limits": (0, 0),
    "check": (0, 0), "move": (1, 3), "jog": (1, 3), "speed": (0, 1), "raw": (1, 1),
    "param": (1, 3), "log": (2, 4), "macro": (1, 2), **{name: (0, 20) for name in DEVICE_COMMANDS},
}  # fmt: skip
_USAGE = {
    "move": "move X Y [Z]",
    "jog": "jog DX DY [DZ]",
    "speed": "speed [VALUE]",
    "raw": "raw TEXT",
    "param": "param list | param set NAME|ID VALUE | param write FILE",
    "macro": "macro list | macro run NAME | macro import FILE | macro export FILE",
}
_PARAM_ARITY = {"list": 0, "set": 2, "write": 1}
_MACRO_ARITY = {"list": 0, "run": 1, "import": 1, "export": 1}


class UsageError(BadInput):
    """The command line itself is wrong (exit 2, nothing sent)."""


def usage_of(command: str) -> str:
    """How a command is typed, its arguments named (`move X Y [Z]`)."""
    if command in DEVICE_COMMANDS:
        return DEVICE_COMMANDS[command][1]
    if command == "log":
        return LOG_USAGE
    return _USAGE.get(command, command)


def check_arity(command: str, args: list[str]) -> None:
    """Refuse a command with the wrong number of arguments (UsageError)."""
    low, high = _ARITY[command]
    if not low <= len(args) <= high:
        raise UsageError(
            Message(
                "usage: {usage} (got {count} arguments)",
                usage=_USAGE.get(command, command),
                count=len(args),
            )
        )
    if command == "param" and _PARAM_ARITY.get(args[0]) != len(args) - 1:
        raise UsageError(Message("usage: {usage}", usage=_USAGE["param"]))
    if command == "macro" and _MACRO_ARITY.get(args[0]) != len(args) - 1:
        raise UsageError(Message("usage: {usage}", usage=_USAGE["macro"]))


def numbers(args: list[str], names: Sequence[str]) -> list[float]:
    """The arguments as numbers, named in any error; missing ones are 0."""
    values = [parse_number(text, name) for text, name in zip(args, names, strict=False)]
    return values + [0.0] * (3 - len(values))


def position_result(report: PositionReport) -> dict[str, Any]:
    """A position as motionctl reports it."""
    result: dict[str, Any] = {"position": [report.x, report.y, report.z]}
    if not report.measured:
        result["measured"] = False
    return result


def kind_jog(motion: Motion, dx: float, dy: float, dz: float, kind: str) -> dict[str, Any]:
    """A rotational or steps jog, reported in its own unit; where the firmware is known to
    read the digits as µm whatever the type letter, what it really moves, and the position
    that follows from it (not from degrees or steps)."""
    command = cmd.MoveBy(dx, dy, dz, kind)
    protocol = motion.client.protocol
    packet = protocol.encode(command)
    before = motion.last_position
    report = motion.move_by(dx, dy, dz, kind=kind)
    sent = {"x": dx, "y": dy, "unit": KIND_UNITS.get(kind, kind), "kind": kind}
    sent["packet"] = packet.decode("latin-1")
    moved = firmware_move_mm(protocol, packet)
    if moved is not None and before is not None and not report.measured:
        # Motion counted the move as the firmware makes it (µm digits, whole steps, the Y
        # loop): what the stage really moved is the difference, not the digits read as µm.
        moved = (report.x - before.x, report.y - before.y, report.z - before.z)
    result = {"jog": sent, **position_result(report)}
    if moved is not None:
        result["firmware_mm"] = list(moved)
        result["firmware_note"] = kind_note(kind, moved)
    return result


def run_command(
    motion: Motion,
    command: str,
    args: list[str],
    kind: str = "linear",
    remember: Any = None,
    force: bool = False,
) -> dict[str, Any]:
    """Carry out one motionctl command; returns the JSON-able result (`force`: `raw` bytes the
    protocol cannot read go even where a travel box is set)."""
    if command == "param":
        return run_param(motion, args, remember or (lambda values: None))
    if command in DEVICE_COMMANDS:
        return run_device(motion, command, args)
    if command == "id":
        if not motion.capabilities.identity_queryable:  # nothing to ask: no placeholder name
            return {"id": None, "identity": no_identity(motion.client.protocol)}
        return {"id": motion.identify()}
    if command == "position":
        return position_result(motion.position())
    if command == "home":
        return position_result(motion.home())
    if command == "set-home":
        motion.set_home()
        return {"ok": True}
    if command == "move":
        return position_result(motion.move_to(*numbers(args, ("x", "y", "z"))))
    if command == "jog":
        dx, dy, dz = numbers(args, ("dx", "dy", "dz"))
        if kind != "linear":
            return kind_jog(motion, dx, dy, dz, kind)
        return position_result(motion.move_by(dx, dy, dz))
    if command == "speed":
        if args:
            requested = parse_number(args[0], "speed")
            result: dict[str, Any] = {"speed": motion.set_speed(requested), "requested": requested}
        else:
            result = {"speed": motion.speed()}
        if motion.capabilities.speed_in_moves:
            result["in_moves"] = True  # the speed of the moves that follow, kept for the port
        return result
    if command == "limits":
        low, high = motion.speed_limits()
        return {"min_speed": low, "max_speed": high}
    if command == "check":
        motion.check()
        return {"errors": []}
    received: list[bytes] = []
    link = motion.client.link

    def keep(record: Traffic) -> None:
        if record.direction == RX:
            received.append(record.data)

    link.listeners.append(keep)
    try:
        motion.raw(args[0].encode("utf-8"), force)  # through the motion guard
    finally:
        link.listeners.remove(keep)
    text = b"".join(received).decode("ascii", errors="backslashreplace")
    return {"reply": text.splitlines()}


def validate_offline(
    command: str,
    args: list[str],
    protocol: Protocol,
    travel: TravelLimits | None,
    kind: str,
    force: bool = False,
) -> None:
    """Refuse what can be refused before the port is even opened."""
    check_arity(command, args)
    caps = protocol.capabilities
    if kind != "linear" and command != "jog":
        raise UsageError(
            Message("--kind {kind} refused: --kind is for jog only (move is in mm)", kind=kind)
        )
    if command in ("move", "jog") and len(args) < min(2, len(caps.axes)):
        axes = " ".join(a.upper() for a in caps.axes)
        raise UsageError(
            Message(
                "usage: {command} {axes} ({protocol} has {count} axes)",
                command=command,
                axes=axes,
                protocol=protocol.name,
                count=len(caps.axes),
            )
        )
    if kind not in caps.move_kinds and command == "jog":
        raise BadInput(
            Message(
                "--kind {kind} refused: {protocol} moves are {kinds}",
                kind=kind,
                protocol=protocol.name,
                kinds=", ".join(caps.move_kinds),
            )
        )
    if command == "move":
        x, y, z = numbers(args, ("x", "y", "z"))
        # A relative-only device is sent the distance from where this run starts: the origin.
        protocol.encode(cmd.MoveTo(x, y, z) if caps.absolute_moves else cmd.MoveBy(x, y, z))
        check_resolution((x, y, z), ("x", "y", "z"), caps.resolution)
        if travel is not None:
            travel.apply((x, y, z), Message("move to ({x:g}, {y:g}, {z:g}) mm", x=x, y=y, z=z))
    elif command == "jog":
        dx, dy, dz = numbers(args, ("dx", "dy", "dz"))
        # A device with absolute moves only is sent the target: checked here from the origin.
        protocol.encode(
            cmd.MoveBy(dx, dy, dz, kind) if caps.relative_moves else cmd.MoveTo(dx, dy, dz)
        )
        if kind == "linear":
            check_resolution((dx, dy, dz), ("dx", "dy", "dz"), caps.resolution)
    elif command == "speed" and args:
        speed = parse_number(args[0], "speed")
        if caps.speed_range is not None and not caps.speed_range[0] <= speed <= caps.speed_range[1]:
            low, high = caps.speed_range
            raise BadInput(
                Message(
                    "speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s",
                    speed=speed,
                    low=low,
                    high=high,
                )
            )
        if caps.speed_in_moves:  # nothing is sent: the speed goes with the moves that follow
            return
        for part in protocol.expand(cmd.SetSpeed(speed)):
            try:
                protocol.encode(part)
            except BadInput as exc:
                raise BadInput(
                    Message("speed {speed:g} mm/s refused ({error})", speed=speed, error=exc)
                ) from None
    elif command == "raw":
        frame = protocol.encode(cmd.Raw(args[0].encode("utf-8")))
        guard = MotionGuard(travel)
        move = guard.read_raw(protocol, frame, force)  # unreadable with a box: refused here
        if isinstance(move, cmd.MoveTo):  # like `move`: an absolute target is checked now
            target = (move.x, move.y, move.z)
            check_resolution(target, ("x", "y", "z"), caps.resolution)
            what = Message("raw move to ({x:g}, {y:g}, {z:g}) mm", x=move.x, y=move.y, z=move.z)
            guard.exact(target, what)
    elif command == "param":
        check_param_offline(protocol, args)
    elif command == "log":
        check_log_offline(args)
    elif command == "run":
        check_run_offline(protocol, args, travel)
    elif command in DEVICE_COMMANDS:
        check_device_offline(protocol, command, args)
