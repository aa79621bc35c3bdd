"""`motionctl`: one command to a device from the shell, with stable exit codes."""

from __future__ import annotations

import argparse
import json
import logging
import sys
from collections.abc import Sequence
from contextlib import ExitStack
from typing import Any

from drivers import commands as cmd
from drivers.client import Client
from drivers.errors import BadInput, CommunicationError, DeviceError, MotionError, UnknownProtocol
from drivers.events import PositionReport
from drivers.motion import Motion
from drivers.numbers import parse_number
from drivers.protocols.base import Protocol
from drivers.registry import create_protocol
from drivers.traffic import RX, Traffic, TrafficLogWriter
from drivers.transport import open_link

log = logging.getLogger("motionctl")

EXIT_OK = 0
EXIT_DEVICE_ERROR = 1
EXIT_BAD_INPUT = 2
EXIT_NO_DEVICE = 3
EXIT_INTERRUPTED = 130  # Ctrl-C, as shells report it

PROTOCOL_CHOICES = ("coxiris", "visiomex", "laser-frame", "pi-frame", "firmata")
COMMANDS = ("id", "position", "home", "set-home", "move", "jog", "speed", "limits", "check", "raw")
_ARITY = {
    "id": (0, 0), "position": (0, 0), "home": (0, 0), "set-home": (0, 0), "limits": (0, 0),
    "check": (0, 0), "move": (2, 3), "jog": (2, 3), "speed": (0, 1), "raw": (1, 1),
}  # fmt: skip
_USAGE = {
    "move": "move X Y [Z]",
    "jog": "jog DX DY [DZ]",
    "speed": "speed [VALUE]",
    "raw": "raw TEXT",
}


class UsageError(Exception):
    """The command line itself is wrong (exit 2, nothing sent)."""


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for motionctl."""
    parser = argparse.ArgumentParser(
        prog="motionctl",
        description="Send one command to a stepper positioning device.",
        epilog="exit status: 0 ok, 1 device reported an error, 2 bad input (nothing sent), "
        "3 timeout, no device or port error",
    )
    parser.add_argument(
        "--port", required=True, help="device path, COM name or pyserial URL (sim://coxiris)"
    )
    parser.add_argument("--protocol", required=True, choices=PROTOCOL_CHOICES)
    parser.add_argument("--baud", type=int, help="line speed (default: the protocol's)")
    parser.add_argument(
        "--timeout", type=float, default=2.0, help="seconds to wait for a reply (default 2)"
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    parser.add_argument("--log", metavar="FILE", help="append a hexdump of all traffic to FILE")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress on stderr")
    parser.add_argument("command", choices=COMMANDS, metavar="COMMAND", help=" | ".join(COMMANDS))
    parser.add_argument("args", nargs=argparse.REMAINDER, metavar="ARGS")
    return parser


def _check_arity(command: str, args: list[str]) -> None:
    low, high = _ARITY[command]
    if not low <= len(args) <= high:
        raise UsageError(f"usage: {_USAGE.get(command, command)} (got {len(args)} arguments)")


def _numbers(args: list[str], names: Sequence[str]) -> list[float]:
    values = [parse_number(text, name) for text, name in zip(args, names, strict=False)]
    return values + [0.0] * (3 - len(values))


def _position(report: PositionReport) -> dict[str, Any]:
    result: dict[str, Any] = {"position": [report.x, report.y, report.z]}
    if not report.measured:
        result["measured"] = False
    return result


def _text(result: dict[str, Any]) -> str:
    if "position" in result:
        text = " ".join(f"{v:.2f}" for v in result["position"])
        return text if result.get("measured", True) else text + " (commanded, not measured)"
    if "id" in result:
        return str(result["id"])
    if "speed" in result:
        return f"{result['speed']:g} mm/s"
    if "min_speed" in result:
        return f"min {result['min_speed']:g} mm/s, max {result['max_speed']:g} mm/s"
    if "reply" in result:
        return "\n".join(result["reply"])
    return "ok"


def run_command(motion: Motion, command: str, args: list[str]) -> dict[str, Any]:
    """Carry out one motionctl command; returns the JSON-able result."""
    if command == "id":
        return {"id": motion.identify()}
    if command == "position":
        return _position(motion.position())
    if command == "home":
        return _position(motion.home())
    if command == "set-home":
        motion.set_home()
        return {"ok": True}
    if command == "move":
        return _position(motion.move_to(*_numbers(args, ("x", "y", "z"))))
    if command == "jog":
        return _position(motion.move_by(*_numbers(args, ("dx", "dy", "dz"))))
    if command == "speed":
        if args:
            requested = parse_number(args[0], "speed")
            return {"speed": motion.set_speed(requested), "requested": requested}
        return {"speed": motion.speed()}
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
        motion.raw(args[0].encode("utf-8"))
    finally:
        link.listeners.remove(keep)
    text = b"".join(received).decode("ascii", errors="backslashreplace")
    return {"reply": text.splitlines()}


def _validate_offline(command: str, args: list[str], protocol: Protocol) -> None:
    """Refuse what can be refused before the port is even opened."""
    _check_arity(command, args)
    if command == "move":
        protocol.encode(cmd.MoveTo(*_numbers(args, ("x", "y", "z"))))
    elif command == "jog":
        protocol.encode(cmd.MoveBy(*_numbers(args, ("dx", "dy", "dz"))))
    elif command == "speed" and args:
        protocol.encode(cmd.SetSpeed(parse_number(args[0], "speed")))
    elif command == "raw":
        protocol.encode(cmd.Raw(args[0].encode("utf-8")))


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of motionctl; returns the exit status."""
    parser = build_parser()
    try:
        options = parser.parse_args(argv)
    except SystemExit as exc:
        return EXIT_OK if exc.code == 0 else EXIT_BAD_INPUT
    logging.basicConfig(
        level=logging.INFO if options.verbose else logging.WARNING,
        format="motionctl: %(message)s",
        stream=sys.stderr,
    )
    try:
        protocol = create_protocol(options.protocol)
        _validate_offline(options.command, options.args, protocol)
        if options.timeout <= 0:
            raise UsageError("--timeout must be positive")
    except (UsageError, BadInput, UnknownProtocol) as exc:
        print(f"motionctl: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    baud = options.baud or protocol.capabilities.default_baud
    if options.baud is not None and options.baud <= 0:
        return _fail(UsageError("--baud must be a positive number of bits per second"), 2)
    with ExitStack() as stack:
        try:
            if options.log:
                stream = stack.enter_context(open(options.log, "a", encoding="utf-8"))
        except OSError as exc:
            return _fail(UsageError(f"cannot write the log {options.log}: {exc}"), EXIT_BAD_INPUT)
        try:
            link = open_link(options.port, baud)
            stack.callback(link.close)
            if options.log:
                link.listeners.append(TrafficLogWriter(stream))
            motion = Motion(Client(link, protocol, timeout=options.timeout))
            result = run_command(motion, options.command, options.args)
        except BadInput as exc:
            return _fail(exc, EXIT_BAD_INPUT)
        except DeviceError as exc:
            return _fail(exc, EXIT_DEVICE_ERROR)
        except (CommunicationError, OSError) as exc:
            return _fail(exc, EXIT_NO_DEVICE)
        except MotionError as exc:
            return _fail(exc, EXIT_DEVICE_ERROR)
        except KeyboardInterrupt:
            return _fail(
                UsageError("interrupted; the device may still be moving"), EXIT_INTERRUPTED
            )
    if options.json:
        print(json.dumps(result))
    else:
        print(_text(result))
    return EXIT_OK


def _fail(exc: Exception, status: int) -> int:
    message = str(exc).replace("\n", " ")
    print(f"motionctl: {message}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main())
