"""Issue 28 item 22: once a device that cannot be asked reaches a known place, the status bar no
longer says its position is unknown."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from app.window.main_window import MainWindow
from widgets import status_line as status

pytestmark = pytest.mark.timeout(40)
UNKNOWN = "position unknown: the device cannot be asked; Home or Set Home to start counting"


def _connect(qtbot, window: MainWindow, url: str, protocol: str, baud: int) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device(url, protocol, baud, "seed")
    assert window.status_line.message() == UNKNOWN


def test_set_home_on_visiomex_replaces_position_unknown(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://visiomex?instant=1", "visiomex", 9600)
    window.coordinates.confirm = lambda question: True
    qtbot.waitUntil(window.coordinates.set_home_button.isEnabled, timeout=5000)
    qtbot.mouseClick(window.coordinates.set_home_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.status() == "live", timeout=5000)
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=5000)
    message = window.status_line.message()
    assert "position unknown" not in message
    assert message == "home set: the position is counted from here"
    window.console.flush()
    assert "home set: the position is counted from here" in window.console.text()
