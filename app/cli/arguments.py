"""motionctl's command line: options before or after the command, and which commands need a
port or a protocol (those that need no device need no `--port`)."""

from __future__ import annotations

import argparse
from typing import Any

from app.cli.command_line import COMMANDS, PROTOCOL_CHOICES, UsageError
from drivers.messages import Message

_OFFLINE_MACRO = frozenset({"list", "import", "export"})


def _add_options(parser: argparse.ArgumentParser, after: bool) -> None:
    """motionctl's options; `after`: with no defaults, for those typed after the command."""
    default: dict[str, Any] = {"default": argparse.SUPPRESS} if after else {}
    parser.add_argument(
        "--port",
        help="device path, COM name or pyserial URL (sim://coxiris); not needed by log decode, "
        "param list, macro list|import|export",
        **default,
    )
    parser.add_argument(
        "--bench",
        metavar="FILE",
        help="a bench file (TOML, [devices.NAME] tables): the device's port, protocol and "
        "settings come from it",
        **default,
    )
    parser.add_argument(
        "--device", metavar="NAME", help="the bench's device to drive (--bench)", **default
    )
    parser.add_argument(
        "--protocol",
        choices=PROTOCOL_CHOICES,
        help="the device's protocol; log decode: the one the log's connection notes name, "
        "macro list: every protocol's macros, unless given",
        **default,
    )
    parser.add_argument(
        "--variant",
        help="the protocol's wire variant (visiomex: seed, prefixed, board12; default: the first)",
        **default,
    )
    parser.add_argument("--baud", type=int, help="line speed (default: the protocol's)", **default)
    parser.add_argument(
        "--timeout",
        type=float,
        help="seconds to wait for a reply (default 2)",
        **(default or {"default": 2.0}),
    )
    flag: dict[str, Any] = {"action": "store_true", **default}
    parser.add_argument("--json", help="print one JSON object on stdout", **flag)
    parser.add_argument(
        "--log", metavar="FILE", help="append a hexdump of all traffic to FILE", **default
    )
    parser.add_argument(
        "--travel",
        metavar="X0:X1,Y0:Y1,Z0:Z1",
        help="travel limits in mm for moves, or 'none' (default: those saved in the panel "
        "for this port, else the protocol's)",
        **default,
    )
    parser.add_argument(
        "--clamp",
        help="a move beyond the travel limits goes to their edge instead of being refused",
        **flag,
    )
    parser.add_argument(
        "--ticks-per-mm",
        type=float,
        help="pi-frame: encoder ticks per mm (default: the panel's for this port, else 100)",
        **default,
    )
    parser.add_argument(
        "--steps-per-mm",
        type=float,
        help="firmata: motor steps per mm (default: the panel's for this port, else 80)",
        **default,
    )
    parser.add_argument(
        "--kind",
        choices=("linear", "rotational", "steps"),
        help="jog: distances in mm (linear), degrees (rotational) or motor steps (the protocols "
        "with such moves: visiomex)",
        **(default or {"default": "linear"}),
    )
    parser.add_argument(
        "--force",
        help="raw: send bytes the protocol cannot read even though travel limits are set "
        "(they cannot be checked against them)",
        **flag,
    )
    parser.add_argument("-v", "--verbose", help="log progress on stderr", **flag)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for motionctl."""
    parser = argparse.ArgumentParser(
        prog="motionctl",
        description="Send one command to a stepper positioning device. Options may come before "
        "or after the command.",
        epilog="exit status: 0 ok, 1 device reported an error, 2 bad input (nothing sent), "
        "3 timeout, no device or port error, 130 interrupted (Ctrl-C)",
    )
    _add_options(parser, after=False)
    parser.add_argument("command", choices=COMMANDS, metavar="COMMAND", help=" | ".join(COMMANDS))
    parser.add_argument("args", nargs=argparse.REMAINDER, metavar="ARGS")
    return parser


def _after_parser() -> argparse.ArgumentParser:
    """motionctl's options alone, exactly as spelled (a command's own `--cw`, `--pins`,
    `--filter`... are not taken for an abbreviation of one)."""
    parser = argparse.ArgumentParser(prog="motionctl", allow_abbrev=False, add_help=False)
    _add_options(parser, after=True)
    return parser


def parse_command_line(arguments: list[str]) -> argparse.Namespace:
    """The options and the command; motionctl's options typed after the command
    (`log decode FILE --json`) are taken out of its arguments (SystemExit: refused)."""
    arguments = join_travel(arguments)
    options = build_parser().parse_args(arguments)
    if any(a.startswith("-") and not _number_like(a) for a in options.args):
        after, rest = _after_parser().parse_known_args(options.args, argparse.Namespace())
        for name, value in vars(after).items():
            setattr(options, name, value)
        options.args = rest
    return options


def _number_like(text: str) -> bool:
    """`-5`, `-.5`: a negative number, not an option."""
    return text[1:2].isdigit() or text[1:3].startswith(".")


def join_travel(arguments: list[str]) -> list[str]:
    """`--travel -50:50,...` as `--travel=-50:50,...` (argparse reads a leading - as an option)."""
    joined: list[str] = []
    index = 0
    while index < len(arguments):
        if arguments[index] == "--travel" and index + 1 < len(arguments):
            joined.append(f"--travel={arguments[index + 1]}")
            index += 2
        else:
            joined.append(arguments[index])
            index += 1
    return joined


def needs_port(command: str, args: list[str]) -> bool:
    """Whether the command talks to a device (the others read files and settings only)."""
    if command == "log":
        return False
    if command == "param":
        return args[:1] != ["list"]
    if command == "macro":
        return args[:1] not in ([], *([name] for name in _OFFLINE_MACRO))
    return True


def check_needs(options: argparse.Namespace) -> None:
    """Refuse (UsageError) a command without the --port or --protocol it needs."""
    command, args = options.command, options.args
    if options.force and command != "raw":
        raise UsageError(Message("--force is for raw only"))
    if options.port is None and needs_port(command, args):
        raise UsageError(Message("{command} needs --port (the device to talk to)", command=command))
    offline = command == "log" or (command == "macro" and args[:1] == ["list"])
    if options.protocol is None and not offline:
        raise UsageError(
            Message(
                "{command} needs --protocol ({choices})",
                command=command,
                choices=", ".join(PROTOCOL_CHOICES),
            )
        )
