"""An X11 auto-repeat pair that Qt delivered as a real release and a real press (a loaded
machine: the press was not read yet when Qt handled the release) starts no jog after the stop.

The key events here are made by the test with the timestamps X gives such a pair (the same
server time), so these prove the key handlers and what follows them, not Qt's xcb plugin: the
real-input check is tests/acceptance/test_held_key.py.
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import QEvent, Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QApplication, QWidget

from app.window.main_window import MainWindow
from widgets import status_line as status
from widgets._key_pairs import KeyReleases
from widgets.jog_panel import JogPanel

pytestmark = pytest.mark.timeout(40)

PRESS, RELEASE, RIGHT = QEvent.Type.KeyPress, QEvent.Type.KeyRelease, Qt.Key.Key_Right
QUIET_MS = 300  # a negative check ("nothing more was sent") waits this long after a sync point


def _send(target: QWidget, kind: QEvent.Type, key: Qt.Key, time_ms: int) -> None:
    """Deliver a key event (not flagged auto-repeat) of server time `time_ms`, through the
    application (its event filters see it)."""
    event = QKeyEvent(kind, key, Qt.KeyboardModifier.NoModifier, "", False)
    event.setTimestamp(time_ms)
    QApplication.sendEvent(target, event)


class Jogs:
    """What a panel emitted: "jog" per jog started, "released" per held jog ended."""

    def __init__(self, panel: JogPanel) -> None:
        self.said: list[str] = []
        panel.jog_requested.connect(lambda *_: self.said.append("jog"))
        panel.jog_released.connect(lambda: self.said.append("released"))


def test_a_press_at_its_release_time_starts_no_jog_handler_only(qtbot) -> None:
    panel = JogPanel()
    qtbot.addWidget(panel)
    jogs = Jogs(panel)
    _send(panel, PRESS, RIGHT, 10_000)
    _send(panel, RELEASE, RIGHT, 10_660)  # the split pair: the jog ends at once
    assert jogs.said == ["jog", "released"] and panel.held() is None
    _send(panel, PRESS, RIGHT, 10_660)  # ...its press: the key is still down
    assert jogs.said == ["jog", "released"] and panel.held() is None
    _send(panel, RELEASE, RIGHT, 10_900)  # the real release: a step still under way stops
    assert jogs.said == ["jog", "released", "released"] and panel.held() is None
    _send(panel, RELEASE, RIGHT, 10_950)  # said once: a stray release says nothing more
    assert jogs.said == ["jog", "released", "released"]
    _send(panel, PRESS, RIGHT, 11_400)  # pressed again: it jogs
    assert jogs.said == ["jog", "released", "released", "jog"] and panel.held() == ("x", 1.0)


def test_a_press_a_millisecond_after_its_release_pairs_with_it_handler_only(qtbot) -> None:
    panel = JogPanel()
    qtbot.addWidget(panel)
    jogs = Jogs(panel)
    _send(panel, PRESS, Qt.Key.Key_Up, 500)
    _send(panel, RELEASE, Qt.Key.Key_Up, 1_000)
    _send(panel, PRESS, Qt.Key.Key_Up, 1_001)
    _send(panel, PRESS, Qt.Key.Key_Down, 1_000)  # another key at that time: a press of its own
    assert jogs.said == ["jog", "released", "jog"] and panel.held() == ("y", -1.0)


def test_unknown_times_never_pair_handler_only(qtbot) -> None:
    """Events without a time (0, as QTest's widget key clicks make) are taken as they say."""
    panel = JogPanel()
    qtbot.addWidget(panel)
    jogs = Jogs(panel)
    for _ in range(2):
        _send(panel, PRESS, RIGHT, 0)
        _send(panel, RELEASE, RIGHT, 0)
    assert jogs.said == ["jog", "released", "jog", "released"]


def test_a_step_key_pair_changes_the_step_once_handler_only(qtbot) -> None:
    panel = JogPanel()
    qtbot.addWidget(panel)
    panel.set_key_map({}, {Qt.Key.Key_BracketRight.value: 1}, "")
    panel.set_step(1.0)
    _send(panel, PRESS, Qt.Key.Key_BracketRight, 2_000)
    _send(panel, RELEASE, Qt.Key.Key_BracketRight, 2_660)
    _send(panel, PRESS, Qt.Key.Key_BracketRight, 2_660)
    assert panel.step() == 10.0


def test_release_times_pair_within_a_millisecond() -> None:
    releases = KeyReleases()
    assert not releases.pairs(RIGHT.value, 7_000)  # never released
    releases.released(RIGHT.value, 7_000)
    assert releases.pairs(RIGHT.value, 7_000)
    assert releases.pairs(RIGHT.value, 7_001) and releases.pairs(RIGHT.value, 6_999)
    assert not releases.pairs(RIGHT.value, 7_002)
    assert not releases.pairs(RIGHT.value, 0)  # a press of unknown time
    assert not releases.pairs(Qt.Key.Key_Left.value, 7_000)
    releases.released(RIGHT.value, 0)  # a release of unknown time forgets nothing
    assert releases.pairs(RIGHT.value, 7_000)


def test_a_split_pair_after_the_stop_moves_the_laser_no_more_handler_only(
    qtbot, window: MainWindow
) -> None:
    """The reported case: a held Right on laser-frame, its release sent STOP, then the press of
    the split pair came: the stage stays where the stop left it."""
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device("sim://laser-frame", "laser-frame", 115200)
    window.speed.set_value(10)
    window.speed.apply()
    qtbot.waitUntil(
        lambda: window.status_line.state() == status.IDLE and window.job_desk.jog_job is None,
        timeout=5000,
    )
    window.jog_panel.set_step(10)  # 1 s a step at 10 mm/s
    view = window.view2d
    view.setFocus()
    qtbot.waitUntil(lambda: "keys active" in window.jog_panel.hint_label.text(), timeout=3000)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    _send(view, PRESS, RIGHT, 50_000)
    qtbot.waitUntil(lambda: device.position()[0] > 4.0, timeout=5000)  # held, not a tap
    _send(view, RELEASE, RIGHT, 50_660)  # the stop goes now
    _send(view, PRESS, RIGHT, 50_660)
    assert window.jog_panel.held() is None
    qtbot.waitUntil(
        lambda: window.status_line.state() == status.IDLE and window.job_desk.jog_job is None,
        timeout=5000,
    )
    stopped = device.position()[0]
    assert 4.0 < stopped < 10.0
    qtbot.wait(QUIET_MS)
    assert device.position()[0] == pytest.approx(stopped, abs=1e-6)
    assert [values[0] for word, values in device.executed if word == 0x01] == [10.0]
    _send(view, RELEASE, RIGHT, 51_200)  # the real release: nothing to end
    qtbot.wait(QUIET_MS)
    assert [values[0] for word, values in device.executed if word == 0x01] == [10.0]


def test_a_split_pair_taken_for_a_tap_still_stops_at_the_real_release_handler_only(
    qtbot, window: MainWindow
) -> None:
    """Seen in CI under load: the split pair came within a tap's 0.3 s, so its release sent no
    STOP and the step ran on; the real release later must stop it (laser-frame), not let the
    whole 10 mm go after the operator let go."""
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device("sim://laser-frame", "laser-frame", 115200)
    window.speed.set_value(10)
    window.speed.apply()
    qtbot.waitUntil(
        lambda: window.status_line.state() == status.IDLE and window.job_desk.jog_job is None,
        timeout=5000,
    )
    window.jog_panel.set_step(10)  # 1 s a step at 10 mm/s
    view = window.view2d
    view.setFocus()
    qtbot.waitUntil(lambda: "keys active" in window.jog_panel.hint_label.text(), timeout=3000)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    _send(view, PRESS, RIGHT, 60_000)
    _send(view, RELEASE, RIGHT, 60_040)  # split at once: within a tap, no stop
    _send(view, PRESS, RIGHT, 60_040)
    assert window.jog_panel.held() is None
    qtbot.waitUntil(lambda: device.position()[0] > 4.0, timeout=5000)  # the step runs on
    _send(view, RELEASE, RIGHT, 60_600)  # the real release
    qtbot.waitUntil(
        lambda: window.status_line.state() == status.IDLE and window.job_desk.jog_job is None,
        timeout=5000,
    )
    stopped = device.position()[0]
    assert 4.0 < stopped < 10.0  # stopped where it was, not run to the step's end
    assert [values[0] for word, values in device.executed if word == 0x01] == [10.0]
