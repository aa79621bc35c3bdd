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
    once the window has settled in `layout` at its present size, its views built."""

    def found() -> list[int] | None:
        panel.alive()
        try:
            data = json.loads(report.read_text(encoding="utf-8"))
        except (FileNotFoundError, json.JSONDecodeError):
            return None
        if data["layout"] != layout or data["window"] != list(panel.geometry()[2:]):
            return None
        if not data["views_ready"]:  # the docks under the views take their height after them
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


SELECTED = 0x308CC6  # a selected table row's background (the style's highlight)
WHITE = 0xFFFFFF
WRITTEN = (370, 480)  # the Last written column's x range in the table (parameter_table.py)
MARK_WIDTH = 28  # px of "(computed)" compared: "(comp", which an elided cell still shows
SAME_TEXT = 0.85  # correlation: "(comp" drawn elsewhere ~0.9, "(pow" or "s (po" ~0.75


def _mask(image: QImage, rgb: int) -> np.ndarray:
    """Where `image` has exactly the colour `rgb`."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    width, height = image.width(), image.height()
    pixels = np.frombuffer(image.constBits(), dtype=np.uint32, count=width * height)
    return (pixels.reshape(height, width) & 0xFFFFFF) == rgb


def _selected_row(image: QImage, region: tuple[int, int, int, int]) -> tuple[int, int] | None:
    """The selected table row within `region` of a screen grab: (left, top) on the screen,
    None while no row is drawn selected."""
    x0, y0, w, h = region
    mask = _mask(image, SELECTED)[y0 : y0 + h, x0 : x0 + w]
    rows = np.nonzero(mask.sum(axis=1) > 200)[0]
    if len(rows) == 0:
        return None
    top = int(rows[0])
    band = mask[top : top + 10].any(axis=0)  # the current cell may be framed on its top line
    return x0 + int(np.nonzero(band)[0][0]), y0 + top


def _written_ink(image: QImage, left: int, top: int, pitch: int, row: int) -> np.ndarray:
    """How dark each pixel of a Last written cell is (0 white, 255 black), `row` rows below
    the one whose top is `top`."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    width, height = image.width(), image.height()
    pixels = np.frombuffer(image.constBits(), dtype=np.uint32, count=width * height)
    y = top + row * pitch
    cell = pixels.reshape(height, width)[
        y + 2 : y + pitch - 2, left + WRITTEN[0] : left + WRITTEN[1]
    ]
    channels = [((cell >> shift) & 0xFF).astype(float) for shift in (16, 8, 0)]
    return 255.0 - sum(channels) / 3


def _mark(ink: np.ndarray) -> np.ndarray | None:
    """The start of the word after the first space of a cell's text ("1 (computed)" gives
    "(comp"), None if the text has no second word."""
    columns = np.nonzero((ink > 255 - INK).any(axis=0))[0]
    gaps = np.nonzero(np.diff(columns) > 3)[0]  # a space is wider than the gaps in a word
    if len(gaps) == 0:
        return None
    start = int(columns[gaps[0] + 1])
    return ink[:, start : start + MARK_WIDTH] if start + MARK_WIDTH <= ink.shape[1] else None


def _shows(ink: np.ndarray, mark: np.ndarray) -> bool:
    """Whether `mark` is drawn somewhere along the cell's text `ink` (the best normalised
    correlation at any offset; text is placed to fractions of a pixel, so not exactly)."""
    width = mark.shape[1]
    best = 0.0
    for x in range(ink.shape[1] - width + 1):
        part = ink[:, x : x + width]
        norm = float(np.sqrt((part * part).sum() * (mark * mark).sum()))
        best = max(best, float((part * mark).sum()) / norm if norm else 0.0)
    return best >= SAME_TEXT


def test_set_of_21_shows_25_recomputed_and_marked(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Set up (Ctrl+2), 21 = 6000 typed into the table and written: the device confirms it,
    and the firmware's recomputed 25 (600 s) is shown marked "(computed)" as 27 (forced to 1)
    is, unlike the power-on value of 24 (the issue saw the table keep what was there)."""
    size = "{}x{}".format(*any_screen.size)
    sim, panel, report = _start(rig, any_screen, tmp_path)
    panel.key("ctrl+2")
    area = _rect(panel, report, "setup", "parameterEditorPanel")
    column = _mask(any_screen.grab(shots / "panel.png", area), WHITE)[:, 20]
    inside = int(np.nonzero(column)[0][0]) + 5  # the first white cell of the ID column
    _click(panel, area[0] + 20, area[1] + inside)

    def selected(other: tuple[int, int] | None, what: str) -> tuple[int, int]:
        """The selected row once it is not at `other` and two grabs in a row agree."""
        seen: list[tuple[int, int] | None] = [None]

        def moved() -> tuple[int, int] | None:
            row = _selected_row(any_screen.grab(shots / "screen.png"), area)
            still = row is not None and row == seen[-1] and row != other
            seen.append(row)
            return row if still else None

        return wait_for(moved, 10.0, what, 0.2)

    panel.key("ctrl+Home")
    first = selected(None, "row 1 selected")
    panel.key("Down")
    second = selected(first, "row 2 selected")
    pitch = second[1] - first[1]
    panel.key(*["Down"] * 25)  # to 27, which scrolls it into view
    panel.key(*["Up"] * 6)  # back to 21, still in view
    left, top = selected(second, "row 21 selected")  # in view, with 24 to 27 below it
    panel.type("6000")
    panel.key("Return", "Tab", "space")  # the value, then Write selected
    wait_for(lambda: b"FS0021" in _answers(panel), ANSWER_S, "the firmware's confirmation of 21")
    assert b"S21006000" in sim.record.received_bytes()

    seen: list[str] = []

    def marked() -> bool:
        image = any_screen.grab(shots / f"written-{size}.png")
        row_21 = _selected_row(image, area)  # still selected; the table may have scrolled
        if row_21 is None:
            return False
        left, top = row_21
        row_24, row_25, row_27 = (_written_ink(image, left, top, pitch, n) for n in (3, 4, 6))
        mark = _mark(row_27)  # 27: "1 (computed)", short enough to be whole
        seen.append("27 unmarked" if mark is None else "")
        return mark is not None and _shows(row_25, mark) and not _shows(row_24, mark)

    try:
        wait_for(marked, 10.0, "25 marked (computed) as 27 is, and 24 not", 0.3)
    except AssertionError as exc:
        where = f"row 21 at {left}, {top}, rows {pitch} px apart"
        raise AssertionError(f"{exc} ({sorted(set(seen))}, {where}); see {shots}") from None
