"""The traffic console: every frame decoded, filtered and searched, and a send line.

Lines live in a TrafficIndex (on disk, a few bytes each in memory), shown by a table that reads
only the rows on screen, so a million lines stay light. New traffic is decoded in turns of at
most 2 ms and shown at most 10 times a second, in a turn of its own. With a line limit the
console is a scrollback buffer: it keeps the newest lines, dropping the oldest a block at a time
(see set_max_lines); the session log on disk keeps every line.
"""

from __future__ import annotations

import csv
import logging
import time
from collections import deque
from collections.abc import Callable
from pathlib import Path

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QModelIndex, Qt, QTimer, Signal
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
    QComboBox,
    QFileDialog,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QMenu,
    QPushButton,
    QSizePolicy,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from app.common.messages import localized
from app.window.traffic_table import (
    BYTES,
    COLUMNS,
    CSV_COLUMNS,
    DISPLAY_MODES,
    HEX,
    KIND_NAMES,
    LINE,
    MEANING,
    REPLY,
    TEXT,
    TIME,
    TIME_MODES,
    TrafficModel,
    TrafficView,
    stamp,
)
from drivers.protocols.base import Protocol
from drivers.traffic_index import KINDS, FilterError, TrafficIndex, compile_filter
from widgets._i18n import fill
from widgets._pacer import run_paced
from widgets.send_line import SendLine

log = logging.getLogger(__name__)

TX, RX, NOTE = "tx", "rx", "note"
FLUSH_INTERVAL_MS = 100  # 10 Hz: a flood costs a repaint of the table per flush
TYPING_PAUSE_MS = 250  # a filter or search is applied this long after the last key
FLUSH_BUDGET = 0.002  # s of decoding per turn of the event loop; the rest waits its turn
RECENT_RECORDS = 20_000  # raw records kept for `records()`; the index keeps every line
HIDDEN_BY_DEFAULT = ("poll",)
STATUS_INTERVAL_S = 0.25  # the status line's counts follow a flood at most 4 times a second
TRIM_MARGIN = 0.1  # past its line limit by this fraction, the console drops its oldest lines

# the names shown for the keys (marked here, translated at use); the keys stay as they are
MODE_NAMES = {
    "text": QT_TRANSLATE_NOOP("RawConsole", "text"),
    "hex": QT_TRANSLATE_NOOP("RawConsole", "hex"),
    "mixed": QT_TRANSLATE_NOOP("RawConsole", "mixed"),
    "relative": QT_TRANSLATE_NOOP("RawConsole", "relative"),
    "absolute": QT_TRANSLATE_NOOP("RawConsole", "absolute"),
    "delta": QT_TRANSLATE_NOOP("RawConsole", "delta"),
}

Record = tuple[str, bytes, float]  # (direction or "note", data, timestamp in seconds)
Incoming = tuple[float, str, bytes, float | None]  # (timestamp, direction or "", data, wall)


def _when(item: Incoming) -> float:
    return item[0]


def ask_save_path(parent: QWidget) -> str:
    """Ask where to export the view (.txt or .csv); "" when cancelled."""
    csv_filter = QCoreApplication.translate("RawConsole", "CSV (*.csv)")
    filters = ";;".join(
        (
            QCoreApplication.translate("RawConsole", "Text (*.txt)"),
            csv_filter,
            QCoreApplication.translate("RawConsole", "All files (*)"),
        )
    )
    path, chosen = QFileDialog.getSaveFileName(
        parent, QCoreApplication.translate("RawConsole", "Export traffic"), "traffic.txt", filters
    )
    if path and chosen == csv_filter and not path.lower().endswith(".csv"):
        path += ".csv"
    return path


def localized_index(protocol: Protocol | None = None) -> TrafficIndex:
    """A traffic index whose frames' meanings read in the interface's language."""
    index = TrafficIndex(protocol)
    index.meaning_text = localized
    return index


class RawConsole(QWidget):
    """Decoded traffic with filters, search and export, and a send line emitting bytes."""

    send_requested = Signal(object)  # bytes
    lines_added = Signal(int, int)  # first new line, how many
    line_activated = Signal(int)  # a line the user chose (double-click)
    reset = Signal()  # cleared, or another session's lines loaded

    def __init__(self, parent: QWidget | None = None, sending: bool = True) -> None:
        super().__init__(parent)
        self.setObjectName("rawConsole")
        self.ask_export_path: Callable[[], str] = lambda: ask_save_path(self)
        self.clock: Callable[[], float] = time.monotonic  # the traffic's clock, for notes
        # (time, direction or "" for a note, data, wall clock or None): arrived and not yet
        # looked at; taken and waiting for their turn (in time order); the latest taken
        self._incoming: list[Incoming] = []
        self._pending: list[Incoming] = []
        self._recent: deque[Incoming] = deque(maxlen=RECENT_RECORDS)
        self._shown_at = 0.0  # perf_counter of the last update of the table
        self._show_due = False  # the table's update waits for the next turn (see _timed_flush)
        self._status_at = 0.0  # and of the status line
        self.index = localized_index()
        self.max_lines = 0  # 0: keep every line (see set_max_lines)
        self._trim_noted = False  # the note saying lines are being dropped was added
        self._model = TrafficModel(self.index, self)  # goes with the console, never before it
        self._origin_set = False
        self._shown_until = 0  # lines up to here have been through the filter
        self._follow = True
        self._scrolling = False
        self._pattern = None
        self._search = None
        self._pattern_text = self._search_text = ""
        self._kinds = {k for k in KINDS if k not in HIDDEN_BY_DEFAULT}
        self._directions = {"tx", "rx", ""}
        self._flush_timer = QTimer(self)
        self._flush_timer.setObjectName("consoleFlushTimer")
        self._flush_timer.setSingleShot(True)
        self._flush_timer.setInterval(FLUSH_INTERVAL_MS)
        self._flush_timer.timeout.connect(self._timed_flush)
        self._status_timer = QTimer(self)
        self._status_timer.setObjectName("consoleStatusTimer")
        self._status_timer.setSingleShot(True)
        self._status_timer.setInterval(int(STATUS_INTERVAL_S * 1000))
        self._status_timer.timeout.connect(self._update_status)
        self._build(sending)

    # -- building --------------------------------------------------------------------------

    def _combo(self, name: str, items: tuple[str, ...], tip: str, slot: Callable) -> QComboBox:
        combo = QComboBox()
        combo.setObjectName(name)
        for key in items:  # the key as item data: the shown name may be translated
            name = MODE_NAMES.get(key, key)
            combo.addItem(QCoreApplication.translate("RawConsole", name), key)
        combo.setToolTip(tip)
        combo.currentIndexChanged.connect(lambda index: slot(combo.itemData(index)))
        return combo

    def _check(self, text: str, name: str, tip: str, checked: bool = True) -> QCheckBox:
        box = QCheckBox(text)
        box.setObjectName(name)
        box.setChecked(checked)
        box.setToolTip(tip)
        box.toggled.connect(self._filters_changed)
        return box

    def _button(self, text: str, name: str, tip: str, slot: Callable) -> QPushButton:
        button = QPushButton(text)
        button.setObjectName(name)
        button.setToolTip(tip)
        button.clicked.connect(slot)
        return button

    def _build(self, sending: bool) -> None:
        self._typing = QTimer(self)  # a million lines are not filtered again at every key
        self._typing.setObjectName("consoleTypingTimer")
        self._typing.setSingleShot(True)
        self._typing.setInterval(TYPING_PAUSE_MS)
        self._typing.timeout.connect(self._typed)
        self.mode_combo = self._combo(
            "consoleDisplayMode",
            DISPLAY_MODES,
            self.tr(
                "Bytes as text (\\r \\n \\xNN escapes), hex (47 45 54), or mixed (text, <0A> for "
                "the rest)"
            ),
            self.set_display_mode,
        )
        self.time_combo = self._combo(
            "consoleTimeMode",
            TIME_MODES,
            self.tr(
                "Times: seconds since the session start, wall-clock time, or the gap since the"
                " line above"
            ),
            self.set_time_mode,
        )
        self.timestamps_check = QCheckBox(self.tr("Time"))
        self.timestamps_check.setObjectName("consoleTimestamps")
        self.timestamps_check.setChecked(True)
        self.timestamps_check.setToolTip(self.tr("Show the time column"))
        self.timestamps_check.toggled.connect(self.set_timestamps)
        self.tx_check = self._check(
            self.tr("TX"), "consoleShowTx", self.tr("Show what was sent to the device")
        )
        self.rx_check = self._check(
            self.tr("RX"), "consoleShowRx", self.tr("Show what the device sent")
        )
        self.kind_button = QToolButton()
        self.kind_button.setObjectName("consoleKinds")
        self.kind_button.setText(self.tr("Kinds"))
        self.kind_button.setToolTip(self.tr("Which kinds of lines to show"))
        self.kind_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        menu = QMenu(self.kind_button)
        self.kind_actions = {}
        for kind in KINDS:
            name = KIND_NAMES.get(kind, kind)
            action = menu.addAction(self.tr(name))
            action.setCheckable(True)
            action.setChecked(kind in self._kinds)
            action.setObjectName(f"consoleKind_{kind}")
            action.toggled.connect(self._kinds_changed)
            self.kind_actions[kind] = action
        self.kind_button.setMenu(menu)
        self.poll_check = QCheckBox(self.tr("Poll"))
        self.poll_check.setObjectName("consoleShowPoll")
        self.poll_check.setToolTip(
            self.tr(
                "Show the idle position queries and their replies"
                " (hidden by default; counted below)"
            )
        )
        self.poll_check.toggled.connect(self.kind_actions["poll"].setChecked)
        self.filter_edit = QLineEdit()
        self.filter_edit.setObjectName("consoleFilter")
        self.filter_edit.setPlaceholderText(self.tr("filter (regex)"))
        self.filter_edit.setClearButtonEnabled(True)
        self.filter_edit.setMinimumWidth(80)
        self.filter_edit.setToolTip(
            self.tr(
                "Show only lines matching this regular expression (case-insensitive) in their "
                "direction, kind, hex, text or meaning, e.g. error|FA00"
            )
        )
        self.filter_edit.textChanged.connect(self._typing.start)  # applied when typing pauses
        self.paused_label = QLabel(self.tr("paused"))
        self.paused_label.setObjectName("consolePaused")
        self.paused_label.setToolTip(
            self.tr("New lines do not scroll the view: scroll to the bottom to follow")
        )
        self.paused_label.setStyleSheet("color: #8a4b00;")
        self.paused_label.setVisible(False)
        top = QHBoxLayout()
        for widget in (
            self.mode_combo,
            self.time_combo,
            self.timestamps_check,
            self.tx_check,
            self.rx_check,
            self.kind_button,
            self.poll_check,
        ):
            top.addWidget(widget)

        self.search_edit = QLineEdit()
        self.search_edit.setObjectName("consoleSearch")
        self.search_edit.setPlaceholderText(self.tr("search (regex)"))
        self.search_edit.setClearButtonEnabled(True)
        self.search_edit.setMinimumWidth(80)
        self.search_edit.setToolTip(
            self.tr("Highlight matching lines; Enter or F3: next, Shift+F3: previous")
        )
        self.search_edit.textChanged.connect(self._typing.start)
        self.search_edit.returnPressed.connect(self.find_next)
        previous = self._button(
            "◀", "consoleSearchPrevious", self.tr("Previous match (Shift+F3)"), self.find_previous
        )
        following = self._button(
            "▶", "consoleSearchNext", self.tr("Next match (F3)"), self.find_next
        )
        for button in (previous, following):
            button.setMaximumWidth(32)
        QShortcut(
            QKeySequence("F3"),
            self,
            self.find_next,
            context=Qt.ShortcutContext.WidgetWithChildrenShortcut,
        )
        QShortcut(
            QKeySequence("Shift+F3"),
            self,
            self.find_previous,
            context=Qt.ShortcutContext.WidgetWithChildrenShortcut,
        )
        self.status_label = QLabel()
        self.status_label.setObjectName("consoleStatus")
        self.status_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.status_label.setMinimumWidth(0)
        self.status_label.setToolTip(
            self.tr("Lines in the session, shown, hidden polls, errors, matches")
        )
        export_button = self._button(
            self.tr("Export…"),
            "consoleExport",
            self.tr("Save the lines shown (filtered) as text or CSV"),
            self.export_interactively,
        )
        clear_button = self._button(
            self.tr("Clear"),
            "consoleClear",
            self.tr("Forget the lines (the session log keeps them)"),
            self.clear,
        )
        top.addWidget(self.status_label, 1)  # shrinks first: its tooltip has it all
        top.addWidget(self.paused_label)
        second = QHBoxLayout()
        second.addWidget(self.filter_edit, 1)
        second.addWidget(self.search_edit, 1)
        second.addWidget(previous)
        second.addWidget(following)
        second.addWidget(export_button)
        second.addWidget(clear_button)

        self.view = TrafficView(self._model)
        self.view.setObjectName("consoleView")
        self.view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        header = self.view.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        width = self.view.fontMetrics().horizontalAdvance("0")
        for column, chars in ((LINE, 8), (TIME, 13), (2, 4), (BYTES, 34), (MEANING, 34)):
            header.resizeSection(column, width * chars + 12)
        header.setStretchLastSection(True)
        self.view.setToolTip(
            self.tr(
                "TX (blue): sent to the device; RX (green): received; grey: notes and the"
                " device's own text; red: errors. Double-click a line to go to its request,"
                " reply or first copy."
            )
        )
        self.view.doubleClicked.connect(self._double_clicked)
        self.view.verticalScrollBar().valueChanged.connect(self._scrolled)
        self.view.verticalScrollBar().rangeChanged.connect(self._range_changed)

        self.send_line = SendLine()
        self.send_line.send_requested.connect(self.send_requested)
        self.send_edit = self.send_line.edit
        self.send_mode_combo = self.send_line.mode_combo
        self.ending_combo = self.send_line.ending_combo
        self.send_button = self.send_line.button
        self.error_label = self.send_line.error_label
        self.send_line.setVisible(sending)

        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addLayout(second)
        layout.addWidget(self.view, 1)
        layout.addWidget(self.send_line)
        self._update_status()

    # -- traffic in ------------------------------------------------------------------------

    def set_protocol(self, protocol: Protocol | None) -> None:
        """Decode the traffic that comes next with `protocol`'s own decoders."""
        self.flush()
        self.index.set_protocol(protocol)

    def append_traffic(
        self, direction: str, data: bytes, timestamp: float, wall: float | None = None
    ) -> None:
        """Take bytes sent ("tx") or received ("rx") at `timestamp` (s); shown at the next flush."""
        if direction not in (TX, RX):
            raise ValueError(f"direction must be 'tx' or 'rx', not {direction!r}")
        if not self._incoming:  # the timer runs while anything is waiting (see _take_pending)
            self._schedule()
        self._incoming.append((timestamp, direction, bytes(data), wall))

    def append_note(self, text: str, timestamp: float | None = None) -> None:
        """Log an information line such as "connected" (timestamp: the clock's now by default)."""
        when = self.clock() if timestamp is None else timestamp
        if not self._incoming:
            self._schedule()
        self._incoming.append((when, "", text.encode("utf-8"), time.time() - (self.clock() - when)))

    def _take_pending(self, deadline: float | None = None) -> None:
        """Into the index, in time order (a note is stamped when added, traffic comes batched);
        with a `deadline` (perf_counter), what is left when it passes waits for the next turn."""
        if self._incoming:
            incoming, self._incoming = self._incoming, []
            self._recent.extend(incoming)
            self._pending.extend(incoming)
            self._pending.sort(key=_when)  # stable: ties keep their order
        if not self._pending:
            return
        pending, index = self._pending, self.index
        if not self._origin_set and not len(index):
            self._model.origin = pending[0][0]
        if index.wall_offset is None:  # (traffic fed without a wall-clock time: now's)
            when, _, _, wall = pending[0]
            index.wall_offset = (time.time() if wall is None else wall) - when
        taken = index.add_many(pending, deadline)
        self._pending = pending[taken:] if taken < len(pending) else []
        index.commit()

    def _schedule(self) -> None:
        if not self._flush_timer.isActive():
            self._flush_timer.start(FLUSH_INTERVAL_MS)

    def set_time_origin(self, timestamp: float) -> None:
        """Times are shown as seconds since `timestamp` (default: the first line)."""
        self._model.origin = timestamp
        self._origin_set = True
        self._model.refresh()

    def time_origin(self) -> float:
        """What relative times count from."""
        return self._model.origin

    def backlog(self) -> int:
        """Records received but not yet decoded and shown (a flood beyond the budget)."""
        return len(self._pending) + len(self._incoming)

    def records(self) -> list[Record]:
        """The latest raw records (bounded), as they came: (direction or "note", data, time)."""
        recent = [*self._recent, *self._incoming][-RECENT_RECORDS:]
        return [(direction or NOTE, data, when) for when, direction, data, _ in recent]

    def _timed_flush(self) -> None:
        """The timer's turn: at most FLUSH_BUDGET of decoding, or the table's update, so a flood
        never stalls the window. The table is updated at most every FLUSH_INTERVAL_MS (its
        repaint is dear), in a turn after the decoding's: the two together, and the window's
        repaint that follows, made one of the window's longest stalls. Each turn is paced: not
        in the same turn of the event loop as the views' heavy work."""
        if not run_paced(self._flush_timer):
            return
        if self._show_due:
            self._show_due = False
            self._show_new()
            # Painted now, in this turn: else the table is painted with the next repaint of
            # the window, which a plot's change makes at once, and the two add up.
            self.view.viewport().repaint()
        else:
            now = time.perf_counter()
            self._take_pending(now + FLUSH_BUDGET)
            if not self._pending or now - self._shown_at >= FLUSH_INTERVAL_MS / 1000:
                self._show_due = True
        if self._pending or self._show_due:
            self._flush_timer.start(0)  # the rest after the events waiting now
        elif self._incoming:  # arrived since the decoding turn: the next batch, in its time
            self._flush_timer.start(FLUSH_INTERVAL_MS)

    def _typed(self) -> None:
        """The filter or search text stopped changing: apply what changed."""
        self._typing.stop()
        if self.filter_edit.text() != self._pattern_text:
            self._filters_changed()
        if self.search_edit.text() != self._search_text:
            self._search_changed(self.search_edit.text())

    def flush(self) -> None:
        """Show every line added since the last flush (and a filter still being typed)."""
        if self._typing.isActive():
            self._typed()
        self._flush_timer.stop()
        self._take_pending(None)
        self._show_new()

    def set_max_lines(self, lines: int) -> None:
        """Keep the newest `lines` lines (0: every line), as a terminal's scrollback does: once
        past the limit by TRIM_MARGIN (a tenth), the oldest are dropped down to the limit, a
        block at a time. Lines keep their numbers; the session log on disk keeps every line."""
        self.max_lines = max(0, int(lines))
        self._trim()
        self._update_status()

    def _trim(self) -> None:
        """Past the line limit (and its margin): drop the oldest lines, down to the limit. A
        view following the tail keeps following; one scrolled up keeps its top line in place
        (or shows the oldest line kept, if its own was dropped)."""
        limit, index = self.max_lines, self.index
        if not limit or index.kept <= limit + int(limit * TRIM_MARGIN):
            return
        view, model = self.view, self._model
        top_row = view.rowAt(0)
        top_line = int(model.rows[top_row]) if 0 <= top_row < len(model.rows) else None
        self._scrolling = True  # (Qt's own scrolling as the rows go is not the user's)
        try:
            index.drop_oldest(index.kept - limit)
            model.drop_before(index.first)
            if self._follow:
                view.scrollToBottom()
            elif top_line is not None and len(model.rows):
                row = min(model.row_of(top_line), len(model.rows) - 1)
                view.scrollTo(model.index(row, BYTES), QAbstractItemView.ScrollHint.PositionAtTop)
        finally:
            self._scrolling = False
        if not self._trim_noted:
            self._trim_noted = True
            note = self.tr(
                "the console keeps the newest %1 lines: older lines are dropped from it as new"
                " ones come; the session log keeps every line"
            )
            self.append_note(fill(note, f"{limit:,}"))

    def _show_new(self) -> None:
        """Put the lines decoded since the last time in the table (through the filters)."""
        self._trim()
        self._show_due = False
        self._flush_timer.setInterval(FLUSH_INTERVAL_MS)
        self._shown_at = time.perf_counter()
        total = len(self.index)
        if total == self._shown_until:
            return
        first = min(max(self._shown_until, self.index.first), total)  # (some maybe dropped)
        rows = self.index.select(self._directions, self._kinds, self._pattern, start=first)
        if self._search is not None:
            self._model.add_matches(self.index.select(None, None, self._search, start=first))
        self._shown_until = total
        self._model.append_rows(rows)
        if self._shown_at - self._status_at >= STATUS_INTERVAL_S:
            self._update_status()
        elif not self._status_timer.isActive():
            self._status_timer.start()
        self.lines_added.emit(first, total - first)
        if self._follow:
            self._scroll_to_end()

    # -- filters and modes -----------------------------------------------------------------

    def _kinds_changed(self) -> None:
        self._kinds = {kind for kind, action in self.kind_actions.items() if action.isChecked()}
        self.poll_check.blockSignals(True)
        self.poll_check.setChecked("poll" in self._kinds)
        self.poll_check.blockSignals(False)
        self._refilter()

    def _filters_changed(self) -> None:
        self._pattern_text = self.filter_edit.text()
        try:
            self._pattern = compile_filter(self._pattern_text)
        except FilterError as exc:
            self.filter_edit.setStyleSheet("color: #c62828;")
            self.filter_edit.setToolTip(localized(exc))
            return
        self.filter_edit.setStyleSheet("")
        self._directions = {
            d for d, box in (("tx", self.tx_check), ("rx", self.rx_check)) if box.isChecked()
        }
        self._directions.add("")
        self._refilter()

    def set_filter(
        self,
        pattern: str | None = None,
        directions: set[str] | None = None,
        kinds: set[str] | None = None,
    ) -> None:
        """Set the filters (None: leave as is); raises FilterError for a bad expression."""
        if pattern is not None:
            compile_filter(pattern)
            self.filter_edit.setText(pattern)
            self._typed()
        if directions is not None:
            self.tx_check.setChecked("tx" in directions)
            self.rx_check.setChecked("rx" in directions)
        if kinds is not None:
            for kind, action in self.kind_actions.items():
                action.setChecked(kind in kinds)

    def show_poll(self, shown: bool) -> None:
        """Show or hide the position poll's lines."""
        self.poll_check.setChecked(shown)

    def _refilter(self) -> None:
        self.flush()
        current = self._current_line()
        rows = self.index.select(self._directions, self._kinds, self._pattern)
        self._shown_until = len(self.index)
        self._model.set_rows(rows)
        self._update_status()
        if self._follow or current is None:
            self._scroll_to_end()
        else:
            self._go_to_row(min(self._model.row_of(current), len(rows) - 1))

    def kinds(self) -> set[str]:
        """The kinds of lines shown."""
        return set(self._kinds)

    def display_mode(self) -> str:
        """`"text"`, `"hex"` or `"mixed"`."""
        return self._model.mode

    def set_display_mode(self, mode: str) -> None:
        """Show bytes as escaped text, hex, or mixed."""
        if mode not in DISPLAY_MODES:
            raise ValueError(f"display mode must be one of {DISPLAY_MODES}, not {mode!r}")
        if mode != self._model.mode:
            self._model.mode = mode
            self.mode_combo.setCurrentIndex(self.mode_combo.findData(mode))
            self._model.refresh()

    def time_mode(self) -> str:
        """`"relative"`, `"absolute"` or `"delta"`."""
        return self._model.time_mode

    def set_time_mode(self, mode: str) -> None:
        """Show times since the session start, as wall-clock times, or as gaps."""
        if mode not in TIME_MODES:
            raise ValueError(f"time mode must be one of {TIME_MODES}, not {mode!r}")
        if mode != self._model.time_mode:
            self._model.time_mode = mode
            self.time_combo.setCurrentIndex(self.time_combo.findData(mode))
            self._model.refresh()

    def timestamps(self) -> bool:
        """Whether the time column is shown."""
        return not self.view.isColumnHidden(TIME)

    def set_timestamps(self, shown: bool) -> None:
        """Show or hide the time column."""
        self.view.setColumnHidden(TIME, not shown)
        self.timestamps_check.setChecked(shown)

    # -- search ----------------------------------------------------------------------------

    def _search_changed(self, text: str) -> None:
        self._search_text = text
        try:
            self._search = compile_filter(text)
        except FilterError as exc:
            self.search_edit.setStyleSheet("color: #c62828;")
            self.search_edit.setToolTip(localized(exc))
            return
        self.search_edit.setStyleSheet("")
        self.flush()
        hits = (
            self.index.select(None, None, self._search)
            if self._search is not None
            else np.zeros(0, dtype=np.int64)
        )
        self._model.set_matches(hits)
        self._update_status()

    def search(self, text: str) -> int:
        """Highlight lines matching `text` (a regex); returns how many match."""
        self.search_edit.setText(text)
        self._typed()
        return len(self._model.matches)

    def _visible_matches(self) -> np.ndarray:
        matches = self._model.matches
        return matches[np.isin(matches, self._model.rows)]

    def find_next(self) -> int | None:
        """Go to the next shown line that matches the search; returns its line number."""
        return self._find(forward=True)

    def find_previous(self) -> int | None:
        """Go to the previous shown line that matches the search; returns its line number."""
        return self._find(forward=False)

    def _find(self, forward: bool) -> int | None:
        self.flush()
        matches = self._visible_matches()
        if not len(matches):
            return None
        current = self._current_line()
        if current is None:
            target = matches[0] if forward else matches[-1]
        elif forward:
            after = matches[matches > current]
            target = after[0] if len(after) else matches[0]  # wraps around
        else:
            before = matches[matches < current]
            target = before[-1] if len(before) else matches[-1]
        self.jump_to_line(int(target))
        return int(target)

    # -- moving around ---------------------------------------------------------------------

    def _current_line(self) -> int | None:
        index = self.view.currentIndex()
        if not index.isValid() or index.row() >= len(self._model.rows):
            return None
        return int(self._model.rows[index.row()])

    def current_line(self) -> int | None:
        """The line of the selected row."""
        return self._current_line()

    def jump_to_line(self, line: int, reveal: bool = False) -> None:
        """Select `line` (or the next shown line after it) and scroll to it; stops following.
        With `reveal`, a line of a hidden kind (the poll) has its kind shown first."""
        self.flush()
        if line < self.index.first:  # dropped by the line limit: the oldest line kept instead
            note = self.tr(
                "line %1 is no longer in the console (its line limit dropped it); the session"
                " log has it"
            )
            self.show_error(fill(note, line))
        elif reveal and line < len(self.index):
            kind = self.index.line(line).kind
            if kind not in self._kinds:
                self.kind_actions[kind].setChecked(True)
        row = self._model.row_of(line)
        if row >= len(self._model.rows):
            row = len(self._model.rows) - 1
        if row < 0:
            return
        self._go_to_row(row)

    def _go_to_row(self, row: int) -> None:
        if row < 0:
            return
        index = self._model.index(row, BYTES)
        self._scrolling = True
        try:
            self.view.setCurrentIndex(index)
            self.view.scrollTo(index, QAbstractItemView.ScrollHint.PositionAtCenter)
        finally:
            self._scrolling = False
        self._set_follow(row == len(self._model.rows) - 1)  # a line chosen stays in view

    def _double_clicked(self, index: QModelIndex) -> None:
        line = self._model.line_at(index.row())
        target = line.pair if line.pair >= 0 else line.first_copy
        if index.column() == REPLY and line.first_copy >= 0:
            target = line.first_copy
        if target >= 0:
            self.jump_to_line(target)
        self.line_activated.emit(line.number)

    def _scroll_to_end(self) -> None:
        self._scrolling = True
        try:
            self.view.scrollToBottom()
        finally:
            self._scrolling = False

    def _range_changed(self) -> None:
        if self._follow and not self._scrolling:  # (scrolling to the end does it anyway)
            self._scroll_to_end()

    def _scrolled(self, value: int) -> None:
        if self._scrolling:
            return
        self._set_follow(value >= self.view.verticalScrollBar().maximum())

    def _set_follow(self, follow: bool) -> None:
        self._follow = follow
        self.paused_label.setVisible(not follow)

    def is_following(self) -> bool:
        """Whether new lines scroll the view (False while the user has scrolled up)."""
        return self._follow

    def _update_status(self) -> None:
        self._status_timer.stop()
        self._status_at = time.perf_counter()
        counts = self.index.counts
        parts = [
            fill(self.tr("%1 lines"), f"{self.index.kept:,}"),
            fill(self.tr("%1 shown"), f"{len(self._model.rows):,}"),
        ]
        if self.index.first:
            parts.append(fill(self.tr("%1 older in the session log"), f"{self.index.first:,}"))
        if "poll" not in self._kinds and counts["poll"]:
            parts.append(fill(self.tr("%1 poll hidden"), f"{counts['poll']:,}"))
        if counts["error"]:
            parts.append(fill(self.tr("%1 errors"), f"{counts['error']:,}"))
        if self._search is not None:
            parts.append(fill(self.tr("%1 matches"), f"{len(self._model.matches):,}"))
        self.status_label.setText(" · ".join(parts))
        tip = parts
        if self.max_lines:
            limit = self.tr(
                "The console keeps the newest %1 lines (Settings): older lines are dropped from"
                " it, the session log on disk keeps every line"
            )
            tip = [*parts, fill(limit, f"{self.max_lines:,}")]
        self.status_label.setToolTip("\n".join(tip))

    def status_text(self) -> str:
        """The counts under the filters (lines, shown, hidden polls, errors, matches)."""
        if self._status_timer.isActive():  # a flood's counts are shown a few times a second
            self._update_status()
        return self.status_label.text()

    # -- text out --------------------------------------------------------------------------

    def row_text(self, row: int) -> str:
        """One shown line as text: `time DIR  bytes  meaning  [reply]` (time if shown)."""
        return self._model.row_text(row, self.timestamps())

    def text(self) -> str:
        """The shown (filtered) lines as text, one a line (after a flush)."""
        return "\n".join(self.row_text(row) for row in range(len(self._model.rows)))

    def shown_lines(self) -> list[int]:
        """The line numbers shown, in order."""
        return [int(n) for n in self._model.rows]

    def clear(self) -> None:
        """Forget all lines (the session log on disk keeps them) and empty the view."""
        protocol = self.index.protocol
        self.index.close()
        self.index = localized_index(protocol)
        self._recent.clear()
        self._pending.clear()
        self._incoming.clear()
        self._shown_until = 0
        self._trim_noted = False
        self._model.set_index(self.index)
        self._set_follow(True)
        self._update_status()
        self.reset.emit()

    def load(self, index: TrafficIndex) -> None:
        """Show another index (an opened log) in place of the session's."""
        self.index.close()
        self.index = index
        self._recent.clear()
        self._pending.clear()
        self._incoming.clear()
        self._shown_until = 0
        self._trim_noted = False
        self._model.set_index(index)
        self._model.origin = index.time(index.first) if index.kept else 0.0
        self._origin_set = True
        self._model.set_rows(self.index.select(self._directions, self._kinds, self._pattern))
        self._shown_until = len(index)
        self._update_status()
        self.reset.emit()

    def export(self, path: str | Path) -> int:
        """Write the shown lines as text (or CSV for a `.csv` path); returns the lines written."""
        self.flush()
        target = Path(path)
        if target.suffix.lower() == ".csv":
            return self.export_csv(target)
        with target.open("w", encoding="utf-8") as out:
            for row in range(len(self._model.rows)):
                out.write(self.row_text(row) + "\n")
        return len(self._model.rows)

    def export_csv(self, path: str | Path) -> int:
        """Write the shown lines as CSV (CSV_COLUMNS: line, time, direction, kind, bytes, …, and
        the wall-clock time_iso last)."""
        self.flush()
        model = self._model
        with Path(path).open("w", encoding="utf-8", newline="") as out:
            writer = csv.writer(out)
            writer.writerow(CSV_COLUMNS)
            for row in range(len(model.rows)):
                writer.writerow(model.csv_row(row))
        return len(model.rows)

    def export_interactively(self) -> None:
        """Ask for a file and export the shown lines to it, saying how it went."""
        path = self.ask_export_path()
        if not path:
            return
        try:
            count = self.export(path)
        except OSError as exc:
            log.warning("export to %s failed: %s", path, exc)
            self.show_error(fill(self.tr("export failed: %1"), localized(exc)))
        else:
            self.show_error("")
            self.append_note(fill(self.tr("exported %1 lines to %2"), count, path))

    # -- sending (the SendLine does the work) ----------------------------------------------

    def send(self) -> None:
        """Send what is in the send line (what Enter and Send do)."""
        self.send_line.send()

    def send_mode(self) -> str:
        """How the send line is read: `"text"` or `"hex"`."""
        return self.send_line.mode()

    def set_send_mode(self, mode: str) -> None:
        """Read the send line as text (with escapes and line ending) or as hex bytes."""
        self.send_line.set_mode(mode)

    def set_line_ending(self, ending: bytes) -> None:
        """The bytes appended to a text line: b"\\n", b"\\r", b"\\r\\n" or b""."""
        self.send_line.set_line_ending(ending)

    def set_send_enabled(self, enabled: bool) -> None:
        """Allow sending (e.g. only while connected); the log stays usable either way."""
        self.send_line.setEnabled(enabled)

    def show_error(self, message: str) -> None:
        """Show a problem under the send line ("" hides it)."""
        self.send_line.show_error(message)


__all__ = ["COLUMNS", "HEX", "TEXT", "RawConsole", "stamp"]
