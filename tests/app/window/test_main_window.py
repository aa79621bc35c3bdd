"""The main window against the simulated device, driven as an operator would."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton, QWidget

from app.window.main_window import MainWindow
from tests.support.relay import wait_in_gui

pytestmark = pytest.mark.timeout(30)

CONTRACT_NAMES = [
    "connectionBar",
    "jogPanel",
    "coordinateEntry",
    "speedControl",
    "positionReadout",
    "positionView3d",
    "positionView2d",
    "rawConsole",
]


def _connect(qtbot, win: MainWindow, url: str = "sim://coxiris?speed=100") -> None:
    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device(url, "coxiris", 115200)


def _position(win: MainWindow) -> tuple[float, float, float] | None:
    return win.readout.position()


def test_contract_object_names(window: MainWindow) -> None:
    for name in CONTRACT_NAMES:
        assert window.findChild(QWidget, name) is not None, name
    plus = [b for b in window.findChildren(QPushButton) if b.text() == "X+"]
    assert plus and plus[0].objectName() == "jogXPlus"


def test_controls_disabled_until_connected(qtbot, window: MainWindow) -> None:
    assert not window.jog_panel.isEnabled()
    _connect(qtbot, window)
    assert window.jog_panel.isEnabled()
    assert window.connection_bar.state() == "connected"


def test_jog_button_moves_the_stage_and_the_console_shows_it(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(10)
    button = window.findChild(QPushButton, "jogXPlus")
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: _position(window) == (10.0, 0.0, 0.0), timeout=5000)

    def console_shows_it() -> None:
        window.console.flush()
        assert "DELTA_MOVE 10 0 0" in window.console.text()
        assert "DONE DELTA_MOVE" in window.console.text()

    qtbot.waitUntil(console_shows_it, timeout=5000)
    assert len(window.buffer) >= 2


def test_keyboard_jog(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(1)
    window.view2d.setFocus()
    qtbot.keyClick(window.view2d, Qt.Key.Key_Up)
    # The step's end, not only its position: a press while a step is under way is not queued.
    qtbot.waitUntil(
        lambda: _position(window) == (0.0, 1.0, 0.0) and window.job_desk.jog_job is None,
        timeout=5000,
    )
    qtbot.keyClick(window.view2d, Qt.Key.Key_PageDown, Qt.KeyboardModifier.ShiftModifier)
    qtbot.waitUntil(lambda: _position(window) == (0.0, 1.0, -10.0), timeout=5000)


def test_go_to_home_and_set_home(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    entry = window.coordinates
    entry.set_values(10, -5, 2.5)
    with wait_in_gui(qtbot, window.worker.job_finished):
        entry.go_requested.emit("absolute", entry.values())
    qtbot.waitUntil(lambda: _position(window) == (10.0, -5.0, 2.5), timeout=5000)
    with wait_in_gui(qtbot, window.worker.job_finished):
        entry.home_requested.emit()
    qtbot.waitUntil(lambda: _position(window) == (0.0, 0.0, 0.0), timeout=5000)


def test_speed_change_reads_back_rounded(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    assert window.speed.speed_range() == (1.0, 100.0)
    with wait_in_gui(qtbot, window.worker.speed_changed) as changed:
        window.speed.speed_requested.emit(12.5)
    assert changed.args == [13.0]

    def console_shows_it() -> None:
        window.console.flush()
        assert "SET_SPEED 12.5" in window.console.text()

    qtbot.waitUntil(console_shows_it, timeout=5000)


def test_stop_reports_what_was_not_sent(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://coxiris?speed=1")
    window.jog_panel.set_step(100)
    with wait_in_gui(qtbot, window.worker.busy_changed):
        window.jog_panel.jog_requested.emit("x", 100.0)
    window.coordinates.go_requested.emit("relative", (0.0, 100.0, 0.0))
    window.job_desk.stop()
    window.console.flush()
    assert "1 command(s) not sent: relative move by (0, 100, 0) mm" in window.console.text()
    assert "not sent" in window.status_line.message()
    assert window.jog_panel.held() is None  # Stop also ends a held jog


def test_settings_are_saved_and_restored(qtbot, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(tmp_path / "s.ini"))
    first = MainWindow()
    qtbot.addWidget(first)
    first.jog_panel.set_step(10)
    first.connection_bar.set_port("loop://")
    first.settings.setValue("port", "loop://")
    first.close()
    second = MainWindow()
    qtbot.addWidget(second)
    assert second.jog_panel.step() == 10
    assert second.connection_bar.port() == "loop://"
    second.close()


@pytest.mark.gl
@pytest.mark.skipif(
    "DISPLAY" not in __import__("os").environ
    or __import__("os").environ.get("QT_QPA_PLATFORM") == "offscreen",
    reason="needs Xvfb or a display, and a platform that draws OpenGL (not offscreen)",
)
def test_3d_view_is_real_opengl_and_draws_the_trail(qtbot, window: MainWindow) -> None:
    from widgets.position_view_3d import PositionView3D

    assert isinstance(window.view3d, PositionView3D), getattr(window.view3d, "reason", "")
    _connect(qtbot, window)
    blank = window.view3d.grabFramebuffer()
    window.jog_panel.jog_requested.emit("x", 50.0)
    qtbot.waitUntil(lambda: _position(window) == (50.0, 0.0, 0.0), timeout=5000)
    window.view3d.refresh()
    qtbot.waitUntil(lambda: window.view3d.trail.visible(), timeout=2000)
    drawn = window.view3d.grabFramebuffer()
    assert drawn != blank  # the marker moved and a trail appeared


def test_ports_appearing_and_disappearing_are_noticed(
    qtbot, window: MainWindow, monkeypatch: pytest.MonkeyPatch
) -> None:
    from app.window.device import ports

    listing = [("/dev/ttyUSB0", "USB serial")]
    monkeypatch.setattr(ports, "list_serial_ports", lambda: list(listing))
    window.port_watcher.refresh()
    listing.append(("/dev/ttyACM0", "Arduino Uno"))
    window.port_watcher._check()
    assert "port /dev/ttyACM0 appeared" in window.status_line.message()
    listing.pop(0)
    window.port_watcher._check()
    assert "port /dev/ttyUSB0 disappeared" in window.status_line.message()
    combo = window.connection_bar.port_combo
    texts = " ".join(combo.itemText(i) for i in range(combo.count()))
    assert "/dev/ttyACM0" in texts and "sim://coxiris" in texts


def test_polling_rates_come_from_the_settings(qtbot, tmp_path: Path, monkeypatch) -> None:
    path = tmp_path / "rates.ini"
    path.write_text("[General]\npoll_moving_hz=5\npoll_idle_s=50\n")
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(path))
    win = MainWindow()
    qtbot.addWidget(win)
    assert win.worker.poll_moving_hz == 5.0
    assert win.worker.poll_idle_s == 10.0  # clamped: idle polling is never slower than 10 s
    win.close()


def test_menus_reset_views_and_toggle_panels(qtbot, window: MainWindow) -> None:
    titles = [action.text() for action in window.menuBar().actions()]
    assert titles == ["&File", "&Motion", "&View", "&Help"]
    view_menu = window.menuBar().actions()[2].menu()
    names = [action.text() for action in view_menu.actions()]
    assert "&Reset views" in names and "Console" in names
    console_toggle = next(a for a in view_menu.actions() if a.text() == "Console")
    assert not window.console.isVisible()  # Operate has no console
    console_toggle.trigger()
    assert window.console.isVisible()
    console_toggle.trigger()
    assert not window.console.isVisible()
    window.reset_views()


def test_export_from_the_menu(qtbot, window: MainWindow, tmp_path: Path) -> None:
    _connect(qtbot, window)
    target = tmp_path / "traffic.txt"
    window.console.ask_export_path = lambda: str(target)
    file_menu = window.menuBar().actions()[0].menu()
    next(a for a in file_menu.actions() if a.text().startswith("&Export")).trigger()
    assert "TX  GET_ID\\n" in target.read_text()


def test_window_adapts_to_a_two_axis_commanded_only_protocol(qtbot, window: MainWindow) -> None:
    from app.window.device.connect_options import DeviceInfo
    from drivers.protocols.capabilities import Capabilities, Completion

    caps = Capabilities(
        axes=("x", "y"),
        position_feedback=False,
        completion=Completion.ESTIMATE,
        speed_range=(1.0, 50.0),
    )
    window.connection._on_device_ready(DeviceInfo("sim://other", "other", "test device", caps))
    assert window.findChild(QPushButton, "jogXPlus").isEnabled()
    assert not window.findChild(QPushButton, "jogZPlus").isEnabled()
    assert not window.readout.is_measured()
    assert window.speed.speed_range() == (1.0, 50.0)


@pytest.mark.e2e
def test_reconnects_when_the_lost_port_comes_back_slot_only(qtbot, window: MainWindow) -> None:
    """Only the window's slot for a port the port list shows again; the worker's own watch for
    a lost port is tested with real processes in test_reconnect_real.py."""
    from tests.support.simproc import SimProcess

    sim = SimProcess("coxiris", "--speed", "100")
    try:
        with qtbot.waitSignal(window.settled, timeout=10000):
            window.connect_device(sim.path, "coxiris", 115200)
        window.jog_panel.jog_requested.emit("x", 3.0)
        qtbot.waitUntil(lambda: window.readout.position() == (3.0, 0.0, 0.0), timeout=5000)
        sim.kill()
        qtbot.waitUntil(lambda: window.connection_bar.state() == "error", timeout=5000)
        window.disconnect_device()  # the worker watches no more: only the slot reconnects
        qtbot.waitUntil(lambda: window.worker._watch is None, timeout=5000)
        sim = SimProcess("coxiris", "--speed", "100")  # a new device process
        # The kernel may hand out another pty number: the port that "comes back" is the old one
        # only when the numbers match, so announce the new path as the lost port's return.
        window.connection.last = (sim.path, "coxiris", 115200)
        with qtbot.waitSignal(window.settled, timeout=10000):
            window.port_watcher.port_added.emit(sim.path)
        assert window.connection_bar.state() == "connected"
        assert window.readout.position() == (0.0, 0.0, 0.0)  # re-read from the new device
        assert window.jog_panel.isEnabled()
    finally:
        if sim.proc.poll() is None:
            sim.stop()


def test_escape_stops(qtbot, window: MainWindow) -> None:
    window.worker.submit(__import__("app.window.device.jobs").window.device.jobs.HomeJob())
    qtbot.keyClick(window, Qt.Key.Key_Escape)
    assert "not sent" in window.status_line.message()
