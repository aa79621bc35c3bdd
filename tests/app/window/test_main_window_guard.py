"""The window and the motion guard: the console's send line cannot move the stage out of its box,
bytes the protocol cannot read go only once confirmed, and the readout says when the stage is
outside its travel limits."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QMessageBox

from app.common.settings import write_travel
from app.window.main_window import MainWindow
from drivers.device.travel import TravelLimits

pytestmark = pytest.mark.timeout(40)

SIM = "sim://coxiris?speed=100"
BOX = ((-50.0, 50.0), (-50.0, 50.0), (0.0, 10.0))
QUIET_MS = 300  # a negative check ("nothing was sent") waits this long after a sync point


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device(SIM, "coxiris", 115200)


def _sent(win: MainWindow) -> list[bytes]:
    win.console.flush()
    return [d for k, d, _ in win.console.records() if k == "tx"]


def _type(qtbot, win: MainWindow, text: str) -> None:
    """Type a line in the console's send line and press Enter, as an operator does."""
    edit = win.console.send_edit
    edit.setFocus()
    edit.clear()
    qtbot.keyClicks(edit, text)
    qtbot.keyClick(edit, Qt.Key.Key_Return)


def test_the_send_line_cannot_move_the_stage_out_of_its_box(qtbot, window: MainWindow) -> None:
    write_travel(window.settings, "coxiris", SIM, TravelLimits(BOX))
    _connect(qtbot, window)
    _type(qtbot, window, "ABSOLUTE_MOVE 100 0 0")
    qtbot.waitUntil(lambda: "X 100 mm is outside" in window.status_line.message(), timeout=5000)
    qtbot.wait(QUIET_MS)
    assert not [d for d in _sent(window) if b"MOVE" in d]
    _type(qtbot, window, "ABSOLUTE_MOVE 20 0 0")
    qtbot.waitUntil(lambda: window.readout.position() == (20.0, 0.0, 0.0), timeout=5000)


def test_unreadable_bytes_go_only_once_confirmed(
    qtbot, window: MainWindow, monkeypatch: pytest.MonkeyPatch
) -> None:
    write_travel(window.settings, "coxiris", SIM, TravelLimits(BOX))
    _connect(qtbot, window)
    window.console.send_line.set_line_ending(b"")  # the device would wait for the rest
    asked: list[str] = []

    def answer(reply: QMessageBox.StandardButton):
        def question(parent, title, text, *args):
            asked.append(text)
            return reply

        return question

    monkeypatch.setattr(QMessageBox, "question", answer(QMessageBox.StandardButton.No))
    _type(qtbot, window, "ABSOLUTE_MOVE 100 0")
    assert asked and "X -50..50" in asked[0]
    assert "not sent" in window.status_line.message()
    qtbot.wait(QUIET_MS)
    assert not [d for d in _sent(window) if b"ABSOLUTE_MOVE 100" in d]
    monkeypatch.setattr(QMessageBox, "question", answer(QMessageBox.StandardButton.Yes))
    _type(qtbot, window, "GET_I")
    qtbot.waitUntil(lambda: any(d.startswith(b"GET_I") for d in _sent(window)), timeout=5000)
    assert len(asked) == 2


def test_the_readout_says_the_stage_is_outside_its_box(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.coordinates.go_requested.emit("absolute", (100.0, 0.0, 0.0))
    qtbot.waitUntil(lambda: window.readout.position() == (100.0, 0.0, 0.0), timeout=5000)
    label = window.findChild(QLabel, "positionOutsideTravel")
    assert label is not None and label.isHidden()
    window.machine.apply_travel(TravelLimits(BOX))  # as the Travel limits dialog does on OK
    assert not label.isHidden()
    assert label.text() == "outside the travel limits: X 100.00 mm (-50.00..50.00)"
    window.jog_panel.jog_requested.emit("x", -10.0)  # back towards the box: allowed
    qtbot.waitUntil(lambda: window.readout.position() == (90.0, 0.0, 0.0), timeout=5000)
    qtbot.waitUntil(lambda: "X 90.00 mm" in label.text(), timeout=5000)
    window.coordinates.go_requested.emit("absolute", (40.0, 0.0, 0.0))
    qtbot.waitUntil(lambda: label.isHidden(), timeout=5000)
