"""Pause's tooltip says what Pause really does on the device connected: on laser-frame the
device runs the moves it holds; on the others the move under way finishes."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QPushButton

from app.window.main_window import MainWindow

pytestmark = pytest.mark.timeout(60)


def _pause_tip(window: MainWindow) -> str:
    button = window.findChild(QPushButton, "programPause")
    assert button is not None
    return button.toolTip()


def test_pause_says_what_it_does_on_each_device(qtbot, window: MainWindow) -> None:
    before = _pause_tip(window)
    assert "queued moves go on" in before  # no device: what it does depends on the device
    for url, protocol, says in (
        ("sim://laser-frame?instant=1", "laser-frame", "goes on running the moves it already"),
        ("sim://coxiris?instant=1", "coxiris", "The move under way finishes"),
        ("sim://pi-frame?instant=1", "pi-frame", "The move under way finishes"),
    ):
        with qtbot.waitSignal(window.settled, timeout=10_000):
            window.connect_device(url, protocol, 115200)
        tip = _pause_tip(window)
        assert says in tip, (protocol, tip)
        assert "no feed hold" in tip
    window.disconnect_device()
    qtbot.waitUntil(lambda: _pause_tip(window) == before, timeout=5000)
