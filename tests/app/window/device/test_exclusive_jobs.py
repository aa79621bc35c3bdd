"""While a program, a macro or a parameter write runs, motion is off and refused out loud, never
queued to run after it (issue 19, item 6)."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QEvent, Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QApplication

from app.window.device import jobs
from app.window.main_window import MainWindow
from widgets import status_line as status

pytestmark = pytest.mark.timeout(60)

QUIET_MS = 500  # a negative check ("nothing was sent after it") waits this long after a sync
MOVE_LINEAR = 0x01  # the laser frame's queued move


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device("sim://laser-frame", "laser-frame", 115200)


def _program(path: Path, count: int, speed: float) -> Path:
    lines = ["x,y,z,speed"] + [f"{i * 0.5:g},0,0,{speed}" for i in range(1, count + 1)]
    path.write_text("\n".join(lines) + "\n")
    return path


def _moves_executed(win: MainWindow) -> list[tuple[float, float]]:
    device = win.worker.session.simulator  # type: ignore[union-attr]
    return [values[:2] for word, values, *_ in device.executed if word == MOVE_LINEAR]


def _tx_frames(win: MainWindow) -> int:
    win.console.flush()
    return sum(1 for kind, *_ in win.console.records() if kind == "tx")


def test_a_jog_during_a_program_is_refused_and_nothing_moves_after_it(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(30)
    panel = window.devices.program
    path = _program(tmp_path / "line.csv", 30, speed=10.0)  # 0.5 mm at 10 mm/s: 1.5 s in all
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: panel.stop_button.isEnabled(), timeout=5000)

    # Off, and saying why; Stop stays on.
    jog_button = window.jog_panel.buttons[("x", 1.0)]
    assert not jog_button.isEnabled() and not window.jog_panel.isEnabled()
    assert "keys off: run line.csv (30 points) is under way" in window.jog_panel.hint_label.text()
    assert not window.coordinates.go_button.isEnabled()
    assert not window.coordinates.home_button.isEnabled()
    assert not window.speed.isEnabled()
    assert window.coordinates.stop_button.isEnabled() and window.stop_action.isEnabled()
    assert panel.stop_button.isEnabled() and panel.pause_button.isEnabled()

    qtbot.mouseClick(jog_button, Qt.MouseButton.LeftButton)  # a disabled button: nothing
    view = window.view2d
    view.setFocus()
    QApplication.sendEvent(
        view, QKeyEvent(QEvent.Type.KeyPress, Qt.Key.Key_Right, Qt.KeyboardModifier.NoModifier)
    )
    assert "jog refused: run line.csv (30 points) is under way" in window.status_line.message()
    # A press that still gets through (it raced the disabling), the console, a macro's move:
    # refused, with the reason.
    window.jog_panel.jog_requested.emit("x", 30.0)
    assert "refused" in window.status_line.message()
    assert window.status_line.message_kind() == status.WARNING
    assert window.job_desk.jog_job is None and window.jog_panel.held() is None
    assert not window.submit_job(jobs.MoveToJob(30.0, 0.0, 0.0))
    assert "move to (30, 0, 0) mm refused: run line.csv" in window.status_line.message()
    assert not window.submit_job(jobs.RawJob(b"\x00"))

    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=20000)  # the program ended
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=5000)
    frames = _tx_frames(window)
    qtbot.wait(QUIET_MS)
    assert _moves_executed(window) == [(i * 0.5, 0.0) for i in range(1, 31)]  # no X = 30 after
    assert window.readout.position()[0] == pytest.approx(15.0, abs=0.01)  # type: ignore[index]
    # Nothing was queued behind it: only the idle polls follow (no move frame at all).
    assert _tx_frames(window) - frames <= 2
    assert _moves_executed(window) == [(i * 0.5, 0.0) for i in range(1, 31)]

    # On again once it ended: a jog now moves.
    assert window.jog_panel.isEnabled() and window.coordinates.go_button.isEnabled()
    assert "keys active" in window.jog_panel.hint_label.text()
    qtbot.mouseClick(window.jog_panel.buttons[("x", -1.0)], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: len(_moves_executed(window)) == 31, timeout=10000)
    assert _moves_executed(window)[-1] == (-15.0, 0.0)


def test_a_program_cannot_start_while_a_macro_runs(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    from app.common.macros import Macro

    _connect(qtbot, window)
    panel = window.devices.program
    path = _program(tmp_path / "line.csv", 3, speed=100.0)
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    assert panel.run_button.isEnabled()
    macro = Macro("slow", "laser-frame", ("speed 5", "move 5 0", "move 0 0"))  # 2 s of moves
    assert window.submit_job(jobs.MacroJob(macro))
    assert not panel.run_button.isEnabled()
    assert "Not now" in panel.run_button.toolTip()
    assert not window.jog_panel.isEnabled()
    toolpath = window.devices.programs.toolpath
    assert not window.submit_job(jobs.StreamJob(toolpath, name="line.csv"))
    assert not window.submit_job(jobs.MacroJob(macro))  # nor a second macro behind it
    assert "refused: macro slow" in window.status_line.message()
    qtbot.waitUntil(lambda: window.jog_panel.isEnabled(), timeout=15000)
    assert panel.run_button.isEnabled() and "Not now" not in panel.run_button.toolTip()
    assert [x for x, _ in _moves_executed(window)] == [5.0, 0.0]  # the macro's, nothing else


def test_motion_is_off_while_parameters_are_written_and_on_after_a_cancel(
    qtbot, window: MainWindow
) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device("sim://visiomex", "visiomex", 9600, "seed")
    window.layouts.switch("setup")  # the parameter editor is in Set up
    editor = window.parameters.editor
    qtbot.mouseClick(editor.write_all_button, Qt.MouseButton.LeftButton)  # 27 writes
    assert editor.writing()
    assert not window.jog_panel.isEnabled() and "under way" in window.jog_panel.hint_label.text()
    assert not window.submit_job(jobs.MoveByJob(1.0, 0.0, 0.0))
    assert "refused" in window.status_line.message()
    qtbot.mouseClick(editor.cancel_button, Qt.MouseButton.LeftButton)  # the rest is dropped
    qtbot.waitUntil(lambda: not editor.writing(), timeout=15000)
    qtbot.waitUntil(lambda: window.jog_panel.isEnabled(), timeout=5000)
    assert "under way" not in window.jog_panel.hint_label.text()
    assert window.coordinates.go_button.isEnabled()
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.jog_panel.buttons[("x", 1.0)], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=10000)
