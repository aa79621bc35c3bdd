"""CoordinateEntry: Go in both modes, Home, Set Home with confirmation, Stop, ranges, axes."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox

from widgets.coordinate_entry import SET_HOME_QUESTION, CoordinateEntry

LEFT = Qt.MouseButton.LeftButton


def test_object_names_units_and_tooltips(entry: CoordinateEntry) -> None:
    assert entry.objectName() == "coordinateEntry"
    for axis in "xyz":
        field = entry.fields[axis]
        assert field.objectName() == f"coord{axis.upper()}"
        assert field.suffix() == " mm"
        assert field.decimals() == 3
        assert "mm" in field.toolTip()
    for button in (entry.go_button, entry.home_button, entry.set_home_button, entry.stop_button):
        assert button.toolTip()
    assert entry.mode() == "absolute"


def test_typing_and_enter_goes_absolute(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    field = entry.fields["x"]
    field.lineEdit().selectAll()
    qtbot.keyClicks(field, "12.5")
    qtbot.keyClick(field, Qt.Key.Key_Return)
    assert calls == [("absolute", (12.5, 0.0, 0.0))]
    assert isinstance(calls[0][1], tuple)


def test_go_button_relative(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_values(5.0, 6.0, 7.0)
    qtbot.mouseClick(entry.relative_radio, LEFT)
    assert entry.mode() == "relative"
    assert entry.values() == (0.0, 0.0, 0.0)  # a coordinate is never reused as a distance
    entry.set_values(-1.25, 0.0, 2.0)
    qtbot.mouseClick(entry.go_button, LEFT)
    assert calls == [("relative", (-1.25, 0.0, 2.0))]


def test_disabled_axis(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_axes_enabled(["x", "y"])
    assert not entry.fields["z"].isEnabled()
    assert entry.fields["x"].isEnabled()
    entry.set_mode("relative")
    entry.fields["z"].setValue(3.0)
    entry.set_values(1.0, 2.0, 3.0)
    qtbot.mouseClick(entry.go_button, LEFT)
    assert calls == [("relative", (1.0, 2.0, 0.0))]  # no distance on an axis it lacks


def test_fields_are_bounded_by_the_travel_box(entry) -> None:
    assert entry.box() is None and entry.fields["x"].maximum() > 10000
    entry.set_box(((-10.0, 20.0), (-5.0, 5.0), (0.0, 2.0)))
    entry.set_values(50.0, -50.0, 5.0)
    assert entry.values() == (20.0, -5.0, 2.0)
    assert "travel limits" in entry.fields["x"].toolTip()
    entry.set_mode("relative")
    assert entry.fields["x"].maximum() == 30.0
    assert entry.fields["x"].minimum() == -30.0
    assert entry.fields["y"].maximum() == 10.0
    entry.set_box(None)
    assert "no travel limits set" in entry.fields["x"].toolTip()
    with pytest.raises(ValueError):
        entry.set_mode("sideways")


def test_resolution_and_stop_mode(entry) -> None:
    entry.set_resolution(0.01)
    assert entry.fields["x"].decimals() == 2
    entry.set_stop_mode(False, "drops what is queued; a move under way finishes")
    assert entry.stop_button.text() == "Drop queued"
    assert "finishes" in entry.stop_button.toolTip()
    entry.set_stop_mode(True, "halts the move")
    assert entry.stop_button.text() == "Stop"


def test_home_and_stop(entry, qtbot, record) -> None:
    homes, stops = record(entry.home_requested), record(entry.stop_requested)
    qtbot.mouseClick(entry.home_button, LEFT)
    qtbot.mouseClick(entry.stop_button, LEFT)
    assert homes == [()]
    assert stops == [()]


def test_set_home_needs_confirmation(entry, qtbot, record) -> None:
    calls = record(entry.set_home_requested)
    asked: list[str] = []
    entry.confirm = lambda question: asked.append(question) or False
    qtbot.mouseClick(entry.set_home_button, LEFT)
    assert calls == []
    entry.confirm = lambda question: True
    qtbot.mouseClick(entry.set_home_button, LEFT)
    assert calls == [()]
    assert asked == [SET_HOME_QUESTION]


def test_default_confirmation_uses_a_message_box(entry, qtbot, record, monkeypatch) -> None:
    calls = record(entry.set_home_requested)
    answers = iter([QMessageBox.StandardButton.No, QMessageBox.StandardButton.Yes])
    monkeypatch.setattr(QMessageBox, "question", lambda *args: next(answers))
    qtbot.mouseClick(entry.set_home_button, LEFT)
    qtbot.mouseClick(entry.set_home_button, LEFT)
    assert calls == [()]


def test_set_current_fills_fields_without_emitting(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.set_mode("relative")
    entry.set_current(1.5, -2.25, 3.125)
    assert entry.mode() == "absolute"
    assert entry.values() == (1.5, -2.25, 3.125)
    assert calls == []


def test_use_current_button(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    assert not entry.use_current_button.isEnabled()  # no position known yet
    entry.set_known_position(4.0, 5.0, 6.0)
    assert entry.values() == (0.0, 0.0, 0.0)  # remembering does not touch the fields
    qtbot.mouseClick(entry.use_current_button, LEFT)
    assert entry.values() == (4.0, 5.0, 6.0)
    assert calls == []


@pytest.mark.qt_log_ignore("Keyboard event not accepted")  # QTest: the disabled field ignores it
def test_disabled_widget_does_not_go(entry, qtbot, record) -> None:
    calls = record(entry.go_requested)
    entry.setEnabled(False)
    qtbot.keyClick(entry.fields["x"], Qt.Key.Key_Return)
    qtbot.mouseClick(entry.go_button, LEFT)
    assert calls == []
