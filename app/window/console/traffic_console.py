"""The traffic console: every frame decoded, filtered and searched, and a send line.

Lines live in a TrafficIndex (on disk, a few bytes each in memory), shown by a table that reads
only the rows on screen, so a million lines stay light. New traffic is decoded in turns of at
most 2 ms and shown at most 10 times a second, in a turn of its own (traffic_pacing.py). With a
line limit the console is a scrollback buffer: it keeps the newest lines, dropping the oldest a
block at a time (see set_max_lines); the session log on disk keeps every line. The filters and
search bar: traffic_filter_bar.py; the export: traffic_export.py.
"""

from __future__ import annotations

import logging
import time
from collections import deque
from collections.abc import Callable
from pathlib import Path

import numpy as np
from PySide6.QtCore import QModelIndex, Signal
from PySide6.QtWidgets import (
    QAbstractItemView,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.common.messages import localized
from app.window.console.display import DisplayOptions
from app.window.console.export import (
    ask_save_path,
    exported_text,
    tell_window,
    write_csv,
    write_text,
)
from app.window.console.filter_bar import TrafficFilterBar
from app.window.console.navigation import TrafficNavigator
from app.window.console.pacing import BACKLOG, FeedPacer, Incoming
from app.window.console.status import ConsoleStatus, StatusFigures
from app.window.console.table import (
    BYTES,
    COLUMNS,
    HEX,
    LINE,
    MEANING,
    REPLY,
    TEXT,
    TIME,
    TrafficModel,
    TrafficView,
    stamp,
)
from drivers.link.records import RX, TX, Note, Traffic
from drivers.link.records import Record as TrafficRecord
from drivers.protocols.base import Protocol
from drivers.traffic.index import TrafficIndex
from widgets._i18n import fill
from widgets.send_line import SendLine

log = logging.getLogger(__name__)

NOTE_KIND = "note"  # what `records()` calls a note's direction
TRIM_MARGIN = 0.1  # past its line limit by this fraction, the console drops its oldest lines

Record = tuple[str, bytes, float]  # (direction or "note", data, timestamp in seconds)


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
        self.feed = FeedPacer(self, self._take_into_index, self._show_and_paint)
        self.index = localized_index()
        self.max_lines = 0  # 0: keep every line (see set_max_lines)
        self._trim_noted = False  # the note saying lines are being dropped was added
        self._model = TrafficModel(self.index, self)  # goes with the console, never before it
        self._origin_set = False
        self._shown_until = 0  # lines up to here have been through the filter
        self.filter_bar = TrafficFilterBar(self)
        self.filter_bar.filters_changed.connect(self._refilter)
        self.filter_bar.search_changed.connect(self._search_changed)
        self.filter_bar.find_requested.connect(self._find)
        self.status = ConsoleStatus(self, self._status_figures)
        self._build(sending)

    # -- building --------------------------------------------------------------------------

    def _button(self, text: str, name: str, tip: str, slot: Callable) -> QPushButton:
        button = QPushButton(text)
        button.setObjectName(name)
        button.setToolTip(tip)
        button.clicked.connect(slot)
        return button

    def _build(self, sending: bool) -> None:
        bar = self.filter_bar
        self.tx_check, self.rx_check, self.poll_check = bar.tx_check, bar.rx_check, bar.poll_check
        self.kind_button, self.kind_actions = bar.kind_button, bar.kind_actions
        self.filter_edit, self.search_edit = bar.filter_edit, bar.search_edit
        self.view = self._build_view()
        self.display = DisplayOptions(self, self.view, self._model)
        self.mode_combo, self.time_combo = self.display.mode_combo, self.display.time_combo
        self.timestamps_check = self.display.timestamps_check
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

        self.status_label = self.status.label
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
        second.addWidget(self.filter_bar.previous_button)
        second.addWidget(self.filter_bar.next_button)
        second.addWidget(export_button)
        second.addWidget(clear_button)

        self.navigator = TrafficNavigator(self, self.view, self._model, self.paused_label)

        self.send_line = SendLine()
        self.send_line.send_requested.connect(self._typed)  # first: before it is sent
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
        self.status.refresh()

    def _build_view(self) -> TrafficView:
        view = TrafficView(self._model)
        view.setObjectName("consoleView")
        view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        header = view.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        width = view.fontMetrics().horizontalAdvance("0")
        for column, chars in ((LINE, 8), (TIME, 13), (2, 4), (BYTES, 34), (MEANING, 34)):
            header.resizeSection(column, width * chars + 12)
        header.setStretchLastSection(True)
        view.setToolTip(
            self.tr(
                "TX (blue): sent to the device; RX (green): received; grey: notes and the"
                " device's own text; red: errors. Double-click a line to go to its request,"
                " reply or first copy."
            )
        )
        view.doubleClicked.connect(self._double_clicked)
        return view

    # -- traffic in (paced: traffic_pacing.py) ---------------------------------------------

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
        if wall is None:
            self.feed.add(Traffic(direction, bytes(data), timestamp))  # (wall: now's)
        else:
            self.feed.add(Traffic(direction, bytes(data), timestamp, wall))

    def append_records(self, records: list[TrafficRecord]) -> None:
        """Take records as the tap made them (a worker's batch), unchanged; shown at the next
        flush."""
        self.feed.extend(records)

    def append_note(self, text: str, timestamp: float | None = None) -> None:
        """Log an information line such as "connected" (timestamp: the clock's now by default)."""
        when = self.clock() if timestamp is None else timestamp
        self.feed.add(Note(text, when, time.time() - (self.clock() - when)))

    def _take_into_index(self, pending: deque[Incoming], deadline: float | None) -> int:
        """Records into the index, in order, until `deadline` (perf_counter; None: all);
        returns how many it took."""
        index = self.index
        if not self._origin_set and not len(index):
            self._model.origin = pending[0].time
        if index.wall_offset is None:  # (traffic fed without a wall-clock time: now's)
            first = pending[0]
            wall = first.wall
            index.wall_offset = (time.time() if wall is None else wall) - first.time
        taken = index.add_many(pending, deadline)
        index.commit()
        return taken

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
        return self.feed.backlog()

    def behind(self) -> bool:
        """Whether a backlog is being drained (more than the feed's BACKLOG records wait)."""
        return self.feed.backlog() > BACKLOG

    def records(self) -> list[Record]:
        """The latest raw records (bounded), as they came: (direction or "note", data, time)."""
        return [(r.direction or NOTE_KIND, r.data, r.time) for r in self.feed.records()]

    def flush(self) -> None:
        """Show every line added since the last flush (and a filter still being typed)."""
        self.filter_bar.apply_typing()
        self.feed.flush()
        self._show_new()

    def set_max_lines(self, lines: int) -> None:
        """Keep the newest `lines` lines (0: every line), as a terminal's scrollback does: once
        past the limit by TRIM_MARGIN (a tenth), the oldest are dropped down to the limit, a
        block at a time. Lines keep their numbers; the session log on disk keeps every line."""
        self.max_lines = max(0, int(lines))
        self._trim()
        self.status.refresh()

    def _trim(self) -> None:
        """Past the line limit (and its margin): drop the oldest lines, down to the limit. A
        view following the tail keeps following; one scrolled up keeps its top line in place
        (or shows the oldest line kept, if its own was dropped)."""
        limit, index = self.max_lines, self.index
        if not limit or index.kept <= limit + int(limit * TRIM_MARGIN):
            return

        def drop() -> None:
            index.drop_oldest(index.kept - limit)
            self._model.drop_before(index.first)

        self.navigator.keep_place(drop)
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
        shown_at = self.feed.showing()
        total = len(self.index)
        if total == self._shown_until:
            return
        bar = self.filter_bar
        first = min(max(self._shown_until, self.index.first), total)  # (some maybe dropped)
        rows = self.index.select(bar.directions, bar.kinds, bar.pattern, start=first)
        if bar.search is not None:
            self._model.add_matches(self.index.select(None, None, bar.search, start=first))
        self._shown_until = total
        self._model.append_rows(rows)
        self.status.refresh_soon(shown_at)
        self.lines_added.emit(first, total - first)
        self.navigator.follow_tail()

    def _show_and_paint(self) -> None:
        """The feed's turn to show: the new lines, painted now, in this turn: else the table
        is painted with the next repaint of the window, which a plot's change makes at once,
        and the two add up."""
        self._show_new()
        self.view.viewport().repaint()

    # -- filters and modes (the filters and search bar: traffic_filter_bar.py) -------------

    def set_filter(
        self,
        pattern: str | None = None,
        directions: set[str] | None = None,
        kinds: set[str] | None = None,
    ) -> None:
        """Set the filters (None: leave as is); raises FilterError for a bad expression."""
        self.filter_bar.set_filter(pattern, directions, kinds)

    def show_poll(self, shown: bool) -> None:
        """Show or hide the position poll's lines."""
        self.poll_check.setChecked(shown)

    def _refilter(self) -> None:
        self.flush()
        navigator = self.navigator
        current = navigator.current_line()
        bar = self.filter_bar
        rows = self.index.select(bar.directions, bar.kinds, bar.pattern)
        self._shown_until = len(self.index)
        self._model.set_rows(rows)
        self.status.refresh()
        if navigator.following or current is None:
            navigator.scroll_to_end()
        else:
            navigator.go_to_row(min(self._model.row_of(current), len(rows) - 1))

    def kinds(self) -> set[str]:
        """The kinds of lines shown."""
        return set(self.filter_bar.kinds)

    def display_mode(self) -> str:
        """`"text"`, `"hex"` or `"mixed"`."""
        return self._model.mode

    def set_display_mode(self, mode: str) -> None:
        """Show bytes as escaped text, hex, or mixed."""
        self.display.set_display_mode(mode)

    def time_mode(self) -> str:
        """`"relative"`, `"absolute"` or `"delta"`."""
        return self._model.time_mode

    def set_time_mode(self, mode: str) -> None:
        """Show times since the session start, as wall-clock times, or as gaps."""
        self.display.set_time_mode(mode)

    def timestamps(self) -> bool:
        """Whether the time column is shown."""
        return self.display.timestamps()

    def set_timestamps(self, shown: bool) -> None:
        """Show or hide the time column."""
        self.display.set_timestamps(shown)

    # -- search ----------------------------------------------------------------------------

    def _search_changed(self) -> None:
        self.flush()
        search = self.filter_bar.search
        hits = (
            self.index.select(None, None, search)
            if search is not None
            else np.zeros(0, dtype=np.int64)
        )
        self._model.set_matches(hits)
        self.status.refresh()

    def search(self, text: str) -> int:
        """Highlight lines matching `text` (a regex); returns how many shown lines match (the
        status line says how many more the filters hide)."""
        self.filter_bar.set_search(text)
        return self._model.shown_matches()

    def find_next(self) -> int | None:
        """Go to the next shown line that matches the search; returns its line number."""
        return self._find(forward=True)

    def find_previous(self) -> int | None:
        """Go to the previous shown line that matches the search; returns its line number."""
        return self._find(forward=False)

    def _find(self, forward: bool) -> int | None:
        self.flush()
        target = self.navigator.next_match(forward)
        if target is not None:
            self.jump_to_line(target)
        return target

    # -- moving around ---------------------------------------------------------------------

    def current_line(self) -> int | None:
        """The line of the selected row."""
        return self.navigator.current_line()

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
            if kind not in self.filter_bar.kinds:
                self.filter_bar.show_kind(kind)
        row = self._model.row_of(line)
        if row >= len(self._model.rows):
            row = len(self._model.rows) - 1
        if row < 0:
            return
        self.navigator.go_to_row(row)

    def _double_clicked(self, index: QModelIndex) -> None:
        line = self._model.line_at(index.row())
        target = line.pair if line.pair >= 0 else line.first_copy
        if index.column() == REPLY and line.first_copy >= 0:
            target = line.first_copy
        if target >= 0:
            self.jump_to_line(target)
        self.line_activated.emit(line.number)

    def is_following(self) -> bool:
        """Whether new lines scroll the view (False while the user has scrolled up)."""
        return self.navigator.following

    def _status_figures(self) -> StatusFigures:
        index, bar = self.index, self.filter_bar
        counts = index.counts
        shown_matches = self._model.shown_matches() if bar.search is not None else 0
        return StatusFigures(
            kept=index.kept,
            shown=len(self._model.rows),
            older=index.first,
            poll_hidden=0 if "poll" in bar.kinds else counts["poll"],
            errors=counts["error"],
            matches=None if bar.search is None else shown_matches,
            limit=self.max_lines,
            matches_hidden=len(self._model.matches) - shown_matches
            if bar.search is not None
            else 0,
        )

    def status_text(self) -> str:
        """The counts under the filters (lines, shown, hidden polls, errors, matches)."""
        return self.status.text()

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
        self.feed.clear()
        self._shown_until = 0
        self._trim_noted = False
        self._model.set_index(self.index)
        self.navigator.set_follow(True)
        self.status.refresh()
        self.reset.emit()

    def load(self, index: TrafficIndex) -> None:
        """Show another index (an opened log) in place of the session's."""
        self.index.close()
        self.index = index
        self.feed.clear()
        self._shown_until = 0
        self._trim_noted = False
        self._model.set_index(index)
        self._model.origin = index.time(index.first) if index.kept else 0.0
        self._origin_set = True
        bar = self.filter_bar
        self._model.set_rows(self.index.select(bar.directions, bar.kinds, bar.pattern))
        self._shown_until = len(index)
        self.status.refresh()
        self.reset.emit()

    def export(self, path: str | Path) -> int:
        """Write the shown lines as text (or CSV for a `.csv` path); returns the lines written."""
        self.flush()
        if Path(path).suffix.lower() == ".csv":
            return self.export_csv(path)
        return write_text(self._model, path, self.timestamps())

    def export_csv(self, path: str | Path) -> int:
        """Write the shown lines as CSV (CSV_COLUMNS: line, time, direction, kind, bytes, …, and
        the wall-clock time_iso last)."""
        self.flush()
        return write_csv(self._model, path)

    def export_interactively(self) -> None:
        """Ask for a file and export the shown lines to it, saying how it went."""
        path = self.ask_export_path()
        if not path:
            return
        try:
            count = self.export(path)
        except OSError as exc:
            log.warning("export to %s failed: %s", path, exc)
            failed = fill(self.tr("export failed: %1"), localized(exc))
            self.show_error(failed)
            tell_window(self, failed, failed=True)
        else:
            self.show_error("")
            said = exported_text(count, path)
            self.append_note(said)
            tell_window(self, said)  # seen even where the console is hidden

    # -- sending (the SendLine does the work) ----------------------------------------------

    def _typed(self, data: bytes) -> None:
        """What the operator typed is always shown: its frames are not the panel's polling."""
        self.index.typed(bytes(data), time.monotonic())

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
