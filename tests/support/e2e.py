"""What the end-to-end tests share: their reading of traffic logs, and running motionctl.

The logs (motionctl's `--log`, a simulator's `--record`, the session log) are read with the
project's own reader, `drivers.traffic.log_reader.read_log`; here its records keep the hexdump's
spelling
of the direction ("TX"/"RX"), and its notes (`#` lines) are left out.
"""

from __future__ import annotations

import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from drivers.traffic.log_reader import read_log
from tests.support.simproc import ROOT

_NOTE = re.compile(r"^(?:\d{6,}\.\d{3} )?#|^\s*$")  # a `#` line (or a blank one)


@dataclass(frozen=True)
class Record:
    """One write or read of a link, as a hexdump shows it: direction "TX" or "RX"."""

    time: float
    direction: str
    data: bytes


def traffic(log: Path) -> list[Record]:
    """The log's records (a long record spans full lines with one stamp); none for a missing or
    empty file, or one of notes alone, which is what a run that never opened its link, or never
    used it, leaves."""
    if not log.exists() or log.stat().st_size == 0:
        return []
    if all(_NOTE.match(line) for line in log.read_text(encoding="utf-8").splitlines()):
        return []  # the header alone (a simulator's record names its protocol as it starts)
    return [Record(r.time, r.direction.upper(), r.data) for r in read_log(log) if r.direction]


def stream(log: Path, direction: str) -> bytes:
    """All the bytes of one direction ("TX" or "RX"), in order."""
    return b"".join(r.data for r in traffic(log) if r.direction == direction)


def sent(log: Path) -> list[Record]:
    """What the log's owner wrote, record by record."""
    return [r for r in traffic(log) if r.direction == "TX"]


def received(log: Path) -> list[Record]:
    """What the log's owner read, record by record (for the bytes alone: `stream(log, "RX")`)."""
    return [r for r in traffic(log) if r.direction == "RX"]


def device_received(record: Path) -> bytes:
    """Everything the simulated device read (the RX records of its own hexdump)."""
    return stream(record, "RX")


def device_received_text(record: Path) -> str:
    """What the simulated device read, as text ("" where its record is not written yet)."""
    return device_received(record).decode("latin-1") if record.exists() else ""


def device_sent(record: Path) -> list[Record]:
    """What the simulated device wrote."""
    return sent(record)


@dataclass
class Run:
    """A finished motionctl run."""

    returncode: int
    stdout: str
    stderr: str
    seconds: float


def motionctl(
    protocol: str,
    port: str,
    *args: str,
    log: Path | None = None,
    options: tuple[str, ...] = (),
    timeout: float = 60,
) -> Run:
    """Run `motionctl --port PORT --protocol PROTOCOL [OPTIONS] [--log LOG] ARGS`; how long it
    took too."""
    command = [sys.executable, "-m", "app.cli", "--port", port, "--protocol", protocol]
    command += [*options, *(("--log", str(log)) if log is not None else ()), *args]
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, cwd=ROOT)
    return Run(done.returncode, done.stdout, done.stderr, time.monotonic() - start)


def motionctl_as_typed(*args: str, timeout: float = 60) -> subprocess.CompletedProcess[str]:
    """`python -m app.cli ARGS`, exactly as given (no --port or --protocol added)."""
    return subprocess.run(
        [sys.executable, "-m", "app.cli", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=ROOT,
    )
