"""Running ser2net for tests and benchmarks: a device served over RFC 2217 on 127.0.0.1."""

from __future__ import annotations

import shutil
import socket
import subprocess
import time
from pathlib import Path

SER2NET = shutil.which("ser2net") or (
    "/usr/sbin/ser2net" if Path("/usr/sbin/ser2net").exists() else None
)
START_TIMEOUT = 10.0  # seconds ser2net may take to accept connections
PORT_ATTEMPTS = 5  # free ports tried when another program takes the one picked first


SAFE_OPTIONS = ("max-connections: 1",)  # the README's: one client at a time


def ser2net_yaml(device: str, port: int, baud: int = 115200, *options: str) -> str:
    """The configuration serving `device` as rfc2217://127.0.0.1:`port` (the README's: loopback
    only, one client at a time), with more connection `options` ("chardelay: false")."""
    text = (
        "connection: &motionsim\n"
        f"  accepter: telnet(rfc2217),tcp,127.0.0.1,{port}\n"
        f"  connector: serialdev,{device},{baud}n81,local\n"
    )
    return text + "  options:\n" + "".join(f"    {o}\n" for o in (*SAFE_OPTIONS, *options))


def free_port() -> int:
    """A TCP port nothing listens on now (the system's pick)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def accepts(port: int) -> bool:
    """Whether something accepts connections on 127.0.0.1:`port` now."""
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=0.5):
            return True
    except OSError:
        return False


class Ser2netProcess:
    """ser2net in the foreground serving `device`; `url` is the rfc2217:// URL to open."""

    def __init__(
        self, device: str, folder: Path, baud: int = 115200, options: tuple[str, ...] = ()
    ) -> None:
        if SER2NET is None:
            raise RuntimeError("ser2net is not installed (Debian: apt-get install ser2net)")
        self.folder = folder
        self.output = folder / "ser2net.out"
        for _ in range(PORT_ATTEMPTS):
            self.port = free_port()
            config = folder / "ser2net.yaml"
            config.write_text(ser2net_yaml(device, self.port, baud, *options), encoding="utf-8")
            with open(self.output, "wb") as out:
                # -n: foreground; -u: no UUCP lock files; -P: a pid file of its own
                self.proc = subprocess.Popen(
                    [SER2NET, "-n", "-u", "-P", str(folder / "ser2net.pid"), "-c", str(config)],
                    stdin=subprocess.DEVNULL,
                    stdout=out,
                    stderr=subprocess.STDOUT,
                )
            if self._wait_until_listening():
                self.url = f"rfc2217://127.0.0.1:{self.port}"
                return
            self.stop()
        raise RuntimeError(f"ser2net did not start: {self.log()}")

    def _wait_until_listening(self) -> bool:
        """Whether ser2net accepts on its port before the deadline (False: it exited, e.g. the
        port was taken in the meantime)."""
        deadline = time.monotonic() + START_TIMEOUT
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                return False
            if accepts(self.port):
                return True
            time.sleep(0.02)  # polling the condition, with the deadline above
        return False

    def log(self) -> str:
        """What ser2net printed."""
        try:
            return self.output.read_text(encoding="utf-8", errors="replace")
        except OSError:
            return ""

    def stop(self, timeout: float = 10.0) -> None:
        """Stop ser2net (SIGTERM, then SIGKILL if it lingers)."""
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout)
