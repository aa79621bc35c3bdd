"""`motionctl`: one command to a device from the shell, with stable exit codes."""

from __future__ import annotations

import argparse
import json
import logging
import sys
from collections.abc import Sequence
from contextlib import ExitStack
from typing import Any

from app.cli.command_line import (
    COMMANDS,
    PROTOCOL_CHOICES,
    UsageError,
    run_command,
    validate_offline,
)
from app.cli.count import CliCount
from app.cli.interrupt import MoveTracker, after_interrupt
from app.cli.log import decode_log
from app.cli.macro import find_macro, macro_offline, macro_text, run_macro
from app.cli.params import param_rows, param_table
from app.common.settings import (
    open_settings,
    read_parameters,
    read_protocol_settings,
    read_travel,
    write_parameters,
    write_protocol_settings,
)
from drivers.client import Client
from drivers.errors import BadInput, CommunicationError, DeviceError, MotionError, UnknownProtocol
from drivers.motion import Motion
from drivers.protocols.base import Protocol
from drivers.registry import create_protocol
from drivers.traffic import TrafficLogWriter
from drivers.transport import open_link
from drivers.travel import TravelLimits, parse_travel
from drivers.urlhandler.protocol_sim import with_sim_variant

log = logging.getLogger("motionctl")

EXIT_OK = 0
EXIT_DEVICE_ERROR = 1
EXIT_BAD_INPUT = 2
EXIT_NO_DEVICE = 3
EXIT_INTERRUPTED = 130  # Ctrl-C, as shells report it


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
    parser.add_argument(
        "--variant",
        help="the protocol's wire variant (visiomex: seed, prefixed, board12; default: the first)",
    )
    parser.add_argument("--baud", type=int, help="line speed (default: the protocol's)")
    parser.add_argument(
        "--timeout", type=float, default=2.0, help="seconds to wait for a reply (default 2)"
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    parser.add_argument("--log", metavar="FILE", help="append a hexdump of all traffic to FILE")
    parser.add_argument(
        "--travel",
        metavar="X0:X1,Y0:Y1,Z0:Z1",
        help="travel limits in mm for moves, or 'none' (default: those saved in the panel "
        "for this port, else the protocol's)",
    )
    parser.add_argument(
        "--clamp",
        action="store_true",
        help="a move beyond the travel limits goes to their edge instead of being refused",
    )
    parser.add_argument(
        "--ticks-per-mm",
        type=float,
        help="pi-frame: encoder ticks per mm (default: the panel's for this port, else 100)",
    )
    parser.add_argument(
        "--steps-per-mm",
        type=float,
        help="firmata: motor steps per mm (default: the panel's for this port, else 80)",
    )
    parser.add_argument(
        "--kind",
        default="linear",
        choices=("linear", "rotational", "steps"),
        help="jog: distances in mm (linear), degrees (rotational) or motor steps (visiomex)",
    )
    parser.add_argument(
        "--force",
        action="store_true",
        help="raw: send bytes the protocol cannot read even though travel limits are set "
        "(they cannot be checked against them)",
    )
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress on stderr")
    parser.add_argument("command", choices=COMMANDS, metavar="COMMAND", help=" | ".join(COMMANDS))
    parser.add_argument("args", nargs=argparse.REMAINDER, metavar="ARGS")
    return parser


def _text(result: dict[str, Any]) -> str:
    if {"macros", "exported", "imported", "macro"} & result.keys():
        return macro_text(result, _text)
    if "position" in result:
        return _position_text(result)
    if "id" in result:
        return str(result["id"] if result["id"] is not None else result["identity"])
    if "speed" in result:
        return f"{result['speed']:g} mm/s"
    if "min_speed" in result:
        return f"min {result['min_speed']:g} mm/s, max {result['max_speed']:g} mm/s"
    if "reply" in result:
        return "\n".join(result["reply"]) or "sent; the device answered nothing"
    if "configured" in result:
        done = result["configured"]
        pins = " ".join(str(p) for p in done["pins"])
        library = result["version"]
        return f"configured: {done['steps_per_rev']} steps/rev on pins {pins} (library {library})"
    if "text" in result:
        return "\n".join(result["text"])
    if "frames" in result:
        return (
            f"{result['executed']}/{result['instructions']} instructions executed in "
            f"{result['frames']} frames, {result['retransmissions']} retransmission(s), "
            f"{result['seconds']:.1f} s"
        )
    if "status" in result:
        status = result["status"]
        return f"queue {status['queue']}, {'moving' if status['moving'] else 'idle'}"
    if "messages" in result:
        count, seconds = result["messages"], result["seconds"]
        return f"{result['steps']} steps in {count} message(s), about {seconds:.1f} s"
    if "version" in result:
        return f"stepper library version {result['version']}"
    if "parameters" in result:
        return param_table(result["parameters"])
    if "written" in result:
        return "\n".join(
            f"{w['name']} = {w['value']:g} {w['unit']}".rstrip() for w in result["written"]
        )
    return "ok"


def _position_text(result: dict[str, Any]) -> str:
    """A position, with the jog in degrees or steps that led to it and what the firmware did."""
    lines = []
    jog = result.get("jog")
    if jog is not None:
        lines.append(f"jog X {jog['x']:g} Y {jog['y']:g} {jog['unit']}, packet {jog['packet']}")
    if "firmware_note" in result:
        lines.append(result["firmware_note"])
    if result["position"] is None:
        lines.append(result["position_note"])
    else:
        text = " ".join(f"{v:.2f}" for v in result["position"])
        if result.get("counted"):
            text += " (counted, not measured)"
        elif not result.get("measured", True):
            text += " (commanded, not measured)"
        lines.append(text)
    return "\n".join(lines)


def _travel(options: argparse.Namespace) -> TravelLimits | None:
    """The travel limits: --travel, else those the panel saved for this port."""
    if options.travel is not None:
        limits = parse_travel(options.travel)
    else:
        limits = read_travel(open_settings(), options.protocol, options.port)
    if limits is not None and options.clamp:
        limits = TravelLimits(limits.box, clamp=True)
    return limits


def _protocol_settings(options: argparse.Namespace, protocol: Protocol) -> dict[str, float]:
    """The protocol's settings: the options given, else those the panel saved for this port."""
    values = read_protocol_settings(open_settings(), protocol.name, options.port)
    given = {"ticks_per_mm": options.ticks_per_mm, "steps_per_mm": options.steps_per_mm}
    names = {s.name for s in protocol.settings}
    for name, value in given.items():
        if value is None:
            continue
        if name not in names:
            raise UsageError(f"--{name.replace('_', '-')} is not a {protocol.name} setting")
        values[name] = value
    return {name: value for name, value in values.items() if name in names}


def _keep_numbering(protocol: Protocol, settings: Any, options: argparse.Namespace) -> None:
    """The next frame number, for the next run to go on from (laser link)."""
    following = getattr(protocol, "sequence", None)
    if isinstance(following, int) and any(s.name == "next_sequence" for s in protocol.settings):
        values = {"next_sequence": float(following)}
        write_protocol_settings(settings, options.protocol, options.port, values)


def _join_travel(arguments: list[str]) -> list[str]:
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


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of motionctl; returns the exit status."""
    arguments = _join_travel(list(sys.argv[1:] if argv is None else argv))
    if arguments[:1] == ["bridge"]:  # `motionctl bridge --port DEVICE --protocol P ...`
        from app.cli.bridge import main as bridge_main

        return bridge_main(arguments[1:])
    parser = build_parser()
    try:
        options = parser.parse_args(arguments)
    except SystemExit as exc:
        if exc.code != 0 and "--json" in arguments:
            print(json.dumps({"error": "invalid command line (see the usage above)", "exit": 2}))
        return EXIT_OK if exc.code == 0 else EXIT_BAD_INPUT
    logging.basicConfig(
        level=logging.INFO if options.verbose else logging.WARNING,
        format="motionctl: %(message)s",
        stream=sys.stderr,
    )
    report = _Reporter(options.json)
    try:
        protocol = create_protocol(options.protocol, options.variant)
        protocol.configure(_protocol_settings(options, protocol))
        travel = _travel(options)
        if options.force and options.command != "raw":
            raise UsageError("--force is for raw only")
        validate_offline(
            options.command, options.args, protocol, travel, options.kind, options.force
        )
        if options.timeout <= 0:
            raise UsageError("--timeout must be positive")
        if options.baud is not None and options.baud <= 0:
            raise UsageError("--baud must be a positive number of bits per second")
    except (UsageError, BadInput, UnknownProtocol) as exc:
        return report.fail(exc, EXIT_BAD_INPUT)
    baud = options.baud or protocol.capabilities.default_baud
    settings = open_settings()
    last_written = read_parameters(settings, options.protocol, options.port)
    protocol.assume_parameters(last_written)
    if options.command == "param" and options.args[0] == "list":
        return report.done({"parameters": param_rows(protocol, last_written)})
    if options.command == "log":  # offline: no port is opened
        try:
            return report.done(decode_log(protocol, options.args))
        except BadInput as exc:
            return report.fail(exc, EXIT_BAD_INPUT)
    macro = None
    if options.command == "macro":  # all but `run` offline; `run` is checked whole first
        try:
            offline = macro_offline(settings, protocol, options.args)
            if offline is not None:
                return report.done(offline)
            macro = find_macro(settings, protocol, options.args[1])
        except BadInput as exc:
            return report.fail(exc, EXIT_BAD_INPUT)

    count = CliCount(settings, protocol, options.port)  # Visiomex: where the panel counted
    try:
        count.check(options.command, macro.steps if macro is not None else ())
    except BadInput as exc:
        return report.fail(exc, EXIT_BAD_INPUT)

    def remember(values: dict[str, float]) -> None:
        write_parameters(settings, options.protocol, options.port, values)

    motion: Motion | None = None  # (what Ctrl-C stops: see after_interrupt)
    moves = MoveTracker()
    with ExitStack() as stack:
        try:
            if options.log:
                stream = stack.enter_context(open(options.log, "a", encoding="utf-8"))
        except OSError as exc:
            return report.fail(f"cannot write the log {options.log}: {exc}", EXIT_BAD_INPUT)
        try:
            variant = protocol.variant.name if options.variant and protocol.variant else ""
            link = open_link(
                with_sim_variant(options.port, variant), baud, dtr=protocol.capabilities.dtr
            )
            stack.callback(link.close)
            stack.callback(_keep_numbering, protocol, settings, options)  # failed or not
            if options.log:
                link.listeners.append(TrafficLogWriter(stream))
            motion = Motion(Client(link, protocol, timeout=options.timeout))
            motion.travel = travel
            count.begin(motion)
            motion.notice_listeners.append(report.notice)
            motion.move_listeners.append(moves)
            if options.command != "config":
                motion.start()  # e.g. the saved Firmata config: the board reset when opened
            if macro is not None:
                result = run_macro(motion, macro)
            else:
                result = run_command(
                    motion, options.command, options.args, options.kind, remember, options.force
                )
            if options.command == "config":
                saved = {s.name: protocol.values[s.name] for s in protocol.settings}
                write_protocol_settings(settings, options.protocol, options.port, saved)
            count.done(motion, options.command, options.args, result)
        except BadInput as exc:
            count.failed(moves.last is not None)
            return report.fail(exc, EXIT_BAD_INPUT)
        except DeviceError as exc:
            count.failed(moves.last is not None)
            return report.fail(exc, EXIT_DEVICE_ERROR)
        except (CommunicationError, OSError) as exc:
            count.failed(moves.last is not None)
            return report.fail(exc, EXIT_NO_DEVICE)
        except MotionError as exc:
            count.failed(moves.last is not None)
            return report.fail(exc, EXIT_DEVICE_ERROR)
        except KeyboardInterrupt:  # the protocol's stop where it has one, else what goes on
            count.failed(moves.last is not None)
            return report.fail(after_interrupt(motion, options.command, moves), EXIT_INTERRUPTED)
    return report.done(result)


class _Reporter:
    """Tells the user about failures and notices: on stderr, and as JSON on stdout with --json."""

    def __init__(self, as_json: bool) -> None:
        self.as_json = as_json
        self.notices: list[str] = []

    def notice(self, text: str) -> None:
        """Something the user should know that is not a failure (e.g. a clamped move)."""
        self.notices.append(text)
        print(f"motionctl: {text}", file=sys.stderr)

    def done(self, result: dict[str, Any]) -> int:
        """Print the result (text, or one JSON object); returns EXIT_OK."""
        if self.as_json:
            if self.notices:
                result["notices"] = self.notices
            print(json.dumps(result))
        else:
            print(_text(result))
        return EXIT_OK

    def fail(self, problem: Exception | str, status: int) -> int:
        """Report a failure; returns the exit status."""
        message = str(problem).replace("\n", " ")
        print(f"motionctl: {message}", file=sys.stderr)
        if self.as_json:
            print(json.dumps({"error": message, "exit": status}))
        return status


if __name__ == "__main__":
    sys.exit(main())
