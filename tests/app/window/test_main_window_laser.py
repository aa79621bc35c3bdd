"""The window on the simulated laser robot: a program loaded, previewed, streamed, stopped."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget

from app.window.main_window import MainWindow
from drivers.toolpath.point_program import read_program
from widgets import status_line as status

pytestmark = pytest.mark.timeout(60)


def _connect(qtbot, win: MainWindow, url: str) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(url, "laser-frame", 115200)


def _program(path: Path, count: int, speed: float = 1000.0) -> Path:
    lines = ["x,y,z,speed"] + [f"{i % 10},{i // 10},0,{speed}" for i in range(count)]
    path.write_text("\n".join(lines) + "\n")
    return path


def _acknowledged(figures: str) -> int:
    found = re.search(r"acknowledged (\d+)", figures)
    return int(found.group(1)) if found else 0


def test_a_program_streams_under_corruption_with_progress(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window, "sim://laser-frame?instant=1&corrupt=0.01&seed=5")
    dock = window.findChild(QDockWidget, "programPanelDock")
    assert dock is not None and dock.isVisible()
    panel = window.devices.program
    path = _program(tmp_path / "grid.csv", 100)
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    drawn = window.view2d.program()  # the whole path, before anything is sent
    assert [tuple(row[:2]) for row in drawn[1:]] == [(i % 10, i // 10) for i in range(100)]
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: panel.progress.value() == 100, timeout=40000)
    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=5000)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    moves = [values[:2] for word, values, *_ in device.executed if word == 0x01]
    assert moves == [(float(i % 10), float(i // 10)) for i in range(100)]  # once each, in order
    assert "executed 100" in panel.figures.text()
    saved = tmp_path / "grid.json"
    panel._choose_save_path = lambda: str(saved)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.save_button, Qt.MouseButton.LeftButton)
    assert [(p.x, p.y) for p in read_program(saved)] == [(i % 10, i // 10) for i in range(100)]
    assert window.readout.position()[:2] == (9.0, 9.0)  # type: ignore[index]


def test_a_malformed_program_is_refused_and_nothing_is_sent(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window, "sim://laser-frame?instant=1")
    panel = window.devices.program
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,z,speed\n1,2,3,4\n1,2,three,4\n")
    panel._choose_path = lambda: str(bad)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    assert "line 3" in panel.figures.text() and "three" in panel.figures.text()
    assert not panel.run_button.isEnabled()


def test_stop_flushes_the_queue(qtbot, window: MainWindow, tmp_path: Path) -> None:
    _connect(qtbot, window, "sim://laser-frame")
    panel = window.devices.program
    path = _program(tmp_path / "slow.csv", 40, speed=5.0)  # 1 mm moves at 5 mm/s: 8 s in all
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: panel.stop_button.isEnabled(), timeout=5000)
    # (the dock shows the progress at 10 Hz: a count may be skipped, so at least, not exactly)
    qtbot.waitUntil(lambda: _acknowledged(panel.figures.text()) >= 14, timeout=5000)
    qtbot.mouseClick(panel.stop_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=10000)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    assert device.queue_length() == 0
    assert len([w for w, *_ in device.executed if w == 0x01]) < 40


def test_stop_halts_a_move_under_way(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://laser-frame")
    window.speed.set_value(10)
    window.speed.apply()
    window.coordinates.set_values(100, 0, 0)  # 10 s at 10 mm/s
    qtbot.mouseClick(window.coordinates.go_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: (window.readout.position() or (0, 0, 0))[0] > 2, timeout=5000)
    assert window.stop_action.text() == "&Stop"
    window.stop_action.trigger()
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=5000)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    x = device.position()[0]
    assert 2 < x < 50
    assert window.readout.position()[0] == pytest.approx(x, abs=0.5)  # type: ignore[index]
