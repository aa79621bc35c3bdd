"""The window's tools end to end, over a real pty to motionsim in another process: a homing and
probe macro built in the window and run, work coordinates zeroed and gone to, the serial control
lines, the settings dialog changing the poll rate, and the Help menu."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtWidgets import QDialogButtonBox, QLabel

from app.common import macros
from app.window.main_window import MainWindow
from tests.support.e2e import device_received
from tests.support.simproc import SimProcess
from widgets.about_dialog import AboutDialog
from widgets.shortcuts_dialog import ShortcutsDialog

pytestmark = [pytest.mark.timeout(60), pytest.mark.e2e]


@pytest.fixture
def record(tmp_path: Path) -> Path:
    return tmp_path / "device.log"


@pytest.fixture
def sim(record: Path) -> Iterator[SimProcess]:
    process = SimProcess("coxiris", "--record", str(record), "--speed", "100")
    yield process
    if process.proc.poll() is None:
        assert process.stop() == 0


def _connect(
    qtbot, window: MainWindow, port: str, protocol: str = "coxiris", baud: int = 115200
) -> None:
    with qtbot.waitSignal(window.settled, timeout=15000):
        window.connect_device(port, protocol, baud)


def _console(window: MainWindow) -> str:
    window.console.flush()
    return window.console.text()


def test_a_homing_and_probe_macro_built_in_the_window_runs_on_the_device(
    qtbot, window: MainWindow, sim: SimProcess, record: Path
) -> None:
    _connect(qtbot, window, sim.path)
    dock = window.tools.macros
    qtbot.waitUntil(lambda: dock.protocol is not None and dock.protocol.name == "coxiris")
    editor = dock.new()
    assert editor is not None
    editor.name_edit.setText("home and probe")
    editor.steps_edit.setPlainText("home\nmove 10 5 0\njog 0 0 -2\nfly away")
    ok = editor.buttons.button(QDialogButtonBox.StandardButton.Ok)
    assert not ok.isEnabled()
    assert "step 4 ('fly away'): unknown command 'fly'" in editor.problem.text()
    editor.steps_edit.setPlainText("home\nmove 10 5 0\njog 0 0 -2\nwait 0.1\nposition")
    assert ok.isEnabled()
    ok.click()
    assert [m.name for m in macros.read_saved(window.settings, "coxiris")] == ["home and probe"]
    button = dock.panel.buttons["home and probe"]
    qtbot.waitUntil(button.isEnabled)
    button.click()
    qtbot.waitUntil(lambda: window.readout.position() == (10.0, 5.0, -2.0), timeout=15000)
    qtbot.waitUntil(lambda: "macro home and probe: step 5/5: position" in _console(window))
    sent = device_received(record)
    assert sent.index(b"GO_HOME") < sent.index(b"ABSOLUTE_MOVE 10") < sent.index(b"DELTA_MOVE")


def test_a_macro_with_a_bad_step_sends_nothing(
    qtbot, window: MainWindow, sim: SimProcess, record: Path
) -> None:
    macros.save(window.settings, "coxiris", [macros.Macro("bad", "coxiris", ("home", "move x"))])
    _connect(qtbot, window, sim.path)
    dock = window.tools.macros
    dock.set_protocol("visiomex")
    dock.set_protocol("coxiris")  # read again from the settings
    before = device_received(record)
    assert not dock.run("bad")
    assert "macro bad, step 2 ('move x')" in window.status_line.message()
    assert "nothing sent" in window.status_line.message()
    assert device_received(record) == before


def test_zero_the_work_coordinates_and_go_there(
    qtbot, window: MainWindow, sim: SimProcess, record: Path
) -> None:
    _connect(qtbot, window, sim.path)
    window.coordinates.set_values(10.0, 5.0, 0.0)
    window.coordinates.go_button.click()
    qtbot.waitUntil(lambda: window.readout.position() == (10.0, 5.0, 0.0), timeout=15000)
    qtbot.waitUntil(window.readout.zero_all_button.isEnabled)
    window.readout.zero_all_button.click()
    assert window.readout.work_text("x") == "0.00 mm"
    assert window.readout.text("x") == "10.00 mm"
    window.coordinates.set_frame("work")
    window.coordinates.set_values(1.0, 1.0, 0.0)
    window.coordinates.go_button.click()
    qtbot.waitUntil(lambda: window.readout.position() == (11.0, 6.0, 0.0), timeout=15000)
    assert window.readout.work_text("x") == "1.00 mm"
    assert b"ABSOLUTE_MOVE 11" in device_received(record)  # the device is sent machine mm


def test_control_lines_on_a_pty_say_there_are_none(
    qtbot, window: MainWindow, sim: SimProcess
) -> None:
    _connect(qtbot, window, sim.path)
    lines = window.connection_bar.control_lines
    qtbot.waitUntil(lambda: lines.indicator_state("cts") == "unknown")
    assert not lines.dtr_toggle.isEnabled()  # a pty has no modem lines: nothing to toggle
    assert not lines.break_button.isEnabled()


def test_dtr_resets_a_firmata_board_and_is_remembered(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://firmata?reset_delay=0.05", "firmata", 57600)
    lines = window.connection_bar.control_lines
    qtbot.waitUntil(lambda: lines.dtr_toggle.isEnabled() and lines.dtr_toggle.isChecked())
    assert lines.indicator_state("cts") == "on"
    lines.dtr_toggle.click()  # off
    qtbot.waitUntil(lambda: "DTR off" in _console(window))
    lines.dtr_toggle.click()  # on again: the board resets and announces itself
    qtbot.waitUntil(lambda: "DTR on" in _console(window))
    key = "devices/firmata/sim%3A%2F%2Ffirmata/dtr"
    assert window.settings.value(key) == "true"


def test_the_settings_dialog_changes_the_poll_rate(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window, "sim://coxiris?instant=1")
    window.tools.edit_settings()
    dialog = window.tools.settings_dialog
    dialog.fields["poll_idle_s"].setValue(0.5)
    dialog.findChild(QDialogButtonBox).button(QDialogButtonBox.StandardButton.Ok).click()
    qtbot.waitUntil(lambda: window.worker.poll_idle_s == 0.5)
    assert window.tools.prefs.poll_idle_s == 0.5
    assert float(window.settings.value("poll_idle_s")) == 0.5
    assert window.status_line.message() == "settings saved"


def test_help_menu_shows_shortcuts_and_about(qtbot, window: MainWindow) -> None:
    help_menu = window.menuBar().actions()[3].menu()
    assert [a.objectName() for a in help_menu.actions()] == ["shortcutsAction", "aboutAction"]
    help_menu.actions()[0].trigger()
    shortcuts = window.findChild(ShortcutsDialog)
    assert shortcuts is not None and shortcuts.isVisible()
    texts = [what for _keys, what in shortcuts.shortcuts()]
    assert "Jog X - / +" in texts
    assert any("Stop" in text for text in texts)
    shortcuts.close()
    help_menu.actions()[1].trigger()
    about = window.findChild(AboutDialog)
    assert about is not None and about.isVisible()
    shown = " ".join(label.text() for label in about.findChildren(QLabel))
    assert "MIT" in shown and "0.1.0" in shown
    about.close()


def test_jog_keys_and_units_from_the_preferences(qtbot, window: MainWindow) -> None:
    import dataclasses

    from PySide6.QtCore import Qt

    _connect(qtbot, window, "sim://coxiris?instant=1")
    panel = window.jog_panel
    assert panel.key_hint.startswith("Keys: ←/→ X, ↑/↓ Y, PgUp/PgDown Z, Shift ×10, [/] step")
    prefs = dataclasses.replace(
        window.tools.prefs, jog_key_x_minus="A", jog_key_x_plus="D", units="in"
    )
    window.tools.apply_preferences(prefs)
    jogs: list[tuple[str, float]] = []
    panel.jog_requested.connect(lambda axis, distance: jogs.append((axis, distance)))
    panel.set_step(1.0)
    assert panel.handle_key(Qt.Key.Key_D)
    panel.release()
    assert not panel.handle_key(Qt.Key.Key_Right)  # no longer a jog key
    assert panel.handle_key(Qt.Key.Key_BracketRight)  # the next larger inch step
    assert panel.step() == pytest.approx(2.54)  # 0.1 in, in mm
    assert jogs == [("x", 1.0)]
    assert window.coordinates.units() == "in"
    assert panel.key_hint.startswith("Keys: A/D X")
    assert window.readout.units() == "in"
    assert window.readout.text("x").endswith(" in")


def test_the_session_log_follows_its_settings_at_once(
    qtbot, window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _connect(qtbot, window, "sim://coxiris?instant=1")
    first = window.link.session_log_path
    assert first is not None and first.is_file()
    monkeypatch.delenv("MOTIONPANEL_LOG_DIR")  # the environment would come before the setting
    chosen = tmp_path / "chosen-logs"
    chosen.mkdir()  # the setting takes a folder that exists
    window.tools.apply_preferences(dataclasses.replace(window.tools.prefs, log_folder=str(chosen)))
    second = window.link.session_log_path
    assert second is not None and second.parent == chosen
    # The worker switches between its jobs: a jog sent in the same moment may still go in the
    # first file (an operator's next press comes a human moment later).
    qtbot.waitUntil(lambda: f"continued from {first}" in second.read_text(encoding="utf-8"))
    window.jog_panel.jog_requested.emit("x", 1.0)  # the open connection goes on in the new file
    qtbot.waitUntil(lambda: "DELTA_MOVE" in second.read_text(encoding="utf-8"), timeout=10000)
    qtbot.waitUntil(lambda: f"goes on in {second}" in first.read_text(encoding="utf-8"))
    assert "DELTA_MOVE" not in first.read_text(encoding="utf-8")
    assert window.status_line.message() == "settings saved"
    window.tools.apply_preferences(dataclasses.replace(window.tools.prefs, session_log=False))
    assert window.link.session_log_path is None
    qtbot.waitUntil(lambda: "turned off" in second.read_text(encoding="utf-8"))
    assert "no session log from now on" in _console(window)
