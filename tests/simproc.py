"""Running `motionsim` in another process for tests: start, read its path, stop."""

from __future__ import annotations

import selectors
import signal
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


class SimProcess:
    """A motionsim process; `path` is the pty it serves."""

    def __init__(self, *args: str, startup_timeout: float = 10.0) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "app.simcli", *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            cwd=ROOT,
        )
        assert self.proc.stdout is not None
        selector = selectors.DefaultSelector()
        selector.register(self.proc.stdout, selectors.EVENT_READ)
        if not selector.select(startup_timeout):
            self.proc.kill()
            raise RuntimeError("motionsim printed no device path")
        self.path = self.proc.stdout.readline().strip()
        selector.close()
        if not self.path.startswith("/dev/"):
            self.proc.kill()
            raise RuntimeError(f"motionsim printed {self.path!r}, not a device path")

    def stop(self, sig: int = signal.SIGTERM, timeout: float = 10.0) -> int:
        """Send `sig` and return the exit status."""
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        return self.proc.wait(timeout)

    def kill(self) -> None:
        """Make the device vanish at once."""
        self.proc.kill()
        self.proc.wait(10)
