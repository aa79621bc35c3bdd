"""Issue 28 item 29: the 3D view keeps drawing, and draws the moving stage, while Settings is open.

The real panel on the simulated COXIRIS stage: a Go to X 300 typed (30 s at 10 mm/s), then
File → Settings opened with its shortcut (Ctrl+,) while the stage moves, and moved aside as an
operator would, to watch the stage; in it, the theme set to Dark and applied (Apply: the dialog
stays open), then to Light and applied; the panel's window resized and fitted again; the
dialog closed. At each step the part of the 3D view the dialog does not cover is grabbed from
the screen: it must show the scene (many colours, grid and axis lines over the background), in
the applied theme's background, and change from one grab to the next while the stage moves.
A blank view (the background alone, or nothing painted) shows only the overlay buttons and the
scale text: few colours and almost no lines. The blank view of the report did not reproduce
under Xvfb + openbox with Mesa (nor with the Windows style replaced by Fusion, nor with the
dialog run by exec()): this scenario guards against it.
"""

from __future__ import annotations

import itertools
import json
import re
import time
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtGui import QImage

from app.window.layout.layout_report import ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, XServer, hold, wait_for

pytestmark = pytest.mark.timeout(180)

DARK_BACKGROUND = 0x18181C  # app/window/theme.py DARK_PLOT_COLORS.background
LIGHT_BACKGROUND = 0xFFFFFF  # LIGHT_PLOT_COLORS.background
# Measured at 1280x720 on the part right of the dialog: a drawn scene shows 690-1900 colours
# (antialiased lines) with 3-5% of its pixels off the background; the view painted as its
# background alone, or not painted at all, about 80 colours (the Follow button, the scale
# text) and 0.1-0.4%.
MIN_COLOURS = 200
MIN_LINE_SHARE = 0.01
MOVING_CHANGE = 30  # pixels that differ between two grabs while the stage moves
STAGE_IN_SIGHT_S = 12.0  # after the Go to, the stage (X 120 of 300 mm) is right of the dialog


def _geometry(x: XServer, window: str) -> tuple[int, int, int, int]:
    """A window's x, y, width, height on the screen, as xwininfo tells."""
    info = x.run("xwininfo", "-id", window).stdout
    found = [
        re.search(rf"{label}:\s+(-?\d+)", info)
        for label in ("Absolute upper-left X", "Absolute upper-left Y", "Width", "Height")
    ]
    assert all(found), f"no geometry in xwininfo's answer: {info}"
    x0, y0, w, h = (int(match.group(1)) for match in found if match is not None)
    return x0, y0, w, h


def _view_rect(panel: Panel, report: Path) -> tuple[int, int, int, int]:
    """The 3D view's rectangle on the screen, from the layout report of the window's size."""
    left, top, width, height = panel.geometry()

    def rect() -> list[int] | None:
        try:
            data = json.loads(report.read_text(encoding="utf-8"))
        except (FileNotFoundError, json.JSONDecodeError):
            return None
        if data["window"] != [width, height] or not data["views_ready"]:
            return None
        plots = {p["name"]: p for p in data["plots"] if p["visible"]}
        return plots.get("positionView3d", {}).get("rect")

    rx, ry, rw, rh = wait_for(rect, 20.0, f"a layout report of the {width}x{height} window", 0.1)
    return left + rx, top + ry, rw, rh


def _uncovered(view: tuple[int, int, int, int], dialog: tuple[int, int, int, int]):
    """The part of `view` right of the dialog (its frame included), as (x, y, width, height)."""
    vx, vy, vw, vh = view
    right = dialog[0] + dialog[2] + 8  # the window manager's border
    left = max(vx, right)
    assert vx + vw - left >= 200, f"the dialog {dialog} leaves too little of the view {view}"
    return left, vy, vx + vw - left, vh


def _pixels(image: QImage) -> np.ndarray:
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    count = image.width() * image.height()
    return np.frombuffer(image.constBits(), dtype=np.uint32, count=count).copy() & 0xFFFFFF


class Drawn:
    """What a grab of the view shows: its colours, the most common one, the share of others."""

    def __init__(self, pixels: np.ndarray) -> None:
        self.pixels = pixels
        values, counts = np.unique(pixels, return_counts=True)
        self.colours = len(values)
        self.background = int(values[counts.argmax()])
        self.line_share = 1.0 - counts.max() / len(pixels)

    def problem(self, background: int | None = None) -> str:
        """Why this grab is not a drawn scene (on `background`), "" when it is."""
        if self.colours < MIN_COLOURS or self.line_share < MIN_LINE_SHARE:
            return (
                f"blank: {self.colours} colours, {self.line_share:.2%} of it off its "
                f"background #{self.background:06x}"
            )
        if background is not None and _distance(self.background, background) > 12:
            return f"its background is #{self.background:06x}, not #{background:06x}"
        return ""

    def __str__(self) -> str:
        return f"{self.colours} colours, {self.line_share:.2%} lines on #{self.background:06x}"


def _distance(a: int, b: int) -> int:
    return max(abs(((a >> s) & 0xFF) - ((b >> s) & 0xFF)) for s in (16, 8, 0))


class Watcher:
    """Grabs a region of the screen under names, keeping what each showed."""

    def __init__(self, x: XServer, shots: Path) -> None:
        self.x, self.shots = x, shots
        self.seen: list[tuple[str, Drawn]] = []

    def grab(self, name: str, region: tuple[int, int, int, int]) -> Drawn:
        """The region now (kept as NAME.png, the whole screen as NAME-screen.png)."""
        self.x.screenshot(self.shots / f"{len(self.seen):02d}-{name}-screen.png")
        drawn = Drawn(_pixels(self.x.grab(self.shots / f"{len(self.seen):02d}-{name}.png", region)))
        self.seen.append((name, drawn))
        return drawn

    def report(self) -> str:
        """Each grab, for a failure's message."""
        return "; ".join(f"{name}: {drawn}" for name, drawn in self.seen)


def _saved_theme(settings: Path) -> str:
    return str(QSettings(str(settings), QSettings.Format.IniFormat).value("view/theme", ""))


def _apply_theme(x: XServer, letter: str, settings: Path, value: str) -> None:
    """From the Theme list (focused), choose by its first letter; Apply (back past the page's
    scroll area and the tab bar to the Apply button, Space); wait until it is saved. Ends with
    the focus on Theme again."""
    x.xdotool("type", "--delay", "60", letter)
    x.xdotool("key", "--delay", "60", "shift+Tab", "shift+Tab", "shift+Tab", "space")
    wait_for(lambda: _saved_theme(settings) == value, 10.0, f"the theme {value} saved by Apply")
    x.xdotool("key", "--delay", "60", "Tab", "Tab", "Tab")


def _visible(x: XServer, title: str, window: str) -> bool:
    shown = x.run("xdotool", "search", "--onlyvisible", "--name", title, check=False)
    return window in shown.stdout.split()


def test_the_3d_view_keeps_drawing_the_moving_stage_while_settings_changes_the_theme(
    x_server: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    report = tmp_path / "layout-report.json"
    settings = tmp_path / "settings.ini"
    panel = rig.panel(
        x_server, "--port", "sim://coxiris", settings=settings, env={ENVIRONMENT: str(report)}
    )
    panel.wait_ready(b"DONE GET_SPEED")
    watch = Watcher(x_server, shots)
    before = watch.grab("before", _view_rect(panel, report))

    panel.key("alt+x")  # Go to X: 300 mm at 10 mm/s, 30 s
    panel.key("ctrl+a")
    panel.type("300")
    panel.key("Return")
    started = time.monotonic()
    panel.wait_state("moving", 10.0)
    panel.key("ctrl+comma")  # File → Settings
    dialog = panel.dialog("^Settings$")
    x_server.xdotool("windowmove", "--sync", dialog, "0", "0")  # aside, over the docks
    wait_for(lambda: _geometry(x_server, dialog)[0] < 40, 5.0, "the dialog moved aside")
    x_server.xdotool("windowactivate", "--sync", dialog)
    hold(0.5)

    def strip() -> tuple[int, int, int, int]:
        return _uncovered(_view_rect(panel, report), _geometry(x_server, dialog))

    opened = []
    for i in range(2):
        opened.append(watch.grab(f"open-{i}", strip()))
        hold(0.6)
    x_server.xdotool("key", "--delay", "60", "ctrl+shift+Tab", "Tab", "Tab")  # to Theme
    _apply_theme(x_server, "D", settings, "dark")
    hold(0.8)
    dark = watch.grab("dark-applied", strip())
    assert _visible(x_server, "^Settings$", dialog), "Apply closed the Settings dialog"
    _apply_theme(x_server, "L", settings, "light")
    hold(0.8)
    light = watch.grab("light-applied", strip())
    hold(max(0.0, STAGE_IN_SIGHT_S - (time.monotonic() - started)))
    moving = []
    for i in range(3):
        moving.append(watch.grab(f"light-moving-{i}", strip()))
        hold(0.6)

    width, height = x_server.size
    x_server.xdotool("windowsize", panel.window, str(width - 180), str(height - 70))
    wait_for(lambda: panel.geometry()[2] < width - 100, 10.0, "the window made smaller")
    hold(0.8)
    resized = watch.grab("resized", strip())
    panel.fit_to_screen()
    hold(0.8)
    refitted = watch.grab("refitted", strip())

    x_server.xdotool("key", "Escape")  # Cancel: closes it (what was applied stays)
    wait_for(lambda: not _visible(x_server, "^Settings$", dialog), 10.0, "the dialog closed")
    hold(0.8)
    after = watch.grab("after", _view_rect(panel, report))

    problems = [
        f"{name}: {why}"
        for name, drawn, background in (
            ("before Settings", before, None),
            *((f"just opened {i}", d, None) for i, d in enumerate(opened)),
            *((f"light, moving {i}", d, LIGHT_BACKGROUND) for i, d in enumerate(moving)),
            ("dark applied", dark, DARK_BACKGROUND),
            ("light applied", light, LIGHT_BACKGROUND),
            ("window resized", resized, LIGHT_BACKGROUND),
            ("window fitted again", refitted, LIGHT_BACKGROUND),
            ("closed", after, LIGHT_BACKGROUND),
        )
        if (why := drawn.problem(background))
    ]
    changes = [
        int((a.pixels != b.pixels).sum())
        for a, b in itertools.pairwise(moving)
        if a.pixels.shape == b.pixels.shape
    ]
    if not any(change >= MOVING_CHANGE for change in changes):
        problems.append(f"the view did not change while the stage moved: {changes} pixels")
    print(f"grabs of the 3D view: {watch.report()}; moving, pixels changed: {changes}")
    assert not problems, "; ".join(problems) + f" (grabs: {watch.report()}; see {shots})"
