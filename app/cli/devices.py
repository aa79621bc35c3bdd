"""motionctl commands of some devices: Firmata config, step, version; pi-frame dwell, arc;
laser-frame status, stop; and `run` (app/cli/run_program.py), which every device has."""

from __future__ import annotations

import logging
import sys
from typing import Any

from app.cli.run_program import RUN_USAGE, run_program
from drivers.device import commands as cmd
from drivers.device.motion import Motion
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.firmata import (
    FirmataProtocol,
    StepperConfig,
    StepperStep,
    StepperVersion,
    configure_stepper,
    step_parts,
)
from drivers.protocols.laser.protocol import GetStatus
from drivers.protocols.numbers import parse_number

log = logging.getLogger(__name__)

ANY_PROTOCOL = "*"  # a command every protocol has
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


# The commands that step a Firmata board's motor (a macro's steps included).
_STEPPING = frozenset({"move", "jog", "home", "step", "run"})


class DeviceUsageError(BadInput):
    """A device command's arguments are wrong (exit 2, nothing sent)."""


class NotConfigured(BadInput):
    """A Firmata motor move where no stepper config is kept for the port (exit 2)."""


def check_stepper(protocol: Protocol, port: str, command: str, steps: tuple[str, ...]) -> None:
    """Refuse (NotConfigured) a command that steps a Firmata motor where no stepper config is
    kept for the port: the board, reset as the port opens, answers each step 'not configured'.
    A config kept (motionctl config, or the panel's Stepper setup) is sent at the start of
    every run, as the panel sends it at each connection."""
    if not isinstance(protocol, FirmataProtocol) or protocol.pins():
        return
    for name in (command, *(step.split(" ", 1)[0].lower() for step in steps)):
        if name in _STEPPING:
            raise NotConfigured(
                Message(
                    "{command} refused: the stepper is not configured for {port} (the board "
                    "forgets it at each reset, and none is kept for this port); run "
                    "motionctl --port {port} --protocol firmata config --steps-per-rev 200 "
                    "--pins 8 9 with your motor's steps per revolution and pins (or Configure "
                    "in the panel's Stepper setup): it is kept and sent again at each run",
                    command=name,
                    port=port,
                )
            )


def _whole(text: str, what: str) -> int:
    value = parse_number(text, what)
    if value != int(value):
        raise DeviceUsageError(f"{what} {text!r} refused: a whole number is needed")
    return int(value)


def _config_args(args: list[str]) -> tuple[int, tuple[int, ...]]:
    steps_per_rev: int | None = None
    pins: list[int] = []
    index = 0
    while index < len(args):
        if args[index] == "--steps-per-rev" and index + 1 < len(args):
            steps_per_rev = _whole(args[index + 1], "steps per revolution")
            index += 2
        elif args[index] == "--pins":
            index += 1
            while index < len(args) and not args[index].startswith("--"):
                pins.append(_whole(args[index], "pin"))
                index += 1
        else:
            raise DeviceUsageError(f"usage: {DEVICE_COMMANDS['config'][1]} (got {args[index]!r})")
    if steps_per_rev is None or not pins:
        raise DeviceUsageError(f"usage: {DEVICE_COMMANDS['config'][1]}")
    return steps_per_rev, tuple(pins)


def _arc(args: list[str]) -> cmd.Arc:
    directions = [a for a in args if a in ("--cw", "--ccw")]
    numbers = [a for a in args if a not in ("--cw", "--ccw")]
    if len(directions) != 1 or len(numbers) != 5:
        raise DeviceUsageError(f"usage: {DEVICE_COMMANDS['arc'][1]}")
    names = ("centre X", "centre Y", "radius", "start angle", "end angle")
    cx, cy, radius, start, end = (parse_number(t, n) for t, n in zip(numbers, names, strict=True))
    if radius <= 0:
        raise DeviceUsageError(f"radius {radius:g} mm refused: it must be above 0")
    return cmd.Arc(cx, cy, radius, start, end, directions[0] == "--ccw")


def check_device_offline(protocol: Protocol, command: str, args: list[str]) -> None:
    """Refuse a device command that is wrong before the port is opened (BadInput)."""
    owner, usage = DEVICE_COMMANDS[command]
    if owner not in (ANY_PROTOCOL, protocol.name):
        raise DeviceUsageError(f"'{command}' is a {owner} command, not {protocol.name}'s")
    if command == "config":
        steps_per_rev, pins = _config_args(args)
        protocol.encode(StepperConfig(steps_per_rev, pins))
    elif command == "step":
        if len(args) != 2:
            raise DeviceUsageError(f"usage: {usage}")
        for part in step_parts(_whole(args[0], "speed (rpm)"), _whole(args[1], "steps")):
            protocol.encode(part)
    elif command == "version" and args:
        raise DeviceUsageError(f"usage: {usage}")
    elif command == "dwell":
        if len(args) != 1:
            raise DeviceUsageError(f"usage: {usage}")
        protocol.encode(cmd.Dwell(_whole(args[0], "dwell (ms)")))
    elif command == "arc":
        protocol.encode(_arc(args))
    elif command in ("status", "stop") and args:
        raise DeviceUsageError(f"usage: {usage}")


def run_device(motion: Motion, command: str, args: list[str]) -> dict[str, Any]:
    """Carry out a device command; returns the JSON-able result."""
    client = motion.client
    if command == "config":
        steps_per_rev, pins = _config_args(args)
        version = configure_stepper(client, steps_per_rev, pins)
        return {
            "configured": {"steps_per_rev": steps_per_rev, "pins": list(pins)},
            "version": version,
        }
    if command == "version":
        return {"version": int(str(client.execute(StepperVersion()).value))}
    if command == "step":
        parts = step_parts(_whole(args[0], "speed (rpm)"), _whole(args[1], "steps"))
        _guard_steps(motion, parts)
        seconds = 0.0
        for index, part in enumerate(parts, start=1):
            client.send_only(part)
            timing = client.protocol.move_timing(part, (0, 0, 0), (0, 0, 0)) or (0.0, 0.0)
            if len(parts) > 1:
                print(
                    f"motionctl: message {index}/{len(parts)}: {part.steps} steps", file=sys.stderr
                )
            if motion.wait(sum(timing)):
                break
            seconds += sum(timing)
        return {"messages": len(parts), "steps": sum(p.steps for p in parts), "seconds": seconds}
    if command == "dwell":
        motion.dwell(_whole(args[0], "dwell (ms)"))
        return {"ok": True}
    if command == "status":
        return {"status": client.execute(GetStatus()).value}
    if command == "stop":
        client.execute(cmd.Stop())
        return {"ok": True}
    if command == "run":
        return run_program(motion, args)
    report = motion.arc(_arc(args))
    return {"position": [report.x, report.y, report.z], "measured": False}


def _guard_steps(motion: Motion, parts: list[StepperStep]) -> None:
    """Pass every step message through the motion guard before the first is sent: read back
    with the protocol's decoder, each is checked from where the one before it ends."""
    protocol = motion.client.protocol
    here = motion.position()
    start = (here.x, here.y, here.z)
    for part in parts:
        move = motion.guard.read_raw(protocol, protocol.encode(part))
        if move is not None:
            planned = motion.guard.raw_move(
                protocol, move, start, motion.capabilities.resolution, log.warning
            )
            start = planned.target
