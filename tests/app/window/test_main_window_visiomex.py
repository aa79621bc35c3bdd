"""The window on the simulated Visiomex controller: it adapts, and the parameter editor writes."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QPushButton

from app.common.settings import read_parameters
from app.window.main_window import MainWindow
from drivers.device.param_profile import format_profile
from drivers.protocols.visiomex.params import PARAMETERS

pytestmark = pytest.mark.timeout(40)
URL = "sim://visiomex?instant=1"


def _connect(qtbot, win: MainWindow, url: str = URL) -> None:
    with qtbot.waitSignal(win.settled, timeout=8000):
        win.connect_device(url, "visiomex", 9600, "seed")
    win.layouts.switch("setup")  # the parameter editor is in Set up (not shown in Operate)


def test_the_window_adapts_to_two_axes_and_commanded_positions(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.layouts.switch("setup")  # the parameters are in Set up
    dock = window.findChild(QDockWidget, "parameterEditor")
    assert dock is not None and dock.isVisible()
    assert window.readout.labels["z"].isHidden() and not window.readout.labels["y"].isHidden()
    assert not window.coordinates.isHidden()
    assert window.readout.position() == (0.0, 0.0, 0.0)
    assert window.readout.measured_label.text() == "commanded, not measured"
    assert "(15, 16) alone" in window.speed.note()  # (its first clause shown, all in the tooltip)
    assert window.connection_bar.variant() == "seed" and window.connection_bar.baud() == 9600
    assert window.console.send_line.ending_combo.currentText() == "none"
    assert "relative move" in window.coordinates.home_button.toolTip()

    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=8000)
    assert window.readout.measured_label.text() == "commanded, move confirmed"

    def console_shows_the_packet() -> None:
        window.console.flush()
        assert "MLP0001000P0000000" in window.console.text()
        assert "FA0001" in window.console.text()

    qtbot.waitUntil(console_shows_the_packet, timeout=5000)


def _sent_sets(window: MainWindow) -> list[bytes]:
    """The set packets the console has shown as sent, in order."""
    window.console.flush()
    return [
        data
        for direction, data, _ in window.console.records()
        if data[:1] == b"S" and direction == "tx"
    ]


def test_write_changed_after_a_three_value_profile_sends_three_packets(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window)
    editor = window.parameters.editor
    assert editor.changed_inputs() == []  # the table starts at the power-on values
    assert not editor.write_changed_button.isEnabled()
    chosen = [p for p in PARAMETERS if p.id in (3, 9, 27)]
    values = {"pulley_diameter_x": 40.5, "max_speed_x": 30, "driving_mechanism": 0}
    profile = tmp_path / "three.toml"
    profile.write_text(format_profile(values, tuple(chosen), "visiomex"))
    editor._choose_path = lambda save: str(profile)  # type: ignore[method-assign]
    qtbot.mouseClick(editor.load_button, Qt.MouseButton.LeftButton)
    assert editor.value("pulley_diameter_x") == 40.5
    assert "nothing sent" in editor.message()
    editor.set_values({"step_delay_acceleration_avg_x": 3000})  # an output: never sent by it

    qtbot.mouseClick(editor.write_changed_button, Qt.MouseButton.LeftButton)
    assert editor.writing()
    assert "27 to 1" in editor.message()  # warned before it is sent, not refused
    qtbot.waitUntil(lambda: not editor.writing(), timeout=30000)
    qtbot.waitUntil(lambda: len(_sent_sets(window)) >= 3, timeout=5000)
    assert [packet[:3] for packet in _sent_sets(window)] == [b"S03", b"S09", b"S27"]
    for parameter in chosen:
        assert editor.status(parameter.id) == "confirmed", parameter.name
    assert editor.status(17) == "not written"
    assert editor.last_written()["pulley_diameter_x"] == 40.5
    # The firmware forces driving_mechanism to 1 after every set: the editor says so.
    assert editor.last_written()["driving_mechanism"] == 1
    assert "driving_mechanism" in editor.changed_names()  # 0 in the editor, 1 on the device
    saved = read_parameters(window.settings, "visiomex", URL)
    assert saved["pulley_diameter_x"] == 40.5 and saved["driving_mechanism"] == 1


def test_a_saved_profile_has_no_outputs(qtbot, window: MainWindow, tmp_path: Path) -> None:
    _connect(qtbot, window)
    editor = window.parameters.editor
    path = tmp_path / "saved.toml"
    editor._choose_path = lambda save: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(editor.save_button, Qt.MouseButton.LeftButton)
    text = path.read_text(encoding="utf-8")
    inputs = [p for p in PARAMETERS if not p.output]
    assert f"saved {len(inputs)} values" in editor.message()
    assert "outputs are never saved" in editor.message()
    for parameter in PARAMETERS:
        assert (f"\n{parameter.name} = " in text) is not parameter.output, parameter.name


def test_a_fresh_connection_says_the_position_is_unknown_until_home(
    qtbot, window: MainWindow
) -> None:
    _connect(qtbot, window)
    unknown = "position unknown: the device cannot be asked; Home or Set Home to start counting"
    assert window.readout.status() == "uncounted"
    assert window.readout.status_label.text() == unknown
    assert "link failed" not in window.readout.status_label.text()
    assert window.status_line.message() == unknown
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=8000)
    assert window.readout.status() == "uncounted"  # a relative move counts from nothing known

    qtbot.waitUntil(window.coordinates.home_button.isEnabled, timeout=5000)
    qtbot.mouseClick(window.coordinates.home_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.readout.status() == "live", timeout=8000)
    assert window.readout.position() == (0.0, 0.0, 0.0)
    assert window.readout.status_label.isHidden()
    assert "home confirmed" in window.status_line.message()


def test_home_clicked_during_a_jog_step_says_home_confirmed_when_it_ends(
    qtbot, window: MainWindow
) -> None:
    """The jog's end, reported after Home was queued behind it, does not clear Home's turn."""
    _connect(qtbot, window)
    window.jog_panel.set_step(1)
    qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    jog = window.machine.busy_job
    assert jog is not None and window.coordinates.home_button.isEnabled()
    qtbot.mouseClick(window.coordinates.home_button, Qt.MouseButton.LeftButton)
    assert window.machine.busy_job is not jog  # Home waits its turn behind the jog
    qtbot.waitUntil(lambda: window.readout.status() == "live", timeout=8000)
    assert window.readout.position() == (0.0, 0.0, 0.0)
    assert "home confirmed" in window.status_line.message()


def test_a_malformed_profile_is_refused_and_nothing_is_sent(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window)
    editor = window.parameters.editor
    bad = tmp_path / "bad.toml"
    bad.write_text("[parameters]\npulley_diameter_x = -4\n")
    editor._choose_path = lambda save: str(bad)  # type: ignore[method-assign]
    before = editor.values()
    qtbot.mouseClick(editor.load_button, Qt.MouseButton.LeftButton)
    assert "refused" in editor.message() and "line 2" in editor.message()
    assert editor.values() == before
    assert not editor.writing()


def test_cancel_stops_after_the_packet_in_flight(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    editor = window.parameters.editor
    qtbot.mouseClick(editor.write_all_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: editor.status(1) == "confirmed", timeout=5000)
    qtbot.mouseClick(editor.cancel_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not editor.writing(), timeout=5000)
    statuses = [editor.status(p.id) for p in PARAMETERS]
    assert statuses.count("cancelled") >= 20
    assert statuses[0] == "confirmed"
    assert "pending" not in statuses


def test_a_set_of_21_shows_the_25_the_firmware_recomputed(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    editor = window.parameters.editor
    assert editor.value("delta_t_x") == 10  # power-on: 100 ÷ 10
    editor.set_values({"input_speed_steady_x": 6000})
    qtbot.mouseClick(editor.write_changed_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not editor.writing(), timeout=30000)
    assert [packet[:3] for packet in _sent_sets(window)] == [b"S21"]
    assert editor.value("delta_t_x") == 600  # 21 ÷ 23, recomputed after the set
    assert editor.last_written()["delta_t_x"] == 600
    assert "delta_t_x" not in editor.changed_names()
    assert read_parameters(window.settings, "visiomex", URL)["delta_t_x"] == 600


def test_the_built_in_device_speaks_the_variant_chosen(qtbot, window: MainWindow) -> None:
    """The window hands the plain sim:// URL to the device session, which makes it speak the
    variant in the bar (board12: 12-character packets at 115200 baud)."""
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device("sim://visiomex?instant=1", "visiomex", 115200, "board12")
    device = window.worker.session.simulator  # type: ignore[union-attr]
    assert device.variant.name == "board12"
