"""The parameter editor's parts: the table model, the checking value delegate, the table view,
and the box of derived values.

Values are kept as the editor holds them and as they were last written (the device cannot be
read back).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from PySide6.QtCore import (
    QT_TRANSLATE_NOOP,
    QAbstractItemModel,
    QAbstractTableModel,
    QEvent,
    QItemSelectionModel,
    QModelIndex,
    QObject,
    QPersistentModelIndex,
    QSignalBlocker,
    Qt,
    Signal,
)
from PySide6.QtGui import QBrush, QColor, QFont, QKeyEvent
from PySide6.QtWidgets import (
    QAbstractItemDelegate,
    QAbstractItemView,
    QGridLayout,
    QGroupBox,
    QLabel,
    QLineEdit,
    QStyledItemDelegate,
    QStyleOptionViewItem,
    QTableView,
    QWidget,
)

from widgets._i18n import fill
from widgets.parameter_values import (
    OUTPUT_TIP,
    STATUS_COLOURS,
    ParameterRow,
    RowState,
    allowed,
    check_row,
    check_value,
    format_value,
    translated,
    with_unit,
)
from widgets.table_columns import FittedColumns

COLUMNS = (  # the headers, translated at use (ParameterModel context)
    QT_TRANSLATE_NOOP("ParameterModel", "ID"),
    QT_TRANSLATE_NOOP("ParameterModel", "Name"),
    QT_TRANSLATE_NOOP("ParameterModel", "Unit"),
    QT_TRANSLATE_NOOP("ParameterModel", "Value"),
    QT_TRANSLATE_NOOP("ParameterModel", "Last written"),
    QT_TRANSLATE_NOOP("ParameterModel", "Kind"),
    QT_TRANSLATE_NOOP("ParameterModel", "Description"),
    QT_TRANSLATE_NOOP("ParameterModel", "Status"),
)
COLUMN_WIDTHS = (40, 170, 60, 100, 110, 60, 240, 160)  # Description takes the width left
DESC_LEAST = 240  # px: the Description never narrower (the table scrolls sideways instead)
ID_COL, NAME_COL, UNIT_COL, VALUE_COL, WRITTEN_COL, KIND_COL, DESC_COL, STATUS_COL = range(8)
CHANGED_BACKGROUND = "#fff3cd"
OUTPUT_COLOUR = "#757575"
REFUSED_STYLE = "background: #ffcdd2; border: 1px solid #c62828;"
_NO_UPDATE = QItemSelectionModel.SelectionFlag.NoUpdate
ROW_ROLE = Qt.ItemDataRole.UserRole + 1  # the ParameterRow of any cell
ERROR_STYLE = "color: #c62828; font-weight: bold;"
Derivation = Callable[[dict[str, float]], list[tuple[str, str]]]
_HEADER_TIPS = {  # translated at use
    VALUE_COL: QT_TRANSLATE_NOOP(
        "ParameterModel",
        "The value to write, in the unit beside it (double-click, F2, Enter or type)",
    ),
    WRITTEN_COL: QT_TRANSLATE_NOOP(
        "ParameterModel",
        "What this panel last wrote to the device (the device cannot be read back)",
    ),
    KIND_COL: QT_TRANSLATE_NOOP(
        "ParameterModel", "input: set by you; output: computed by the firmware"
    ),
    STATUS_COL: QT_TRANSLATE_NOOP(
        "ParameterModel", "The outcome of the last write of this parameter"
    ),
}


def _as_text(value: Any) -> str:
    """Text for check_value: as typed, or the shortest repr of a number (numpy ones too)."""
    if isinstance(value, str):
        return value
    try:
        return repr(float(value))
    except (TypeError, ValueError):
        return str(value)


class ParameterModel(QAbstractTableModel):
    """The rows, their editor values, last written values and write status."""

    refused = Signal(str)  # why a value was not stored
    values_changed = Signal()
    written_changed = Signal()

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._states: list[RowState] = []

    # -- Qt model interface -------------------------------------------------------------

    def rowCount(self, parent: Any = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else len(self._states)

    def columnCount(self, parent: Any = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else len(COLUMNS)

    def headerData(self, section: int, orientation: Qt.Orientation, role: int = 0) -> Any:
        if orientation != Qt.Orientation.Horizontal:
            return None
        if role == Qt.ItemDataRole.DisplayRole:
            return self.tr(COLUMNS[section])
        if role == Qt.ItemDataRole.ToolTipRole:
            tip = _HEADER_TIPS.get(section)
            return self.tr(tip) if tip else None
        return None

    def flags(self, index: QModelIndex | QPersistentModelIndex) -> Qt.ItemFlag:
        flags = super().flags(index)
        return flags | Qt.ItemFlag.ItemIsEditable if index.column() == VALUE_COL else flags

    def data(self, index: QModelIndex | QPersistentModelIndex, role: int = 0) -> Any:
        if not index.isValid():
            return None
        state, column = self._states[index.row()], index.column()
        row = state.row
        if role == ROW_ROLE:
            return row
        if role == Qt.ItemDataRole.DisplayRole:
            return self._display(state, column)
        if role == Qt.ItemDataRole.EditRole:
            return "" if state.value is None else format_value(row, state.value)
        if role == Qt.ItemDataRole.ToolTipRole:
            return self._tooltip(state, column)
        if role == Qt.ItemDataRole.ForegroundRole:
            if column == STATUS_COL:
                return QBrush(QColor(STATUS_COLOURS[state.status]))
            if row.output and column in (NAME_COL, KIND_COL):
                return QBrush(QColor(OUTPUT_COLOUR))
        if role == Qt.ItemDataRole.FontRole:
            font = QFont()
            if column == VALUE_COL and state.changed():
                font.setBold(True)
                return font
            if column == KIND_COL and row.output:
                font.setItalic(True)
                return font
        if role == Qt.ItemDataRole.BackgroundRole and column == VALUE_COL and state.changed():
            return QBrush(QColor(CHANGED_BACKGROUND))
        if role == Qt.ItemDataRole.TextAlignmentRole and column in (ID_COL, VALUE_COL, WRITTEN_COL):
            return int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        return None

    def _display(self, state: RowState, column: int) -> str:
        row = state.row
        if column == VALUE_COL:
            if state.value is None:
                return "—"
            text = format_value(row, state.value)
            return f"• {text}" if state.changed() else text
        if column == WRITTEN_COL:
            written = state.written
            if written is not None and state.computed:  # the firmware's value, not a write
                shown = with_unit(format_value(row, written), row.unit)
                return fill(self.tr("%1 (computed)"), shown)
            if written is not None:
                return with_unit(format_value(row, written), row.unit)
            if row.power_on is not None:  # what the device holds until written
                shown = with_unit(format_value(row, row.power_on), row.unit)
                return fill(self.tr("%1 (power-on)"), shown)
            return "—"
        if column == STATUS_COL:
            return state.status_text()
        return {
            ID_COL: str(row.id),
            NAME_COL: row.name,
            UNIT_COL: row.unit,
            KIND_COL: self.tr("output") if row.output else self.tr("input"),
            DESC_COL: row.description,
        }[column]

    def _tooltip(self, state: RowState, column: int) -> str:
        row = state.row
        if column == KIND_COL:
            if row.output:
                return translated(OUTPUT_TIP)
            return self.tr("Input: set by you and written to the device")
        if column == STATUS_COL:
            return state.status_text().replace(" — ", "\n")
        if column == WRITTEN_COL:
            if state.written is None and row.power_on is not None:
                shown = with_unit(format_value(row, row.power_on), row.unit)
                return fill(
                    self.tr(
                        "%1: never written to this device from this panel; it holds %2 from "
                        "power-on"
                    ),
                    row.name,
                    shown,
                )
            if state.written is None:
                return fill(self.tr("%1: never written to this device from this panel"), row.name)
            shown = with_unit(format_value(row, state.written), row.unit)
            if state.computed:
                return fill(
                    self.tr("%1: the device holds %2, computed by its firmware %3"),
                    row.name,
                    shown,
                    translated(state.computed),
                )
            return fill(self.tr("%1: last written %2"), row.name, shown)
        lines = [
            f"{row.id} {row.name}: {row.description}",
            fill(self.tr("Allowed: %1"), allowed(row)),
        ]
        if column == VALUE_COL and state.value is not None:
            shown = with_unit(format_value(row, state.value), row.unit)
            lines.insert(1, fill(self.tr("Value: %1"), shown))
            if state.changed():
                lines.append(self.tr("• Differs from what was last written to this device"))
        if row.output:
            lines.append(translated(OUTPUT_TIP))
        if row.warning:
            lines.append(row.warning)
        return "\n".join(lines)

    def setData(
        self, index: QModelIndex | QPersistentModelIndex, value: Any, role: int = 2
    ) -> bool:
        """Store a typed value (text or number) in the Value column if it passes the checks."""
        if not index.isValid() or index.column() != VALUE_COL:
            return False
        if role != Qt.ItemDataRole.EditRole:
            return False
        state = self._states[index.row()]
        number, why = check_value(state.row, _as_text(value))
        if number is None:
            self.refused.emit(why)
            return False
        state.value = number
        self._row_changed(index.row())
        self.values_changed.emit()
        return True

    # -- the editor's interface ---------------------------------------------------------

    def set_rows(self, rows: list[ParameterRow]) -> None:
        """Replace the table; values, last written, statuses and notes are forgotten."""
        for row in rows:
            check_row(row)
        for key in ("id", "name"):
            seen = [getattr(row, key) for row in rows]
            if len(set(seen)) != len(seen):
                raise ValueError(f"parameter {key}s repeat: {seen}")
        self.beginResetModel()
        self._states = [RowState(row) for row in rows]
        self.endResetModel()
        self.values_changed.emit()
        self.written_changed.emit()

    def states(self) -> list[RowState]:
        return self._states

    def index_of(self, *, name: str | None = None, id: int | None = None) -> int:
        """The table row of a parameter, by name or by id (ValueError if there is none)."""
        for position, state in enumerate(self._states):
            if state.row.name == name or (id is not None and state.row.id == id):
                return position
        raise ValueError(f"no parameter {name if id is None else f'id {id}'}")

    def set_values(self, values: dict[str, float]) -> list[str]:
        """Store the acceptable values by name; the refusals, one message each."""
        problems = []
        stored = False
        for name, value in values.items():
            try:
                state = self._states[self.index_of(name=name)]
            except ValueError:
                problems.append(fill(self.tr("%1: no such parameter"), name))
                continue
            number, why = check_value(state.row, _as_text(value))
            if number is None:
                problems.append(why)
            else:
                state.value, stored = number, True
        if stored:
            self._all_changed()
            self.values_changed.emit()
        return problems

    def set_written(self, values: dict[str, float], *, replace: bool = True) -> None:
        """What the device holds, by name (unknown names ignored); replace forgets the rest."""
        for state in self._states:
            if state.row.name in values:
                new = float(values[state.row.name])
                if new != state.written:  # a computed value kept as it is stays marked
                    state.computed = ""
                state.written = new
            elif replace:
                state.written, state.computed = None, ""
        self._all_changed()
        self.written_changed.emit()

    def set_computed(self, values: dict[str, float], when: str) -> None:
        """Values the firmware recomputed itself (`when`: AFTER_SET or AT_MOVE), by name: what
        the device holds, marked computed; a value not being edited follows (unknown names
        ignored)."""
        for state in self._states:
            if state.row.name in values:
                edited = state.changed()
                state.written, state.computed = float(values[state.row.name]), when
                if not edited:
                    state.value = state.written
        self._all_changed()
        self.values_changed.emit()
        self.written_changed.emit()

    def set_status(self, position: int, status: str, message: str = "") -> None:
        if status not in STATUS_COLOURS:
            raise ValueError(f"unknown status {status!r}: one of {list(STATUS_COLOURS)}")
        state = self._states[position]
        state.status, state.message = status, message
        self._row_changed(position)

    def set_note(self, position: int, note: str) -> None:
        self._states[position].note = note
        self._row_changed(position)

    def _row_changed(self, position: int) -> None:
        self.dataChanged.emit(self.index(position, 0), self.index(position, len(COLUMNS) - 1))

    def _all_changed(self) -> None:
        if self._states:
            last = self.index(len(self._states) - 1, len(COLUMNS) - 1)
            self.dataChanged.emit(self.index(0, 0), last)


class _ValueEditor(QLineEdit):
    """The Value cell's editor; knows its row."""

    def __init__(self, row: ParameterRow, parent: QWidget) -> None:
        super().__init__(parent)
        self.row = row


class ValueDelegate(QStyledItemDelegate):
    """A QLineEdit for the Value column that checks as you type; Enter keeps only a good value."""

    feedback = Signal(str, bool)  # message, is an error

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.closeEditor.connect(self._closed)

    def _closed(self, editor: QWidget, hint: QAbstractItemDelegate.EndEditHint) -> None:
        reverted = hint == QAbstractItemDelegate.EndEditHint.RevertModelCache
        if reverted and isinstance(editor, _ValueEditor):
            message = self.tr("%1: edit cancelled, value unchanged")
            self.feedback.emit(fill(message, editor.row.name), False)

    def createEditor(
        self,
        parent: QWidget,
        option: QStyleOptionViewItem,
        index: QModelIndex | QPersistentModelIndex,
    ) -> QWidget:
        row: ParameterRow = index.data(ROW_ROLE)
        editor = _ValueEditor(row, parent)
        editor.setObjectName("parameterValueEditor")
        output = "\n" + translated(OUTPUT_TIP) if row.output else ""
        warning = "\n" + row.warning if row.warning else ""
        editor.setToolTip(f"{row.name}: {allowed(row)}" + output + warning)
        editor.textEdited.connect(lambda _text: self._check(editor, row))
        if row.output:
            why = row.warning or translated(OUTPUT_TIP)
            self.feedback.emit(fill(self.tr("%1 is an output. %2"), row.name, why), False)
        elif row.warning:
            self.feedback.emit(fill(self.tr("%1: %2"), row.name, row.warning), False)
        return editor

    def setEditorData(self, editor: QWidget, index: QModelIndex | QPersistentModelIndex) -> None:
        assert isinstance(editor, QLineEdit)
        with QSignalBlocker(editor):
            editor.setText(index.data(Qt.ItemDataRole.EditRole))
        editor.selectAll()

    def setModelData(
        self,
        editor: QWidget,
        model: QAbstractItemModel,
        index: QModelIndex | QPersistentModelIndex,
    ) -> None:
        assert isinstance(editor, QLineEdit)
        row: ParameterRow = index.data(ROW_ROLE)
        if editor.text() == index.data(Qt.ItemDataRole.EditRole):
            return  # untouched: nothing to check or store
        number, _why = check_value(row, editor.text(), editor.locale())  # 38,2 in Spanish
        typed = editor.text() if number is None else number  # refused: the model says why
        if model.setData(index, typed, Qt.ItemDataRole.EditRole):
            shown = with_unit(index.data(Qt.ItemDataRole.EditRole), row.unit)
            message = fill(self.tr("%1 = %2, not yet written to the device"), row.name, shown)
            if row.warning:  # said before it is sent: a warning, not a refusal
                message = fill(self.tr("%1. Warning: %2"), message, row.warning)
            self.feedback.emit(message, False)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Enter on a refused value keeps the editor open (and says why) instead of closing."""
        if (
            isinstance(watched, _ValueEditor)
            and event.type() == QEvent.Type.KeyPress
            and isinstance(event, QKeyEvent)
            and event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter)
            and not self._check(watched, watched.row)
        ):
            return True
        return super().eventFilter(watched, event)

    def _check(self, editor: QLineEdit, row: ParameterRow) -> bool:
        """Colour the editor and say what is wrong (or what Enter will keep)."""
        value, why = check_value(row, editor.text(), editor.locale())
        style = "" if value is not None else REFUSED_STYLE
        if editor.styleSheet() != style:
            editor.setStyleSheet(style)
        if value is None:
            self.feedback.emit(why, True)
        else:
            shown = with_unit(format_value(row, value), row.unit)
            message = self.tr("%1: %2 (Enter keeps it, Escape cancels)")
            self.feedback.emit(fill(message, row.name, shown), False)
        return value is not None


class ParameterTableView(QTableView):
    """Enter or F2 on any cell of a row edits its value; typing a digit starts an edit."""

    def __init__(self, model: ParameterModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("parameterTable")
        self.setModel(model)
        self.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.setSelectionMode(QAbstractItemView.SelectionMode.ExtendedSelection)
        triggers = QAbstractItemView.EditTrigger
        self.setEditTriggers(
            triggers.DoubleClicked
            | triggers.EditKeyPressed
            | triggers.AnyKeyPressed
            | triggers.SelectedClicked
        )
        self.setTabKeyNavigation(False)  # Tab leaves the table for the buttons
        self.setHorizontalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
        self.setWordWrap(False)
        self.verticalHeader().hide()
        self.verticalHeader().setDefaultSectionSize(self.fontMetrics().height() + 8)
        header = self.horizontalHeader()
        header.setMinimumSectionSize(36)
        for column, width in enumerate(COLUMN_WIDTHS):
            header.resizeSection(column, width)
        # No Stretch section (it pinned the others: a border dragged did nothing once it was
        # at its minimum): Name and Last written fit their text ("600 s (computed)"), the
        # Description takes the width left, at least DESC_LEAST, scrolling sideways below that.
        fitted = (NAME_COL, WRITTEN_COL)
        self.columns = FittedColumns(self, fitted, {DESC_COL: 1.0}, DESC_LEAST)
        self.setToolTip(
            self.tr("Double-click a value, or select a row and press Enter or type, to edit")
        )

    def keyPressEvent(self, event: QKeyEvent) -> None:
        current = self.currentIndex()
        if current.isValid() and self.state() != QAbstractItemView.State.EditingState:
            target = current.siblingAtColumn(VALUE_COL)
            keys = (Qt.Key.Key_Return, Qt.Key.Key_Enter, Qt.Key.Key_F2)
            if event.key() in keys and not event.modifiers() & ~Qt.KeyboardModifier.KeypadModifier:
                self.selectionModel().setCurrentIndex(target, _NO_UPDATE)
                self.edit(target)
                event.accept()
                return
            if event.text() and event.text()[0] in "0123456789-+.":
                self.selectionModel().setCurrentIndex(target, _NO_UPDATE)
        super().keyPressEvent(event)


class DerivedValues(QGroupBox):
    """(label, text) pairs computed from the values, one to a line; or why they cannot be."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setTitle(self.tr("Derived values"))
        self.setObjectName("derivedValues")
        self.setToolTip(self.tr("Computed from the values in the table, not read from the device"))
        self.grid = QGridLayout(self)
        self.grid.setContentsMargins(6, 2, 6, 2)
        self.grid.setHorizontalSpacing(12)
        self.grid.setColumnStretch(1, 1)  # the text takes the width, and wraps in a narrow dock
        self.pairs: list[tuple[str, str]] = []
        self.error = ""

    def show_derivation(self, fn: Derivation, values: dict[str, float]) -> None:
        """Show fn(values); a ValueError, ArithmeticError or LookupError shows why instead."""
        while self.grid.count():
            item = self.grid.takeAt(0)
            if widget := item.widget():
                widget.hide()  # gone at once; deleted when the event loop next runs
                widget.deleteLater()
        self.pairs, self.error = [], ""
        try:
            self.pairs = list(fn(values))
        except KeyError as exc:  # a value the derivation needs is not in the table yet
            what = exc.args[0] if exc.args else self.tr("a parameter")
            self._show_error(fill(self.tr("needs a value for %1"), what))
            return
        except (ValueError, ArithmeticError, LookupError) as exc:
            self._show_error(str(exc) or type(exc).__name__)
            return
        for position, (name, text) in enumerate(self.pairs):
            value = QLabel(text)
            value.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
            value.setWordWrap(True)
            self.grid.addWidget(QLabel(f"{name}:"), position, 0, Qt.AlignmentFlag.AlignTop)
            self.grid.addWidget(value, position, 1)

    def _show_error(self, error: str) -> None:
        self.error = error
        label = QLabel(error)
        label.setObjectName("derivedError")
        label.setStyleSheet(ERROR_STYLE)
        label.setWordWrap(True)
        self.grid.addWidget(label, 0, 0, 1, 2)
