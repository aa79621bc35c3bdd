"""Issue 28 items 1 and 6 on the simulated Visiomex controller (motionsim on a pty), with real X
input: a Y jog at power-on, which the firmware's Y loop does not make, never shows Y moved; an X
jog shows where the device went; a parameter set shows what the firmware recomputed, marked.

Observed only through the session log (the packets and the firmware's own answers), the
simulator (`where`, its record), screenshots and the window's geometry (the layout report)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtGui import QImage

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, Sim, XServer, wait_for, write_settings

pytestmark = pytest.mark.timeout(150)

REPORT = "MOTIONPANEL_LAYOUT_REPORT"
ANSWER_S = 15.0  # the firmware answers a packet after 1 s of silence, then moves at 3.125 mm/s
INK = 200  # a pixel darker than this (mean of its channels) is text


def _start(rig: Rig, screen: XServer, tmp_path: Path) -> tuple[Sim, Panel, Path]:
    """A Visiomex simulator with its control channel and the panel on it, step 1 mm, until
    the panel is connected (Idle) and its layout report is written."""
    sim = rig.sim("visiomex", control=True)
    settings = write_settings(
        tmp_path / "settings.ini", protocol="visiomex", port=sim.path, jog_step=1.0
    )
    report = tmp_path / "layout.json"
    panel = rig.panel(
        screen,
        "--port",
        sim.path,
        "--protocol",
        "visiomex",
        settings=settings,
        env={REPORT: str(report)},
    )
    panel.wait_state("idle", 30.0)
    return sim, panel, report


def _rect(panel: Panel, report: Path, layout: str, name: str) -> tuple[int, int, int, int]:
    """The control `name` on the screen (x, y, width, height), from the layout report written
    once the window has settled in `layout` at its present size."""

    def found() -> list[int] | None:
        panel.alive()
        try:
            data = json.loads(report.read_text(encoding="utf-8"))
        except (FileNotFoundError, json.JSONDecodeError):
            return None
        if data["layout"] != layout or data["window"] != list(panel.geometry()[2:]):
            return None
        return next((c["rect"] for c in data["controls"] if c["name"] == name), None)

    x, y, w, h = wait_for(found, 20.0, f"{name} in a layout report of {layout}", 0.1)
    left, top = panel.geometry()[:2]
    return left + x, top + y, w, h


def _click(panel: Panel, x: int, y: int) -> None:
    panel.activate()
    panel.x.xdotool("mousemove", str(x), str(y), "click", "1")


def _set_home(panel: Panel, report: Path) -> None:
    """Click Set Home and answer its question Yes (Alt+Y)."""
    x, y, w, h = _rect(panel, report, "operate", "setHomeButton")
    _click(panel, x + w // 2, y + h // 2)
    question = panel.dialog("^Motion Panel$")
    wait_for(
        lambda: panel.x.xdotool("getactivewindow").strip() == question,
        5.0,
        "the Set Home question active",
    )
    panel.x.xdotool("key", "alt+y")


def _rows_shown(image: QImage) -> list[np.ndarray]:
    """The readout's Machine numbers (bands of text at least 15 px high in the left part of
    the Position panel, past the axis letters): X first, then Y."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    width, height = image.width(), image.height()
    rgb = np.frombuffer(image.constBits(), dtype=np.uint32, count=width * height)
    pixels = rgb.reshape(height, width)[:, 40 : width * 6 // 10]
    grey = ((pixels >> 16) & 0xFF) // 3 + ((pixels >> 8) & 0xFF) // 3 + (pixels & 0xFF) // 3
    inked = np.concatenate(((grey < INK).any(axis=1), [False]))
    bands, top = [], None
    for row, dark in enumerate(inked):
        if dark and top is None:
            top = row
        elif not dark and top is not None:
            if row - top >= 15:
                bands.append(pixels[top:row].copy())
            top = None
    return bands[:2]


def _settled_rows(panel: Panel, region: tuple[int, int, int, int], shot: Path) -> list:
    """The X and Y numbers the readout shows once the panel is Idle and two grabs in a row
    agree (no estimate being drawn)."""
    seen: list[list[np.ndarray]] = []

    def still() -> list[np.ndarray] | None:
        panel.alive()
        rows = _rows_shown(panel.x.grab(shot, region))
        seen.append(rows)
        previous = seen[-2] if len(seen) > 1 else None
        same = previous is not None and len(rows) == len(previous) == 2
        if same and all(np.array_equal(a, b) for a, b in zip(rows, previous, strict=True)):
            return rows if panel.state() == "idle" else None
        return None

    return wait_for(still, ANSWER_S, "the readout settled with X and Y numbers", 0.3)


def _where(sim: Sim) -> list[float]:
    """Where the simulated axes really are (mm)."""
    return [float(v) for v in sim.fault("where").split()[2:]]


def _answers(panel: Panel) -> bytes:
    """What the firmware sent, every connection."""
    return b"".join(e.data for e in panel.logs.entries() if e.direction == "rx")


def _wait_answer(panel: Panel, count: int, what: str) -> None:
    """Wait for the firmware's `count`th move answer (FA0001) in the session log."""
    wait_for(lambda: _answers(panel).count(b"FA0001") >= count, ANSWER_S, what, 0.1)


def test_y_jog_at_power_on_shows_y_unmoved_and_x_follows(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Set Home, step 1 mm, Up (Y+): the device stays at (0, 0) and the readout's Y still says
    0.000 (the issue saw 1.000 "move confirmed"); Right (X+): the device is at (1, 0), the X
    number changes and Y's does not."""
    size = "{}x{}".format(*any_screen.size)
    sim, panel, report = _start(rig, any_screen, tmp_path)
    readout = _rect(panel, report, "operate", "positionReadout")
    _set_home(panel, report)
    home = _settled_rows(panel, readout, shots / f"home-{size}.png")
    assert np.array_equal(home[0], home[1]), "after Set Home X and Y do not show the same number"

    panel.key("Up")
    _wait_answer(panel, 1, "the firmware's answer to the Y+ packet")
    after_y = _settled_rows(panel, readout, shots / f"after-y-{size}.png")
    any_screen.screenshot(shots / f"after-y-screen-{size}.png")
    assert _where(sim) == [0.0, 0.0]
    assert np.array_equal(after_y[1], home[1]), (
        f"Y+ left the device at Y 0 but the readout's Y number changed: see {shots}"
    )
    assert np.array_equal(after_y[0], home[0]), f"Y+ changed the X number: see {shots}"

    panel.key("Right")
    _wait_answer(panel, 2, "the firmware's answer to the X+ packet")
    after_x = _settled_rows(panel, readout, shots / f"after-x-{size}.png")
    any_screen.screenshot(shots / f"after-x-screen-{size}.png")
    assert _where(sim) == [1.0, 0.0]
    assert not np.array_equal(after_x[0], home[0]), f"X+ moved X but X shows 0: see {shots}"
    assert np.array_equal(after_x[1], home[1]), f"X+ changed the Y number: see {shots}"
