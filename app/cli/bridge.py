"""`motionctl bridge --port DEVICE --protocol P`: sit between another program and a device.

    motionctl bridge --port DEVICE --protocol P [--variant V] [--baud N] [--log FILE] [--json] [-v]

Opens DEVICE (a path or any pyserial URL), offers a pseudo-terminal to another program and
forwards every byte both ways unchanged (drivers/bridge/snoop.py). `bridge` must be the first
argument;
the options are motionctl's global ones, with the same meaning.

stdout: the pty's path first, flushed (as `motionsim` prints its own), then one line per frame
as it crosses, decoded by the protocol's own decoders (`000001.039 TX  ...  GET_POSITION`, time in
seconds since the bridge started, TX from the program to the device, RX back). With `--json` the
first line is `{"path": "/dev/pts/N"}` and each frame is one JSON object per line with the keys
of `motionctl log decode --json`'s frames: time, direction, hex, meaning, kind; a failure is
`{"error": "...", "exit": N}`. `--log FILE` appends the traffic in the hexdump of every other
motionctl command (`#` lines say when the bridge started and ended), each record written and
flushed before its bytes are forwarded. Decoding and printing run on a thread of their own, so a
slow reader of stdout never delays the bytes (its lines queue up meanwhile).

Runs until SIGINT or SIGTERM (exit 0). A device port that cannot be opened, or that fails or
vanishes while bridging, exits 3 with one line on stderr; bad input (an unknown protocol or
variant, a bad --baud, an unwritable --log) exits 2 and opens nothing.
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import queue
import signal
import sys
import threading
import time
from collections.abc import Sequence
from contextlib import ExitStack
from types import FrameType
from typing import TextIO

from app.cli.report import log_to_stderr, plain_error, usage_exit
from drivers.bridge.snoop import Bridge
from drivers.errors import BadInput, CommunicationError, UnknownProtocol
from drivers.link.records import Traffic, TrafficLogWriter
from drivers.protocols.base import Protocol
from drivers.protocols.registry import create_protocol, protocol_names
from drivers.traffic.decoding import DecodedFrame, StreamDecoder
from drivers.traffic.log_reader import LogRecord

log = logging.getLogger("motionctl")

EXIT_OK = 0
EXIT_BAD_INPUT = 2
EXIT_NO_DEVICE = 3


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for `motionctl bridge`."""
    parser = argparse.ArgumentParser(
        prog="motionctl bridge",
        description="Offer a pseudo-terminal to another program and forward every byte between "
        "it and the device unchanged, printing each frame decoded. The first line on stdout is "
        "the pseudo-terminal's path; it runs until SIGINT or SIGTERM.",
        epilog="exit status: 0 stopped by a signal, 2 bad input (nothing opened), "
        "3 no device or the device vanished",
    )
    parser.add_argument("--port", required=True, help="the device: path or pyserial URL")
    parser.add_argument("--protocol", required=True, choices=protocol_names())
    parser.add_argument("--variant", help="the protocol's wire variant (visiomex)")
    parser.add_argument("--baud", type=int, help="line speed (default: the protocol's)")
    parser.add_argument("--json", action="store_true", help="one JSON object per line")
    parser.add_argument("--log", metavar="FILE", help="append a hexdump of all traffic to FILE")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress on stderr")
    return parser


class _Printer:
    """Decodes and prints the traffic on a thread of its own, in the order it crossed."""

    def __init__(self, protocol: Protocol, start: float, as_json: bool, out: TextIO) -> None:
        self.decoder = StreamDecoder(protocol)
        self.start = start
        self.as_json = as_json
        self.out = out
        self.queue: queue.SimpleQueue[Traffic | None] = queue.SimpleQueue()
        self.thread = threading.Thread(target=self._run, name="bridge-printer", daemon=True)
        self.broken = False

    def start_thread(self) -> None:
        """Start printing, with SIGINT and SIGTERM blocked in the printer's thread.

        A signal the kernel gave to that thread would leave the main thread asleep in `poll`
        with the Python handler (the bridge's stop) not run until the next byte crossed.
        """
        stops = {signal.SIGINT, signal.SIGTERM}
        previous = signal.pthread_sigmask(signal.SIG_BLOCK, stops)  # the thread inherits it
        try:
            self.thread.start()
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, previous)

    def put(self, record: Traffic) -> None:
        """Queue a record (called from the bridge's thread: never blocks)."""
        self.queue.put(record)

    def finish(self, timeout: float = 5.0) -> None:
        """Print what is queued, then stop (idempotent)."""
        if self.thread.is_alive():
            self.queue.put(None)
            self.thread.join(timeout)

    def _run(self) -> None:
        while (record := self.queue.get()) is not None:
            if not self.broken:
                self._print(record)

    def _print(self, record: Traffic) -> None:
        entry = LogRecord(record.time - self.start, record.direction, record.data)
        try:
            frames = self.decoder.feed(entry)
        except Exception:  # a decoder's bug must not stop the printing of what follows
            log.exception("decoding %s %s failed", record.direction, record.data.hex(" "))
            return
        try:
            for frame in frames:
                self.out.write(self._format(frame) + "\n")
            self.out.flush()
        except (OSError, ValueError) as exc:  # e.g. `| head` has quit
            self.broken = True
            log.warning("stdout is gone (%s): bridging on without printing", exc)
            _silence_stdout()

    def _format(self, frame: DecodedFrame) -> str:
        if not self.as_json:
            return frame.line()
        return json.dumps(frame.as_dict())


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that exiting does not complain about the broken pipe."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)
    except (OSError, ValueError):
        pass


def _fail(message: object, status: int, as_json: bool) -> int:
    text = plain_error(message)  # one prefix, each errno once
    print(f"motionctl: {text}", file=sys.stderr, flush=True)
    if as_json:
        print(json.dumps({"error": text, "exit": status}), flush=True)
    return status


def main(argv: Sequence[str]) -> int:
    """Entry point of `motionctl bridge` (ARGS after the word `bridge`); the exit status."""
    arguments = list(argv)
    try:
        options = build_parser().parse_args(arguments)
    except SystemExit as exc:
        return usage_exit(exc, arguments)
    log_to_stderr(options.verbose)
    as_json = options.json
    try:
        protocol = create_protocol(options.protocol, options.variant)
        if options.baud is not None and options.baud <= 0:
            raise BadInput("--baud must be a positive number of bits per second")
    except (BadInput, UnknownProtocol) as exc:
        return _fail(exc, EXIT_BAD_INPUT, as_json)
    start = time.monotonic()
    with ExitStack() as stack:
        writer: TrafficLogWriter | None = None
        if options.log:
            try:
                stream = stack.enter_context(open(options.log, "a", encoding="utf-8"))
            except OSError as exc:
                return _fail(f"cannot write the log {options.log}: {exc}", EXIT_BAD_INPUT, as_json)
            writer = TrafficLogWriter(stream, start)
        printer = _Printer(protocol, start, as_json, sys.stdout)

        def tap(record: Traffic) -> None:
            try:
                if writer is not None:
                    writer(record)  # on disk before the bytes go on
            finally:
                printer.put(record)  # shown even if the log fails (the bridge logs that)

        # Opened as a device session opens it: the protocol's baud and DTR unless given, a
        # sim:// device in the protocol's variant.
        bridge = Bridge(options.port, options.baud, tap, protocol=protocol)

        def stop(signum: int, frame: FrameType | None) -> None:
            bridge.stop()  # a stop before serve_forever makes it return at once

        previous = {sig: signal.signal(sig, stop) for sig in (signal.SIGINT, signal.SIGTERM)}
        for sig, handler in previous.items():
            stack.callback(signal.signal, sig, handler)
        try:
            bridge.open()
        except CommunicationError as exc:
            return _fail(exc, EXIT_NO_DEVICE, as_json)
        stack.callback(bridge.close)
        if writer is not None:
            writer.note(f"bridge {options.port} <-> {bridge.path} ({options.protocol})")
        print(json.dumps({"path": bridge.path}) if as_json else bridge.path, flush=True)
        printer.start_thread()
        stack.callback(printer.finish)
        try:
            bridge.serve_forever()
        except CommunicationError as exc:
            if writer is not None:
                writer.note(f"bridge ended: {exc}")
            printer.finish()
            return _fail(exc, EXIT_NO_DEVICE, as_json)
        if writer is not None:
            writer.note(
                f"bridge stopped: {bridge.bytes_to_device} bytes to the device, "
                f"{bridge.bytes_from_device} from it"
            )
        log.info(
            "stopped: %d bytes to the device, %d from it",
            bridge.bytes_to_device,
            bridge.bytes_from_device,
        )
    return EXIT_OK
