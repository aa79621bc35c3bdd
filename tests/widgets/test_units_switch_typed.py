"""Issue 28 item 28: a change of units never shows a value nobody typed. The issue typed a
refused "0.001" in Go to X (finer than COXIRIS's 0.01 mm), switched to inches, and X showed
1.5748 in: the last usable value, 40 mm, converted. A refused number is cleared, saying why;
unreadable text stays as typed; a usable number converts exactly."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.widgets.test_units_shown import english_numbers  # noqa: F401 (autouse)
from widgets.coordinate_entry import CoordinateEntry

pytestmark = pytest.mark.timeout(30)


def _number(field) -> str:
    """What the field shows, without its unit."""
    return field.lineEdit().displayText().removesuffix(field.suffix()).strip()


def _typed(qtbot, entry: CoordinateEntry, text: str):
    """Go to X at 40 mm on a 0.01 mm device, then `text` typed over it (no Enter)."""
    entry.set_resolution(0.01)
    entry.set_values(40.0, 0.0, 0.0)
    field = entry.fields["x"]
    field.setFocus()
    field.lineEdit().selectAll()
    qtbot.keyClicks(field, text)
    return field


def test_a_refused_number_is_cleared_with_why_not_converted(qtbot, entry, record) -> None:
    calls = record(entry.go_requested)
    field = _typed(qtbot, entry, "0.001")
    assert "more than 2 decimals" in field.problem()
    entry.set_units("in")
    assert "1.5748" not in field.lineEdit().displayText()
    assert _number(field) == ""
    why = field.problem()
    assert "0.001" in why and "more than 2 decimals" in why and "cleared" in why, why
    assert why.split("\n")[0] in field.toolTip()
    assert field.property("invalidInput") is True
    qtbot.keyClick(field, Qt.Key.Key_Return)
    assert calls == []  # nothing is sent for the cleared field
    qtbot.keyClicks(field, "0.5")  # typed again: checked on its own, and sent
    assert field.problem() == ""
    qtbot.keyClick(field, Qt.Key.Key_Return)
    assert calls == [("absolute", (12.7, 0.0, 0.0))]


def test_an_out_of_range_number_is_cleared_too(qtbot, entry) -> None:
    entry.set_box(((-50.0, 50.0), (-50.0, 50.0), (-50.0, 50.0)))
    field = _typed(qtbot, entry, "80")
    assert "outside" in field.problem()
    entry.set_units("in")
    assert _number(field) == ""
    assert "80" in field.problem() and "cleared" in field.problem()


def test_unreadable_text_stays_as_typed(qtbot, entry) -> None:
    field = _typed(qtbot, entry, "4o")
    assert "not a number" in field.problem()
    entry.set_units("in")
    assert field.lineEdit().displayText() == "4o in"
    assert "not a number" in field.problem()
    entry.set_units("mm")
    assert field.lineEdit().displayText() == "4o mm"


def test_a_usable_number_typed_converts_exactly(qtbot, entry) -> None:
    field = _typed(qtbot, entry, "12.7")
    entry.set_units("in")
    assert field.lineEdit().displayText() == "0.5000 in"
    assert entry.values() == (12.7, 0.0, 0.0)
    entry.set_units("mm")
    assert field.lineEdit().displayText() == "12.70 mm"
    assert entry.values() == (12.7, 0.0, 0.0)


def test_a_refused_inch_value_is_cleared_on_the_way_back(qtbot, entry) -> None:
    entry.set_resolution(0.01)
    entry.set_units("in")
    field = entry.fields["x"]
    field.setFocus()
    field.lineEdit().selectAll()
    qtbot.keyClicks(field, "0.00001")
    assert field.problem()
    entry.set_units("mm")
    assert _number(field) == ""
    assert "0.00001" in field.problem() and "mm" in field.problem()
