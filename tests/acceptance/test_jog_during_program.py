"""Issue 19 item 6: a jog pressed while a program runs is refused, never queued behind it."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import (
    XServer,
    colour_count,
    hold,
    laser_moves,
    wait_for,
    write_program,
    write_settings,
)

# 24 moves of about 2 mm at 5 mm/s: about 10 s of running, streamed into a queue of 8 (so that
# the panel is still sending the program when the key is pressed)
PROGRAM = [(i * 0.5, (i % 2) * 2.0, 0.0, 5.0) for i in range(1, 25)]
QUEUE = "8"
WARNING_TEXT = 0x8A4B00  # the status line's warning text (widgets/status_line.py)
OBSERVATION_S = 1.5  # after the program's end: a queued jog would be sent within this


def test_jog_key_while_a_program_runs_is_refused(
    x_server: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Right pressed while the program runs: the status line says it is refused, and the device
    receives exactly the program's moves, nothing after its last point."""
    sim = rig.sim("laser-frame", "--speed", "10", "--queue", QUEUE)
    settings = write_settings(
        tmp_path / "settings.ini", protocol="laser-frame", port=sim.path, jog_step=10.0
    )
    program = write_program(tmp_path / "zigzag.csv", PROGRAM)
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "laser-frame", settings=settings)
    wait_for(lambda: panel.state() == "idle", 30.0, "the laser robot connected")
    record = sim.record

    def moves() -> list[tuple[float, ...]]:
        return laser_moves(frame.text for frame in record.received_frames("laser-frame"))

    panel.load_program(program)
    panel.key("alt+r")  # Run
    wait_for(lambda: moves(), 15.0, "the program's first moves at the device")
    left, top, width, height = panel.geometry()  # the status bar: the window's last 30 px
    bottom = min(top + height, x_server.size[1])
    status = (max(left, 0), bottom - 30, min(width, 800), 30)
    before = colour_count(x_server.grab(shots / "status-before.png", status), WARNING_TEXT, 30)
    assert len(moves()) < len(PROGRAM), "the program was all sent before the jog key was pressed"
    panel.key("Right")
    refused_shown = wait_for(
        lambda: (
            colour_count(x_server.grab(shots / "status-refused.png", status), WARNING_TEXT, 30)
            > before + 100
        ),
        5.0,
        "the jog's refusal in the status line",
        interval=0.1,
    )
    wait_for(lambda: len(moves()) >= len(PROGRAM), 30.0, "the whole program at the device")
    panel.wait_state("idle", 30.0)
    hold(OBSERVATION_S, every=record.observe)
    sent = moves()
    assert sent == PROGRAM, f"the device received {len(sent)} moves: {sent[len(PROGRAM) - 2 :]}"
    assert refused_shown
