"""The Program dock says what is true now (issue 28, items 11 and 24): Run off while no device
is connected, saying why; no last run's counts beside another file or device; one unit of
progress from loading to the end; a first time-left estimate near the program's own."""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QTabBar

from app.window.docks.program_dock import ProgramDock
from app.window.keyboard_jog import arrow_key_user
from app.window.main_window import MainWindow
from drivers.toolpath.streaming import StreamProgress
from tests.app.window.docks.test_program_dock import (
    GCODE,
    _connect,
    _gcode,
    _load,
    _parts,
    _run_to_end,
)
from tests.support.relay import wait_in_gui
from widgets.program_panel import ProgramPanel

pytestmark = pytest.mark.timeout(60)
# A device run move by move, and one that runs arcs itself (a run counts other things).
MODES = [("sim://coxiris?speed=100", "coxiris"), ("sim://pi-frame?instant=1", "pi-frame")]


def _program_on(
    qtbot, window: MainWindow, tmp_path: Path, url: str, protocol: str
) -> tuple[ProgramPanel, ProgramDock]:
    """The window connected to `url` (a pi-frame sent to a known place: its program needs one),
    the square program loaded."""
    _connect(qtbot, window, url, protocol)
    if protocol == "pi-frame":
        with wait_in_gui(qtbot, window.worker.job_finished, timeout=5000):
            window.coordinates.go_requested.emit("absolute", (0.0, 0.0, 0.0))
    _load(qtbot, window, _gcode(tmp_path))
    return _parts(window)


def test_run_is_off_while_disconnected_and_its_tooltip_says_why(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    panel, _ = _parts(window)
    _load(qtbot, window, _gcode(tmp_path))
    assert panel.run_button.text() and not panel.run_button.isEnabled()
    assert "Not now: not connected to a device" in panel.run_button.toolTip()
    _connect(qtbot, window, "sim://coxiris?speed=100", "coxiris")
    qtbot.waitUntil(panel.run_button.isEnabled, timeout=5000)
    assert "not connected" not in panel.run_button.toolTip()
    window.disconnect_device()
    qtbot.waitUntil(lambda: not panel.run_button.isEnabled(), timeout=5000)
    assert "not connected to a device" in panel.run_button.toolTip()


def test_run_is_off_while_the_pi_frame_position_is_unknown_and_says_why(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    """A fresh pi-frame (nothing kept for the port): its session says the position is not
    known, so Run is off with the reason; an absolute Go to makes it known, and Run on."""
    panel, _ = _parts(window)
    _connect(qtbot, window, "sim://pi-frame?instant=1", "pi-frame")
    _load(qtbot, window, _gcode(tmp_path))
    assert not panel.run_button.isEnabled()
    assert "Not now: the position is unknown" in panel.run_button.toolTip()
    with wait_in_gui(qtbot, window.worker.job_finished, timeout=5000):
        window.coordinates.go_requested.emit("absolute", (0.0, 0.0, 0.0))
    qtbot.waitUntil(panel.run_button.isEnabled, timeout=5000)
    assert "position is unknown" not in panel.run_button.toolTip()


@pytest.mark.parametrize(("url", "protocol"), MODES)
def test_the_progress_counts_one_unit_from_loading_to_the_end(
    qtbot, window: MainWindow, tmp_path: Path, url: str, protocol: str
) -> None:
    panel, dock = _program_on(qtbot, window, tmp_path, url, protocol)
    sources = len(GCODE.splitlines())
    loaded_total = panel.progress.maximum()
    assert loaded_total != sources  # the file's lines are not what a run counts
    totals: list[int] = []
    window.worker.stream_progress.connect(lambda state: totals.append(state.total))
    _run_to_end(qtbot, window)
    assert totals and set(totals) == {loaded_total}, (loaded_total, set(totals))
    assert panel.progress.maximum() == loaded_total == dock.instructions()


def test_the_last_runs_figures_go_with_another_file_and_another_device(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    panel, _ = _program_on(qtbot, window, tmp_path, *MODES[0])
    _run_to_end(qtbot, window)
    assert "sent " in panel.figures.text() and panel.progress.value() > 0
    _load(qtbot, window, _gcode(tmp_path, GCODE.replace("Y8", "Y7"), "other.nc"))
    assert "sent " not in panel.figures.text() and panel.progress.value() == 0
    _run_to_end(qtbot, window)
    assert "sent " in panel.figures.text()
    window.disconnect_device()
    qtbot.waitUntil(lambda: "sent " not in panel.figures.text(), timeout=5000)
    _connect(qtbot, window, "sim://pi-frame?instant=1", "pi-frame")
    qtbot.waitUntil(lambda: not _parts(window)[1].reading, timeout=5000)
    assert "sent " not in panel.figures.text() and panel.progress.value() == 0
    assert not panel.run_button.isEnabled()  # a fresh pi-frame: its position is not known yet
    assert "position is unknown" in panel.run_button.toolTip()


def test_the_first_time_left_is_near_the_programs_own_estimate(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    """81 instructions, a 9 s program: the first took 1.5 s (the move to the start and the
    set-up). The rate alone says 120 s left; the dock says about the program's 9 s."""
    panel, dock = _parts(window)
    _load(qtbot, window, _gcode(tmp_path))
    assert dock.summary is not None
    dock.summary = dataclasses.replace(dock.summary, seconds=9.0)
    panel.set_running(True)
    first = StreamProgress(81, sent=10, acknowledged=5, executed=1, started=time.monotonic() - 1.5)
    assert first.seconds_left() == pytest.approx(120.0, rel=0.05)
    dock._show_progress(first)
    left = panel.figures.text().split("about ")[1].split(" s left")[0]
    assert 7 <= float(left) <= 10, panel.figures.text()
    late = StreamProgress(81, sent=81, acknowledged=81, executed=60, started=time.monotonic() - 6)
    dock._show_progress(late)  # most of it run: the rate measured (6 s for 60: 2 s for 21)
    left = panel.figures.text().split("about ")[1].split(" s left")[0]
    assert float(left) == pytest.approx(2.1, abs=0.6)
    panel.set_running(False)


@pytest.mark.parametrize("stop", [False, True], ids=["ended", "stopped"])
def test_after_a_program_the_arrow_keys_jog_again(
    qtbot, window: MainWindow, tmp_path: Path, stop: bool
) -> None:
    """Run clicked (the focus on it), the program ends or is stopped: the keys are not left on
    the dock's tab bar (whose arrows switch tabs); → jogs X."""
    panel, _ = _program_on(qtbot, window, tmp_path, "sim://coxiris?speed=20", "coxiris")
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    # Run went off under the focus: Qt moved it on (to the tab bar in the issue, here maybe
    # elsewhere): wherever it went, it must come back where the keys jog
    qtbot.waitUntil(panel.stop_button.isEnabled, timeout=5000)
    tabs = [bar for bar in window.findChildren(QTabBar) if bar.isVisible()]
    assert tabs
    tabs[0].setFocus()  # where the issue saw it go (a tab bar), whatever the chain does here
    qtbot.waitUntil(tabs[0].hasFocus, timeout=2000)
    if stop:
        qtbot.mouseClick(panel.stop_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(panel.run_button.isEnabled, timeout=30000)
    focus = QApplication.focusWidget()
    assert not isinstance(focus, QTabBar) and arrow_key_user(focus) == "", focus
    window.jog_panel.set_step(1)
    qtbot.waitUntil(lambda: "keys off" not in window.jog_panel.hint_label.text(), timeout=5000)
    start = window.readout.position()
    assert start is not None
    qtbot.keyClick(focus or window, Qt.Key.Key_Right)
    qtbot.waitUntil(
        lambda: window.readout.position() == pytest.approx((start[0] + 1, *start[1:]), abs=0.01),
        timeout=10000,
    )
