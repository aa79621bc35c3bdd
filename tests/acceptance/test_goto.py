"""Issue 19 item 4: a typed coordinate is sent exactly as typed, or not at all (with the reason)."""

from __future__ import annotations

from pathlib import Path

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import (
    Line,
    Timeout,
    XServer,
    colour_count,
    numbers,
    wait_for,
    write_settings,
)

BOX = ((-50.0, 50.0), (-50.0, 50.0), (-50.0, 50.0))
REFUSAL_RED = 0xC62828  # widgets/_number_field.py, widgets/status_line.py


def _moves_to(record_moves: list[Line], x: float) -> list[Line]:
    return [m for m in record_moves if numbers(m)[:1] == [x]]


def test_go_to_x_sends_exactly_what_was_typed(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Box ±50: `80` moves nothing (and says why, in red); then `12.5` sends 12.5, not 12 or 1."""
    sim = rig.sim("coxiris", "--speed", "100")
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=sim.path, travel=BOX
    )
    panel = rig.panel(any_screen, "--port", sim.path, "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    width, height = any_screen.size
    before = any_screen.grab(shots / "before.png")

    panel.key("alt+x")  # the Go to X field (its label's mnemonic)
    panel.key("ctrl+a")
    panel.type("80")
    panel.key("Return")
    try:
        shown_red = wait_for(
            lambda: (
                colour_count(any_screen.grab(shots / "refused.png"), REFUSAL_RED, 24)
                > colour_count(before, REFUSAL_RED, 24) + 20
            ),
            10.0,
            "the refusal of 80 shown in red",
            interval=0.2,
        )
    except Timeout:
        shown_red = False
    (shots / "refused.png").rename(shots / f"goto-80-refused-{width}x{height}.png")

    panel.key("ctrl+a")
    panel.type("12.5")
    panel.key("Return")
    record = sim.record
    wait_for(
        lambda: _moves_to(record.commands("ABSOLUTE_MOVE"), 12.5),
        15.0,
        "ABSOLUTE_MOVE 12.5 at the device",
    )
    sent = [m.text for m in record.commands("ABSOLUTE_MOVE")]
    assert len(sent) == 1 and numbers(record.commands("ABSOLUTE_MOVE")[0]) == [12.5, 0.0, 0.0], (
        f"the device received {sent} for `80` (refused) then `12.5`"
    )
    assert shown_red, f"`80` out of the box was not shown in red: see {shots}"


def test_go_to_in_spanish_takes_the_typed_decimal(
    x_server: XServer, rig: Rig, tmp_path: Path
) -> None:
    """Spanish interface: `12,5` and `12.5` both send 12.5 (the issue saw `12.5` become 12)."""
    sim = rig.sim("coxiris", "--speed", "100")
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=sim.path, travel=BOX
    )
    panel = rig.panel(
        x_server, "--port", sim.path, "--protocol", "coxiris", "--lang", "es", settings=settings
    )
    panel.wait_ready(b"DONE GET_SPEED")
    record = sim.record
    for typed, value in (("12.5", 12.5), ("-7,25", -7.25)):
        panel.key("alt+x")
        panel.key("ctrl+a")
        panel.type(typed)
        panel.key("Return")
        wait_for(
            lambda value=value: _moves_to(record.commands("ABSOLUTE_MOVE"), value),
            15.0,
            f"ABSOLUTE_MOVE {value} for {typed!r}",
        )
    assert [numbers(m)[0] for m in record.commands("ABSOLUTE_MOVE")] == [12.5, -7.25]
