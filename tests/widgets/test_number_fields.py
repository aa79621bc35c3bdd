"""Every typed number, typed with real key events: the text stays as typed, a number out of range
or unreadable is shown in red with why and its range and is never sent (nor replaced by another),
and both "." and the locale's decimal mark are read (Spanish and French use ",")."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import QLocale, Qt
from PySide6.QtGui import QPalette
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QAbstractItemView, QAbstractSpinBox, QLineEdit, QPushButton

from app.window.preferences import DEFAULTS
from widgets._number_field import INVALID_PROPERTY, INVALID_TEXT, parse_decimal, parse_whole
from widgets.arc_entry import ArcEntry
from widgets.coordinate_entry import CoordinateEntry
from widgets.dwell_entry import DwellEntry
from widgets.jog_panel import JogPanel
from widgets.parameter_editor import ParameterEditor, ParameterRow
from widgets.parameter_table import NAME_COL
from widgets.settings_dialog import SettingsDialog
from widgets.speed_control import SpeedControl
from widgets.travel_limits_dialog import TravelLimitsDialog

pytestmark = pytest.mark.timeout(60)

LEFT = Qt.MouseButton.LeftButton
BOX = ((-50.0, 50.0), (-50.0, 50.0), (0.0, 20.0))
DECIMAL_LOCALES = ("es_ES", "fr_FR", "en_US")
TYPED_12_5 = ("12,5", "12.5")


@pytest.fixture
def numbers_in() -> Iterator[object]:
    """`numbers_in("es_ES")`: the default locale (the interface's) for this test only."""
    before = QLocale()

    def use(name: str) -> QLocale:
        QLocale.setDefault(QLocale(name))
        return QLocale()

    yield use
    QLocale.setDefault(before)


def _shown(qtbot, widget):
    qtbot.addWidget(widget)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


def _type(qtbot, field: QAbstractSpinBox, text: str) -> None:
    """Select the number in the field and type `text` over it, key by key."""
    field.setFocus()
    field.lineEdit().selectAll()
    qtbot.keyClicks(field, text)


def _is_red(field: QAbstractSpinBox) -> bool:
    colour = field.lineEdit().palette().color(QPalette.ColorRole.Text).name()
    marked = bool(field.property(INVALID_PROPERTY))
    assert marked == (colour == INVALID_TEXT), (marked, colour)
    return marked


def _spanish_or_typed(locale: str, typed: str) -> bool:
    """Whether `typed` is a decimal number in `locale` ("12,5" is not one in English)."""
    return "," not in typed or QLocale(locale).decimalPoint() == ","


# -- the reading itself -----------------------------------------------------------------------


@pytest.mark.parametrize("locale", DECIMAL_LOCALES)
def test_both_decimal_marks_are_read_and_nothing_else(locale: str) -> None:
    where = QLocale(locale)
    assert parse_decimal("12.5", where) == (12.5, 1)
    assert parse_decimal("-0.250", where) == (-0.25, 2)  # trailing zeros are not finer
    assert parse_decimal("12,5", where) == ((12.5, 1) if locale != "en_US" else None)
    for text in ("", "-", "1.2.3", "abc", "1e3", "inf", "1 000", "12,5.0"):
        assert parse_decimal(text, where) is None, text
    assert parse_whole("1500", where) == 1500
    assert parse_whole("12.5", where) is None and parse_whole("12,5", where) is None


# -- Go to ------------------------------------------------------------------------------------


def test_go_to_80_in_a_50_box_stays_80_shows_red_and_go_sends_nothing(qtbot, record) -> None:
    entry = _shown(qtbot, CoordinateEntry())
    entry.set_box(BOX)
    sent, refused = record(entry.go_requested), record(entry.refused)
    x = entry.fields["x"]
    _type(qtbot, x, "80")
    assert x.text() == "80 mm"  # the 0 was not dropped
    assert _is_red(x)
    assert "X: 80 mm is outside -50 to 50 mm" in x.toolTip()
    assert "travel limits" in x.toolTip()  # the field's own tooltip follows the reason
    qtbot.keyClick(x, Qt.Key.Key_Return)
    assert sent == [] and x.text() == "80 mm"
    assert refused == [("X: 80 mm is outside -50 to 50 mm; nothing sent",)]
    qtbot.mouseClick(entry.go_button, LEFT)
    entry.fields["y"].setFocus()  # focus leaves: Qt would put the last value back
    assert sent == [] and x.text() == "80 mm" and _is_red(x)
    assert len(refused) == 2
    _type(qtbot, x, "-30")
    assert not _is_red(x) and x.toolTip().startswith("X target coordinate")
    qtbot.keyClick(x, Qt.Key.Key_Return)
    assert sent == [("absolute", (-30.0, 0.0, 0.0))]


def test_go_to_refuses_an_unreadable_number_and_too_many_decimals(qtbot, record) -> None:
    entry = _shown(qtbot, CoordinateEntry())
    sent, refused = record(entry.go_requested), record(entry.refused)
    y = entry.fields["y"]
    _type(qtbot, y, "1..5")
    assert y.text() == "1..5 mm" and _is_red(y)
    qtbot.keyClick(y, Qt.Key.Key_Return)
    _type(qtbot, y, "1.2345")  # the device takes 0.001 mm: never rounded behind the operator
    qtbot.keyClick(y, Qt.Key.Key_Return)
    assert sent == []
    assert [why for (why,) in refused] == [
        "Y: “1..5” is not a number (-99999 to 99999 mm); nothing sent",
        "Y: 1.2345 mm has more than 3 decimals; nothing sent",
    ]


@pytest.mark.parametrize("locale", DECIMAL_LOCALES)
@pytest.mark.parametrize("typed", TYPED_12_5)
def test_go_to_reads_both_decimal_marks(qtbot, record, numbers_in, locale, typed) -> None:
    numbers_in(locale)
    entry = _shown(qtbot, CoordinateEntry())
    sent, refused = record(entry.go_requested), record(entry.refused)
    _type(qtbot, entry.fields["x"], typed)
    qtbot.keyClick(entry.fields["x"], Qt.Key.Key_Return)
    if _spanish_or_typed(locale, typed):
        assert sent == [("absolute", (12.5, 0.0, 0.0))] and refused == []
    else:  # "12,5" in English: a thousands comma or a slip, never 12 nor 125
        assert sent == [] and "“12,5” is not a number" in refused[0][0]


def test_a_spanish_field_on_an_english_interface(qtbot, record) -> None:
    entry = _shown(qtbot, CoordinateEntry())
    entry.fields["z"].setLocale(QLocale("es_ES"))
    sent = record(entry.go_requested)
    _type(qtbot, entry.fields["z"], "12,5")
    qtbot.keyClick(entry.fields["z"], Qt.Key.Key_Return)
    assert sent == [("absolute", (0.0, 0.0, 12.5))]


# -- Arc --------------------------------------------------------------------------------------


@pytest.mark.parametrize("typed", TYPED_12_5)
def test_arc_reads_both_marks_and_refuses_an_angle_out_of_range(
    qtbot, record, numbers_in, typed
) -> None:
    numbers_in("es_ES")
    arc = _shown(qtbot, ArcEntry())
    runs = record(arc.arc_requested)
    _type(qtbot, arc.radius_field, typed)
    qtbot.keyClick(arc.radius_field, Qt.Key.Key_Return)
    assert arc.values()["radius"] == 12.5
    start = arc.fields["start"]
    _type(qtbot, start, "400")
    assert start.text() == "400 °" and _is_red(start)
    assert "400 ° is outside 0 to 360 °" in arc.problem()
    assert not arc.run_button.isEnabled() and "0 to 360" in arc.run_button.toolTip()
    arc.fields["end"].setFocus()
    assert start.text() == "400 °"
    qtbot.mouseClick(arc.run_button, LEFT)
    assert runs == []
    _type(qtbot, start, "45,5")
    qtbot.keyClick(start, Qt.Key.Key_Return)
    assert arc.problem() == "" and arc.run_button.isEnabled()
    qtbot.mouseClick(arc.run_button, LEFT)
    assert runs[0][0]["start"] == 45.5 and runs[0][0]["radius"] == 12.5


# -- Dwell ------------------------------------------------------------------------------------


def test_dwell_beyond_its_range_stays_and_sends_nothing(qtbot, record, numbers_in) -> None:
    numbers_in("es_ES")
    dwell = _shown(qtbot, DwellEntry())
    sent, refused = record(dwell.dwell_requested), record(dwell.refused)
    _type(qtbot, dwell.spin, "70000")
    assert dwell.spin.text() == "70000 ms" and _is_red(dwell.spin)
    qtbot.keyClick(dwell.spin, Qt.Key.Key_Return)
    qtbot.mouseClick(dwell.dwell_button, LEFT)
    assert sent == []
    assert refused == [("Dwell: 70000 ms is outside 0 to 65535 ms; nothing sent",)] * 2
    _type(qtbot, dwell.spin, "12,5")  # milliseconds are whole: never 12 nor 125
    qtbot.keyClick(dwell.spin, Qt.Key.Key_Return)
    assert sent == [] and "12,5 ms is not a whole number" in refused[-1][0]
    _type(qtbot, dwell.spin, "1500")
    qtbot.keyClick(dwell.spin, Qt.Key.Key_Return)
    assert sent == [(1500,)] and not _is_red(dwell.spin)


# -- Jog step ---------------------------------------------------------------------------------


@pytest.mark.parametrize("typed", TYPED_12_5)
def test_jog_step_reads_both_marks_and_a_step_too_big_jogs_nothing(
    qtbot, record, numbers_in, typed
) -> None:
    numbers_in("es_ES")
    jog = _shown(qtbot, JogPanel())
    jogs, refused = record(jog.jog_requested), record(jog.refused)
    _type(qtbot, jog.step_spin, typed)
    assert jog.step() == 12.5
    qtbot.mouseClick(jog.buttons[("x", 1.0)], LEFT)
    assert jogs == [("x", 12.5)]
    _type(qtbot, jog.step_spin, "2000")
    assert jog.step_spin.text() == "2000 mm" and _is_red(jog.step_spin)
    qtbot.mouseClick(jog.buttons[("x", 1.0)], LEFT)
    assert jogs == [("x", 12.5)]  # not the 200 Qt left, nor 1000, nor the last 12.5
    assert refused == [("Step: 2000 mm is outside 0,001 to 1000 mm; no jog",)]
    assert jog.held() is None


# -- Speed ------------------------------------------------------------------------------------


@pytest.mark.parametrize("typed", TYPED_12_5)
def test_speed_reads_both_marks_and_refuses_too_fast(qtbot, record, numbers_in, typed) -> None:
    numbers_in("fr_FR")
    speed = _shown(qtbot, SpeedControl())
    speed.set_range(0.0, 100.0)
    sent, refused = record(speed.speed_requested), record(speed.refused)
    _type(qtbot, speed.spin, "150")
    qtbot.keyClick(speed.spin, Qt.Key.Key_Return)
    qtbot.mouseClick(speed.apply_button, LEFT)
    assert sent == [] and speed.spin.text() == "150 mm/s" and _is_red(speed.spin)
    assert refused[0][0].endswith("150 mm/s is outside 0 to 100 mm/s; nothing sent")
    _type(qtbot, speed.spin, typed)
    qtbot.keyClick(speed.spin, Qt.Key.Key_Return)
    assert sent == [(12.5,)]


# -- Travel limits ----------------------------------------------------------------------------


@pytest.mark.parametrize("typed", TYPED_12_5)
def test_travel_limits_read_both_marks_and_ok_waits_for_a_number(qtbot, numbers_in, typed) -> None:
    numbers_in("es_ES")
    dialog = _shown(qtbot, TravelLimitsDialog("COXIRIS", BOX, False))
    high = dialog.findChild(QAbstractSpinBox, "travelXMax")
    ok = dialog.buttons.button(dialog.buttons.StandardButton.Ok)
    _type(qtbot, high, "100000")
    assert high.text() == "100000 mm" and _is_red(high)
    assert not ok.isEnabled()
    assert "X max: 100000 mm is outside -99999 to 99999 mm" in dialog.problem_label.text()
    qtbot.keyClick(high, Qt.Key.Key_Return)
    assert dialog.isVisible() and high.text() == "100000 mm"
    _type(qtbot, high, typed)
    assert ok.isEnabled() and dialog.problem_label.text() == ""
    qtbot.mouseClick(ok, LEFT)
    assert dialog.result_limits()[0][0] == (-50.0, 12.5)


# -- Parameters -------------------------------------------------------------------------------

PULLEY = ParameterRow(1, "pulley_diameter_x", "mm", 0.0, 99999.9, 0.1, False, "X pulley diameter")


@pytest.mark.parametrize("typed", ("38,2", "38.2"))
def test_a_parameter_reads_both_marks(qtbot, numbers_in, typed) -> None:
    numbers_in("es_ES")
    editor = _shown(qtbot, ParameterEditor())
    editor.set_parameters([PULLEY])
    editor.set_values({"pulley_diameter_x": 12.7})
    editor.table.setCurrentIndex(editor.model.index(0, NAME_COL))
    editor.table.setFocus()
    QTest.keyClick(editor.table, Qt.Key.Key_F2)
    (line,) = [e for e in editor.table.findChildren(QLineEdit, "parameterValueEditor")]
    line.selectAll()
    qtbot.keyClicks(line, typed)
    assert line.text() == typed and line.styleSheet() == ""  # not refused
    qtbot.keyClick(line, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: editor.table.state() != QAbstractItemView.State.EditingState)
    assert editor.value("pulley_diameter_x") == 38.2


# -- Settings ---------------------------------------------------------------------------------


@pytest.mark.parametrize("typed", ("2,5", "2.5"))
def test_a_setting_reads_both_marks_and_keeps_a_number_out_of_range(
    qtbot, numbers_in, typed
) -> None:
    numbers_in("es_ES")
    dialog = _shown(qtbot, SettingsDialog(DEFAULTS))
    idle = dialog.findChild(QAbstractSpinBox, "pollIdleS")
    ok = dialog.findChild(QPushButton, "settingsOk")
    _type(qtbot, idle, "12")
    assert idle.text() == "12 s" and _is_red(idle)  # 12 s: out of 0.2 to 10 s, but kept
    assert not ok.isEnabled() and "12 is not a number from 0.2 to 10 s" in dialog.problems()[0]
    dialog.findChild(QAbstractSpinBox, "pollMovingHz").setFocus()
    assert idle.text() == "12 s"
    _type(qtbot, idle, typed)
    assert ok.isEnabled() and not _is_red(idle)
    assert dialog.preferences().poll_idle_s == 2.5


# -- in the window: the refusal on the status line, nothing on the wire ----------------------


def test_the_window_says_why_go_to_sent_nothing_and_sends_what_was_typed(qtbot, window) -> None:
    with qtbot.waitSignal(window.settled, timeout=5000):
        window.connect_device("sim://coxiris?speed=100", "coxiris", 115200)
    entry = window.coordinates
    entry.set_box(BOX)
    x = entry.fields["x"]
    _type(qtbot, x, "80")
    qtbot.keyClick(x, Qt.Key.Key_Return)
    assert window.status_line.message() == "X: 80 mm is outside -50 to 50 mm; nothing sent"
    assert window.status_line.message_kind() == "warning"
    _type(qtbot, x, "30")
    qtbot.keyClick(x, Qt.Key.Key_Return)

    def sent_30() -> None:
        window.console.flush()
        assert "ABSOLUTE_MOVE 30 0 0" in window.console.text()

    qtbot.waitUntil(sent_30, timeout=5000)
    window.console.flush()
    assert "ABSOLUTE_MOVE 8" not in window.console.text()  # the 80 was never cut to 8
