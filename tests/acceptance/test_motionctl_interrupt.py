"""Issue 19 item 8: Ctrl-C during `motionctl move` sends the stop the protocol has."""

from __future__ import annotations

import signal
import subprocess
import sys
from collections.abc import Callable

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import ROOT, wait_for


def _interrupted(port: str, protocol: str, arrived: Callable[[], object], *args: str) -> str:
    """Run `motionctl ARGS`, Ctrl-C it (SIGINT) once `arrived()` says the move is at the
    device; it must exit 130. What it printed on stderr."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "app.cli", "--port", port, "--protocol", protocol, *args],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        # Ctrl-C as an interactive shell gives it (a shell that ran the tests in the background
        # leaves SIGINT ignored, and a child inherits that)
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    try:
        wait_for(arrived, 15.0, "the move at the device")
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=15)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=10)
    assert proc.returncode == 130, err
    return err


def test_ctrl_c_during_a_laser_move_sends_stop(rig: Rig) -> None:
    """laser-frame at 10 mm/s, `move 100 0 0`, SIGINT once the move is at the device: exit 130,
    and the device receives STOP after the move."""
    sim = rig.sim("laser-frame", "--speed", "10")

    def frames() -> list[str]:
        return [f.text for f in sim.record.received_frames("laser-frame")]

    moved = lambda: any("100" in f for f in frames())  # noqa: E731
    _interrupted(sim.path, "laser-frame", moved, "move", "100", "0", "0")
    wait_for(lambda: "STOP" in frames(), 5.0, "STOP at the device")
    sent = frames()
    move = next(i for i, f in enumerate(sent) if "100" in f)
    assert "STOP" in sent[move:], sent


def test_ctrl_c_during_a_coxiris_move_says_what_the_device_does(rig: Rig) -> None:
    """COXIRIS has no stop: exit 130, and the message says the move under way finishes."""
    sim = rig.sim("coxiris", "--speed", "10")
    moved = lambda: sim.record.commands("ABSOLUTE_MOVE")  # noqa: E731
    err = _interrupted(sim.path, "coxiris", moved, "move", "50", "0", "0")
    assert "finish" in err.lower() or "still moving" in err.lower(), err
