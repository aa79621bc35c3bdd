"""Ctrl-C during a motionctl move (issue 19, item 8): a real motionsim process, a real motionctl
process, and a real SIGINT once the simulator's own record shows that the move arrived.

Where the protocol has a stop (laser-frame), motionctl sends it, waits for its acknowledgement
and says where the stage stopped; where it has none (COXIRIS), it says what the device does next.
Either way the exit status is 130.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from drivers.errors import BadFile
from drivers.framers.stuffed import StuffedFramer
from drivers.protocols.laser.codec import decode_instructions
from tests.support.e2e import device_received
from tests.support.simproc import ROOT, SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60), pytest.mark.usefixtures("settings_file")]

MOVE_LINEAR, STOP, SEQUENCE = 0x01, 0x13, 0x20
DEADLINE_S = 20.0


def _received(record: Path) -> bytes:
    """What the simulated device has read so far (b"" while a line is still being written)."""
    try:
        return device_received(record)
    except BadFile:
        return b""


def _laser_words(data: bytes) -> list[list[int]]:
    """The command words of each whole frame the device read, in order."""
    framer = StuffedFramer()
    words = []
    while data:
        used, frame = framer.decode(data)
        if not used:
            break  # an incomplete frame at the end: still arriving
        data = data[used:]
        if frame is not None:
            words.append([i.word for i in decode_instructions(frame)])
    return words


def _wait_for(condition: Callable[[], bool], what: str) -> None:
    """Poll another process's file until `condition` holds (nothing to wait on but the file)."""
    deadline = time.monotonic() + DEADLINE_S
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"{what} did not happen within {DEADLINE_S:g} s")
        time.sleep(0.02)


def _motionctl(protocol: str, port: str, *args: str) -> subprocess.Popen[str]:
    """motionctl in its own process, with Ctrl-C (SIGINT) as an interactive shell gives it."""
    return subprocess.Popen(
        [sys.executable, "-m", "app.cli", "--port", port, "--protocol", protocol, *args],
        cwd=ROOT,
        env=dict(os.environ),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        # (a shell that ran the tests in the background may have left SIGINT ignored)
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )


@pytest.fixture
def sim_factory(tmp_path: Path) -> Iterator[Callable[[str], tuple[SimProcess, Path]]]:
    started: list[SimProcess] = []

    def start(protocol: str) -> tuple[SimProcess, Path]:
        record = tmp_path / f"{protocol}-device.log"
        sim = SimProcess(protocol, "--record", str(record))
        started.append(sim)
        return sim, record

    yield start
    for sim in started:
        sim.stop()


def _interrupt(run: subprocess.Popen[str]) -> tuple[int, str, str]:
    run.send_signal(signal.SIGINT)
    try:
        out, err = run.communicate(timeout=DEADLINE_S)
    except subprocess.TimeoutExpired:
        run.kill()
        out, err = run.communicate()
        raise AssertionError(f"motionctl did not end after Ctrl-C: {err}") from None
    return run.returncode, out, err


@pytest.mark.parametrize("command", ["move", "jog", "run"])
def test_ctrl_c_sends_the_laser_stop_and_says_where_the_stage_stopped(
    sim_factory, tmp_path: Path, command: str
) -> None:
    sim, record = sim_factory("laser-frame")
    program = tmp_path / "program.csv"
    program.write_text("x,y,z,speed\n" + "".join(f"{n % 50 + 1},0,0,20\n" for n in range(400)))
    args = {"move": ["200", "0", "0"], "jog": ["200", "0", "0"], "run": [str(program)]}[command]
    run = _motionctl("laser-frame", sim.path, "--travel", "none", command, *args)
    try:
        _wait_for(
            lambda: any(MOVE_LINEAR in w for w in _laser_words(_received(record))),
            "the move frame's arrival at the device",
        )
    except AssertionError:
        run.kill()
        raise
    status, out, err = _interrupt(run)
    assert status == 130, err
    words = _laser_words(_received(record))
    moved = next(i for i, w in enumerate(words) if MOVE_LINEAR in w)
    assert [STOP] in words[moved + 1 :], words  # the stop went after the move
    stopped = re.search(r"interrupted: stopped at \(([-\d.e]+), ([-\d.e]+), ([-\d.e]+)\) mm", err)
    assert stopped is not None, err
    assert "stop was acknowledged" in err and "may still be moving" not in err
    x = float(stopped.group(1))
    if command == "run":  # the program's points lie in x 1..50
        assert 0.0 <= x <= 50.0, err
    else:
        assert 0.0 < x < 200.0, err  # on its way, short of the target: it stopped
    assert out == ""


def test_ctrl_c_without_a_stop_says_what_the_coxiris_device_does_next(sim_factory) -> None:
    sim, record = sim_factory("coxiris")
    run = _motionctl("coxiris", sim.path, "--travel", "none", "move", "200", "0", "0")
    try:
        _wait_for(
            lambda: b"ABSOLUTE_MOVE 200" in _received(record), "the move's arrival at the device"
        )
    except AssertionError:
        run.kill()
        raise
    status, _, err = _interrupt(run)
    assert status == 130, err
    assert "COXIRIS has no stop command" in err, err
    assert "finishes the move under way to (200, 0, 0) mm" in err, err
    assert "motionctl sent nothing more" in err
    received = _received(record)
    assert received.endswith(b"ABSOLUTE_MOVE 200 0 0\n"), received  # nothing after the move


def test_ctrl_c_before_a_move_is_sent_says_the_stage_does_not_move() -> None:
    from app.cli.interrupt import MoveTracker, after_interrupt
    from drivers.link.transport import open_link
    from drivers.protocols.registry import create_protocol
    from drivers.session.device_session import DeviceSession

    link = open_link("sim://coxiris", 115200)
    try:
        session = DeviceSession(link, create_protocol("coxiris"))
        tracker = MoveTracker()
        session.on_move_started(tracker)
        text = after_interrupt(session, "move", tracker)
        assert text == "interrupted before the move was sent: the stage does not move"
        session.move_to(0.5, 0.0, 0.0)
        assert tracker.last is not None and tracker.last.target == (0.5, 0.0, 0.0)
        assert "to (0.5, 0, 0) mm" in after_interrupt(session, "move", tracker)
        assert after_interrupt(session, "position", tracker) == (
            "interrupted: position does not move the stage"
        )
    finally:
        link.close()
