"""Issue 28 items 2 and 12 with real X input, at each screen size.

2: COXIRIS, Go to X -40 typed; the device killed mid-move: the readout shows the estimate at the
loss, marked (its badge and blue-grey italic numbers, not the start position as "last known");
the device served again on the same link: the panel reconnects and shows what `where` says.
12: a laser-frame program run, Pause (Alt+A): the device's record shows no move sent after it,
its queue drains (GET_STATUS in the session log) and it stands at the last move it got.

Observed only through the session log, the simulator (`where`, its record), screenshots and the
window's geometry (the layout report)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.test_laser_pause_follows import _STATUS, _replies, decoded_after
from tests.acceptance.test_visiomex_truth import REPORT, _rect, _rows_shown, _settled_rows
from tests.acceptance.xsession import (
    XServer,
    colour_count,
    hold,
    laser_moves,
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
    in the session log) drains to 0, and it stands at the last move it got (`where`)."""
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

    def drained() -> bool:
        after = decoded_after(panel.logs.frames("laser-frame"), pressed)
        return any(status[0] == 0 for status in _replies(after, _STATUS))

    wait_for(drained, 30.0, "GET_STATUS saying the device's queue is empty, after the pause")
    hold(0.5)  # the status line's last word on the pause
    any_screen.screenshot(shots / f"still-{size}.png")
    moves = received()
    assert len(moves) == got_at_pause < len(PROGRAM), "moves were sent after the pause"
    where = _where(sim)
    assert where == pytest.approx(list(moves[-1][:3]), abs=0.01), (where, moves[-1])
    panel.key("alt+s")  # Stop
    panel.wait_state("idle", 15.0)
