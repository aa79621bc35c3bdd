"""Settings → Units shown, in the fields: Go to, the jog step, the speed and the arc show and take
inches when the operator chose them, and still hand the window mm and mm/s."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QLocale, Qt
from PySide6.QtWidgets import QPushButton

from widgets._i18n import number_text
from widgets._units import UnitSpinBox
from widgets.arc_entry import ArcEntry
from widgets.coordinate_entry import CoordinateEntry
from widgets.jog_panel import INCH_STEP_PRESETS, STEP_PRESETS, JogPanel
from widgets.speed_control import SLIDER_STEPS

pytestmark = pytest.mark.timeout(60)

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture(autouse=True)
def english_numbers() -> object:
    """Numbers with a decimal point, whatever the machine's locale."""
    before = QLocale()
    QLocale.setDefault(QLocale(QLocale.Language.English, QLocale.Country.UnitedStates))
    yield None
    QLocale.setDefault(before)


@pytest.fixture
def jog(qtbot) -> JogPanel:
    widget = JogPanel()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def _type(qtbot, field, text: str) -> None:
    field.lineEdit().selectAll()
    qtbot.keyClicks(field, text)
    qtbot.keyClick(field, Qt.Key.Key_Return)


# -- Go to ------------------------------------------------------------------------------------


def test_one_inch_typed_in_go_to_x_sends_25_4_mm(entry: CoordinateEntry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_units("in")
    field = entry.fields["x"]
    assert field.objectName() == "coordX"  # the contract is kept
    assert field.suffix() == " in"
    assert " in " in field.toolTip() and "mm" not in field.toolTip()
    assert "inches" in entry.absolute_radio.toolTip()
    _type(qtbot, field, "1")
    assert calls == [("absolute", (25.4, 0.0, 0.0))]
    entry.set_mode("relative")
    _type(qtbot, entry.fields["y"], "-0.5")
    assert calls[-1] == ("relative", (0.0, -12.7, 0.0))


def test_go_to_in_inches_is_sent_on_the_device_resolution(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_resolution(0.01)
    entry.set_units("in")
    assert entry.fields["x"].decimals() == 4
    _type(qtbot, entry.fields["x"], "0.1234")  # 3.13436 mm
    assert calls == [("absolute", (3.13, 0.0, 0.0))]


def test_use_current_in_inches_goes_back_exactly(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_units("in")
    entry.set_current(10.001, -3.0, 0.5)
    assert entry.fields["x"].text() == "0.3937 in"
    qtbot.mouseClick(entry.go_button, LEFT)
    assert calls == [("absolute", (10.001, -3.0, 0.5))]  # not 9.99998 through the inches


def test_out_of_range_is_said_in_inches(entry) -> None:
    entry.set_box(((0.0, 254.0), (-25.4, 25.4), (0.0, 50.8)))
    assert "0 to 254 mm (travel limits)" in entry.fields["x"].toolTip()
    entry.set_units("in")
    field = entry.fields["x"]
    assert (field.minimum(), field.maximum()) == (0.0, 10.0)
    assert "X target coordinate, 0 to 10 in (travel limits)" in field.toolTip()
    assert "-1 to 1 in" in entry.fields["y"].toolTip()
    entry.set_values(300.0, -100.0, 1.0)  # clamped to the box
    assert entry.values() == (254.0, -25.4, 1.0)
    entry.set_mode("relative")
    assert "Z distance to move, -2 to 2 in" in entry.fields["z"].toolTip()


def test_switching_units_converts_the_fields_and_emits_nothing(entry, record) -> None:
    calls = record(entry.go_requested)
    entry.set_values(12.5, -3.175, 100.0)
    entry.set_units("in")
    assert [entry.fields[a].text() for a in "xyz"] == ["0.4921 in", "-0.1250 in", "3.9370 in"]
    assert entry.values() == (12.5, -3.175, 100.0)
    entry.set_units("mm")
    assert [entry.fields[a].text() for a in "xyz"] == ["12.500 mm", "-3.175 mm", "100.000 mm"]
    assert entry.fields["x"].suffix() == " mm" and "mm" in entry.fields["x"].toolTip()
    assert entry.values() == (12.5, -3.175, 100.0)
    assert calls == []
    with pytest.raises(ValueError):
        entry.set_units("ft")


def test_the_work_frame_in_inches(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_units("in")
    entry.set_work_zero((25.4, 0.0, 0.0))
    entry.set_frame("work")
    _type(qtbot, entry.fields["x"], "1")
    assert calls == [("absolute", (50.8, 0.0, 0.0))]


# -- jog step ---------------------------------------------------------------------------------


def test_inch_step_presets_move_by_the_right_mm(jog: JogPanel, qtbot, record) -> None:
    calls = record(jog.jog_requested)
    jog.set_units("in")
    assert all(b.isHidden() for b in jog.preset_buttons.values())
    shown = [b for b in jog.inch_preset_buttons.values() if not b.isHidden()]
    assert [b.text() for b in shown] == ["0.001 in", "0.01 in", "0.1 in", "1 in"]
    assert [b.objectName() for b in shown] == [
        "jogStepIn0_001",
        "jogStepIn0_01",
        "jogStepIn0_1",
        "jogStepIn1",
    ]
    assert tuple(jog.inch_preset_buttons) == INCH_STEP_PRESETS
    qtbot.mouseClick(jog.inch_preset_buttons[0.1], LEFT)
    assert jog.step() == pytest.approx(2.54)
    assert jog.inch_preset_buttons[0.1].isChecked()
    assert jog.step_spin.suffix() == " in" and jog.step_spin.text() == "0.1000 in"
    qtbot.mouseClick(jog.findChild(QPushButton, "jogXPlus"), LEFT)
    jog.release()
    assert jog.handle_key(Qt.Key.Key_Up, Qt.KeyboardModifier.ShiftModifier)  # the keyboard jog
    jog.release()
    assert calls == [("x", pytest.approx(2.54)), ("y", pytest.approx(25.4))]
    assert "+0.1 in (Shift: +1 in)" in jog.findChild(QPushButton, "jogXPlus").toolTip()
    jog.step_spin.lineEdit().selectAll()
    qtbot.keyClicks(jog.step_spin, "0.5")
    jog.step_spin.interpretText()
    assert jog.step() == pytest.approx(12.7)


def test_step_keys_go_through_the_inch_presets(jog: JogPanel) -> None:
    jog.set_units("in")
    jog.set_step(1.0)  # 1 mm, kept from an mm session: 0.0394 in
    assert jog.step_spin.text() == "0.0394 in"
    assert not any(b.isChecked() for b in jog.inch_preset_buttons.values())
    assert jog.change_step(1) == pytest.approx(2.54)  # the next larger: 0.1 in
    assert jog.change_step(1) == pytest.approx(25.4)
    assert jog.change_step(1) == pytest.approx(25.4)  # the largest already
    assert jog.change_step(-1) == pytest.approx(2.54)


def test_an_inch_step_is_sent_on_the_device_resolution(jog: JogPanel, record) -> None:
    calls = record(jog.jog_requested)
    jog.set_units("in")
    jog.inch_preset_buttons[0.001].click()
    assert jog.step() == pytest.approx(0.025)  # 0.0254 mm to 0.001 mm
    jog.set_resolution(0.01)  # connected: from the step chosen, not from 0.025 mm again
    assert jog.inch_preset_buttons[0.001].isEnabled()
    assert jog.inch_preset_buttons[0.001].isChecked()
    assert jog.step() == pytest.approx(0.03)
    assert "+0.0012 in" in jog.findChild(QPushButton, "jogXPlus").toolTip()  # as it is sent
    jog.set_resolution(1.0)  # whole mm: 0.001 and 0.01 in are finer than the device
    assert not jog.inch_preset_buttons[0.001].isEnabled()
    assert not jog.inch_preset_buttons[0.01].isEnabled()
    assert jog.inch_preset_buttons[0.1].isEnabled()
    jog.inch_preset_buttons[1.0].click()
    jog.handle_key(Qt.Key.Key_Right)
    assert calls == [("x", 25.0)]


def test_switching_the_step_units_keeps_the_step(jog: JogPanel, record) -> None:
    calls, released = record(jog.jog_requested), record(jog.jog_released)
    jog.set_step(10.0)
    jog.set_units("in")
    assert jog.step_spin.text() == "0.3937 in"
    assert jog.step() == 10.0
    jog.set_units("mm")
    assert jog.step() == 10.0 and jog.preset_buttons[10.0].isChecked()
    assert not any(b.isHidden() for b in jog.preset_buttons.values())
    assert tuple(jog.preset_buttons) == STEP_PRESETS
    assert jog.step_spin.suffix() == " mm"
    assert calls == [] and released == []


# -- speed ------------------------------------------------------------------------------------


def test_speed_shown_in_inches_per_second_maps_to_mm_per_second(speed, qtbot, record) -> None:
    calls = record(speed.speed_requested)
    speed.set_units("in")
    assert speed.spin.objectName() == "speedSpin"
    assert speed.spin.suffix() == " in/s"
    assert "0 to 1.9685 in/s" in speed.spin.toolTip()
    assert "in/s" in speed.slider.toolTip() and "mm" not in speed.slider.toolTip()
    _type(qtbot, speed.spin, "0.5")
    assert calls == [(12.7,)]
    assert speed.slider.value() == round(12.7 / 50.0 * SLIDER_STEPS)
    speed.slider.setValue(SLIDER_STEPS // 2)  # a click on the groove: half the range
    assert calls[-1] == (25.0,)
    assert speed.spin.text() == "0.9843 in/s"
    speed.set_reported(25.4)
    assert speed.reported_label.text() == "device: 1 in/s"


def test_speed_in_inches_is_sent_to_the_device_decimals(speed, qtbot, record) -> None:
    calls = record(speed.speed_requested)
    speed.set_decimals(0)  # whole mm/s
    speed.set_units("in")
    assert speed.spin.decimals() == 2
    _type(qtbot, speed.spin, "0.5")
    assert calls == [(13.0,)]


def test_switching_speed_units_converts_and_emits_nothing(speed, record) -> None:
    calls = record(speed.speed_requested)
    speed.set_value(12.0)
    speed.set_reported(12.0)
    position = speed.slider.value()
    speed.set_units("in")
    assert speed.spin.text() == "0.4724 in/s"
    assert speed.value() == 12.0
    assert speed.reported_label.text() == "device: 0.4724 in/s"
    speed.set_units("mm")
    assert speed.spin.text() == "12.00 mm/s" and speed.value() == 12.0
    assert speed.reported_label.text() == "device: 12 mm/s"
    assert speed.slider.value() == position
    assert calls == []


# -- arc --------------------------------------------------------------------------------------


def test_arc_in_inches(arc: ArcEntry, record) -> None:
    runs, previews = record(arc.arc_requested), record(arc.preview_changed)
    arc.set_values(cx=25.4, cy=0.0, radius=12.7, z=1.0)
    points = arc.arc_points()
    previews.clear()
    arc.set_units("in")
    assert previews == [] and arc.arc_points() == points  # nothing moved
    assert arc.fields["cx"].text() == "1.0000 in"
    assert arc.fields["radius"].suffix() == " in"
    assert arc.fields["start"].suffix() == " °"
    assert "inches" in arc.fields["cx"].toolTip()
    arc.fields["radius"].setValue(1.0)  # typed: 1 in
    assert arc.values()["radius"] == 25.4
    arc.set_units("mm")
    assert arc.fields["cx"].text() == "25.400 mm" and arc.fields["radius"].text() == "25.400 mm"
    arc.run_button.click()
    assert runs[-1][0]["cx"] == 25.4 and runs[-1][0]["radius"] == 25.4


def test_arc_out_of_the_box_is_said_in_inches(arc: ArcEntry) -> None:
    arc.set_box(((0.0, 50.8), (0.0, 50.8), (0.0, 25.4)))
    arc.set_values(cx=50.8, cy=25.4, radius=12.7, start=0.0, end=0.0)  # reaches X 63.5 mm
    assert "(travel 0 to 50.8 mm)" in arc.problem()
    arc.set_units("in")
    assert arc.problem() == (
        "The arc leaves the travel limits: X 1.5000 to 2.5000 in (travel 0 to 2 in)."
    )
    assert arc.problem() in arc.run_button.toolTip()


# -- the helpers ------------------------------------------------------------------------------


def test_numbers_follow_the_locale() -> None:
    QLocale.setDefault(QLocale(QLocale.Language.French, QLocale.Country.France))
    assert number_text(1234.5, 2) == "1234,5"
    assert number_text(0.25, 4, signed=True) == "+0,25"
    assert number_text(-0.00001, 3) == "0"
    assert number_text(2.0, 3, trim=False) == "2,000"


def test_a_unit_field_is_a_plain_spin_box_in_mm(qtbot) -> None:
    field = UnitSpinBox()
    qtbot.addWidget(field)
    field.set_mm_decimals(2)
    field.set_mm_range(-10.0, 10.0)
    field.set_mm_value(1.234)
    assert field.value() == 1.23 and field.mm_value() == 1.23  # as QDoubleSpinBox rounds
    field.set_mm_value(20.0)
    assert field.mm_value() == 10.0


# -- the window -------------------------------------------------------------------------------


def test_the_window_applies_the_units_at_start_and_on_change(
    qtbot, tmp_path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import dataclasses

    from PySide6.QtCore import QSettings

    from app.window.main_window import MainWindow
    from app.window.preferences import DEFAULTS, write_preferences

    path = tmp_path / "settings.ini"
    stored = QSettings(str(path), QSettings.Format.IniFormat)
    write_preferences(stored, dataclasses.replace(DEFAULTS, units="in"))
    stored.sync()
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(path))
    window = MainWindow()
    qtbot.addWidget(window)
    window.show()
    qtbot.waitUntil(window.views.is_ready, timeout=10_000)
    try:
        arc = window.devices.arc
        widgets = (window.coordinates, window.jog_panel, window.speed, arc)
        assert [w.units() for w in widgets] == ["in"] * 4
        assert window.coordinates.fields["x"].suffix() == " in"
        jobs: list[object] = []
        window.coordinates.go_requested.connect(lambda *args: jobs.append(args))
        window.speed.speed_requested.connect(lambda *args: jobs.append(args))
        window.tools.apply_preferences(dataclasses.replace(window.tools.prefs, units="mm"))
        assert [w.units() for w in widgets] == ["mm"] * 4
        assert window.jog_panel.step_spin.suffix() == " mm"
        assert jobs == []  # switching sends nothing
    finally:
        window.close()
