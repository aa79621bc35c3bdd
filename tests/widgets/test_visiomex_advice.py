"""The parameter editor tells what the Visiomex firmware will really do (drivers/protocols/README.md
§2b): steps per move, a 10 mm move's time, whether Y moves, which written values do not stay;
outputs are never written by "Write changed" nor kept in a profile."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QLineEdit

from app.window.docks.parameter_dock import editor_rows, shown_derivation
from drivers.device.param_profile import ProfileError, format_profile, parse_profile
from drivers.protocols.visiomex.advice import firmware_after_writing, timed_move
from drivers.protocols.visiomex.model import (
    OVERWRITTEN_AFTER_SET,
    OVERWRITTEN_AT_MOVE,
    POWER_ON,
)
from drivers.protocols.visiomex.params import BY_ID, PARAMETERS
from drivers.protocols.visiomex.protocol import VisiomexProtocol
from widgets.parameter_editor import ParameterEditor
from widgets.parameter_table import NAME_COL, WRITTEN_COL

RAMPS_21_24 = {  # drivers/protocols/README.md §2b, case "21-24"
    "input_speed_steady_x": 6000,
    "input_speed_steady_y": 6000,
    "input_acceleration_x": 1,
    "input_acceleration_y": 1,
}


@pytest.fixture
def editor(qtbot) -> ParameterEditor:
    """The editor as the window sets it up for a Visiomex that has just been switched on."""
    protocol = VisiomexProtocol()
    widget = ParameterEditor()
    qtbot.addWidget(widget)
    widget.resize(1024, 640)
    widget.set_parameters(editor_rows(PARAMETERS, protocol))
    widget.set_values({p.name: p.default for p in PARAMETERS})
    widget.set_derivation(shown_derivation(protocol.derived_values))
    widget.set_connected(True)
    widget.show()
    return widget


def _derived(editor: ParameterEditor) -> dict[str, str]:
    assert editor.derived_error() == ""
    return dict(editor.derived_values())


def test_the_outputs_are_the_values_the_firmware_overwrites() -> None:
    assert {p.id for p in PARAMETERS if p.output} == OVERWRITTEN_AFTER_SET | OVERWRITTEN_AT_MOVE


def test_at_power_on_y_never_moves_and_10_mm_of_x_is_400_steps(editor: ParameterEditor) -> None:
    derived = _derived(editor)
    assert derived["Steps per move"].startswith("X: 1 mm = 40, 10 mm = 400 · Y: 1 mm = 40,")
    x_move = derived["A 10 mm X move"]
    assert x_move.startswith("400 steps, 3.20 s of stepping")  # 400 × (4 + 4 ms)
    assert "FA0001 about 4.4 s after the packet" in x_move  # §2b: ≈ 1.17 + 3.20 + 0.01 s
    assert derived["Y moves"].startswith("no: ")
    assert "R_y = 0" in derived["Y moves"]
    assert derived["Ramps"].startswith("none")
    assert derived["Overwritten after every set"].startswith("11, 12, 17, 18, 25, 26:")
    assert derived["Overwritten at every move"].startswith("19, 20:")
    assert derived["Never read"].startswith("03, 04, 09, 10, 27:")
    assert derived["Read only at boot"].startswith("01, 02:")
    assert "Not used" not in derived


def test_after_setting_21_to_24_y_moves_and_both_axes_ramp(editor: ParameterEditor) -> None:
    editor.set_values(RAMPS_21_24)
    derived = _derived(editor)
    assert derived["Y moves"].startswith("14 of the 400 steps of a 10 mm Y move")
    assert derived["Ramps"].startswith("X over 14 steps, Y over 14 steps")
    assert "after a move in which Y stepped" in derived["A 10 mm X move"]
    assert editor.changed_inputs() == list(RAMPS_21_24)


def test_the_21_24_case_steps_as_recorded() -> None:
    """§2b: `MLP0005000P0005000` after 21 = 22 = 6000, 23 = 24 = 1: X 0.931 s, then 14 Y steps
    0.082 s; the same move again 0.279 s in all."""
    values = {BY_ID[i].id: v for i, v in ((21, 6000), (22, 6000), (23, 1), (24, 1))}
    state = firmware_after_writing(values)
    assert state.ramp == (14, 14)
    first, total = timed_move(state, 5000, 5000)
    assert first.steps == (200, 200) and first.loops == (200, 14)
    assert first.x_seconds == pytest.approx(0.931, abs=0.001)
    assert first.y_seconds == pytest.approx(0.082, abs=0.001)
    assert total == pytest.approx(1.0 + 0.17 + 1.013, abs=0.1)
    again, _ = timed_move(state, 5000, 5000)
    assert again.seconds == pytest.approx(0.279, abs=0.001)


def test_table_values_the_firmware_ignores_are_named(editor: ParameterEditor) -> None:
    editor.set_values({"thread_distance_x": 5, "max_speed_y": 20})
    derived = _derived(editor)
    assert derived["Not used"].startswith("thread_distance_x, max_speed_y:")
    assert derived["Steps per move"].startswith("X: 1 mm = 40, 10 mm = 400")  # C stays 10 mm


def test_writing_an_overwritten_value_is_warned_not_refused(editor, qtbot, record) -> None:
    warning = "the firmware recomputes 17 after every set: this value will not stay"
    row = [p.id for p in PARAMETERS].index(17)
    editor.table.setCurrentIndex(editor.model.index(row, NAME_COL))
    editor.table.setFocus()
    QTest.keyClick(editor.table, Qt.Key.Key_F2)
    assert warning in editor.message()  # said as the edit starts
    lines = [w for w in editor.table.findChildren(QLineEdit) if w.isVisible()]
    assert len(lines) == 1 and warning in lines[0].toolTip()
    lines[0].selectAll()
    qtbot.keyClicks(lines[0], "3000")
    qtbot.keyClick(lines[0], Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: editor.value("step_delay_acceleration_avg_x") == 3000)
    assert warning in editor.message()  # and again once the value is kept

    assert editor.changed_names() == ["step_delay_acceleration_avg_x"]
    assert editor.changed_inputs() == []  # an output: not for "Write changed"
    assert not editor.write_changed_button.isEnabled()
    writes = record(editor.write_requested)
    editor.table.selectRow(row)
    qtbot.mouseClick(editor.write_selected_button, Qt.MouseButton.LeftButton)
    assert writes == [([(17, 3000.0)],)]  # allowed
    assert f"Warning: {warning}" in editor.message()


def test_write_changed_sends_only_inputs_that_differ(editor, qtbot, record) -> None:
    assert editor.changed_names() == []  # power-on values: what the device holds
    cell = editor.model.index(4, WRITTEN_COL)  # motor_fullcycle_step_x, never written
    assert editor.model.data(cell) == "400 steps (power-on)"
    editor.set_values({"microstep_coeff_x": 4, "delta_t_y": 99, "max_speed_x": 20})
    writes = record(editor.write_requested)
    qtbot.mouseClick(editor.write_changed_button, Qt.MouseButton.LeftButton)
    assert writes == [([(7, 4.0), (9, 20.0)],)]
    assert "never reads 09" in editor.message()


def test_a_profile_never_holds_outputs() -> None:
    values = {p.name: p.default for p in PARAMETERS}
    text = format_profile(values, PARAMETERS, "visiomex")
    outputs = [p.name for p in PARAMETERS if p.output]
    assert all(f"\n{name} = " not in text for name in outputs)
    assert "# Not saved: " + ", ".join(outputs) in text
    skipped: list[str] = []
    parsed = parse_profile(text + "delta_t_x = 7\n", PARAMETERS, "visiomex", outputs=skipped)
    assert parsed == {p.name: float(p.default) for p in PARAMETERS if not p.output}
    assert skipped == ["delta_t_x"]
    with pytest.raises(ProfileError, match="only firmware outputs"):
        parse_profile("[parameters]\ndelta_t_x = 7\n", PARAMETERS, "visiomex")
    with pytest.raises(ProfileError, match=r"delta_t_x: 7\.5 s refused"):
        parse_profile("[parameters]\ndelta_t_x = 7.5\n", PARAMETERS, "visiomex")


def test_power_on_values_are_the_parameter_defaults() -> None:
    assert {p.id: p.default for p in PARAMETERS} == POWER_ON
