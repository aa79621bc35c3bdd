"""Issue 19 items 1 and 2: a raw frame that moves is checked like a typed move, and waited for."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import (
    XServer,
    hold,
    motionctl,
    numbers,
    wait_for,
    write_settings,
)

BOX = ((-50.0, 50.0), (-50.0, 50.0), (-50.0, 50.0))


def _send_line(panel, text: str) -> None:
    """Type `text` in the console's send line (Alt+D, in the Traffic layout: Ctrl+3; the panel
    opens in Operate, which has no console) and press Enter."""
    panel.key("ctrl+3")
    panel.key("alt+d")
    panel.key("ctrl+a")
    panel.type(text)
    panel.key("Return")


def test_console_send_line_cannot_leave_the_box(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """`ABSOLUTE_MOVE 100 0 0` typed in the console with box ±50 never reaches the device;
    `ABSOLUTE_MOVE 10 0 0` after it does."""
    sim = rig.sim("coxiris", "--speed", "100")
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=sim.path, travel=BOX
    )
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    _send_line(panel, "ABSOLUTE_MOVE 100 0 0")
    _send_line(panel, "ABSOLUTE_MOVE 10 0 0")
    record = sim.record
    wait_for(
        lambda: any(numbers(m)[:1] == [10.0] for m in record.commands("ABSOLUTE_MOVE")),
        15.0,
        "ABSOLUTE_MOVE 10 0 0 at the device",
    )
    assert [m.text for m in record.commands("ABSOLUTE_MOVE")] == ["ABSOLUTE_MOVE 10 0 0"]


def test_raw_move_from_the_console_is_waited_for(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """A raw `ABSOLUTE_MOVE 30 0 0` at 10 mm/s (3 s, beyond the 2 s reply timeout) finishes
    without an error or a reconnection: the device sees one GET_ID only."""
    sim = rig.sim("coxiris", "--speed", "10")
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=sim.path, travel=BOX
    )
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    _send_line(panel, "ABSOLUTE_MOVE 30 0 0")
    record = sim.record
    wait_for(
        lambda: any(line.text.startswith("DONE ABSOLUTE_MOVE") for line in record.sent_lines()),
        15.0,
        "the device's DONE ABSOLUTE_MOVE",
    )
    panel.wait_state("idle", 10.0)
    hold(1.0, every=record.observe)  # a reconnection would identify the device again
    assert [m.text for m in record.commands("GET_ID")] == ["GET_ID"]
    assert not any("disconnected" in note for note in panel.logs.notes()), panel.logs.notes()


def test_motionctl_raw_cannot_leave_the_box(rig: Rig) -> None:
    """`motionctl --travel ... raw "ABSOLUTE_MOVE 100 0 0"` exits 2 and sends nothing."""
    sim = rig.sim("coxiris", "--speed", "100")
    done = motionctl(
        "--port",
        sim.path,
        "--protocol",
        "coxiris",
        "--travel",
        "-50:50,-50:50,-50:50",
        "raw",
        "ABSOLUTE_MOVE 100 0 0",
    )
    assert done.returncode == 2, (done.returncode, done.stdout, done.stderr)
    assert "ABSOLUTE_MOVE" not in sim.record.received_bytes().decode("ascii", "replace")
