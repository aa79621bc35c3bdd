"""The main window as an operator uses it: where the jog keys act, held jogs, estimated moves,
travel limits, device errors, Set Home, a laptop screen, Stop and disconnect."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect, Qt
from PySide6.QtWidgets import QApplication, QDockWidget, QMenu, QWidget

from app.common.settings import write_travel
from app.window.main_window import MainWindow
from drivers.device.travel import TravelLimits
from tests.support.relay import wait_in_gui

pytestmark = pytest.mark.timeout(30)

SIM = "sim://coxiris?speed=100"
SLOW_SIM = "sim://coxiris?speed=10"
BOX = ((-5.0, 5.0), (-5.0, 5.0), (0.0, 2.0))
QUIET_MS = 300  # a negative check ("nothing was sent") waits this long after a sync point
# The offscreen platform cannot raise a popup or grab the keyboard for it, and says so.
offscreen_popup = pytest.mark.qt_log_ignore(
    r"^This plugin does not support raise\(\)$",
    r"^This plugin does not support grabbing the keyboard$",
)


def _connect(qtbot, win: MainWindow, url: str = SIM) -> None:
    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device(url, "coxiris", 115200)


def _records(win: MainWindow) -> list[tuple[str, bytes, float]]:
    win.console.flush()
    return win.console.records()


def _moves_sent(win: MainWindow) -> list[bytes]:
    """Every DELTA_MOVE line written to the device so far."""
    return [d for k, d, _ in _records(win) if k == "tx" and d.startswith(b"DELTA_MOVE")]


def _max_moves_in_flight(win: MainWindow) -> int:
    """Scanning the traffic in time order: the most DELTA_MOVEs ever sent without their DONE."""
    in_flight = worst = 0
    received = b""
    done_seen = 0
    for kind, data, _ in _records(win):
        if kind == "tx" and data.startswith(b"DELTA_MOVE"):
            in_flight += 1
        elif kind == "rx":
            received += data  # a reply may come in pieces: count DONEs in the whole stream
            done_now = received.count(b"DONE DELTA_MOVE")
            in_flight -= done_now - done_seen
            done_seen = done_now
        worst = max(worst, in_flight)
    return worst


def _idle(win: MainWindow) -> bool:
    return win.status_line.state() == "idle" and win.jog_panel.held() is None


def _rect_in(widget: QWidget, ancestor: QWidget) -> QRect:
    return QRect(widget.mapTo(ancestor, QPoint(0, 0)), widget.size())


# -- where the jog keys act ----------------------------------------------------------------


@offscreen_popup
def test_arrow_keys_in_an_open_drop_down_do_not_jog(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    combo = window.console.mode_combo
    combo.showPopup()
    qtbot.waitUntil(lambda: QApplication.activePopupWidget() is not None, timeout=3000)
    popup = QApplication.activePopupWidget()
    assert "a menu or list is open" in window.jog_panel.hint_label.text()
    view = combo.view()
    start_row = view.currentIndex().row()
    for _ in range(2):
        qtbot.keyPress(QApplication.focusWidget() or popup, Qt.Key.Key_Down)
    qtbot.waitUntil(lambda: view.currentIndex().row() != start_row, timeout=3000)  # the list had it
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == []
    assert window.jog_panel.held() is None
    qtbot.keyClick(QApplication.focusWidget() or popup, Qt.Key.Key_Escape)  # the list's Escape
    qtbot.waitUntil(lambda: QApplication.activePopupWidget() is None, timeout=3000)
    assert _moves_sent(window) == []


@offscreen_popup
def test_arrow_keys_in_an_open_menu_do_not_jog(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    bar = window.menuBar()
    motion_action = next(a for a in bar.actions() if "Motion" in a.text())
    view_action = next(a for a in bar.actions() if "View" in a.text())
    bar.setActiveAction(motion_action)
    qtbot.waitUntil(lambda: QApplication.activePopupWidget() is motion_action.menu(), timeout=3000)
    qtbot.keyPress(QApplication.activePopupWidget(), Qt.Key.Key_Right)
    # Right walks the menu bar to the next menu: the key went to the menu, not to the jog
    qtbot.waitUntil(lambda: QApplication.activePopupWidget() is view_action.menu(), timeout=3000)
    qtbot.keyPress(QApplication.activePopupWidget(), Qt.Key.Key_Left)
    qtbot.waitUntil(lambda: QApplication.activePopupWidget() is motion_action.menu(), timeout=3000)
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == []
    assert window.jog_panel.held() is None
    popup = QApplication.activePopupWidget()
    assert isinstance(popup, QMenu)
    qtbot.keyClick(popup, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: QApplication.activePopupWidget() is None, timeout=3000)
    assert _moves_sent(window) == []


def test_arrow_keys_belong_to_a_text_field_and_jog_from_the_view(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(1)
    edit = window.console.send_edit
    edit.setText("GET_ID")
    edit.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is edit, timeout=3000)
    assert "keys off" in window.jog_panel.hint_label.text()
    edit.setCursorPosition(3)
    qtbot.keyClick(edit, Qt.Key.Key_Right)
    qtbot.keyClick(edit, Qt.Key.Key_Right)
    assert edit.cursorPosition() == 5  # the field took the arrow keys
    qtbot.keyClick(edit, Qt.Key.Key_Up)
    qtbot.keyClick(edit, Qt.Key.Key_PageDown)
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == []

    window.view2d.setFocus()
    qtbot.waitUntil(lambda: "keys active" in window.jog_panel.hint_label.text(), timeout=3000)
    qtbot.keyClick(window.view2d, Qt.Key.Key_Right)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=5000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    assert [m.strip() for m in _moves_sent(window)] == [b"DELTA_MOVE 1 0 0"]


# -- held jogs -----------------------------------------------------------------------------


def test_held_key_steps_one_at_a_time_and_stops_on_release(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    step = 1.0
    window.jog_panel.set_step(step)
    window.view2d.setFocus()
    qtbot.waitUntil(lambda: "keys active" in window.jog_panel.hint_label.text(), timeout=3000)
    qtbot.keyPress(window.view2d, Qt.Key.Key_Right)
    qtbot.waitUntil(lambda: len(_moves_sent(window)) >= 3, timeout=5000)
    qtbot.keyRelease(window.view2d, Qt.Key.Key_Right)
    at_release = len(_moves_sent(window))
    assert window.jog_panel.held() is None
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    moves = _moves_sent(window)
    assert at_release <= len(moves) <= at_release + 1
    assert {m.strip() for m in moves} == {b"DELTA_MOVE 1 0 0"}
    qtbot.waitUntil(
        lambda: window.readout.position() == (len(moves) * step, 0.0, 0.0), timeout=3000
    )
    assert _max_moves_in_flight(window) == 1
    qtbot.wait(QUIET_MS)  # and nothing more once released and settled
    assert len(_moves_sent(window)) == len(moves)


def test_taps_during_a_step_queue_nothing(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://coxiris?speed=10")
    window.view2d.setFocus()
    qtbot.waitUntil(lambda: "keys active" in window.jog_panel.hint_label.text(), timeout=3000)
    window.jog_panel.set_step(2)
    qtbot.keyClick(window.view2d, Qt.Key.Key_Right)  # a 0.2 s step starts
    qtbot.waitUntil(lambda: len(_moves_sent(window)) == 1, timeout=3000)
    qtbot.keyClick(window.view2d, Qt.Key.Key_Up)  # taps during it, released before its end:
    qtbot.keyClick(window.view2d, Qt.Key.Key_Left)  # no step after it (issue 19, item 5)
    qtbot.waitUntil(lambda: window.readout.position() == (2.0, 0.0, 0.0), timeout=3000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    qtbot.wait(QUIET_MS)
    assert [m.strip() for m in _moves_sent(window)] == [b"DELTA_MOVE 2 0 0"]
    assert _max_moves_in_flight(window) == 1


def test_held_jog_button_steps_until_released(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(1)
    button = window.jog_panel.buttons[("y", 1.0)]
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: len(_moves_sent(window)) >= 2, timeout=5000)
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    at_release = len(_moves_sent(window))
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    moves = _moves_sent(window)
    assert at_release <= len(moves) <= at_release + 1
    qtbot.waitUntil(
        lambda: window.readout.position() == (0.0, float(len(moves)), 0.0), timeout=3000
    )
    assert _max_moves_in_flight(window) == 1


# -- a blocking move -----------------------------------------------------------------------


def test_position_is_estimated_while_the_device_is_silent(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, SLOW_SIM)
    target = (40.0, 25.0, 10.0)
    window.coordinates.go_requested.emit("absolute", target)
    qtbot.waitUntil(lambda: window.readout.status() == "estimated", timeout=3000)
    seen_moving: list[bool] = []

    def moving_between() -> None:
        seen_moving.append(window.status_line.state() == "moving")
        position = window.readout.position()
        assert position is not None and 1.0 < position[0] < 39.0

    qtbot.waitUntil(moving_between, timeout=5000)
    assert seen_moving[-1], window.status_line.state()
    assert window.readout.status() == "estimated"
    assert window.view2d.is_estimated()
    assert _moves_sent(window) == []  # ABSOLUTE_MOVE, not a jog
    window.console.flush()
    assert "ABSOLUTE_MOVE 40 25 10" in window.console.text()

    def arrived() -> None:
        assert window.readout.position() == target
        assert window.readout.status() == "live"
        assert window.status_line.state() == "idle"

    qtbot.waitUntil(arrived, timeout=10000)
    assert not window.view2d.is_estimated()


# -- travel limits -------------------------------------------------------------------------


def test_travel_limits_refuse_then_clamp_a_jog(qtbot, window: MainWindow) -> None:
    write_travel(window.settings, "coxiris", SIM, TravelLimits(BOX))
    _connect(qtbot, window)
    assert window.coordinates.box() == BOX
    assert window.view2d.workspace() == BOX
    window.jog_panel.jog_requested.emit("x", 10.0)

    def refused() -> None:
        assert "travel limits" in window.status_line.message()
        assert window.status_line.message_kind() == "error"

    qtbot.waitUntil(refused, timeout=5000)
    assert "refused" in window.status_line.message()
    assert window.status_line.state() == "error"
    qtbot.wait(QUIET_MS)
    assert _moves_sent(window) == []
    assert window.readout.position() == (0.0, 0.0, 0.0)

    write_travel(window.settings, "coxiris", SIM, TravelLimits(BOX, clamp=True))
    _connect(qtbot, window)  # the saved limits are read again on connecting
    window.jog_panel.jog_requested.emit("x", 10.0)
    qtbot.waitUntil(lambda: window.readout.position() == (5.0, 0.0, 0.0), timeout=5000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    assert "clamped" in window.status_line.message()
    assert window.status_line.message_kind() != "error"
    assert [m.strip() for m in _moves_sent(window)] == [b"DELTA_MOVE 5 0 0"]


# -- device errors -------------------------------------------------------------------------


def test_unknown_console_command_is_an_error_until_the_next_success(
    qtbot, window: MainWindow
) -> None:
    _connect(qtbot, window)
    with wait_in_gui(qtbot, window.worker.job_failed):
        window.console.send_requested.emit(b"FOO 1\n")
    qtbot.waitUntil(
        lambda: "does not know the command 'FOO'" in window.status_line.message(), timeout=3000
    )
    assert window.status_line.message_kind() == "error"
    assert window.status_line.state() == "error"

    window.jog_panel.set_step(1)
    with wait_in_gui(qtbot, window.worker.job_finished):
        window.jog_panel.jog_requested.emit("x", 1.0)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    assert window.status_line.message_kind() != "error"
    assert window.readout.position() == (1.0, 0.0, 0.0)

    window.console.flush()
    text = window.console.text()
    assert text.count("Available commands:") == 1, text  # as RX only, not again as a note
    records = _records(window)
    received = b"".join(data for kind, data, _ in records if kind == "rx")
    assert received.count(b"Available commands:") == 1
    notes = [data for kind, data, _ in records if kind == "note"]
    assert not [n for n in notes if b"Available commands" in n], notes


# -- Set Home ------------------------------------------------------------------------------


def test_set_home_shifts_the_trail(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    with wait_in_gui(qtbot, window.worker.job_finished):
        window.coordinates.go_requested.emit("absolute", (10.0, 0.0, 0.0))
    qtbot.waitUntil(lambda: window.readout.position() == (10.0, 0.0, 0.0), timeout=5000)
    assert window.buffer.view()[:, 1].max() >= 9.99
    assert window.view2d.target() is not None
    window.coordinates.confirm = lambda question: True
    qtbot.mouseClick(window.coordinates.set_home_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (0.0, 0.0, 0.0), timeout=5000)
    qtbot.waitUntil(lambda: _idle(window), timeout=5000)
    rows = window.buffer.view()
    assert len(rows) >= 2
    assert (rows[:, 1] <= 0.01).all(), rows[:, 1]
    assert rows[:, 1].min() <= -9.99  # the old path runs from -10 to 0
    assert window.view2d.target() is None


# -- layout --------------------------------------------------------------------------------


@pytest.mark.parametrize("size", [(1024, 640), (1280, 720)])
def test_window_fits_a_laptop_screen(qtbot, window: MainWindow, size: tuple[int, int]) -> None:
    width, height = size
    window.resize(width, height)
    qtbot.waitUntil(lambda: window.width() <= width and window.height() <= height, timeout=3000)
    QApplication.processEvents()
    hint = window.minimumSizeHint()
    assert hint.height() <= height and hint.width() <= width, hint
    assert window.height() <= height and window.width() <= width

    for dock in window.findChildren(QDockWidget):
        if not dock.isVisible():
            continue
        inner = dock.widget()
        assert dock.rect().contains(inner.geometry()), (dock.windowTitle(), inner.geometry())

    jog, coordinates = window.jog_panel, window.coordinates
    go = _rect_in(coordinates.go_button, window)
    assert not _rect_in(jog.step_spin, window).intersects(go)
    fields = [_rect_in(field, window) for field in coordinates.fields.values()]
    fields.append(go)
    for key, button in jog.buttons.items():
        mapped = _rect_in(button, window)
        for field in fields:
            assert not mapped.intersects(field), (key, mapped, field)


# -- Stop and disconnect -------------------------------------------------------------------


def test_stop_button_says_what_it_does_for_coxiris(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    stop = window.coordinates.stop_button
    assert stop.text() == "Drop queued"
    assert "no stop command" in stop.toolTip()
    assert "Drop queued" in window.stop_action.text().replace("&", "")


def test_disconnect_leaves_a_stale_readout(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    assert window.readout.status() == "live"
    window.disconnect_device()
    qtbot.waitUntil(lambda: window.connection_bar.state() == "disconnected", timeout=5000)
    assert window.readout.status() == "stale"
    assert window.readout.position() == (0.0, 0.0, 0.0)  # the last known one stays shown
    assert window.status_line.state() == "disconnected"
    assert not window.jog_panel.isEnabled()
