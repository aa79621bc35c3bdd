"""Running `motionsim` in another process for tests: start, read its path, stop."""

from __future__ import annotations

import selectors
import signal
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]  # the repository: tests/support/ is two below


class SimProcess:
    """A motionsim process; `path` is the pty it serves."""

    def __init__(self, *args: str, startup_timeout: float = 10.0, control: bool = False) -> None:
        extra = ("--control",) if control else ()
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "app.simcli", *args, *extra],
            stdin=subprocess.PIPE if control else subprocess.DEVNULL,
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

    def fault(self, command: str, timeout: float = 10.0) -> str:
        """Apply a fault (motionsim --control) and return its answer once it is in effect."""
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(command + "\n")
        self.proc.stdin.flush()
        selector = selectors.DefaultSelector()
        selector.register(self.proc.stdout, selectors.EVENT_READ)
        try:
            if not selector.select(timeout):
                raise RuntimeError(f"motionsim did not answer the fault {command!r}")
        finally:
            selector.close()
        answer = self.proc.stdout.readline().strip()
        if not answer.startswith("ok "):
            raise RuntimeError(f"motionsim refused the fault {command!r}: {answer}")
        return answer

    def stop(self, sig: int = signal.SIGTERM, timeout: float = 10.0) -> int:
        """Send `sig` and return the exit status."""
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        return self.proc.wait(timeout)

    def kill(self) -> None:
        """Make the device vanish at once."""
        self.proc.kill()
        self.proc.wait(10)
