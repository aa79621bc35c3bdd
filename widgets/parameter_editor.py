"""The service technician's parameter editor: numbered device parameters, checked and written.

Protocol-independent: it takes `ParameterRow`s and values by name, and asks for writes with
`write_requested([(id, value), …])`. The device cannot be read back, so the editor shows what was
last written beside each value (or the power-on value, never written) and marks the rows that
differ. "Write changed" sends only the inputs that differ: firmware outputs are written only when
asked by row or with "Write all", with the driver's warning shown before they are sent.
"""

from __future__ import annotations

from itertools import pairwise
from pathlib import Path

from PySide6.QtCore import QT_TRANSLATE_NOOP, QEvent, QObject, Qt, Signal
from PySide6.QtWidgets import (
    QFileDialog,
    QFrame,
    QHBoxLayout,
    QLabel,
    QProgressBar,
    QScrollArea,
    QSplitter,
    QVBoxLayout,
    QWidget,
)

from widgets._buttons import make_button
from widgets._i18n import fill
from widgets.parameter_table import (
    ERROR_STYLE,
    Derivation,
    DerivedValues,
    ParameterModel,
    ParameterTableView,
    ValueDelegate,
)
from widgets.parameter_values import (
    CANCELLED,
    CONFIRMED,
    PENDING,
    STATUS_COLOURS,
    ParameterRow,
    translated,
)

__all__ = ["PROFILE_FILTER", "STATUSES", "Derivation", "ParameterEditor", "ParameterRow"]

PROFILE_FILTER = QT_TRANSLATE_NOOP(
    "ParameterEditor", "Parameter profiles (*.toml);;All files (*)"
)  # translated at use
STATUSES = tuple(STATUS_COLOURS)  # not written, pending, confirmed, error, timed out, cancelled
DERIVED_SHARE = 0.3  # of the table's and derived values' height, at most, until the user drags


def _seconds(seconds: float) -> str:
    return f"{seconds:.1f} s" if seconds < 10 else f"{seconds:.0f} s"


class ParameterEditor(QWidget):
    """A table of device parameters: edit, check, write, and follow each write's outcome."""

    write_requested = Signal(list)  # [(id, value), …] in table order
    cancel_requested = Signal()
    load_requested = Signal(str)  # path of a profile to load
    save_requested = Signal(str)  # path to save the values to

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("parameterEditorPanel")
        self._connected = False
        self._writing = False
        self._cancelling = False
        self._write_ids: list[int] = []
        self._in_flight: dict[int, float] = {}
        self._requested: dict[int, float] = {}
        self._seconds_per_packet = 0.0
        self._derivation: Derivation | None = None
        self._last_dir = ""
        self._message_error: bool | None = None

        self.model = ParameterModel(self)
        self.table = ParameterTableView(self.model)
        self.delegate = ValueDelegate(self.table)
        self.table.setItemDelegate(self.delegate)

        self.changed_label = QLabel()
        self.changed_label.setObjectName("changedSummary")
        self.changed_label.setToolTip(
            self.tr("The device cannot be read back: this compares with what this panel last wrote")
        )
        self.message_label = QLabel()
        self.message_label.setObjectName("parameterMessage")
        self.message_label.setWordWrap(True)
        self.message_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.derived_box = DerivedValues()
        self.derived_box.hide()
        # The derived values under the table, their own height at most a share of the room
        # (they scroll); the operator may drag the split, or fold them away.
        self.derived_area = QScrollArea()
        self.derived_area.setObjectName("derivedValuesArea")
        self.derived_area.setWidget(self.derived_box)
        self.derived_area.setWidgetResizable(True)
        self.derived_area.setFrameShape(QFrame.Shape.NoFrame)
        self.derived_area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.derived_area.hide()
        self.splitter = QSplitter(Qt.Orientation.Vertical)
        self.splitter.setObjectName("parameterSplitter")
        self.splitter.addWidget(self.table)
        self.splitter.addWidget(self.derived_area)
        self.splitter.setStretchFactor(0, 1)  # a taller window gives the table the room
        self.splitter.setStretchFactor(1, 0)
        self.splitter.setCollapsible(0, False)
        self.splitter.setCollapsible(1, True)
        self._split_by_user = False
        self.splitter.splitterMoved.connect(self._split_moved)
        self.splitter.installEventFilter(self)
        self.progress = QProgressBar()
        self.progress.setObjectName("writeProgress")
        self.progress.setToolTip(
            self.tr("Packets written so far; each is confirmed before the next")
        )
        self.progress.hide()

        button = make_button
        self.write_selected_button = button(
            self.tr("Write selected"),
            "writeSelectedButton",
            self.tr("Write the values of the selected rows"),
        )
        self.write_all_button = button(
            self.tr("Write all"),
            "writeAllButton",
            self.tr("Write every value in the table, one packet each"),
        )
        self.write_changed_button = button(
            self.tr("Write changed"),
            "writeChangedButton",
            self.tr(
                "Write the input values marked • (they differ from what the device holds); "
                "firmware outputs are not written by it"
            ),
        )
        self.cancel_button = button(
            self.tr("Cancel"),
            "cancelWriteButton",
            self.tr("Stop writing after the packet under way"),
        )
        self.load_button = button(
            self.tr("Load profile…"), "loadProfileButton", self.tr("Fill the table from a file")
        )
        self.save_button = button(
            self.tr("Save profile…"), "saveProfileButton", self.tr("Save the values to a file")
        )
        self.write_selected_button.clicked.connect(self._write_selected)
        self.write_all_button.clicked.connect(self._write_all)
        self.write_changed_button.clicked.connect(self._write_changed)
        self.cancel_button.clicked.connect(self._cancel)
        self.load_button.clicked.connect(lambda: self._ask_path(save=False))
        self.save_button.clicked.connect(lambda: self._ask_path(save=True))
        order = [self.load_button, self.save_button, self.table, self.write_selected_button]
        order += [self.write_all_button, self.write_changed_button, self.cancel_button]

        # Profiles at the top, writing at the bottom: two short rows fit a 1024-pixel window.
        top = QHBoxLayout()
        top.addWidget(self.changed_label, 1)
        top.addWidget(self.load_button)
        top.addWidget(self.save_button)
        buttons = QHBoxLayout()
        for widget in order[3:]:
            buttons.addWidget(widget)
        buttons.addStretch(1)
        self.changed_label.setWordWrap(True)
        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(self.splitter, 1)
        layout.addWidget(self.message_label)
        layout.addWidget(self.progress)
        layout.addLayout(buttons)
        for first, second in pairwise(order):
            QWidget.setTabOrder(first, second)

        self.model.refused.connect(lambda why: self.show_message(why, error=True))
        self.model.values_changed.connect(self._values_changed)
        self.model.written_changed.connect(self._sync)
        self.delegate.feedback.connect(self.show_message)
        self.table.selectionModel().selectionChanged.connect(self._sync)
        self._sync()

    # -- table contents -----------------------------------------------------------------

    def set_parameters(self, rows: list[ParameterRow]) -> None:
        """Build the table; values, last written values, statuses and notes start empty."""
        self._writing = self._cancelling = False
        self._write_ids, self._in_flight, self._requested = [], {}, {}
        self.progress.hide()
        self.model.set_rows(list(rows))

    def parameters(self) -> list[ParameterRow]:
        return [state.row for state in self.model.states()]

    def set_values(self, values: dict[str, float]) -> list[str]:
        """Fill values by name (a profile, the defaults); refused ones are listed and shown."""
        problems = self.model.set_values(values)
        if problems:
            self.show_message(fill(self.tr("Not loaded: %1"), "; ".join(problems)), error=True)
        return problems

    def values(self) -> dict[str, float]:
        """The editor's values by name (rows without a value are left out)."""
        states = self.model.states()
        return {s.row.name: s.value for s in states if s.value is not None}

    def value(self, name: str) -> float | None:
        return self.values().get(name)

    def set_last_written(self, values: dict[str, float]) -> None:
        """What this device was last sent, by name; names left out count as never written."""
        self.model.set_written(values)

    def set_computed(self, values: dict[str, float], when: str) -> None:
        """What the firmware recomputed itself, by name (`when`: parameter_values.AFTER_SET or
        AT_MOVE): shown as the device's, marked computed; unedited values follow."""
        self.model.set_computed(values, when)

    def computed(self) -> dict[str, str]:
        """The rows whose device value the firmware computed, by name: when."""
        return {s.row.name: s.computed for s in self.model.states() if s.computed}

    def last_written(self) -> dict[str, float]:
        states = self.model.states()
        return {s.row.name: s.written for s in states if s.written is not None}

    def changed_names(self) -> list[str]:
        """Names whose value differs from what was last written (or was never written)."""
        return [s.row.name for s in self.model.states() if s.changed()]

    def set_row_note(self, name: str, text: str) -> None:
        """A note shown in the row's Status cell and tooltip ("" removes it)."""
        self.model.set_note(self.model.index_of(name=name), text)

    def show_message(self, text: str, error: bool = False) -> None:
        """The message under the table (load/save results, refused values)."""
        self.message_label.setText(text)
        self.message_label.setToolTip(text)
        if error != self._message_error:  # style sheets are costly: restyle on a change only
            self._message_error = error
            self.message_label.setStyleSheet(ERROR_STYLE if error else "")

    def message(self) -> str:
        return self.message_label.text()

    # -- derived values -----------------------------------------------------------------

    def set_derivation(self, fn: Derivation | None) -> None:
        """fn(values()) → [(label, text), …], shown under the table and redone on every change.

        A ValueError (also ArithmeticError, or KeyError for a value not there yet) shows its
        message in place of the values.
        """
        self._derivation = fn
        self.derived_box.setVisible(fn is not None)
        self.derived_area.setVisible(fn is not None)
        self._derive()
        self._fit_split()

    def derived_values(self) -> list[tuple[str, str]]:
        """The (label, text) pairs shown under the table."""
        return list(self.derived_box.pairs) if self._derivation else []

    def derived_error(self) -> str:
        """The derivation's ValueError message shown instead ("" if none)."""
        return self.derived_box.error if self._derivation else ""

    def _derive(self) -> None:
        if self._derivation is not None:
            self.derived_box.show_derivation(self._derivation, self.values())

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """The split follows the editor's height until the operator drags it."""
        if watched is self.splitter and event.type() == QEvent.Type.Resize:
            self._fit_split()
        return False

    def _split_moved(self) -> None:
        self._split_by_user = True

    def _fit_split(self) -> None:
        """The derived values their own height, at most DERIVED_SHARE; the table the rest."""
        if self._split_by_user or self.derived_area.isHidden():
            return
        total = self.splitter.height() - self.splitter.handleWidth()
        if total <= 0:
            return
        wanted = self.derived_box.sizeHint().height() + 2 * self.derived_area.frameWidth()
        derived = min(wanted, int(total * DERIVED_SHARE))
        self.splitter.setSizes([total - derived, derived])

    # -- writing ------------------------------------------------------------------------

    def set_connected(self, connected: bool) -> None:
        """Enable the write buttons (the table stays editable either way)."""
        self._connected = connected
        self._sync()

    def writing(self) -> bool:
        return self._writing

    def begin_write(self, ids: list[int], seconds_per_packet: float) -> None:
        """These rows are being written, one packet each: mark them pending, show progress."""
        ids = list(dict.fromkeys(ids))
        positions = [self.model.index_of(id=id_) for id_ in ids]
        states = self.model.states()
        self._in_flight = {}
        for id_, position in zip(ids, positions, strict=True):
            value = self._requested.get(id_, states[position].value)
            if value is not None:
                self._in_flight[id_] = value
            self.model.set_status(position, PENDING)
        self._write_ids, self._seconds_per_packet = ids, max(float(seconds_per_packet), 0.0)
        self._writing, self._cancelling = True, False
        self.progress.setRange(0, max(len(ids), 1))
        self.progress.show()
        self._update_progress()
        self._sync()

    def set_status(self, id: int, status: str, message: str = "") -> None:
        """One row's write status; "confirmed" makes the value written its Last written."""
        position = self.model.index_of(id=id)
        self.model.set_status(position, status, message)
        state = self.model.states()[position]
        written = self._in_flight.get(id, state.value)  # outside a write: the value shown
        if status == CONFIRMED and written is not None:
            self.model.set_written({state.row.name: written}, replace=False)
        if self._writing and id in self._write_ids:
            self._update_progress()

    def status(self, id: int) -> str:
        return self.model.states()[self.model.index_of(id=id)].status

    def end_write(self) -> None:
        """The write is over: rows still pending become cancelled; a summary is shown."""
        if not self._writing:
            return
        states = self.model.states()
        counts = dict.fromkeys(STATUSES, 0)
        for id_ in self._write_ids:
            position = self.model.index_of(id=id_)
            if states[position].status == PENDING:
                self.model.set_status(position, CANCELLED)
            counts[states[position].status] += 1
        self._writing = self._cancelling = False
        self._in_flight = {}
        self.progress.hide()
        parts = [f"{count} {translated(status)}" for status, count in counts.items() if count]
        failed = any(count for status, count in counts.items() if status != CONFIRMED)
        summary = ", ".join(parts or [self.tr("nothing sent")])
        self.show_message(fill(self.tr("Write finished: %1"), summary), error=failed)
        self._sync()

    def progress_text(self) -> str:
        return self.progress.format()

    def _update_progress(self) -> None:
        states = self.model.states()
        total = len(self._write_ids)
        done = sum(states[self.model.index_of(id=i)].status != PENDING for i in self._write_ids)
        left = (total - done) * self._seconds_per_packet
        self.progress.setValue(done)
        text = self.tr("%1 / %2 packets, about %3 left")
        self.progress.setFormat(fill(text, done, total, _seconds(left)))

    def _write_selected(self) -> None:
        rows = {index.row() for index in self.table.selectionModel().selectedIndexes()}
        self._request(sorted(rows), self.tr("no row selected"))

    def _write_all(self) -> None:
        self._request(range(self.model.rowCount()), self.tr("the table has no values"))

    def changed_inputs(self) -> list[str]:
        """Names "Write changed" would send: inputs whose value the device does not hold."""
        return [s.row.name for s in self.model.states() if s.changed() and not s.row.output]

    def _write_changed(self) -> None:
        states = self.model.states()
        positions = [p for p, s in enumerate(states) if s.changed() and not s.row.output]
        self._request(positions, self.tr("no input differs"))

    def _request(self, positions: range | list[int], empty: str) -> None:
        states = [self.model.states()[position] for position in positions]
        pairs = [(s.row.id, s.value) for s in states if s.value is not None]
        if not pairs:
            self.show_message(fill(self.tr("Nothing to write: %1"), empty))
            return
        if len(pairs) == 1:
            notes = [self.tr("Writing 1 value")]
        else:
            notes = [fill(self.tr("Writing %1 values"), len(pairs))]
        if skipped := [s.row.name for s in states if s.value is None]:
            notes.append(fill(self.tr("no value, not written: %1"), ", ".join(skipped)))
        written = [s for s in states if s.value is not None]
        if outputs := [s.row.name for s in written if s.row.output and not s.row.warning]:
            why = self.tr("computed by the firmware, which may replace them: %1")
            notes.append(fill(why, ", ".join(outputs)))
        if warnings := [s.row.warning for s in written if s.row.warning]:  # warned, not refused
            notes.append(fill(self.tr("Warning: %1"), "; ".join(warnings)))
        self.show_message("; ".join(notes))
        self._requested = dict(pairs)
        self.write_requested.emit(pairs)

    def _cancel(self) -> None:
        self._cancelling = True
        self._sync()
        self.show_message(
            self.tr("Cancelling: the packet under way finishes, the rest are not sent")
        )
        self.cancel_requested.emit()

    # -- profiles -----------------------------------------------------------------------

    def _choose_path(self, save: bool) -> str:
        """Ask for a profile file ("" if the user gives up); tests replace this."""
        if save:
            path, _ = QFileDialog.getSaveFileName(
                self, self.tr("Save parameter profile"), self._last_dir, self.tr(PROFILE_FILTER)
            )
        else:
            path, _ = QFileDialog.getOpenFileName(
                self, self.tr("Load parameter profile"), self._last_dir, self.tr(PROFILE_FILTER)
            )
        return path

    def _ask_path(self, save: bool) -> None:
        path = self._choose_path(save)
        if not path:
            return
        if save and not Path(path).suffix:
            path += ".toml"
        self._last_dir = str(Path(path).parent)
        (self.save_requested if save else self.load_requested).emit(path)

    # -- keeping the display in step ----------------------------------------------------

    def _values_changed(self) -> None:
        self._derive()
        self._sync()

    def _sync(self) -> None:
        """The changed-rows summary and which buttons can be used."""
        changed = len(self.changed_names())
        has_values = bool(self.values())
        if not self.model.rowCount():
            summary = self.tr("No parameters")
        elif not has_values:
            summary = self.tr("No values yet: load a profile or type them into the Value column")
        elif changed == 1:
            summary = self.tr(
                "1 value differs from what was last written to this device (marked •)"
            )
        elif changed:
            summary = fill(
                self.tr("%1 values differ from what was last written to this device (marked •)"),
                changed,
            )
        else:
            summary = self.tr("Every value is what was last written to this device")
        self.changed_label.setText(summary)
        can_write = self._connected and not self._writing
        selected = self.table.selectionModel().hasSelection()
        self.write_selected_button.setEnabled(can_write and has_values and selected)
        self.write_all_button.setEnabled(can_write and has_values)
        self.write_changed_button.setEnabled(can_write and bool(self.changed_inputs()))
        self.cancel_button.setEnabled(self._writing and not self._cancelling)
