"""A paused program: the device works through its queue, and the window follows it.

Pause sends nothing more, but the laser robot executes what it has queued: the executed count
and the position keep following the device while paused; the time left gives way to "paused",
and goes once the program is stopped.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import Qt

from app.window.main_window import MainWindow

pytestmark = pytest.mark.timeout(60)

POINTS = 300


def _point(i: int) -> tuple[float, float]:
    return float(i % 10), float(i // 10)


def _figure(text: str, name: str) -> int:
    found = re.search(rf"{name} (\d+)", text)
    return int(found.group(1)) if found else 0


def test_while_paused_the_count_and_position_follow_the_device(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device("sim://laser-frame", "laser-frame", 115200)
    panel = window.devices.program
    path = tmp_path / "grid.csv"
    rows = [f"{x:g},{y:g},0,40" for x, y in map(_point, range(POINTS))]  # 40 mm/s: seconds
    path.write_text("x,y,z,speed\n" + "\n".join(rows) + "\n")
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: "s left" in panel.figures.text(), timeout=15000)
    qtbot.waitUntil(lambda: _figure(panel.figures.text(), "acknowledged") >= 40, timeout=15000)

    qtbot.mouseClick(panel.pause_button, Qt.MouseButton.LeftButton)
    assert "paused" in panel.figures.text() and "s left" not in panel.figures.text()
    at_pause = panel.progress.value()
    device = window.worker.session.simulator  # type: ignore[union-attr]
    # The device empties its queue: the count and the readout follow it, still paused.
    qtbot.waitUntil(lambda: device.queue_length() == 0 and not device.is_running(), timeout=20000)
    acknowledged = _figure(panel.figures.text(), "acknowledged")
    assert acknowledged < POINTS
    qtbot.waitUntil(lambda: panel.progress.value() == acknowledged, timeout=5000)
    assert panel.progress.value() > at_pause
    last = _point(acknowledged - 1)
    qtbot.waitUntil(lambda: window.readout.position()[:2] == last, timeout=5000)  # type: ignore[index]
    assert "paused" in panel.figures.text() and "s left" not in panel.figures.text()
    assert panel.pause_button.text() == "Resume"

    qtbot.mouseClick(panel.stop_button, Qt.MouseButton.LeftButton)
    assert "s left" not in panel.figures.text()
    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=10000)
    assert "executed" in panel.figures.text()
    assert "s left" not in panel.figures.text() and "paused" not in panel.figures.text()
