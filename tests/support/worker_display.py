"""An X server of its own for each pytest-xdist worker.

`resources/setup.sh test` runs two test files at a time under one `xvfb-run` display. Windows
of two processes on one display take the keyboard focus from each other, and the panel treats a
lost focus as the release of a held jog key (it must: a key released elsewhere is never seen),
so a worker's window tests would see the other's windows. Each worker therefore starts its own
Xvfb, as the first display had it (1600×1000, GLX), before Qt is loaded, and stops it at exit.
"""

from __future__ import annotations

import atexit
import os
import select
import shutil
import subprocess

STARTUP_S = 20.0


def own_display_per_worker() -> None:
    """Under xdist with a display: point DISPLAY at a new Xvfb for this worker alone."""
    if not os.environ.get("PYTEST_XDIST_WORKER") or "DISPLAY" not in os.environ:
        return
    if shutil.which("Xvfb") is None:
        return
    read, write = os.pipe()
    screen = ("-screen", "0", "1600x1000x24", "+extension", "GLX", "-nolisten", "tcp", "-noreset")
    try:
        server = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write), *screen],
            pass_fds=(write,),
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
    finally:
        os.close(write)
    number = b""
    try:
        while not number.endswith(b"\n"):
            ready, _, _ = select.select([read], [], [], STARTUP_S)
            chunk = os.read(read, 16) if ready else b""
            if not chunk:
                server.kill()
                raise RuntimeError("Xvfb for this test worker did not start")
            number += chunk
    finally:
        os.close(read)
    os.environ["DISPLAY"] = f":{number.decode().strip()}"
    os.environ.pop("XAUTHORITY", None)
    atexit.register(server.terminate)
