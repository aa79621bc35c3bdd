"""Issue 19 item 10: while a laser program is paused, the panel keeps following the device."""

from __future__ import annotations

import re
from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import (
    Frame,
    XServer,
    laser_moves,
    wait_for,
    write_program,
    write_settings,
)

# 40 moves of about 2 mm at 5 mm/s (about 16 s) into a queue of 8: paused after the first
# frames, the device still has several seconds of moves queued
PROGRAM = [(i * 0.5, (i % 2) * 2.0, 0.0, 5.0) for i in range(1, 41)]
QUEUE = "8"
_STATUS = re.compile(r"^GET_STATUS \[(\d+), (\d+)\]")
_POSITION = re.compile(r"^GET_POSITION \[([^\]]*)\]")


def _replies(frames: list[Frame], pattern: re.Pattern[str]) -> list[tuple[float, ...]]:
    """The values of the replies the panel received that match `pattern`."""
    found = []
    for frame in frames:
        hit = pattern.match(frame.meaning)
        if frame.direction == "rx" and hit is not None:
            found.append(tuple(float(v) for v in re.split(r",\s*", ",".join(hit.groups()))))
    return found


def test_paused_program_keeps_reading_the_device(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """Pause (Alt+A) mid-program: the panel sends no more moves, but its session log shows it
    asking GET_STATUS and GET_POSITION on, the device answering with its queue draining to 0
    and its position changing; then Stop (Alt+S) ends the program and the state is Idle."""
    sim = rig.sim("laser-frame", "--speed", "10", "--queue", QUEUE)
    settings = write_settings(tmp_path / "settings.ini", protocol="laser-frame", port=sim.path)
    program = write_program(tmp_path / "zigzag.csv", PROGRAM)
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "laser-frame", settings=settings)
    wait_for(lambda: panel.state() == "idle", 30.0, "the laser robot connected")

    def frames() -> list[Frame]:
        return panel.logs.frames("laser-frame")

    def sent_moves() -> list[tuple[float, ...]]:
        return laser_moves(f.meaning for f in frames() if f.direction == "tx")

    panel.load_program(program)
    panel.key("alt+r")  # Run
    wait_for(lambda: len(sent_moves()) >= 14, 15.0, "the program's second frame sent")
    panel.key("alt+a")  # Pause
    pressed = len(panel.logs.entries())

    def drained() -> bool:
        after = decoded_after(frames(), panel.logs.entries()[pressed - 1].time)
        return any(status[0] == 0 for status in _replies(after, _STATUS))

    wait_for(drained, 20.0, "GET_STATUS saying the queue is empty, after the pause")
    log = frames()
    sent = laser_moves(f.meaning for f in log if f.direction == "tx")
    assert len(sent) < len(PROGRAM), "the program was all sent: the pause came too late"
    last_move = max(f.time for f in log if f.direction == "tx" and f.meaning.startswith("SEQUENCE"))
    after = decoded_after(log, last_move)
    asked = [f.meaning for f in after if f.direction == "tx"]
    statuses = [int(s[0]) for s in _replies(after, _STATUS)]
    positions = _replies(after, _POSITION)
    assert "GET_STATUS" in asked and "GET_POSITION" in asked, sorted(set(asked))
    assert statuses and statuses[-1] == 0, statuses
    assert len(set(statuses)) >= 2 and statuses == sorted(statuses, reverse=True), statuses
    assert len(set(positions)) >= 2, f"the position read back while paused: {positions}"

    panel.key("alt+s")  # Stop
    wait_for(
        lambda: "STOP" in [f.text for f in sim.record.received_frames("laser-frame")],
        10.0,
        "STOP at the device",
    )
    panel.wait_state("idle", 15.0)


def decoded_after(frames: list[Frame], since: float) -> list[Frame]:
    """The frames of `frames` later than the session-log time `since`."""
    return [f for f in frames if f.time > since]
