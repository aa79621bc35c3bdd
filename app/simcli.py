"""`motionsim`: a simulated device on a pseudo-terminal; prints the device path first."""

from __future__ import annotations

import argparse
import logging
import signal
import sys
import threading
from collections.abc import Sequence
from types import FrameType

from drivers.errors import UnknownProtocol
from drivers.link.records import TrafficLogWriter
from drivers.protocols.registry import create_protocol, entries, has_variants
from drivers.sim.faults import FAULT_COMMANDS, FaultError, FaultyDevice
from drivers.sim.pty_server import PtyServer
from drivers.sim.registry import create_device, simulator_names
from drivers.traffic.log_origin import device_side_note

log = logging.getLogger("motionsim")

_LASER_OPTIONS = ("corrupt", "drop", "drop_reply", "delay_reply", "garbage", "seed", "queue")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for motionsim."""
    parser = argparse.ArgumentParser(
        prog="motionsim",
        description="Serve a simulated positioning device on a pseudo-terminal. The first line "
        "on stdout is the device path; it serves until SIGTERM or SIGINT.",
    )
    simulated = [entry for entry in entries() if entry.name in simulator_names()]
    parser.add_argument(
        "protocol",
        help="one of: " + "; ".join(f"{e.name} ({e.description})" for e in simulated),
    )
    parser.add_argument("--baud", type=int, help="line rate to emulate (default: the device's)")
    parser.add_argument(
        "--no-line-timing",
        action="store_true",
        help="deliver bytes at once instead of at the baud rate",
    )
    parser.add_argument(
        "--non-blocking",
        action="store_true",
        help="COXIRIS: answer DONE when a move starts, not when it ends",
    )
    parser.add_argument(
        "--variant",
        choices=list(dict.fromkeys(v for e in simulated for v in e.variants)),
        help="the protocol's wire variant, "
        + "; ".join(f"{e.name}: {', '.join(e.variants)}" for e in simulated if e.variants)
        + " (default: the first)",
    )
    parser.add_argument(
        "--no-bugs",
        action="store_true",
        help="Visiomex: the documented firmware instead of the public one's bugs",
    )
    parser.add_argument(
        "--pace",
        choices=("recorded", "uart"),
        help="Visiomex: send a byte every 1.06 byte times like the recorded firmware "
        "(recorded, the default) or at the board UART's line rate (uart)",
    )
    parser.add_argument(
        "--reset-delay",
        type=float,
        metavar="S",
        help="Firmata: seconds the board ignores input after the port opens (default: 2)",
    )
    for flag, what in (
        ("--corrupt", "each received byte is flipped"),
        ("--drop", "a received frame is ignored"),
        ("--drop-reply", "a reply is not sent"),
        ("--delay-reply", "a reply is sent 0.5 s late"),
        ("--garbage", "noise bytes precede a reply"),
    ):
        parser.add_argument(
            flag, type=float, metavar="F", help=f"laser-frame: probability that {what}"
        )
    parser.add_argument(
        "--seed", type=int, metavar="N", help="laser-frame: seed of the fault generator"
    )
    parser.add_argument(
        "--queue", type=int, metavar="N", help="laser-frame: queue depth in instructions"
    )
    parser.add_argument("--instant", action="store_true", help="moves take no time")
    parser.add_argument("--speed", type=float, help="initial speed (mm/s)")
    parser.add_argument(
        "--fault", action="append", default=[], help="an error CHECK_ERRORS reports (repeatable)"
    )
    parser.add_argument("--mute", action="store_true", help="a device that never answers")
    parser.add_argument(
        "--record", metavar="FILE", help="append a hexdump of the traffic, as the device sees it"
    )
    parser.add_argument(
        "--control",
        action="store_true",
        help="read fault commands on stdin, one a line, each answered on stdout: "
        + "; ".join(f"{name}: {what}" for name, what in FAULT_COMMANDS.items())
        + "; vanish: close the port and exit",
    )
    parser.add_argument(
        "--link",
        metavar="PATH",
        help="keep PATH a symlink to the pty while serving (made at start, replacing what is "
        "there; removed at exit), like socat's link=: a device served again is found under "
        "the same name",
    )
    parser.add_argument("-v", "--verbose", action="store_true", help="log on stderr")
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of motionsim; returns the exit status."""
    options = build_parser().parse_args(argv)
    logging.basicConfig(
        level=logging.DEBUG if options.verbose else logging.WARNING,
        format="motionsim: %(message)s",
        stream=sys.stderr,
    )
    device_options: dict[str, object] = {"instant": options.instant, "mute": options.mute}
    if options.protocol == "coxiris":
        device_options["blocking"] = not options.non_blocking
        device_options["faults"] = tuple(options.fault)
        if options.speed is not None:
            device_options["speed"] = options.speed
    elif options.protocol == "visiomex":
        device_options["bugs"] = not options.no_bugs
        if options.pace is not None:
            device_options["pace"] = options.pace
    elif options.protocol == "firmata" and options.reset_delay is not None:
        device_options["reset_delay"] = options.reset_delay
    elif options.protocol == "laser-frame":
        for key in _LASER_OPTIONS:
            if getattr(options, key) is not None:
                device_options[key] = getattr(options, key)
    if options.variant is not None and has_variants(options.protocol):
        device_options["variant"] = options.variant
    try:
        probe = create_device(options.protocol, **device_options)
    except (UnknownProtocol, ValueError) as exc:  # ValueError: a fault rate out of range
        print(f"motionsim: {exc}", file=sys.stderr)
        return 2
    baud = None if options.no_line_timing else (options.baud or probe.default_baud)
    device = create_device(options.protocol, baud=baud, **device_options)
    faulty = None
    if options.control:
        variant = options.variant if has_variants(options.protocol) else None
        faulty = FaultyDevice(
            lambda: create_device(options.protocol, baud=baud, **device_options),
            create_protocol(options.protocol, variant).new_framer(),
            seed=options.seed or 0,
        )
    record = open(options.record, "a", encoding="utf-8") if options.record else None  # noqa: SIM115
    writer = TrafficLogWriter(record) if record else None
    try:
        server = PtyServer(
            faulty or device,  # type: ignore[arg-type]
            writer,
            link=options.link,
        )
    except OSError as exc:  # the link cannot be made there
        print(f"motionsim: cannot link {options.link}: {exc}", file=sys.stderr)
        return 2
    if writer is not None:  # what the log readers need: protocol, port, and whose side it is
        variant = options.variant if has_variants(options.protocol) else None
        speaks = create_protocol(options.protocol, variant)
        writer.note(device_side_note(server.path, speaks, baud or probe.default_baud))

    def stop(signum: int, frame: FrameType | None) -> None:
        server.stop()

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    print(server.path, flush=True)
    log.info("serving %s on %s", options.protocol, server.path)
    if faulty is not None:
        threading.Thread(target=_control, args=(faulty, server), daemon=True).start()
    try:
        server.serve_forever()
    finally:
        if record is not None:
            record.close()
    return 0


def _control(faulty: FaultyDevice, server: PtyServer) -> None:
    """Apply the fault commands read on stdin; answer each with `ok ...` or `error ...`."""
    for line in sys.stdin:
        if not line.strip():
            continue
        if line.strip().lower() == "vanish":
            print("ok vanish", flush=True)
            server.stop()
            return
        try:
            print(f"ok {faulty.control(line)}", flush=True)
        except FaultError as exc:
            print(f"error {exc}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
