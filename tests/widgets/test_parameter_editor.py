"""ParameterEditor: checked edits, changed rows, writes and their outcome, derived values."""

from __future__ import annotations

import numpy
import pytest
from PySide6.QtCore import QModelIndex, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import (
    QAbstractItemView,
    QApplication,
    QDockWidget,
    QLabel,
    QLineEdit,
    QMainWindow,
    QPushButton,
    QWidget,
)

from widgets.parameter_editor import PROFILE_FILTER, ParameterEditor, ParameterRow
from widgets.parameter_table import (
    KIND_COL,
    NAME_COL,
    REFUSED_STYLE,
    STATUS_COL,
    VALUE_COL,
    WRITTEN_COL,
)
from widgets.parameter_values import check_value

PULLEY = ParameterRow(1, "pulley_diameter_x", "mm", 0.0, 99999.9, 0.1, False, "X pulley diameter")
ROWS = [
    PULLEY,
    ParameterRow(2, "steps_per_rev_x", "steps", 1, 65535, 1, False, "Motor steps per revolution"),
    ParameterRow(3, "pulse_width", "µs", 1, 1000, 1, False, "Step pulse width"),
    ParameterRow(4, "max_speed_x", "mm/s", 0, 2000, 1, True, "Top speed X, from the others"),
    ParameterRow(5, "driving_mechanism", "", 0, 3, 1, False, "0 belt, 1 screw, 2 rack, 3 direct"),
]
DEFAULTS = {
    "pulley_diameter_x": 12.7,
    "steps_per_rev_x": 200,
    "pulse_width": 10,
    "max_speed_x": 500,
    "driving_mechanism": 1,
}
PULLEY_RANGE = "0 to 99999.9 mm in steps of 0.1 mm"
BUTTONS = {
    "writeSelectedButton": "Write selected",
    "writeAllButton": "Write all",
    "writeChangedButton": "Write changed",
    "cancelWriteButton": "Cancel",
    "loadProfileButton": "Load profile…",
    "saveProfileButton": "Save profile…",
}


@pytest.fixture
def editor(qtbot) -> ParameterEditor:
    widget = ParameterEditor()
    qtbot.addWidget(widget)
    widget.resize(1024, 640)
    widget.set_parameters(ROWS)
    widget.set_values(DEFAULTS)
    widget.set_last_written(DEFAULTS)
    widget.set_connected(True)
    widget.show()
    return widget


def _index(editor: ParameterEditor, row: int, column: int = VALUE_COL) -> QModelIndex:
    return editor.model.index(row, column)


def _open_editor(editor: ParameterEditor, row: int) -> QLineEdit:
    """Start editing a value cell the way F2 does, and return the delegate's line edit."""
    index = _index(editor, row, NAME_COL)
    editor.table.setCurrentIndex(index)
    editor.table.setFocus()
    QTest.keyClick(editor.table, Qt.Key.Key_F2)
    return _line(editor)


def _line(editor: ParameterEditor) -> QLineEdit:
    """The open value editor (closed ones linger until deleteLater runs)."""
    lines = editor.table.findChildren(QLineEdit, "parameterValueEditor")
    visible = [line for line in lines if line.isVisible()]
    assert len(visible) == 1, lines
    return visible[0]


def _type(qtbot, line: QLineEdit, text: str) -> None:
    line.selectAll()
    qtbot.keyClicks(line, text)


def _commit(
    qtbot, editor: ParameterEditor, line: QLineEdit, key: Qt.Key = Qt.Key.Key_Return
) -> None:
    """Enter in the editor: the delegate commits and closes it (queued, as Qt does)."""
    qtbot.keyClick(line, key)
    qtbot.waitUntil(lambda: editor.table.state() != QAbstractItemView.State.EditingState)


def _button(editor: ParameterEditor, name: str) -> QPushButton:
    button = editor.findChild(QPushButton, name)
    assert button is not None, name
    return button


def _click(qtbot, editor: ParameterEditor, name: str) -> None:
    button = _button(editor, name)
    assert button.isEnabled(), name
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def test_object_names_columns_and_tooltips(editor: ParameterEditor) -> None:
    assert editor.objectName() == "parameterEditorPanel"
    model = editor.model
    headers = [model.headerData(c, Qt.Orientation.Horizontal) for c in range(model.columnCount())]
    assert headers == [
        "ID",
        "Name",
        "Unit",
        "Value",
        "Last written",
        "Kind",
        "Description",
        "Status",
    ]
    for name, text in BUTTONS.items():
        button = _button(editor, name)
        assert button.text() == text
        assert button.toolTip()
    assert editor.findChild(QDockWidget) is None
    assert model.data(_index(editor, 0, 2)) == "mm"
    assert model.data(_index(editor, 0)) == "12.7"
    assert model.data(_index(editor, 0, WRITTEN_COL)) == "12.7 mm"
    assert PULLEY_RANGE in model.data(_index(editor, 0), Qt.ItemDataRole.ToolTipRole)
    assert model.data(_index(editor, 0, STATUS_COL)) == "not written"


def test_output_rows_look_different(editor: ParameterEditor, qtbot) -> None:
    model = editor.model
    kind = _index(editor, 3, KIND_COL)
    assert model.data(kind) == "output"
    assert model.data(_index(editor, 0, KIND_COL)) == "input"
    assert model.data(kind, Qt.ItemDataRole.FontRole).italic()
    assert model.data(_index(editor, 0, KIND_COL), Qt.ItemDataRole.FontRole) is None
    assert model.data(kind, Qt.ItemDataRole.ForegroundRole) is not None
    assert "computed by the firmware" in model.data(kind, Qt.ItemDataRole.ToolTipRole)
    line = _open_editor(editor, 3)
    assert "computed by the firmware" in line.toolTip()
    assert "max_speed_x is an output" in editor.message()


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("38.25", "not a multiple of 0.1 mm"),
        ("abc", "not a number"),
        ("inf", "not a finite number"),
        ("nan", "not a finite number"),
        ("100000", "above the maximum"),
        ("-0.1", "below the minimum"),
        ("38,2", "use a point for decimals"),
        ("", "empty"),
    ],
)
def test_refused_as_you_type_and_never_stored(editor, qtbot, record, text, reason) -> None:
    writes = record(editor.write_requested)
    line = _open_editor(editor, 0)
    _type(qtbot, line, "38.2")
    assert line.styleSheet() == ""
    assert "Enter keeps it" in editor.message()
    line.selectAll()
    qtbot.keyClick(line, Qt.Key.Key_Delete)
    if text:
        qtbot.keyClicks(line, text)
    message = editor.message()
    assert message.startswith("pulley_diameter_x: ")
    assert reason in message
    assert message.endswith(PULLEY_RANGE)
    assert line.styleSheet() == REFUSED_STYLE
    assert editor.message_label.styleSheet()  # shown as an error
    qtbot.keyClick(line, Qt.Key.Key_Return)  # refused: the editor stays open
    QApplication.processEvents()  # a commit would be queued: let it happen if there were one
    assert editor.table.state() == QAbstractItemView.State.EditingState
    assert editor.value("pulley_diameter_x") == 12.7
    qtbot.keyClick(line, Qt.Key.Key_Escape)
    assert editor.table.state() != QAbstractItemView.State.EditingState
    assert editor.value("pulley_diameter_x") == 12.7
    assert editor.changed_names() == []
    assert writes == []


def test_refusal_message_names_unit_and_range() -> None:
    value, why = check_value(PULLEY, "38.25")
    assert value is None
    assert why == (
        "pulley_diameter_x: 38.25 mm refused (not a multiple of 0.1 mm): "
        "0 to 99999.9 mm in steps of 0.1 mm"
    )
    assert check_value(PULLEY, " 38.2 ") == (38.2, "")
    assert check_value(PULLEY, "99999.9") == (99999.9, "")
    assert check_value(PULLEY, "0.30000000000000004") == (0.3, "")  # within 1e-9 of a step
    assert check_value(ROWS[1], "200.5")[1].endswith("1 to 65535 steps, whole numbers")


def test_model_set_data_refuses_too(editor: ParameterEditor) -> None:
    assert not editor.model.setData(_index(editor, 1), "0")
    assert "steps_per_rev_x: 0 steps refused (below the minimum)" in editor.message()
    assert not editor.model.setData(_index(editor, 0), float("inf"))
    assert not editor.model.setData(_index(editor, 0, NAME_COL), "3")
    assert not editor.model.setData(_index(editor, 0), None)
    assert editor.model.setData(_index(editor, 2), numpy.int64(20))
    assert editor.model.setData(_index(editor, 0), numpy.float64(12.5))
    assert editor.values()["pulse_width"] == 20.0
    editor.set_values(DEFAULTS)
    assert editor.values() == {name: float(v) for name, v in DEFAULTS.items()}


def test_valid_edit_is_stored_and_marked_changed(editor, qtbot) -> None:
    assert editor.changed_label.text() == "Every value is what was last written to this device"
    line = _open_editor(editor, 0)
    _type(qtbot, line, "38.2")
    _commit(qtbot, editor, line)
    assert editor.value("pulley_diameter_x") == 38.2
    assert editor.changed_names() == ["pulley_diameter_x"]
    index = _index(editor, 0)
    assert editor.model.data(index) == "• 38.2"
    assert editor.model.data(index, Qt.ItemDataRole.FontRole).bold()
    assert editor.model.data(index, Qt.ItemDataRole.BackgroundRole) is not None
    assert editor.model.data(_index(editor, 0, WRITTEN_COL)) == "12.7 mm"
    assert editor.changed_label.text().startswith(
        "1 value differs from what was last written to this device"
    )
    assert editor.message() == "pulley_diameter_x = 38.2 mm, not yet written to the device"


def test_never_written_counts_as_changed(editor: ParameterEditor) -> None:
    editor.set_last_written({"pulley_diameter_x": 12.7, "pulse_width": 12})
    assert editor.changed_names() == [
        "steps_per_rev_x",
        "pulse_width",
        "max_speed_x",
        "driving_mechanism",
    ]
    assert editor.changed_label.text().startswith("4 values differ from what was last written")
    assert editor.last_written() == {"pulley_diameter_x": 12.7, "pulse_width": 12.0}


def test_keyboard_enter_edits_the_value_and_typing_starts_an_edit(editor, qtbot) -> None:
    table = editor.table
    table.setCurrentIndex(_index(editor, 2, NAME_COL))
    qtbot.keyClick(table, Qt.Key.Key_Return)
    assert table.state() == QAbstractItemView.State.EditingState
    assert table.currentIndex().column() == VALUE_COL
    qtbot.keyClick(_line(editor), Qt.Key.Key_Escape)
    assert table.state() != QAbstractItemView.State.EditingState
    assert editor.message() == "pulse_width: edit cancelled, value unchanged"
    table.setCurrentIndex(_index(editor, 2, NAME_COL))
    qtbot.keyClick(table, "2")  # a digit on any cell of the row starts editing its value
    line = _line(editor)
    assert line.text() == "2"
    qtbot.keyClicks(line, "5")
    _commit(qtbot, editor, line, Qt.Key.Key_Enter)
    assert editor.value("pulse_width") == 25.0


def test_set_values_reports_refusals_and_keeps_the_rest(editor: ParameterEditor) -> None:
    problems = editor.set_values({"pulley_diameter_x": 40.05, "pulse_width": 20, "bogus": 1})
    assert problems == [
        "pulley_diameter_x: 40.05 mm refused (not a multiple of 0.1 mm): " + PULLEY_RANGE,
        "bogus: no such parameter",
    ]
    assert editor.value("pulley_diameter_x") == 12.7
    assert editor.value("pulse_width") == 20.0
    assert editor.value("bogus") is None
    assert "bogus: no such parameter" in editor.message()


def test_write_buttons_follow_connection_and_selection(editor, qtbot) -> None:
    assert not _button(editor, "writeSelectedButton").isEnabled()  # nothing selected
    assert not _button(editor, "writeChangedButton").isEnabled()  # nothing changed
    assert _button(editor, "writeAllButton").isEnabled()
    assert not _button(editor, "cancelWriteButton").isEnabled()
    editor.set_connected(False)
    assert not _button(editor, "writeAllButton").isEnabled()
    assert _button(editor, "loadProfileButton").isEnabled()
    assert editor.table.model().flags(_index(editor, 0)) & Qt.ItemFlag.ItemIsEditable


def test_write_all_changed_and_selected(editor, qtbot, record) -> None:
    writes = record(editor.write_requested)
    _click(qtbot, editor, "writeAllButton")
    assert writes[-1] == ([(1, 12.7), (2, 200.0), (3, 10.0), (4, 500.0), (5, 1.0)],)
    assert "max_speed_x" in editor.message()  # an output is among them: said so

    editor.set_values({"pulse_width": 30, "pulley_diameter_x": 13.0})
    _click(qtbot, editor, "writeChangedButton")
    assert writes[-1] == ([(1, 13.0), (3, 30.0)],)

    editor.table.selectRow(4)
    editor.table.selectionModel().select(
        _index(editor, 1, 0),
        editor.table.selectionModel().SelectionFlag.Select
        | editor.table.selectionModel().SelectionFlag.Rows,
    )
    _click(qtbot, editor, "writeSelectedButton")
    assert writes[-1] == ([(2, 200.0), (5, 1.0)],)
    assert len(writes) == 3


def test_write_progress_statuses_and_last_written(editor, qtbot, record) -> None:
    editor.set_values({"pulley_diameter_x": 38.2, "pulse_width": 30, "steps_per_rev_x": 400})
    writes = record(editor.write_requested)
    _click(qtbot, editor, "writeChangedButton")
    assert writes == [([(1, 38.2), (2, 400.0), (3, 30.0)],)]
    editor.begin_write([1, 2, 3], 1.0)
    assert editor.writing()
    assert editor.progress.isVisible()
    assert editor.progress.objectName() == "writeProgress"
    assert editor.progress_text() == "0 / 3 packets, about 3.0 s left"
    assert _button(editor, "cancelWriteButton").isEnabled()
    assert not _button(editor, "writeAllButton").isEnabled()
    assert [editor.status(i) for i in (1, 2, 3)] == ["pending"] * 3

    editor.set_status(1, "confirmed")
    assert editor.progress.value() == 1
    assert editor.progress_text() == "1 / 3 packets, about 2.0 s left"
    assert editor.last_written()["pulley_diameter_x"] == 38.2
    assert editor.model.data(_index(editor, 0, WRITTEN_COL)) == "38.2 mm"

    editor.set_status(2, "error", "EP0006 invalid parameter id")
    status_cell = _index(editor, 1, STATUS_COL)
    assert editor.model.data(status_cell) == "error: EP0006 invalid parameter id"
    assert "EP0006" in editor.model.data(status_cell, Qt.ItemDataRole.ToolTipRole)
    assert editor.last_written()["steps_per_rev_x"] == 200.0  # not confirmed: unchanged
    editor.set_status(3, "timed out", "no answer in 2 s")
    assert editor.progress_text() == "3 / 3 packets, about 0.0 s left"
    assert editor.changed_names() == ["steps_per_rev_x", "pulse_width"]

    editor.end_write()
    assert not editor.writing()
    assert not editor.progress.isVisible()
    assert not _button(editor, "cancelWriteButton").isEnabled()
    assert editor.message() == "Write finished: 1 confirmed, 1 error, 1 timed out"
    with pytest.raises(ValueError, match="unknown status"):
        editor.set_status(1, "done")


def test_cancel_and_end_write_turn_pending_into_cancelled(editor, qtbot, record) -> None:
    cancels = record(editor.cancel_requested)
    editor.begin_write([1, 2, 3, 4, 5], 1.2)
    assert editor.progress_text() == "0 / 5 packets, about 6.0 s left"
    editor.set_status(1, "confirmed")
    _click(qtbot, editor, "cancelWriteButton")
    assert cancels == [()]
    assert not _button(editor, "cancelWriteButton").isEnabled()
    editor.set_status(2, "confirmed")
    editor.end_write()
    assert [editor.status(i) for i in range(1, 6)] == ["confirmed"] * 2 + ["cancelled"] * 3
    assert editor.model.data(_index(editor, 4, STATUS_COL)) == "cancelled"
    assert editor.message() == "Write finished: 2 confirmed, 3 cancelled"
    assert _button(editor, "writeAllButton").isEnabled()


def test_confirmed_records_the_value_written_not_a_later_edit(editor, qtbot, record) -> None:
    editor.set_values({"pulse_width": 30})
    _click(qtbot, editor, "writeChangedButton")
    editor.begin_write([3], 1.0)
    editor.set_values({"pulse_width": 40})  # edited while the packet is on its way
    editor.set_status(3, "confirmed")
    editor.end_write()
    assert editor.last_written()["pulse_width"] == 30.0
    assert editor.changed_names() == ["pulse_width"]


def _grid_texts(box: QWidget) -> list[str]:
    grid = box.layout()
    labels = [grid.itemAt(i).widget() for i in range(grid.count())]
    return [label.text() for label in labels if isinstance(label, QLabel)]


def _derive(values: dict[str, float]) -> list[tuple[str, str]]:
    steps = values["steps_per_rev_x"]
    if steps <= 0:
        raise ValueError("steps_per_rev_x must be above 0")
    mm = 3.141592653589793 * values["pulley_diameter_x"] / steps
    return [("mm per step X", f"{mm:.4f} mm"), ("pulse", f"{values['pulse_width']:g} µs")]


def test_derived_values_shown_and_updated_on_edit(editor, qtbot) -> None:
    assert not editor.findChild(type(editor.derived_box), "derivedValues").isVisible()
    editor.set_derivation(_derive)
    box = editor.derived_box
    assert box.objectName() == "derivedValues" and box.isVisible()
    assert editor.derived_values() == [("mm per step X", "0.1995 mm"), ("pulse", "10 µs")]
    line = _open_editor(editor, 1)
    _type(qtbot, line, "400")
    _commit(qtbot, editor, line)
    assert editor.derived_values()[0] == ("mm per step X", "0.0997 mm")
    texts = _grid_texts(box)
    assert texts == ["mm per step X:", "0.0997 mm", "pulse:", "10 µs"]

    editor.set_derivation(lambda values: _derive({**values, "steps_per_rev_x": 0}))
    assert editor.derived_error() == "steps_per_rev_x must be above 0"
    assert editor.derived_values() == []
    texts = _grid_texts(box)
    assert texts == ["steps_per_rev_x must be above 0"]

    editor.set_derivation(_derive)
    editor.set_parameters(ROWS)  # no values yet: a KeyError says which one is missing
    assert editor.derived_error() == "needs a value for steps_per_rev_x"
    editor.set_values(DEFAULTS)
    assert editor.derived_values()[0] == ("mm per step X", "0.1995 mm")


def test_load_and_save_emit_the_chosen_path(editor, qtbot, record, monkeypatch) -> None:
    loads, saves = record(editor.load_requested), record(editor.save_requested)
    asked: list[bool] = []
    paths = iter(["/tmp/profiles/a.toml", "/tmp/profiles/b", ""])

    def choose(save: bool) -> str:
        asked.append(save)
        return next(paths)

    monkeypatch.setattr(editor, "_choose_path", choose)
    _click(qtbot, editor, "loadProfileButton")
    _click(qtbot, editor, "saveProfileButton")
    _click(qtbot, editor, "saveProfileButton")  # the user gave up: nothing
    assert asked == [False, True, True]
    assert loads == [("/tmp/profiles/a.toml",)]
    assert saves == [("/tmp/profiles/b.toml",)]
    assert PROFILE_FILTER == "Parameter profiles (*.toml);;All files (*)"
    editor.show_message("Loaded a.toml")
    assert editor.message() == "Loaded a.toml"
    assert not editor.message_label.styleSheet()
    editor.show_message("a.toml: line 3: not TOML", error=True)
    assert editor.message_label.styleSheet()


def test_row_note_is_visible(editor: ParameterEditor) -> None:
    editor.set_row_note("driving_mechanism", "the firmware forces 1 after every set")
    cell = _index(editor, 4, STATUS_COL)
    assert editor.model.data(cell) == "not written — the firmware forces 1 after every set"
    assert "forces 1" in editor.model.data(cell, Qt.ItemDataRole.ToolTipRole)
    editor.set_status(5, "confirmed")
    assert editor.model.data(cell).startswith("confirmed — the firmware forces 1")
    editor.set_row_note("driving_mechanism", "")
    assert editor.model.data(cell) == "confirmed"
    with pytest.raises(ValueError, match="no parameter nope"):
        editor.set_row_note("nope", "x")


def test_bad_rows_are_refused(editor: ParameterEditor) -> None:
    with pytest.raises(ValueError, match="repeat"):
        editor.set_parameters([PULLEY, PULLEY])
    with pytest.raises(ValueError, match="bad range or step"):
        editor.set_parameters([ParameterRow(9, "z", "", 0, 1, 0, False, "")])


def test_fits_a_dock_in_a_small_window(qtbot) -> None:
    window = QMainWindow()
    qtbot.addWidget(window)
    dock = QDockWidget("Parameters", window)
    panel = ParameterEditor()
    panel.set_parameters(ROWS)
    dock.setWidget(panel)
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, dock)
    window.resize(1024, 640)
    window.show()
    hint = panel.minimumSizeHint()
    assert hint.width() <= 1024 and hint.height() <= 640
    assert panel.table.isVisible()
    assert panel.table.horizontalHeader().sectionSize(6) >= 36
