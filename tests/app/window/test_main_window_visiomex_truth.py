"""The window on the simulated Visiomex controller shows what the firmware does (issue 28):
a Y jog at power-on moves nothing and says so before it is sent (item 1), the speed field is off
with the speed the step delays give (item 3), and the parameter table shows what the firmware
recomputed at a move, marked computed (item 6)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.common.settings import read_parameters
from app.window.main_window import MainWindow
from tests.support.relay import wait_in_gui
from widgets._i18n import number_text

pytestmark = pytest.mark.timeout(60)
URL = "sim://visiomex?instant=1"


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=8000):
        win.connect_device(URL, "visiomex", 9600, "seed")
    win.layouts.switch("setup")


def _device(win: MainWindow):
    return win.worker.session.simulator  # type: ignore[union-attr]


def _jog(qtbot, win: MainWindow, button: str) -> None:
    with wait_in_gui(qtbot, win.worker.job_finished, timeout=10000):
        qtbot.mouseClick(win.findChild(QPushButton, button), Qt.MouseButton.LeftButton)


def test_y_jog_at_power_on_moves_nothing_and_says_so(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.jog_panel.set_step(1)
    _jog(qtbot, window, "jogYPlus")
    qtbot.waitUntil(lambda: "Y will not move" in window.status_line.message(), timeout=5000)
    assert "the firmware's Y loop makes no step" in window.status_line.message()
    qtbot.waitUntil(lambda: window.readout.position() == (0.0, 0.0, 0.0), timeout=5000)
    assert _device(window).position() == (0.0, 0.0)
    _jog(qtbot, window, "jogXPlus")
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=5000)
    assert _device(window).position() == (1.0, 0.0)


def test_speed_field_is_off_and_shows_the_speed_of_the_step_delays(
    qtbot, window: MainWindow
) -> None:
    _connect(qtbot, window)
    speed = window.speed
    qtbot.waitUntil(lambda: speed.reported_label.text() == "device: 3.125 mm/s", timeout=5000)
    assert not speed.spin.isEnabled() and not speed.apply_button.isEnabled()
    assert not speed.slider.isEnabled()
    assert "cannot be set here" in speed.note_label.text()
    assert "cannot be set here" in speed.spin.toolTip()
    refused: list[str] = []
    speed.refused.connect(refused.append)
    speed.apply()
    assert refused and "nothing sent" in refused[0]
    window.console.flush()
    assert not [d for direction, d, _ in window.console.records() if direction == "tx"]


def test_table_shows_what_the_firmware_recomputed_at_a_move(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    editor = window.parameters.editor
    assert editor.value("step_count_acceleration_x") == 50  # power-on, before any move
    window.jog_panel.set_step(1)
    _jog(qtbot, window, "jogXPlus")
    qtbot.waitUntil(lambda: editor.value("step_count_acceleration_x") == 0, timeout=5000)
    assert _device(window).parameters[19] == 0 == editor.last_written()["step_count_acceleration_x"]
    assert editor.computed()["step_count_acceleration_y"] == "at the last move"
    model = editor.model
    row = model.index_of(name="step_count_acceleration_x")
    shown = model.data(model.index(row, 4))
    assert shown == "0 steps (computed)"
    assert "step_count_acceleration_x" not in editor.changed_names()
    saved = read_parameters(window.settings, "visiomex", URL)
    assert saved["step_count_acceleration_y"] == 0


def _write(qtbot, win: MainWindow, items: list[tuple[int, float]]) -> None:
    """Write parameters through the table's dock, until the editor is done with them."""
    editor = win.parameters.editor
    win.parameters.write(items)
    qtbot.waitUntil(lambda: not editor.writing(), timeout=10000)
    assert all(_device(win).parameters[n] == v for n, v in items)  # whole units on the wire


def _x_speed(delays: tuple[float, float]) -> str:
    """The speed label for X stepping at 15 high plus 16 low (µs), 0.025 mm a step."""
    return f"device: {number_text(0.025 / ((delays[0] + delays[1]) * 1e-6), 6)} mm/s"


def test_device_speed_follows_a_write_of_the_step_delays(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    label = window.speed.reported_label
    qtbot.waitUntil(lambda: label.text() == _x_speed((4000, 4000)), timeout=5000)
    _write(qtbot, window, [(15, 2000.0)])
    qtbot.waitUntil(lambda: label.text() == _x_speed((2000, 4000)), timeout=5000)
    assert label.text() == "device: 4.166667 mm/s"


def test_device_speed_follows_a_move_whose_ramps_change_16(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    label = window.speed.reported_label
    _write(qtbot, window, [(22, 6000.0), (24, 1.0)])
    qtbot.waitUntil(lambda: label.text() == _x_speed((4000, 4000)), timeout=5000)
    window.jog_panel.set_step(1)
    _jog(qtbot, window, "jogYPlus")  # its ramp leaves 16 at 358 µs
    editor = window.parameters.editor
    qtbot.waitUntil(lambda: editor.value("step_delay_instantaneous_y") == 358, timeout=5000)
    assert _device(window).parameters[16] == 358
    qtbot.waitUntil(lambda: label.text() == _x_speed((4000, 358)), timeout=5000)
