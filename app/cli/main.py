"""`motionctl`: one command to a device from the shell, with stable exit codes."""

from __future__ import annotations

import argparse
import logging
import os
import sys
from collections.abc import Sequence
from contextlib import ExitStack
from typing import Any

from app.cli.arguments import build_parser, check_needs, join_travel, parse_command_line
from app.cli.bench_entry import at_bench_speed, bench_device
from app.cli.command_help import command_help, wants_help
from app.cli.command_line import UsageError, check_arity, run_command, validate_offline
from app.cli.count import CliCount
from app.cli.devices import check_stepper
from app.cli.interrupt import MoveTracker, after_interrupt
from app.cli.log import decode_log
from app.cli.macro import every_macro, find_macro, macro_offline, run_macro
from app.cli.params import param_rows
from app.cli.report import Reporter, log_to_stderr, usage_exit
from app.cli.saved_speed import SavedSpeed
from app.common.settings import (
    open_settings,
    read_parameters,
    read_protocol_settings,
    read_travel,
    write_parameters,
    write_protocol_settings,
)
from drivers.device.travel import TravelLimits, parse_travel
from drivers.errors import BadInput, CommunicationError, DeviceError, MotionError, UnknownProtocol
from drivers.protocols.base import Protocol
from drivers.protocols.registry import create_protocol
from drivers.session.bench import BenchDevice
from drivers.session.device_session import DeviceSession, open_device

log = logging.getLogger("motionctl")

EXIT_OK = 0
EXIT_DEVICE_ERROR = 1
EXIT_BAD_INPUT = 2
EXIT_NO_DEVICE = 3
EXIT_INTERRUPTED = 130  # Ctrl-C, as shells report it
EXIT_BROKEN_PIPE = 141  # the reader of the output went away (128 + SIGPIPE, as shells report)


__all__ = ["EXIT_BAD_INPUT", "EXIT_NO_DEVICE", "build_parser", "main"]


def _travel(options: argparse.Namespace) -> TravelLimits | None:
    """The travel limits: --travel, else those the panel saved for this port."""
    if options.travel is not None:
        limits = parse_travel(options.travel)
    elif options.port is None:  # a command that needs no device: no moves to check
        return None
    else:
        limits = read_travel(open_settings(), options.protocol, options.port)
    if limits is not None and options.clamp:
        limits = TravelLimits(limits.box, clamp=True)
    return limits


def _protocol_settings(
    options: argparse.Namespace, protocol: Protocol, bench: BenchDevice | None = None
) -> dict[str, float]:
    """The protocol's settings: the options given, else the bench's, else those the panel
    saved for this port."""
    values: dict[str, float] = {}
    if options.port is not None:
        values = read_protocol_settings(open_settings(), protocol.name, options.port)
    if bench is not None:
        values.update(bench.settings)
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


def _any_protocol(options: argparse.Namespace, report: Reporter) -> int:
    """The commands given no --protocol: log decode (by the log's connection notes), macro
    list (every protocol's macros)."""
    try:
        if options.command == "log":
            return report.done(decode_log(None, options.args))
        return report.done(every_macro(open_settings()))
    except BadInput as exc:
        return report.fail(exc, EXIT_BAD_INPUT)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of motionctl; returns the exit status (141 when whoever read its output
    went away, as `motionctl log decode F | head` does: quietly, as Unix tools do)."""
    try:
        status = _main(argv)
        sys.stdout.flush()  # a reader gone shows here, not at the interpreter's exit
        return status
    except BrokenPipeError:
        _quiet_closed_streams()
        return EXIT_BROKEN_PIPE


def _quiet_closed_streams() -> None:
    """Point stdout and stderr at /dev/null where their reader has gone, so that what is left in
    their buffers is not flushed into another BrokenPipeError at exit."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except OSError:
            try:
                devnull = os.open(os.devnull, os.O_WRONLY)
                os.dup2(devnull, stream.fileno())
                os.close(devnull)
            except (OSError, ValueError):  # no file descriptor (a test's captured stream)
                log.debug("cannot quiet %s", stream)


def _main(argv: Sequence[str] | None) -> int:
    arguments = join_travel(list(sys.argv[1:] if argv is None else argv))
    if arguments[:1] == ["bridge"]:  # `motionctl bridge --port DEVICE --protocol P ...`
        from app.cli.bridge import main as bridge_main

        return bridge_main(arguments[1:])
    try:
        options = parse_command_line(arguments)
    except SystemExit as exc:
        return usage_exit(exc, arguments)
    if wants_help(options.args):  # `motionctl macro --help`: that command's own help
        print(command_help(options.command), end="")
        return EXIT_OK
    log_to_stderr(options.verbose)
    report = Reporter(options.json)
    try:
        bench = bench_device(options, arguments)
        check_arity(options.command, options.args)
        check_needs(options)
    except (UsageError, BadInput) as exc:
        return report.fail(exc, EXIT_BAD_INPUT)
    if options.protocol is None:  # log decode: the log's notes name it; macro list: all
        return _any_protocol(options, report)
    try:
        protocol = create_protocol(options.protocol, options.variant)
        protocol.configure(_protocol_settings(options, protocol, bench))
        travel = _travel(options)
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
    last_written: dict[str, float] = {}  # (a command that needs no device may be given no port)
    if options.port is not None:
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
    speed = SavedSpeed(settings, protocol, options.port)  # pi-frame, Firmata, laser: moves' speed
    try:
        count.check(options.command, macro.steps if macro is not None else ())
        check_stepper(protocol, options.port, options.command, macro.steps if macro else ())
    except BadInput as exc:
        return report.fail(exc, EXIT_BAD_INPUT)

    def remember(values: dict[str, float]) -> None:
        write_parameters(settings, options.protocol, options.port, values)

    session: DeviceSession | None = None  # (what Ctrl-C stops: see after_interrupt)
    moves = MoveTracker()
    with ExitStack() as stack:
        try:
            if options.log:
                stream = stack.enter_context(open(options.log, "a", encoding="utf-8"))
        except OSError as exc:
            return report.fail(f"cannot write the log {options.log}: {exc}", EXIT_BAD_INPUT)
        try:
            session = stack.enter_context(
                open_device(
                    options.port,
                    protocol,
                    baud=baud,
                    timeout=options.timeout,
                    travel=travel,
                    log=stream if options.log else None,
                    start=False,
                )
            )
            stack.callback(_keep_numbering, protocol, settings, options)  # failed or not
            count.begin(session)
            speed.begin(session)
            session.on_notice(report.notice)
            session.on_move_started(moves)
            if options.command != "config":
                session.start()  # e.g. the saved Firmata config: the board reset when opened
                at_bench_speed(session, bench, options.command)
            if macro is not None:
                result = run_macro(session, macro)
            else:
                result = run_command(
                    session, options.command, options.args, options.kind, remember, options.force
                )
            if options.command == "config":
                saved = {s.name: protocol.values[s.name] for s in protocol.settings}
                write_protocol_settings(settings, options.protocol, options.port, saved)
            count.done(session, options.command, options.args, result)
            speed.done(session)
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
            return report.fail(after_interrupt(session, options.command, moves), EXIT_INTERRUPTED)
    return report.done(result)


if __name__ == "__main__":
    sys.exit(main())
