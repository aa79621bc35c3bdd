"""Running `motionsim` in another process for a benchmark: its pty path, stopped afterwards."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


@contextmanager
def motionsim(*args: str) -> Iterator[str]:
    """Start `motionsim ARGS`; yield the device path it serves; terminate it at the end."""
    sim = subprocess.Popen(
        [sys.executable, "-m", "app.simcli", *args], stdout=subprocess.PIPE, text=True, cwd=ROOT
    )
    try:
        assert sim.stdout is not None
        yield sim.stdout.readline().strip()
    finally:
        sim.terminate()
        sim.wait(10)
