"""Running motionctl in another process from a Qt test, the window's event loop going on."""

from __future__ import annotations

import subprocess
import sys

from tests.support.simproc import ROOT


def run_motionctl(qtbot, *args: str, timeout_ms: int = 30_000) -> subprocess.CompletedProcess[str]:
    """`motionctl ARGS` to its end, while qtbot keeps the event loop going (bounded)."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "app.cli", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=ROOT,
    )
    try:
        qtbot.waitUntil(lambda: proc.poll() is not None, timeout=timeout_ms)
    finally:
        if proc.poll() is None:
            proc.kill()
    out, err = proc.communicate()
    return subprocess.CompletedProcess(proc.args, proc.returncode, out, err)
