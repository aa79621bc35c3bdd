"""The bridge's added latency: round trips to a pty echo device, directly and through the bridge.

An echo device (a process of its own: the master side of a pty, writing back what it reads) is
asked `count` round trips of a small write directly on its slave, then the same number through a
bridge in another process (`drivers.bridge.snoop.Bridge` alone, or `motionctl bridge` with a log and
its decoded output), in `rounds` alternating blocks so that drift on a noisy machine falls on
both alike. The figures are the median and p99 of each, and of their difference in ms; a round
trip crosses the bridge twice (to the device and back), so one crossing adds about half.

Usage: .venv/bin/python bench/bridge_latency.py [--count N] [--size BYTES] [--rounds N]
                                                [--via bridge|motionctl] [--json]
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import select
import signal
import statistics
import subprocess
import sys
import tempfile
import time
import tty
from collections.abc import Iterator
from pathlib import Path
from types import FrameType

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from drivers.bridge.snoop import Bridge  # noqa: E402

PAYLOAD = bytes((0x00, 0x0A, 0x7E, 0x90, 0xEB, 0xFF, 0x41, 0x0D))
WARM_UP = 50  # round trips not counted at the start of each block
DEADLINE = 5.0  # seconds one round trip may take before the benchmark gives up


# -- the processes --------------------------------------------------------------------------------
def _echo_device() -> None:
    """Serve an echo device on a pty (its slave path on stdout) until SIGTERM."""
    master, slave = os.openpty()
    tty.setraw(slave)  # the slave stays open here: a client's close never hangs the master up
    wake_r, wake_w = os.pipe()
    signal.signal(signal.SIGTERM, lambda signum, frame: os.write(wake_w, b"x"))
    print(os.ttyname(slave), flush=True)
    while True:
        readable, _, _ = select.select([master, wake_r], [], [])
        if wake_r in readable:
            return
        data = os.read(master, 4096)
        while data:
            data = data[os.write(master, data) :]


def _bridge(device: str) -> None:
    """Serve a bare Bridge to `device` (its pty path on stdout) until SIGTERM."""
    with Bridge(device, 115200) as bridge:

        def stop(signum: int, frame: FrameType | None) -> None:
            bridge.stop()

        signal.signal(signal.SIGTERM, stop)
        print(bridge.path, flush=True)
        bridge.serve_forever()


@contextlib.contextmanager
def _process(*args: str) -> Iterator[str]:
    """Start a process that prints a path first; yield the path; terminate it at the end.

    Its stdout goes to a file (a pipe nobody reads would fill up and hold the process up).
    """
    with tempfile.TemporaryFile("w+", encoding="utf-8") as out:
        proc = subprocess.Popen(args, stdout=out, text=True, cwd=ROOT)
        try:
            end = time.monotonic() + 10.0
            path = ""
            while not path.endswith("\n") and time.monotonic() < end and proc.poll() is None:
                time.sleep(0.01)  # a benchmark's start-up, not a measurement
                out.seek(0)
                path = out.readline()
            if not path.startswith("/dev/"):
                raise RuntimeError(f"{' '.join(args)} printed no device path ({path!r})")
            yield path.strip()
        finally:
            proc.terminate()
            proc.wait(10)


def _bridge_command(via: str, device: str, log_file: str) -> tuple[str, ...]:
    if via == "bridge":
        return (sys.executable, __file__, "_bridge", device)
    if via == "motionctl":
        command = ("bridge", "--port", device, "--protocol", "coxiris", "--log", log_file)
        return (sys.executable, "-m", "app.cli", *command)
    raise ValueError(f"via must be 'bridge' or 'motionctl', not {via!r}")


# -- the measurement ------------------------------------------------------------------------------
def _round_trips(path: str, count: int, payload: bytes) -> list[float]:
    """`count` timed round trips (seconds) of `payload` written to `path` and read back."""
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    try:
        tty.setraw(fd)
        times = []
        for index in range(WARM_UP + count):
            start = time.perf_counter()
            os.write(fd, payload)
            got = b""
            while len(got) < len(payload):
                readable, _, _ = select.select([fd], [], [], DEADLINE)
                if not readable:
                    raise RuntimeError(f"no echo from {path} within {DEADLINE} s")
                got += os.read(fd, 4096)
            elapsed = time.perf_counter() - start
            if got != payload:
                raise RuntimeError(f"the echo through {path} differs: {got.hex(' ')}")
            if index >= WARM_UP:
                times.append(elapsed)
        return times
    finally:
        os.close(fd)


def _percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(fraction * (len(ordered) - 1)))]


def _stats(seconds: list[float]) -> dict[str, float]:
    ms = [s * 1000 for s in seconds]
    return {"median_ms": statistics.median(ms), "p99_ms": _percentile(ms, 0.99)}


def measure(
    count: int = 2000, size: int = 8, rounds: int = 4, via: str = "bridge"
) -> dict[str, object]:
    """Round trips direct vs. through the bridge; median and p99 of each and their difference."""
    payload = (PAYLOAD * (size // len(PAYLOAD) + 1))[:size]
    per_round = max(1, count // rounds)
    direct: list[float] = []
    bridged: list[float] = []
    with (
        tempfile.TemporaryDirectory() as folder,
        _process(sys.executable, __file__, "_echo") as device,
    ):
        log_file = str(Path(folder) / "bridge.log")
        for _ in range(rounds):
            direct += _round_trips(device, per_round, payload)
            with _process(*_bridge_command(via, device, log_file)) as path:
                bridged += _round_trips(path, per_round, payload)
    plain, through = _stats(direct), _stats(bridged)
    return {
        "via": via,
        "round_trips": len(direct),
        "bytes": size,
        "direct": plain,
        "bridged": through,
        "added_median_ms": through["median_ms"] - plain["median_ms"],
        "added_p99_ms": through["p99_ms"] - plain["p99_ms"],
    }


def main(argv: list[str] | None = None) -> int:
    """Print the figures (text, or one JSON object with --json)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=2000, help="round trips each way")
    parser.add_argument("--size", type=int, default=8, help="bytes a write")
    parser.add_argument("--rounds", type=int, default=4, help="alternating blocks")
    parser.add_argument("--via", choices=("bridge", "motionctl", "both"), default="both")
    parser.add_argument("--json", action="store_true")
    options = parser.parse_args(argv)
    vias = ("bridge", "motionctl") if options.via == "both" else (options.via,)
    results = [measure(options.count, options.size, options.rounds, via) for via in vias]
    if options.json:
        print(json.dumps(results))
        return 0
    for result in results:
        direct, bridged = result["direct"], result["bridged"]
        assert isinstance(direct, dict) and isinstance(bridged, dict)
        print(
            f"{result['via']:>9}: {result['round_trips']} round trips of {result['bytes']} bytes; "
            f"direct median {direct['median_ms']:.3f} ms p99 {direct['p99_ms']:.3f} ms; "
            f"bridged median {bridged['median_ms']:.3f} ms p99 {bridged['p99_ms']:.3f} ms; "
            f"added median {result['added_median_ms']:.3f} ms p99 {result['added_p99_ms']:.3f} ms"
        )
    return 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["_echo"]:
        _echo_device()
    elif sys.argv[1:2] == ["_bridge"]:
        _bridge(sys.argv[2])
    else:
        sys.exit(main())
