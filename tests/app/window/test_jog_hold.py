"""A held jog steps only while the key or button is held at each step's end (issue 19, item 5).

Real QKeyEvents go through QApplication (its event filter, as from the X server), in the orders
a busy machine delivers them: auto-repeats queued around the release, a release that reaches
the window together with the end of a step.
"""

from __future__ import annotations

import threading

import pytest
from PySide6.QtCore import QCoreApplication, QEvent, Qt, QTimer
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QApplication, QWidget

from app.window.device import jobs
from app.window.main_window import MainWindow
from widgets import status_line as status

pytestmark = pytest.mark.timeout(40)

SLOW_SIM = "sim://coxiris?speed=10"  # a 2 mm step takes 0.2 s
QUIET_MS = 300  # a negative check ("nothing more was sent") waits this long after a sync point
DEADLINE_S = 5.0


def _connect(qtbot, win: MainWindow, url: str = SLOW_SIM, protocol: str = "coxiris") -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(url, protocol, 115200)


def _key(kind: QEvent.Type, key: Qt.Key, auto_repeat: bool = False) -> QKeyEvent:
    return QKeyEvent(kind, key, Qt.KeyboardModifier.NoModifier, "", auto_repeat)


def _send(target: QWidget, kind: QEvent.Type, key: Qt.Key, auto_repeat: bool = False) -> None:
    """Deliver a key event now, through the application (its event filters see it)."""
    QApplication.sendEvent(target, _key(kind, key, auto_repeat))


def _post(target: QWidget, kind: QEvent.Type, key: Qt.Key, auto_repeat: bool = False) -> None:
    """Queue a key event, as the platform does, behind what is queued already."""
    QCoreApplication.postEvent(target, _key(kind, key, auto_repeat))


def _moves_sent(win: MainWindow) -> list[bytes]:
    win.console.flush()
    return [
        d.strip() for k, d, _ in win.console.records() if k == "tx" and d.startswith(b"DELTA_MOVE")
    ]


def _idle(win: MainWindow) -> bool:
    return win.status_line.state() == status.IDLE and win.job_desk.jog_job is None


def _keys_active(qtbot, win: MainWindow) -> QWidget:
    view = win.view2d
    view.setFocus()
    qtbot.waitUntil(lambda: "keys active" in win.jog_panel.hint_label.text(), timeout=3000)
    return view


class StepEnds:
    """Set (in the worker's thread) when the worker has reported a jog step's end: the window's
    queued job_finished is then waiting in the GUI thread's queue, ahead of anything posted."""

    def __init__(self, win: MainWindow) -> None:
        self.ended = threading.Event()
        win.worker.job_finished.connect(self._finished, Qt.ConnectionType.DirectConnection)

    def _finished(self, job: object, _result: object) -> None:
        if isinstance(job, jobs.MoveByJob):
            self.ended.set()


def test_autorepeat_presses_queued_around_the_release_start_no_step(
    qtbot, window: MainWindow
) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(2)
    view = _keys_active(qtbot, window)
    press, release, right = QEvent.Type.KeyPress, QEvent.Type.KeyRelease, Qt.Key.Key_Right
    # What a loaded X client reads in one burst while the first step runs: the real press,
    # auto-repeat pairs, one pair whose repeat flag was lost (the press looked real), the
    # real release, then auto-repeat presses still queued behind it.
    _send(view, press, right)
    for _ in range(3):
        _send(view, release, right, auto_repeat=True)
        _send(view, press, right, auto_repeat=True)
    _send(view, release, right)
    _send(view, press, right)
    _send(view, release, right, auto_repeat=True)
    _send(view, press, right, auto_repeat=True)
    _send(view, release, right)
    _send(view, press, right, auto_repeat=True)
    _send(view, press, right, auto_repeat=True)
    assert window.jog_panel.held() is None
    qtbot.waitUntil(lambda: window.readout.position() == (2.0, 0.0, 0.0), timeout=5000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == [b"DELTA_MOVE 2 0 0"]


def test_a_release_arriving_with_the_step_end_sends_no_next_step(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(2)
    view = _keys_active(qtbot, window)
    steps = StepEnds(window)
    _send(view, QEvent.Type.KeyPress, Qt.Key.Key_Right)
    assert window.jog_panel.held() == ("x", 2.0)
    # The GUI thread is busy (it processes nothing) until the step has ended on the device;
    # the key is let go meanwhile: its release is queued behind the step's end.
    assert steps.ended.wait(DEADLINE_S)
    _post(view, QEvent.Type.KeyRelease, Qt.Key.Key_Right)
    qtbot.waitUntil(lambda: window.jog_panel.held() is None, timeout=3000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == [b"DELTA_MOVE 2 0 0"]
    assert window.readout.position() == (2.0, 0.0, 0.0)


def test_a_key_still_held_at_the_step_end_steps_again(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(2)
    view = _keys_active(qtbot, window)
    steps = StepEnds(window)
    _send(view, QEvent.Type.KeyPress, Qt.Key.Key_Up)
    assert steps.ended.wait(DEADLINE_S)
    _post(view, QEvent.Type.KeyPress, Qt.Key.Key_Up, auto_repeat=True)  # held: X repeats it
    qtbot.waitUntil(lambda: len(_moves_sent(window)) == 2, timeout=5000)
    _send(view, QEvent.Type.KeyRelease, Qt.Key.Key_Up)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == [b"DELTA_MOVE 0 2 0"] * 2


def test_a_button_let_go_before_the_step_end_sends_no_next_step(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(2)
    button = window.jog_panel.buttons[("x", -1.0)]
    assert not button.autoRepeat()  # a held button never makes clicks of its own
    steps = StepEnds(window)
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    assert button.isDown() and window.jog_panel.held() == ("x", -2.0)
    assert steps.ended.wait(DEADLINE_S)
    # Let go; the mouse release is not delivered before the step's end is (a busy GUI).
    button.setDown(False)
    QTimer.singleShot(0, lambda: qtbot.mouseRelease(button, Qt.MouseButton.LeftButton))
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == [b"DELTA_MOVE -2 0 0"]


def test_a_held_jog_on_a_device_with_a_stop_halts_at_the_release(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://laser-frame", "laser-frame")
    window.speed.set_value(10)
    window.speed.apply()
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    window.jog_panel.set_step(10)  # 1 s a step
    view = _keys_active(qtbot, window)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    _send(view, QEvent.Type.KeyPress, Qt.Key.Key_Right)
    # The first step (the press's own) is whole; the next one, sent because the key is held,
    # is halted by the release.
    qtbot.waitUntil(lambda: device.position()[0] > 12.0, timeout=8000)
    _send(view, QEvent.Type.KeyRelease, Qt.Key.Key_Right)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    stopped = device.position()[0]
    assert 12.0 < stopped < 19.0
    qtbot.wait(QUIET_MS)
    assert device.position()[0] == pytest.approx(stopped, abs=1e-6)  # it stays there
    assert [values[0] for word, values in device.executed if word == 0x01] == [10.0, 20.0]
