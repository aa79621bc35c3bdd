"""The window on the simulated pi-frame and Firmata devices: their panels, arcs, setup."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QPushButton

from app.common.settings import read_counted_position, read_protocol_settings
from app.window.main_window import MainWindow
from widgets import status_line as status

pytestmark = pytest.mark.timeout(40)


def _connect(qtbot, win: MainWindow, url: str, protocol: str, baud: int) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(url, protocol, baud)


def _dock(win: MainWindow, name: str) -> QDockWidget:
    dock = win.findChild(QDockWidget, name)
    assert dock is not None, name
    return dock


def test_piframe_arc_is_previewed_then_run(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://pi-frame?instant=1", "pi-frame", 115200)
    assert _dock(window, "arcEntryDock").isVisible()
    assert _dock(window, "dwellEntryDock").isVisible()
    assert not _dock(window, "firmataPanelDock").isVisible()
    assert window.readout.measured_label.text() == "commanded, not measured"
    assert window.devices.piframe.dtr() is True
    arc = window.devices.arc
    arc.set_values(cx=0.0, cy=0.0, radius=5.0, start=0.0, end=180.0, z=0.0)
    arc.ccw_radio.setChecked(True)
    preview = window.view2d.preview()
    assert preview and preview[0][:2] == pytest.approx((5.0, 0.0))
    assert preview[-1][:2] == pytest.approx((-5.0, 0.0), abs=1e-9)
    qtbot.mouseClick(arc.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(
        lambda: window.readout.position() == pytest.approx((-5.0, 0.0, 0.0), abs=1e-9),
        timeout=15000,
    )
    device = window.worker.session.simulator  # type: ignore[union-attr]
    assert [action for action, _ in device.history] == [1, 2]  # to the start, then the arc
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=5000)


def test_piframe_ticks_per_mm_is_used_and_remembered(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://pi-frame?instant=1", "pi-frame", 115200)
    window.devices.piframe.ticks_per_mm_changed.emit(10.0)
    qtbot.waitUntil(lambda: window.jog_panel.step_spin.decimals() == 1, timeout=5000)
    assert (
        read_protocol_settings(window.settings, "pi-frame", "sim://pi-frame")["ticks_per_mm"] == 10
    )
    assert "3276.7" in window.devices.piframe.range_text()


def test_firmata_one_axis_configure_and_jog(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://firmata?reset_delay=0.2&instant=1", "firmata", 57600)
    assert not _dock(window, "firmataPanelDock").isVisible()  # a setup panel: in Set up
    window.layouts.switch("setup")
    assert _dock(window, "firmataPanelDock").isVisible()
    assert not _dock(window, "arcEntryDock").isVisible()
    assert window.findChild(QPushButton, "jogXPlus").isEnabled()
    assert not window.findChild(QPushButton, "jogYPlus").isEnabled()
    assert window.machine.info is not None and window.machine.info.identity == "FirmataPlus.ino 2.5"
    panel = window.devices.firmata
    qtbot.mouseClick(window.findChild(QPushButton, "firmataConfigure"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(
        lambda: panel.findChild(object, "firmataVersionLabel").text() == "5", timeout=5000
    )
    saved = read_protocol_settings(window.settings, "firmata", "sim://firmata")
    assert (saved["pin1"], saved["pin2"], saved["pin3"]) == (8, 9, -1)
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=8000)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    assert device.steps() == 80  # 1 mm at 80 steps/mm


def test_firmata_position_is_unknown_until_set_home_then_counted_for_motionctl(
    qtbot, window: MainWindow
) -> None:
    """Firmata cannot be asked where it is: like Visiomex, a fresh connection counts nothing
    (no count kept for motionctl) until Set Home starts one."""
    url = "sim://firmata?reset_delay=0.2&instant=1"
    _connect(qtbot, window, url, "firmata", 57600)
    assert window.readout.status() == "uncounted"
    assert "position unknown" in window.status_line.message()
    qtbot.mouseClick(window.findChild(QPushButton, "firmataConfigure"), Qt.MouseButton.LeftButton)
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=8000)
    assert read_counted_position(window.settings, "firmata", url) is None
    window.coordinates.confirm = lambda question: True
    qtbot.waitUntil(window.coordinates.set_home_button.isEnabled, timeout=5000)
    qtbot.mouseClick(window.coordinates.set_home_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.status() != "uncounted", timeout=5000)
    # A press while Set Home still runs is not queued (issue 19): wait until it has ended.
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=5000)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=8000)
    qtbot.waitUntil(
        lambda: read_counted_position(window.settings, "firmata", url) == (1.0, 0.0, 0.0),
        timeout=8000,
    )


def test_firmata_string_data_is_shown_in_words(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://firmata?reset_delay=0.2&instant=1", "firmata", 57600)
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: "not configured" in window.status_line.message(), timeout=8000)
