"""The panel keeps the position it counts for a Visiomex port, once Home or Set Home started the
count, where motionctl reads it: a `move X Y` in a later motionctl run goes on from there."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.common.settings import read_counted_position
from app.window.main_window import MainWindow
from tests.support import e2e as e2e_support
from tests.support.e2e import sent

pytestmark = pytest.mark.timeout(60)
URL = "sim://visiomex?instant=1"


def _jog_x(qtbot, window: MainWindow, to: tuple[float, float, float]) -> None:
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == to, timeout=8000)


def test_the_panel_keeps_its_count_for_motionctl(qtbot, window: MainWindow, tmp_path: Path) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device(URL, "visiomex", 9600, "seed")
    window.jog_panel.set_step(1)
    _jog_x(qtbot, window, (1.0, 0.0, 0.0))
    # Nothing counted yet on this fresh connection: no count is kept.
    assert read_counted_position(window.settings, "visiomex", URL) is None

    qtbot.waitUntil(window.coordinates.home_button.isEnabled, timeout=5000)
    qtbot.mouseClick(window.coordinates.home_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(
        lambda: read_counted_position(window.settings, "visiomex", URL) == (0.0, 0.0, 0.0),
        timeout=8000,
    )
    qtbot.waitUntil(window.coordinates.home_button.isEnabled, timeout=5000)
    _jog_x(qtbot, window, (1.0, 0.0, 0.0))
    qtbot.waitUntil(
        lambda: read_counted_position(window.settings, "visiomex", URL) == (1.0, 0.0, 0.0),
        timeout=8000,
    )

    log = tmp_path / "host.log"
    moved = e2e_support.motionctl("visiomex", URL, "move", "3", "0", log=log, timeout=30)
    assert moved.returncode == 0, moved.stderr
    assert [r.data for r in sent(log)] == [b"MLP0002000P0000000"]  # from 1, as the panel counted
    assert moved.stdout.strip() == "3.00 0.00 0.00 (counted, not measured)"
