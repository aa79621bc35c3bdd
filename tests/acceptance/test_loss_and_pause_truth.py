"""Issue 28 items 2 and 12 with real X input, at each screen size.

2: COXIRIS, Go to X -40 typed; the device killed mid-move: the readout shows the estimate at the
loss, marked (its badge and blue-grey italic numbers, not the start position as "last known");
the device served again on the same link: the panel reconnects and shows what `where` says.
12: a laser-frame program run, Pause (Alt+A): the device's record shows no move sent after it,
its queue drains (GET_STATUS in the session log) and it stands at the last move it got; the
session log says at once, before the queue is empty, how many moves the device still holds (as
the device's own record of its replies says), and `motionctl log decode` shows it.

Observed only through the session log, the simulator (`where`, its record), screenshots and the
window's geometry (the layout report)."""

from __future__ import annotations

import itertools
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.test_laser_pause_follows import _STATUS, _replies, decoded_after
from tests.acceptance.test_visiomex_truth import REPORT, _rect, _rows_shown, _settled_rows
from tests.acceptance.xsession import (
    Entry,
    Frame,
    Sim,
    XServer,
    colour_count,
    hold,
    laser_moves,
    motionctl,
    wait_for,
    write_program,
    write_settings,
)

pytestmark = pytest.mark.timeout(180)

# widgets/position_readout.py: the badge border and value colour of each status
LOST_MOVING_BORDER, LOST_MOVING_VALUE = 0x90CAF9, 0x5C7FA3
ESTIMATED_BACKGROUND, STALE_BORDER = 0xE3F2FD, 0xBDBDBD


def _where(sim) -> list[float]:
    return [float(v) for v in sim.fault("where").split()[2:]]


# app/window/device/program_pause.py: what the window says of a paused laser-frame program
_HOLDS = re.compile(r"the device still holds (\d+) move\(s\) .* in about (\d+) s")
_STANDS_STILL = "paused: the device has run what it held; the stage stands still"


def _device_replies(sim: Sim) -> list[Frame]:
    """The frames the device sent, by its own record (motionsim --record), decoded."""
    from drivers.protocols.registry import create_protocol
    from drivers.traffic.decoding import StreamDecoder

    decoder = StreamDecoder(create_protocol("laser-frame"))
    return [
        Frame(frame.time, "rx", str(frame.meaning))
        for entry in sim.record.entries()
        if entry.direction == "tx"  # the device's "tx": what the panel receives
        for frame in decoder.feed_bytes("rx", entry.data, entry.time)
    ]


def _held(status: tuple[float, ...]) -> int:
    """The moves a GET_STATUS reply (queue, state) says the device holds, as the panel counts
    them: its queue, or the move under way once the queue is empty."""
    queue, moving = int(status[0]), bool(status[1])
    return queue + (1 if moving else 0)  # the move under way has left the queue


def _seconds(moves: list[tuple[float, ...]]) -> list[float]:
    """How long each move (x, y, z, speed) takes from the one before it."""
    return [math.dist(a[:3], b[:3]) / b[3] for a, b in itertools.pairwise(moves)]


def test_a_link_lost_mid_move_shows_the_estimate_then_the_device(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Go to X -40 at 10 mm/s, the device killed 1.5 s in: the estimate at the loss, marked;
    served again on the same --link path: reconnected, the readout shows `where` (0, 0, 0)."""
    size = "{}x{}".format(*any_screen.size)
    link = tmp_path / "ttyStage"
    first = rig.sim("coxiris", "--speed", "10", link=link, control=True)
    settings = write_settings(tmp_path / "settings.ini", protocol="coxiris", port=str(link))
    panel = rig.panel(
        any_screen,
        "--port",
        str(link),
        "--protocol",
        "coxiris",
        settings=settings,
        env={REPORT: str(tmp_path / "layout.json")},
    )
    panel.wait_ready(b"DONE GET_SPEED")
    readout = _rect(panel, tmp_path / "layout.json", "operate", "positionReadout")
    assert _where(first) == [0.0, 0.0, 0.0]
    start = _settled_rows(panel, readout, shots / f"start-{size}.png")

    panel.key("alt+x")  # the Go to X field
    panel.key("ctrl+a")
    panel.type("-40")
    panel.key("Return")
    wait_for(lambda: first.record.commands("ABSOLUTE_MOVE"), 10.0, "ABSOLUTE_MOVE at the device")
    hold(1.5)
    at_kill = _where(first)
    first.vanish()
    assert -40.0 < at_kill[0] < -5.0, at_kill  # under way when killed
    panel.wait_state("error", 15.0)

    def marked():
        image = any_screen.grab(shots / f"lost-{size}.png", readout)
        return (
            colour_count(image, LOST_MOVING_BORDER) > 100
            and colour_count(image, LOST_MOVING_VALUE) > 20
            and colour_count(image, ESTIMATED_BACKGROUND) < 50
            and image
        )

    lost = wait_for(marked, 10.0, "the estimate at the loss, marked", 0.3)
    any_screen.screenshot(shots / f"lost-screen-{size}.png")
    assert colour_count(lost, STALE_BORDER) < 50, "shown as the stale 'last known' position"
    rows = _rows_shown(lost)
    assert len(rows) == 2 and not np.array_equal(rows[0], start[0]), (
        f"the readout shows the start position at the loss: see {shots}"
    )

    second = rig.sim("coxiris", "--speed", "10", link=link, control=True)
    panel.wait_handshake(b"DONE GET_ID", 20.0, count=2)
    panel.wait_state("idle", 15.0)
    assert _where(second) == [0.0, 0.0, 0.0]
    again = _settled_rows(panel, readout, shots / f"reconnected-{size}.png")
    any_screen.screenshot(shots / f"reconnected-screen-{size}.png")
    image = any_screen.grab(shots / f"reconnected-{size}.png", readout)
    assert all(np.array_equal(a, b) for a, b in zip(again, start, strict=True)), (
        f"after reconnecting the readout is not the device's (0, 0): see {shots}"
    )
    assert colour_count(image, LOST_MOVING_VALUE) == 0 and colour_count(image, STALE_BORDER) < 50


# 40 moves of about 2 mm at 5 mm/s into a queue of 8 (as test_laser_pause_follows.py)
PROGRAM = [(i * 0.5, (i % 2) * 2.0, 0.0, 5.0) for i in range(1, 41)]


def test_laser_pause_sends_nothing_more_and_the_device_runs_what_it_holds(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Run, then Pause (Alt+A): the device gets no move after the pause; its queue (GET_STATUS
    in the session log) drains to 0, and it stands at the last move it got (`where`). Before
    the queue is empty the session log has the note "the device still holds N moves", N as the
    device answered (its record), then "has run what it held"; motionctl log decode shows both."""
    size = "{}x{}".format(*any_screen.size)
    sim = rig.sim("laser-frame", "--speed", "10", "--queue", "8", control=True)
    settings = write_settings(tmp_path / "settings.ini", protocol="laser-frame", port=sim.path)
    program = write_program(tmp_path / "zigzag.csv", PROGRAM)
    panel = rig.panel(
        any_screen, "--port", sim.path, "--protocol", "laser-frame", settings=settings
    )
    wait_for(lambda: panel.state() == "idle", 30.0, "the laser robot connected")

    def received() -> list[tuple[float, ...]]:
        return laser_moves(f.text for f in sim.record.received_frames("laser-frame"))

    panel.load_program(program)
    panel.key("alt+r")  # Run
    wait_for(lambda: len(received()) >= 14, 15.0, "the program's second frame at the device")
    panel.key("alt+a")  # Pause
    pressed = panel.logs.entries()[-1].time
    hold(0.3)  # the key taken in: a frame on its way when it came may still arrive
    got_at_pause = len(received())
    any_screen.screenshot(shots / f"paused-{size}.png")

    def noted(text: str) -> Entry | None:
        return next((e for e in panel.logs.entries() if e.time >= pressed and text in e.note), None)

    def drained() -> bool:
        after = decoded_after(panel.logs.frames("laser-frame"), pressed)
        return any(status[0] == 0 for status in _replies(after, _STATUS))

    holds = wait_for(lambda: noted("still holds"), 10.0, "the 'still holds' note in the log")
    wait_for(drained, 30.0, "GET_STATUS saying the device's queue is empty, after the pause")
    still = wait_for(lambda: noted(_STANDS_STILL), 10.0, "the 'has run what it held' note")
    hold(0.5)  # the status line's last word on the pause
    any_screen.screenshot(shots / f"still-{size}.png")
    moves = received()
    assert len(moves) == got_at_pause < len(PROGRAM), "moves were sent after the pause"
    where = _where(sim)
    assert where == pytest.approx(list(moves[-1][:3]), abs=0.01), (where, moves[-1])

    # N is what the device itself answered to the panel's last GET_STATUS (or the one before)
    # before the note, by its own record; and it then ran N moves, and the one under way.
    hit = _HOLDS.search(holds.note)
    assert hit is not None, holds.note
    said, about_s = int(hit.group(1)), int(hit.group(2))
    frames = panel.logs.frames("laser-frame")
    seen = _replies([f for f in frames if f.time <= holds.time], _STATUS)
    answered = _replies(_device_replies(sim), _STATUS)
    assert seen and answered[: len(seen)] == seen, "the session log's replies are not the device's"
    assert said in {_held(status) for status in seen[-2:]}, (said, seen[-2:])
    statuses = [f for f in decoded_after(frames, pressed) if _replies([f], _STATUS)]
    empty = next(f.time for f in statuses if _replies([f], _STATUS)[0][0] == 0)
    stood = next(f.time for f in statuses if _replies([f], _STATUS) == [(0.0, 0.0)])
    assert holds.time < empty <= stood <= still.time, (holds.time, empty, stood, still.time)
    ran, took = stood - holds.time, _seconds([(0.0, 0.0, 0.0, 1.0), *moves])
    assert sum(took[-said:]) - 0.3 <= ran <= sum(took[-said - 1 :]) + 1.0, (said, ran, took)
    assert ran <= about_s + 1.0, (ran, about_s)
    panel.key("alt+s")  # Stop
    panel.wait_state("idle", 15.0)

    # A reader of the session log sees the same: the note, then the queue empty, then still.
    log = next(p for p in panel.logs.folder.glob("session-*.log") if holds.note in p.read_text())
    done = motionctl("--port", "none", "--json", "log", "decode", str(log))
    assert done.returncode == 0, done.stderr
    decoded = [f["meaning"] for f in json.loads(done.stdout)["frames"]]
    at = decoded.index(holds.note)
    emptied = next(i for i, m in enumerate(decoded) if i > at and m.startswith("GET_STATUS [0, "))
    assert at < emptied < decoded.index(_STANDS_STILL, at), decoded[at:]
