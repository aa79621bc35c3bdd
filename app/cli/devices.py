"""motionctl commands of some devices: Firmata config, step, version; pi-frame dwell, arc;
laser-frame status, stop; and `run` (app/cli/run_program.py), which every device has."""

from __future__ import annotations

from typing import Any

from app.common.command_words import (
    ANY_PROTOCOL,
    DEVICE_COMMANDS,
    DeviceUsageError,
    check_word_offline,
    run_word,
    whole,
)
from app.common.stepper_config import configure_stepper
from drivers.device.travel import TravelLimits
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.firmata import FirmataProtocol, StepperConfig
from drivers.session.device_session import DeviceSession

__all__ = ["ANY_PROTOCOL", "DEVICE_COMMANDS", "DeviceUsageError", "NotConfigured", "check_stepper"]


# The commands that step a Firmata board's motor (a macro's steps included).
_STEPPING = frozenset({"move", "jog", "home", "step", "run"})


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


def _config_args(args: list[str]) -> tuple[int, tuple[int, ...]]:
    steps_per_rev: int | None = None
    pins: list[int] = []
    index = 0
    while index < len(args):
        if args[index] == "--steps-per-rev" and index + 1 < len(args):
            steps_per_rev = whole(args[index + 1], "steps per revolution")
            index += 2
        elif args[index] == "--pins":
            index += 1
            while index < len(args) and not args[index].startswith("--"):
                pins.append(whole(args[index], "pin"))
                index += 1
        else:
            raise DeviceUsageError(f"usage: {DEVICE_COMMANDS['config'][1]} (got {args[index]!r})")
    if steps_per_rev is None or not pins:
        raise DeviceUsageError(f"usage: {DEVICE_COMMANDS['config'][1]}")
    return steps_per_rev, tuple(pins)


def check_device_offline(
    protocol: Protocol, command: str, args: list[str], travel: TravelLimits | None = None
) -> None:
    """Refuse a device command that is wrong before the port is opened (BadInput)."""
    check_word_offline(command, args, protocol, travel, "linear")
    if command == "config":
        steps_per_rev, pins = _config_args(args)
        protocol.encode(StepperConfig(steps_per_rev, pins))


def run_device(session: DeviceSession, command: str, args: list[str]) -> dict[str, Any]:
    """Carry out a device command; returns the JSON-able result."""
    if command == "config":
        steps_per_rev, pins = _config_args(args)
        version = configure_stepper(session, steps_per_rev, pins)
        return {
            "configured": {"steps_per_rev": steps_per_rev, "pins": list(pins)},
            "version": version,
        }
    if command == "run":  # the program readers (and numpy) only for a program
        from app.cli.run_program import run_program

        return run_program(session, args)
    return run_word(session, command, args)
