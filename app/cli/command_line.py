"""motionctl's command vocabulary: each command checked before the port is opened, and carried
out on a DeviceSession (the words macros share are in app/common/command_words.py)."""

from __future__ import annotations

from typing import Any

from app.cli.devices import DEVICE_COMMANDS, check_device_offline, run_device
from app.cli.log import USAGE as LOG_USAGE
from app.cli.log import check_log_offline
from app.cli.params import check_param_offline, run_param
from app.common.command_words import (
    WORD_ARITY,
    WORD_USAGE,
    UsageError,
    check_word_offline,
    kind_jog,
    numbers,
    position_result,
    run_word,
)
from drivers.device.travel import TravelLimits
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.registry import protocol_names
from drivers.session.device_session import DeviceSession

__all__ = [
    "COMMANDS",
    "PROTOCOL_CHOICES",
    "UsageError",
    "check_arity",
    "kind_jog",
    "numbers",
    "position_result",
    "run_command",
    "usage_of",
    "validate_offline",
]

PROTOCOL_CHOICES = tuple(protocol_names())  # the built-in protocols and the installed plugins'
COMMANDS = (
    "id", "position", "home", "set-home", "move", "jog", "speed", "limits", "check", "raw", "param",
    *DEVICE_COMMANDS, "log", "macro",
)  # fmt: skip
_ARITY = {**WORD_ARITY, "param": (1, 3), "log": (2, 4), "macro": (1, 2)}
_USAGE = {
    **WORD_USAGE,
    "param": "param list | param set NAME|ID VALUE | param write FILE",
    "macro": "macro list | macro run NAME | macro import FILE | macro export FILE",
}
_PARAM_ARITY = {"list": 0, "set": 2, "write": 1}
_MACRO_ARITY = {"list": 0, "run": 1, "import": 1, "export": 1}


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


def run_command(
    session: DeviceSession,
    command: str,
    args: list[str],
    kind: str = "linear",
    remember: Any = None,
    force: bool = False,
) -> dict[str, Any]:
    """Carry out one motionctl command; returns the JSON-able result (`force`: `raw` bytes the
    protocol cannot read go even where a travel box is set)."""
    if command == "param":
        return run_param(session, args, remember or (lambda values: None))
    if command in DEVICE_COMMANDS:
        return run_device(session, command, args)
    return run_word(session, command, args, kind, force)


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
    check_word_offline(command, args, protocol, travel, kind, force)
    if command == "param":
        check_param_offline(protocol, args)
    elif command == "log":
        check_log_offline(args)
    elif command == "run":  # the program readers (and numpy) only for a program
        from app.cli.run_program import check_run_offline

        check_run_offline(protocol, args, travel)
    elif command in DEVICE_COMMANDS:
        check_device_offline(protocol, command, args)
