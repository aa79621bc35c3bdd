"""Issue 28 item 19: the window a first start opens, and one remembered from a larger screen, fit
the screen they open on, status bar included.

The real panel, its window left as it opens (nobody resizes it: `Panel` would fit it to the
screen), on a screen of each size; the window's place (xwininfo) lies inside the screen and the
status bar's state badge is read from a grab of the screen (Panel.state refuses a status bar off
the screen). openbox itself shrinks a window larger than the screen when it maps it, so the
first start is also tried on a screen with no window manager (a kiosk's bare X server), where
nothing but the panel decides its size.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.layout_reading import label
from tests.acceptance.xsession import SCREENS, Panel, XServer, wait_for

pytestmark = pytest.mark.timeout(120)


class AsOpened(Panel):
    """The panel with its window as it opens (not fitted to the screen by the test)."""

    def fit_to_screen(self) -> None:
        """Leave the window as the panel made it."""


def _start(rig: Rig, x: XServer, settings: Path) -> AsOpened:
    panel = AsOpened(x, rig.tmp, "--lang", "en", "--port", "sim://coxiris", settings=settings)
    rig.started.append(panel)
    return panel


def _off_screen(panel: AsOpened) -> str:
    """ "" when the whole window is on its screen, else where it is."""
    left, top, width, height = panel.geometry()
    screen_width, screen_height = panel.x.size
    if left >= 0 and top >= 0 and left + width <= screen_width and top + height <= screen_height:
        return ""
    return f"the window {width}x{height} at ({left}, {top}) is off the {panel.x.size} screen"


def _settled_geometry(panel: AsOpened) -> tuple[int, int, int, int]:
    """The window's geometry once it has stayed the same for a few readings."""
    seen: list[tuple[int, int, int, int]] = []

    def still() -> bool:
        seen.append(panel.geometry())
        return len(seen) >= 5 and len(set(seen[-5:])) == 1

    wait_for(still, 10.0, "the window's geometry to settle", interval=0.1)
    return seen[-1]


def test_a_first_start_fits_the_screen(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    panel = _start(rig, any_screen, tmp_path / "settings.ini")
    panel.wait_ready(b"DONE GET_SPEED")  # the status bar's badge read: it is on the screen
    geometry = _settled_geometry(panel)
    panel.screenshot(shots / f"first-start-{label(any_screen.size)}.png")
    print(f"{any_screen.size}: first window {geometry}")
    assert not _off_screen(panel), _off_screen(panel)
    assert panel.state() == "idle"


def test_a_first_start_fits_a_screen_with_no_window_manager(
    rig: Rig, tmp_path: Path, shots: Path
) -> None:
    bare = XServer(*SCREENS[0])
    try:
        bare.wm.terminate()
        bare.wm.wait(10)
        panel = _start(rig, bare, tmp_path / "settings.ini")
        panel.wait_ready(b"DONE GET_SPEED")
        geometry = _settled_geometry(panel)
        panel.screenshot(shots / "first-start-no-window-manager.png")
        print(f"{SCREENS[0]} without a window manager: first window {geometry}")
        assert not _off_screen(panel), _off_screen(panel)
        panel.close()
    finally:
        bare.stop()


def test_a_geometry_remembered_from_a_larger_screen_is_fitted(
    x_server_of: Callable[[tuple[int, int]], XServer], rig: Rig, tmp_path: Path, shots: Path
) -> None:
    settings = tmp_path / "settings.ini"
    large = x_server_of(SCREENS[2])
    first = _start(rig, large, settings)
    first.wait_ready(b"DONE GET_SPEED")
    large.xdotool("windowmove", first.window, "150", "90")
    wait_for(lambda: first.geometry()[0] >= 150, 10.0, "the window moved")
    kept = first.geometry()
    first.close()  # saves the geometry
    assert kept[0] + kept[2] > SCREENS[0][0] and kept[1] + kept[3] > SCREENS[0][1]

    small = x_server_of(SCREENS[0])
    again = _start(rig, small, settings)
    again.wait_ready(b"DONE GET_SPEED")
    geometry = _settled_geometry(again)
    again.screenshot(shots / f"remembered-on-{label(small.size)}.png")
    print(f"remembered {kept} on {label(large.size)}, opened as {geometry} on {label(small.size)}")
    assert not _off_screen(again), _off_screen(again)
