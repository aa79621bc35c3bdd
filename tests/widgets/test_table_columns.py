"""Issue 28 item 26: the parameter table's and the console's columns get the width their text
needs, and the spare goes where the text is long."""

from __future__ import annotations

import pytest

from app.window.console.table import BYTES, MEANING, REPLY
from widgets.parameter_editor import ParameterEditor, ParameterRow
from widgets.parameter_table import DESC_COL, DESC_LEAST, WRITTEN_COL
from widgets.parameter_values import AFTER_SET

pytestmark = pytest.mark.timeout(30)
ROWS = [
    ParameterRow(25, "max_speed_x", "mm/s", 0, 99999, 0.1, True, "Top speed of X, computed"),
    ParameterRow(1, "pulley_diameter_x", "mm", 0.0, 999.9, 0.1, False, "X pulley diameter"),
]


@pytest.fixture
def editor(qtbot) -> ParameterEditor:
    widget = ParameterEditor()
    qtbot.addWidget(widget)
    widget.resize(1200, 500)
    widget.set_parameters(ROWS)
    widget.set_values({"max_speed_x": 1234.5, "pulley_diameter_x": 12.7})
    widget.set_last_written({"pulley_diameter_x": 12.7})
    widget.model.set_computed({"max_speed_x": 1234.5}, AFTER_SET)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


def _needed(editor: ParameterEditor, column: int) -> int:
    """The width the column's cells need (text and margins), as the view measures it."""
    return editor.table.sizeHintForColumn(column)


def test_last_written_shows_a_computed_value_whole_and_the_description_has_room(
    qtbot, editor: ParameterEditor
) -> None:
    table = editor.table
    assert "(computed)" in str(editor.model.index(0, WRITTEN_COL).data())
    qtbot.waitUntil(lambda: table.columnWidth(WRITTEN_COL) >= _needed(editor, WRITTEN_COL))
    editor.resize(700, 500)  # a narrow dock: the description keeps its room, the table scrolls
    qtbot.waitUntil(lambda: table.columnWidth(DESC_COL) >= DESC_LEAST)
    assert table.columnWidth(WRITTEN_COL) >= _needed(editor, WRITTEN_COL)
    editor.resize(1600, 500)  # a wide one: the description takes the width left
    qtbot.waitUntil(lambda: table.columnWidth(DESC_COL) > DESC_LEAST + 200)


def test_the_console_gives_bytes_and_meaning_the_width_not_the_reply(qtbot) -> None:
    from app.window.console.traffic_console import RawConsole

    console = RawConsole()
    qtbot.addWidget(console)
    console.resize(1500, 400)
    console.show()
    qtbot.waitExposed(console)
    view = console.view
    digit = view.fontMetrics().horizontalAdvance("0")
    qtbot.waitUntil(lambda: view.columnWidth(MEANING) > 50 * digit)
    assert view.columnWidth(BYTES) > 50 * digit
    assert view.columnWidth(REPLY) < 25 * digit
    right = view.columnViewportPosition(REPLY) + view.columnWidth(REPLY)
    assert abs(right - view.viewport().width()) <= 2  # the columns fill the width, no more
