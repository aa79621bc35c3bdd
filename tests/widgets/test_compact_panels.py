"""The jog and speed panels fit a short column (issue 28 item 26, 1024×640): a device's long
speed note shows its first clause (all of it in the tooltip), the step field sits on X+'s row,
and a taller dock's spare height goes below the rows."""

from __future__ import annotations

import pytest

from widgets.jog_panel import JogPanel
from widgets.speed_control import SpeedControl, lead

pytestmark = pytest.mark.timeout(30)

NOTE = (
    "The speed cannot be set here: this firmware revision times its steps from "
    "step_delay_instantaneous (15, 16) alone. Change 15 and 16 in the parameter table."
)


def test_the_lead_of_a_note_is_its_first_clause_else_its_first_sentence() -> None:
    assert lead(NOTE) == "The speed cannot be set here"
    assert lead("Steps are timed by the board. It rounds.") == "Steps are timed by the board"
    assert lead("one short note") == "one short note"
    assert lead(": nothing before the colon") == ": nothing before the colon"
    assert lead("nothing after: ") == "nothing after: "


def test_a_long_speed_note_shows_its_first_clause_and_all_of_it_as_the_tooltip(
    speed: SpeedControl,
) -> None:
    speed.set_note(NOTE)
    assert speed.note_label.isVisible()
    assert speed.note_label.text() == "The speed cannot be set here…"
    assert speed.note_label.toolTip() == NOTE and speed.note() == NOTE
    assert NOTE in speed.apply_button.toolTip()
    speed.set_fixed("set by the device")
    speed.set_fixed("")  # lifted: Apply says all of the note again, not the clause shown
    assert NOTE in speed.apply_button.toolTip()
    speed.set_note("one short note")
    assert speed.note_label.text() == "one short note"
    speed.set_note("")
    assert speed.note_label.isHidden() and speed.note() == ""


def test_a_taller_speed_panel_keeps_its_rows_together(qtbot, speed: SpeedControl) -> None:
    speed.set_note(NOTE)
    speed.resize(360, 400)
    qtbot.waitUntil(lambda: speed.height() == 400)
    gap = speed.spin.geometry().top() - speed.slider.geometry().bottom()
    assert gap < 16, f"{gap} px between the slider and the field"
    assert speed.note_label.geometry().bottom() < 150


def test_the_step_field_is_on_the_row_of_x_plus_and_no_taller_than_it(qtbot) -> None:
    panel = JogPanel()
    qtbot.addWidget(panel)
    panel.show()
    qtbot.waitExposed(panel)
    x_plus, y_plus = panel.buttons[("x", 1.0)], panel.buttons[("y", 1.0)]
    spin = panel.step_spin.geometry()
    assert x_plus.geometry().top() <= spin.top() and spin.bottom() <= x_plus.geometry().bottom()
    assert x_plus.height() == y_plus.height()  # the middle row is a jog button's height
