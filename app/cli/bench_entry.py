"""motionctl `--bench FILE --device NAME`: one device of a bench file, as if its port, protocol,
variant, baud, timeout and travel box had been typed (an option typed wins, except --port and
a --protocol that disagrees, refused); its settings come before the typed ones."""

from __future__ import annotations

import argparse

from app.cli.command_line import UsageError
from drivers.messages import Message
from drivers.session.bench import BenchDevice, read_bench
from drivers.session.device_session import DeviceSession

MOVING = frozenset({"home", "move", "jog", "run", "step", "arc", "macro"})  # at the bench's speed


def bench_device(options: argparse.Namespace, arguments: list[str]) -> BenchDevice | None:
    """The bench device the options name, its entries put in `options` (None: no --bench).
    UsageError for options that do not go together; BenchError for a wrong bench file."""
    if options.bench is None:
        if options.device is not None:
            raise UsageError(Message("--device names a device of a bench: give --bench FILE"))
        return None
    if options.port is not None:
        raise UsageError(Message("--port and --bench both name the device: give one of them"))
    devices = read_bench(options.bench)
    name = options.device
    if name is None:
        if len(devices) > 1:
            raise UsageError(
                Message(
                    "{bench} has {count} devices: choose one with --device ({names})",
                    bench=options.bench,
                    count=len(devices),
                    names=", ".join(devices),
                )
            )
        name = next(iter(devices))
    device = devices.get(name)
    if device is None:
        raise UsageError(
            Message(
                "{bench} has no device {name!r} (it has {names})",
                bench=options.bench,
                name=name,
                names=", ".join(devices),
            )
        )
    if options.protocol is not None and options.protocol != device.protocol:
        raise UsageError(
            Message(
                "--protocol {typed} disagrees with the bench: {name} is {protocol}",
                typed=options.protocol,
                name=name,
                protocol=device.protocol,
            )
        )
    options.port, options.protocol = device.port, device.protocol
    if options.variant is None:
        options.variant = device.variant
    if options.baud is None:
        options.baud = device.baud
    if options.travel is None:
        options.travel = device.travel
    if not any(a == "--timeout" or a.startswith("--timeout=") for a in arguments):
        options.timeout = device.timeout
    return device


def at_bench_speed(session: DeviceSession, device: BenchDevice | None, command: str) -> None:
    """A command that moves goes at the speed the bench names for its device."""
    if device is not None and device.speed is not None and command in MOVING:
        session.speed(device.speed)
