"""Issue 19 item 8: Ctrl-C during `motionctl move` sends the stop the protocol has."""

from __future__ import annotations

import signal
import subprocess
import sys

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import ROOT, wait_for


def test_ctrl_c_during_a_laser_move_sends_stop(rig: Rig) -> None:
    """laser-frame at 10 mm/s, `move 100 0 0`, SIGINT once the move is at the device: exit 130,
    and the device receives STOP after the move."""
    sim = rig.sim("laser-frame", "--speed", "10")
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "app.cli",
            "--port",
            sim.path,
            "--protocol",
            "laser-frame",
            "move",
            "100",
            "0",
            "0",
        ],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        frames = lambda: [f.text for f in sim.record.received_frames("laser-frame")]  # noqa: E731
        wait_for(lambda: any("100" in f for f in frames()), 15.0, "the move at the device")
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=15)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=10)
    assert proc.returncode == 130, err
    wait_for(lambda: "STOP" in frames(), 5.0, "STOP at the device")
    sent = frames()
    move = next(i for i, f in enumerate(sent) if "100" in f)
    assert "STOP" in sent[move:], sent


def test_ctrl_c_during_a_coxiris_move_says_what_the_device_does(rig: Rig) -> None:
    """COXIRIS has no stop: exit 130, and the message says the move under way finishes."""
    sim = rig.sim("coxiris", "--speed", "10")
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "app.cli",
            "--port",
            sim.path,
            "--protocol",
            "coxiris",
            "move",
            "50",
            "0",
            "0",
        ],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        wait_for(lambda: sim.record.commands("ABSOLUTE_MOVE"), 15.0, "the move at the device")
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=15)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=10)
    assert proc.returncode == 130, err
    assert "finish" in err.lower() or "still moving" in err.lower(), err
