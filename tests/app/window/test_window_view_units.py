"""Settings → units in the window: the 2D and 3D views' axes, grid and scale follow it, on a
change and at start-up (the views are built after the first paint), and mm restores them."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.common.settings import open_settings
from app.window.main_window import MainWindow
from app.window.preferences import DEFAULTS, write_preferences
from tests.widgets.test_position_view_3d import needs_display
from widgets.position_view_3d import PositionView3D

pytestmark = [pytest.mark.timeout(60), pytest.mark.gl, needs_display]


def _scale(window: MainWindow) -> str:
    """The 3D grid's scale text."""
    view = window.view3d
    assert isinstance(view, PositionView3D), getattr(view, "reason", "")
    return view.scale_text()


def _assert_views_in(window: MainWindow, unit: str) -> None:
    view2d = window.view2d
    assert view2d.units() == unit
    assert view2d.xy_fit.shown["bottom"] == f"X ({unit})"
    assert view2d.time_fit.shown["left"] == f"position ({unit})"
    axis = view2d.xy_plot.getPlotItem().getAxis("bottom")
    assert axis.scale == pytest.approx(1 / 25.4 if unit == "in" else 1.0)
    assert _scale(window).endswith(f" {unit}")
    assert window.view3d.labels[0].text == f"X ({unit})"


def test_switching_to_inches_and_back_changes_the_views(qtbot, window: MainWindow) -> None:
    _assert_views_in(window, "mm")
    for view in (window.view2d, window.view3d):  # as the travel limits set it
        view.set_workspace(((-50.0, 50.0), (-25.0, 25.0), (0.0, 10.0)))
    box = window.view2d.workspace()
    window.tools.apply_preferences(dataclasses.replace(window.tools.prefs, units="in"))
    _assert_views_in(window, "in")
    assert window.view2d.workspace() == box  # drawn where it was, in mm
    assert _scale(window) == "grid 0.5 in"  # a 100 mm box: about ten half-inch cells
    window.tools.apply_preferences(dataclasses.replace(window.tools.prefs, units="mm"))
    _assert_views_in(window, "mm")
    assert _scale(window) == "grid 10 mm"


@pytest.fixture
def inch_window(qtbot, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[MainWindow]:
    """A window started with inches saved in its settings."""
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(tmp_path / "settings.ini"))
    write_preferences(open_settings(), dataclasses.replace(DEFAULTS, units="in"))
    win = MainWindow()
    qtbot.addWidget(win)
    win.show()
    qtbot.waitUntil(win.views.is_ready, timeout=10_000)
    yield win
    win.close()


def test_a_window_started_in_inches_builds_its_views_in_inches(inch_window) -> None:
    _assert_views_in(inch_window, "in")
