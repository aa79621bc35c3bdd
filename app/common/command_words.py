"""The command words motionctl and macros share: each checked before the port is opened, and
carried out on a DeviceSession (motionctl's own words, `param`, `log`, `macro`, `config`, `run`,
stay in app/cli)."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import Any

from drivers.device.guard import MotionGuard
from drivers.device.motion import KIND_UNITS
from drivers.device.position_count import kind_note, no_identity
from drivers.device.travel import TravelLimits, check_resolution
from drivers.errors import BadInput
from drivers.link.records import RX, Traffic
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.protocols.base import Protocol
from drivers.protocols.firmata import StepperVersion, step_parts
from drivers.protocols.laser.protocol import GetStatus
from drivers.protocols.numbers import parse_number
from drivers.protocols.visiomex.move_digits import firmware_move_mm
from drivers.session.device_session import DeviceSession

ANY_PROTOCOL = "*"  # a command every protocol has
RUN_USAGE = "run FILE [--layer NAME]... [--tolerance MM] [--svg-scale MM]"
DEVICE_COMMANDS = {
    "config": ("firmata", "config --steps-per-rev N --pins P1 P2 [P3 P4]"),
    "step": ("firmata", "step SPEED STEPS   (rpm; negative steps reverse)"),
    "version": ("firmata", "version"),
    "dwell": ("pi-frame", "dwell MS"),
    "arc": ("pi-frame", "arc CX CY RADIUS START END --cw|--ccw"),
    "status": ("laser-frame", "status"),
    "stop": ("laser-frame", "stop"),
    "run": (ANY_PROTOCOL, RUN_USAGE),
}
"""The commands of some devices: (the protocol that has it, or ANY_PROTOCOL; its usage)."""
WORDS = (
    "id", "position", "home", "set-home", "move", "jog", "speed", "limits", "check", "raw",
    "step", "version", "dwell", "arc", "status", "stop",
)  # fmt: skip
"""The words carried out here (`run_word`), a macro's steps among them."""
WORD_ARITY = {
    "id": (0, 0), "position": (0, 0), "home": (0, 0), "set-home": (0, 0), "limits": (0, 0),
    "check": (0, 0), "move": (1, 3), "jog": (1, 3), "speed": (0, 1), "raw": (1, 1),
    **{name: (0, 20) for name in DEVICE_COMMANDS},
}  # fmt: skip
"""How many arguments each word takes (fewest, most)."""
WORD_USAGE = {
    "move": "move X Y [Z]",
    "jog": "jog DX DY [DZ]",
    "speed": "speed [VALUE]",
    "raw": "raw TEXT",
}
"""How the words with arguments are typed (device commands: DEVICE_COMMANDS)."""


class UsageError(BadInput):
    """The command line itself is wrong (exit 2, nothing sent)."""


class DeviceUsageError(BadInput):
    """A device command's arguments are wrong (exit 2, nothing sent)."""


def check_word_arity(command: str, args: list[str]) -> None:
    """Refuse a word with the wrong number of arguments (UsageError)."""
    low, high = WORD_ARITY[command]
    if not low <= len(args) <= high:
        raise UsageError(
            Message(
                "usage: {usage} (got {count} arguments)",
                usage=WORD_USAGE.get(command, command),
                count=len(args),
            )
        )


def numbers(args: list[str], names: Sequence[str]) -> list[float]:
    """The arguments as numbers, named in any error; missing ones are 0."""
    values = [parse_number(text, name) for text, name in zip(args, names, strict=False)]
    return values + [0.0] * (3 - len(values))


def whole(text: str, what: str) -> int:
    """A whole number typed for `what` (DeviceUsageError otherwise)."""
    value = parse_number(text, what)
    if value != int(value):
        raise DeviceUsageError(
            Message("{what} {text!r} refused: a whole number is needed", what=what, text=text)
        )
    return int(value)


def arc_args(args: list[str]) -> cmd.Arc:
    """`arc CX CY RADIUS START END --cw|--ccw` read (DeviceUsageError: refused)."""
    directions = [a for a in args if a in ("--cw", "--ccw")]
    values = [a for a in args if a not in ("--cw", "--ccw")]
    if len(directions) != 1 or len(values) != 5:
        raise DeviceUsageError(Message("usage: {usage}", usage=DEVICE_COMMANDS["arc"][1]))
    names = ("centre X", "centre Y", "radius", "start angle", "end angle")
    cx, cy, radius, start, end = (parse_number(t, n) for t, n in zip(values, names, strict=True))
    if radius <= 0:
        raise DeviceUsageError(
            Message("radius {radius:g} mm refused: it must be above 0", radius=radius)
        )
    return cmd.Arc(cx, cy, radius, start, end, directions[0] == "--ccw")


def position_result(report: Any) -> dict[str, Any]:
    """A position (a PositionReport) as motionctl reports it."""
    result: dict[str, Any] = {"position": [report.x, report.y, report.z]}
    if not report.measured:
        result["measured"] = False
    return result


def kind_jog(session: DeviceSession, dx: float, dy: float, dz: float, kind: str) -> dict[str, Any]:
    """A rotational or steps jog, reported in its own unit; where the firmware is known to
    read the digits as µm whatever the type letter, what it really moves, and the position
    that follows from it (not from degrees or steps)."""
    protocol = session.protocol
    packet = protocol.encode(cmd.MoveBy(dx, dy, dz, kind))
    before = session.last_position
    report = session.move_by(dx, dy, dz, kind=kind)
    sent = {"x": dx, "y": dy, "unit": KIND_UNITS.get(kind, kind), "kind": kind}
    sent["packet"] = packet.decode("latin-1")
    moved = firmware_move_mm(protocol, packet)
    if moved is not None and before is not None and not report.measured:
        # The move was counted as the firmware makes it (µm digits, whole steps, the Y loop):
        # what the stage really moved is the difference, not the digits read as µm.
        moved = (report.x - before.x, report.y - before.y, report.z - before.z)
    result = {"jog": sent, **position_result(report)}
    if moved is not None:
        result["firmware_mm"] = list(moved)
        result["firmware_note"] = kind_note(kind, moved)
    return result


def run_word(
    session: DeviceSession, command: str, args: list[str], kind: str = "linear", force: bool = False
) -> dict[str, Any]:
    """Carry out one of WORDS; the JSON-able result (`force`: `raw` bytes the protocol cannot
    read go even where a travel box is set)."""
    if command in DEVICE_COMMANDS:
        return _run_device_word(session, command, args)
    if command == "id":
        if not session.capabilities.identity_queryable:  # nothing to ask: no placeholder name
            return {"id": None, "identity": no_identity(session.protocol)}
        return {"id": session.identify()}
    if command == "position":
        return position_result(session.position())
    if command == "home":
        return position_result(session.home())
    if command == "set-home":
        session.set_home()
        return {"ok": True}
    if command == "move":
        return position_result(session.move_to(*numbers(args, ("x", "y", "z"))))
    if command == "jog":
        dx, dy, dz = numbers(args, ("dx", "dy", "dz"))
        if kind != "linear":
            return kind_jog(session, dx, dy, dz, kind)
        return position_result(session.move_by(dx, dy, dz))
    if command == "speed":
        if args:
            requested = parse_number(args[0], "speed")
            result: dict[str, Any] = {"speed": session.speed(requested), "requested": requested}
        else:
            result = {"speed": session.speed()}
        if session.capabilities.speed_in_moves:
            result["in_moves"] = True  # the speed of the moves that follow, kept for the port
        return result
    if command == "limits":
        low, high = session.speed_limits()
        return {"min_speed": low, "max_speed": high}
    if command == "check":
        session.check()
        return {"errors": []}
    received: list[bytes] = []

    def keep(record: Traffic) -> None:
        if record.direction == RX:
            received.append(record.data)

    unsubscribe = session.on_traffic(keep)
    try:
        session.raw(args[0].encode("utf-8"), force)  # through the motion guard
    finally:
        unsubscribe()
    text = b"".join(received).decode("ascii", errors="backslashreplace")
    return {"reply": text.splitlines()}


def _run_device_word(session: DeviceSession, command: str, args: list[str]) -> dict[str, Any]:
    """step, version, dwell, arc, status, stop."""
    if command == "version":
        reply = session.send(StepperVersion())
        return {"version": int(str(reply.value if reply is not None else None))}
    if command == "step":
        parts = step_parts(whole(args[0], "speed (rpm)"), whole(args[1], "steps"))
        session.check_commands(parts)  # every message checked before the first is sent
        seconds = 0.0
        for index, part in enumerate(parts, start=1):
            session.send(part, reply=False)
            timing = session.protocol.move_timing(part, (0, 0, 0), (0, 0, 0)) or (0.0, 0.0)
            if len(parts) > 1:
                print(
                    f"motionctl: message {index}/{len(parts)}: {part.steps} steps", file=sys.stderr
                )
            if session.wait(sum(timing)):
                break
            seconds += sum(timing)
        return {"messages": len(parts), "steps": sum(p.steps for p in parts), "seconds": seconds}
    if command == "dwell":
        session.dwell(whole(args[0], "dwell (ms)") / 1000)
        return {"ok": True}
    if command == "status":
        reply = session.send(GetStatus())
        return {"status": reply.value if reply is not None else None}
    if command == "stop":
        session.stop()
        return {"ok": True}
    arc = arc_args(args)
    report = session.arc(arc.cx, arc.cy, arc.radius, arc.start, arc.end, ccw=arc.ccw)
    return {"position": [report.x, report.y, report.z], "measured": False}


def check_word_offline(
    command: str,
    args: list[str],
    protocol: Protocol,
    travel: TravelLimits | None,
    kind: str,
    force: bool = False,
) -> None:
    """Refuse what can be refused of one of WORDS before the port is even opened."""
    if command in WORD_ARITY:
        check_word_arity(command, args)
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
        _check_speed(protocol, parse_number(args[0], "speed"))
    elif command == "raw":
        frame = protocol.encode(cmd.Raw(args[0].encode("utf-8")))
        guard = MotionGuard(travel)
        move = guard.read_raw(protocol, frame, force)  # unreadable with a box: refused here
        if isinstance(move, cmd.MoveTo):  # like `move`: an absolute target is checked now
            target = (move.x, move.y, move.z)
            check_resolution(target, ("x", "y", "z"), caps.resolution)
            what = Message("raw move to ({x:g}, {y:g}, {z:g}) mm", x=move.x, y=move.y, z=move.z)
            guard.exact(target, what)
    elif command in DEVICE_COMMANDS:
        _check_device_word(protocol, command, args)


def _check_speed(protocol: Protocol, speed: float) -> None:
    """A speed outside the device's fixed range, or that the protocol cannot write: refused."""
    caps = protocol.capabilities
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


def _check_device_word(protocol: Protocol, command: str, args: list[str]) -> None:
    """Refuse a device word that is wrong before the port is opened (BadInput)."""
    owner, usage = DEVICE_COMMANDS[command]
    if owner not in (ANY_PROTOCOL, protocol.name):
        raise DeviceUsageError(
            Message(
                "'{command}' is a {owner} command, not {protocol}'s",
                command=command,
                owner=owner,
                protocol=protocol.name,
            )
        )
    if command == "step":
        if len(args) != 2:
            raise DeviceUsageError(Message("usage: {usage}", usage=usage))
        for part in step_parts(whole(args[0], "speed (rpm)"), whole(args[1], "steps")):
            protocol.encode(part)
    elif command == "version" and args:
        raise DeviceUsageError(Message("usage: {usage}", usage=usage))
    elif command == "dwell":
        if len(args) != 1:
            raise DeviceUsageError(Message("usage: {usage}", usage=usage))
        protocol.encode(cmd.Dwell(whole(args[0], "dwell (ms)")))
    elif command == "arc":
        protocol.encode(arc_args(args))
    elif command in ("status", "stop") and args:
        raise DeviceUsageError(Message("usage: {usage}", usage=usage))
