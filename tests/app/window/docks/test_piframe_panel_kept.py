"""The panel keeps the pi-frame's commanded position for its port once a known place is reached
on the connection (never the origin it assumes at connection), where motionctl reads it: a jog
in a later motionctl run goes on from where the panel left the stage."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.common.settings import read_counted_position
from app.window.main_window import MainWindow
from tests.support import e2e as e2e_support
from tests.support.e2e import sent
from widgets import status_line as status

pytestmark = pytest.mark.timeout(60)
URL = "sim://pi-frame?instant=1"


def _idle(window: MainWindow) -> bool:
    return window.status_line.state() == status.IDLE


def test_the_panel_keeps_the_piframe_position_for_motionctl(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device(URL, "pi-frame", 115200)
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    # From an unknown place an absolute-target device would go elsewhere: refused, unsent.
    qtbot.waitUntil(lambda: "jog" in window.status_line.message(), timeout=5000)
    assert "refused: the position is unknown" in window.status_line.message()
    assert window.readout.status() == "uncounted"
    assert read_counted_position(window.settings, "pi-frame", URL) is None

    window.coordinates.go_requested.emit("absolute", (2.0, 1.0, 0.0))  # an absolute target
    qtbot.waitUntil(
        lambda: read_counted_position(window.settings, "pi-frame", URL) == (2.0, 1.0, 0.0),
        timeout=8000,
    )
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)

    log = tmp_path / "host.log"
    jogged = e2e_support.motionctl("pi-frame", URL, "jog", "1", "0", "0", log=log, timeout=30)
    assert jogged.returncode == 0, jogged.stderr
    frame = sent(log)[0].data
    assert struct.unpack(">B3h", frame[2:9]) == (1, 300, 100, 0)  # Linear to (3, 1, 0) mm
    assert jogged.stdout.strip() == "3.00 1.00 0.00 (commanded, not measured)"
