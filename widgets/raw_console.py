"""Raw serial traffic for firmware developers: TX/RX log, text or hex, and a send line."""

from __future__ import annotations

import logging
import time
from collections import deque
from collections.abc import Callable, Iterable
from pathlib import Path

from PySide6.QtCore import QTimer, Signal
from PySide6.QtGui import QColor, QFontDatabase, QTextCharFormat, QTextCursor
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QFileDialog,
    QHBoxLayout,
    QLabel,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from widgets import traffic_format as fmt
from widgets.send_line import SendLine

log = logging.getLogger(__name__)

TX, RX, NOTE = "tx", "rx", "note"
TEXT, HEX = "text", "hex"
FLUSH_INTERVAL_MS = 50  # ~20 Hz
DEFAULT_MAX_LINES = 5000
DEFAULT_MAX_RECORDS = 100_000
COLOURS = {TX: "#1565c0", RX: "#2e7d32", NOTE: "#757575"}

Record = tuple[str, bytes, float]  # (direction or "note", data, timestamp in seconds)


def _time(record: Record) -> float:
    return record[2]


Piece = tuple[str, bool, str]  # (colour kind, starts a line, text)


def ask_save_path(parent: QWidget) -> str:
    """Ask where to export the log; "" when cancelled."""
    path, _ = QFileDialog.getSaveFileName(
        parent, "Export traffic", "traffic.txt", "Text files (*.txt);;All files (*)"
    )
    return path


class RawConsole(QWidget):
    """Buffered, bounded traffic log (flushed at ~20 Hz) and a send line emitting bytes."""

    send_requested = Signal(object)  # bytes

    def __init__(
        self,
        parent: QWidget | None = None,
        max_lines: int = DEFAULT_MAX_LINES,
        max_records: int = DEFAULT_MAX_RECORDS,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("rawConsole")
        self.ask_export_path: Callable[[], str] = lambda: ask_save_path(self)
        # time.monotonic, as the traffic's timestamps: notes' default time and the hex tail wait
        self.clock: Callable[[], float] = time.monotonic
        self._records: deque[Record] = deque(maxlen=max_records)
        self._pending: deque[Record] = deque(maxlen=max(max_lines - 1, 1))  # room for a note
        self._origin: float | None = None
        self._origin_set = False  # by set_time_origin (else: the earliest record)
        self._shown_until: float | None = None  # time of the latest record rendered in the view
        self._tail_since = 0.0  # clock() when the held hex row last got bytes
        self._mode = TEXT
        self._timestamps = True
        self._follow = True
        self._writing = False
        self._assembler = fmt.TextAssembler()
        self._hex = fmt.HexAssembler()
        self._skipped = 0
        self._formats = {}
        for kind, colour in COLOURS.items():
            char_format = QTextCharFormat()
            char_format.setForeground(QColor(colour))
            char_format.setFontItalic(kind == NOTE)
            self._formats[kind] = char_format

        self._build(max_lines)
        self._flush_timer = QTimer(self)
        self._flush_timer.setSingleShot(True)
        self._flush_timer.setInterval(FLUSH_INTERVAL_MS)
        self._flush_timer.timeout.connect(self.flush)

    def _build(self, max_lines: int) -> None:
        self.mode_combo = QComboBox()
        self.mode_combo.setObjectName("consoleDisplayMode")
        self.mode_combo.addItems([TEXT, HEX])
        self.mode_combo.setToolTip("text: bytes as text with \\r \\n \\xNN escapes; hex: hexdump")
        self.mode_combo.currentTextChanged.connect(self.set_display_mode)
        self.timestamps_check = QCheckBox("Timestamps")
        self.timestamps_check.setObjectName("consoleTimestamps")
        self.timestamps_check.setChecked(True)
        self.timestamps_check.setToolTip("Show seconds since the first record (000003.001 s)")
        self.timestamps_check.toggled.connect(self.set_timestamps)
        self.paused_label = QLabel("⏸ autoscroll paused: scroll to the bottom to resume")
        self.paused_label.setObjectName("consolePaused")
        self.paused_label.setStyleSheet("color: #8a4b00;")
        self.paused_label.setVisible(False)
        export_button = QPushButton("Export…")
        export_button.setObjectName("consoleExport")
        export_button.setToolTip("Save the whole retained log (not only what is shown) as text")
        export_button.clicked.connect(self.export_interactively)
        clear_button = QPushButton("Clear")
        clear_button.setObjectName("consoleClear")
        clear_button.setToolTip("Forget the log")
        clear_button.clicked.connect(self.clear)
        top = QHBoxLayout()
        top.addWidget(QLabel("Show:"))
        top.addWidget(self.mode_combo)
        top.addWidget(self.timestamps_check)
        top.addWidget(self.paused_label)
        top.addStretch(1)
        top.addWidget(export_button)
        top.addWidget(clear_button)

        self.view = QPlainTextEdit()
        self.view.setObjectName("consoleView")
        self.view.setReadOnly(True)
        self.view.setUndoRedoEnabled(False)
        self.view.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)
        self.view.setMaximumBlockCount(max_lines)
        self.view.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.view.setToolTip("TX (blue): sent to the device; RX (green): received; grey: notes")
        self.view.verticalScrollBar().valueChanged.connect(self._scrolled)

        self.send_line = SendLine()
        self.send_line.send_requested.connect(self.send_requested)
        self.send_edit = self.send_line.edit
        self.send_mode_combo = self.send_line.mode_combo
        self.ending_combo = self.send_line.ending_combo
        self.send_button = self.send_line.button
        self.error_label = self.send_line.error_label

        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(self.view, 1)
        layout.addWidget(self.send_line)

    # -- traffic in ----------------------------------------------------------------------

    def append_traffic(self, direction: str, data: bytes, timestamp: float) -> None:
        """Log bytes sent ("tx") or received ("rx") at `timestamp` (s); shown at the next flush."""
        if direction not in (TX, RX):
            raise ValueError(f"direction must be 'tx' or 'rx', not {direction!r}")
        self._add((direction, bytes(data), timestamp))

    def append_note(self, text: str, timestamp: float | None = None) -> None:
        """Log an information line such as "connected" (timestamp: monotonic now by default)."""
        when = self.clock() if timestamp is None else timestamp
        self._add((NOTE, text.encode("utf-8"), when))

    def _add(self, record: Record) -> None:
        when = record[2]
        if self._origin is None or (not self._origin_set and when < self._origin):
            if self._origin is not None:
                self._shown_until = float("inf")  # every shown time moves: re-render at flush
            self._origin = when
        records = self._records
        if not records or records[-1][2] <= when:
            records.append(record)  # nearly always: in time order
        else:  # late (a note is stamped when added, traffic comes in batches): insert in place
            index = len(records) - 1
            while index > 0 and records[index - 1][2] > when:
                index -= 1
            if len(records) == records.maxlen:
                records.popleft()
                index = max(index - 1, 0)
            records.insert(index, record)
        if len(self._pending) == self._pending.maxlen:
            self._skipped += 1  # a flood: the oldest unshown record will never be shown
        self._pending.append(record)
        if not self._flush_timer.isActive():
            self._flush_timer.start()

    def set_time_origin(self, timestamp: float) -> None:
        """Timestamps are shown as seconds since `timestamp` (default: the first record)."""
        self._origin = timestamp
        self._origin_set = True
        self._rerender()

    def records(self) -> list[Record]:
        """The retained records (bounded), in time order: (direction or "note", data, time)."""
        return list(self._records)

    def flush(self) -> None:
        """Show the records appended since the last flush (the timer calls this at ~20 Hz)."""
        self._flush_timer.stop()
        if self._pending:
            records = sorted(self._pending, key=_time)  # stable: ties keep their arrival order
            self._pending.clear()
            if self._shown_until is not None and records[0][2] < self._shown_until:
                self._rerender()  # older than what is shown: redo the view in time order
                return
            if self._skipped:
                text = f"{self._skipped} records not shown here (too many at once; export has them)"
                records.insert(0, (NOTE, text.encode(), records[0][2]))
                self._skipped = 0
            self._write(records)
        elif self._hex.pending():
            if self.clock() - self._tail_since >= fmt.HEX_IDLE:
                self._emit([(kind, True, row) for kind, row in self._hex.close()])
            else:
                self._flush_timer.start()  # look again soon

    # -- rendering -----------------------------------------------------------------------

    def _pieces(
        self,
        record: Record,
        timestamps: bool,
        mode: str,
        assembler: fmt.TextAssembler,
        hex_assembler: fmt.HexAssembler,
    ) -> list[Piece]:
        """(colour, starts a line, text) pieces of a record; see TextAssembler, HexAssembler."""
        kind, data, when = record
        seconds = when - (self._origin or 0.0) if timestamps else None
        if kind == NOTE:
            assembler.close()
            pieces: list[Piece] = [(d, True, row) for d, row in hex_assembler.close()]
            pieces.append((NOTE, True, fmt.note_line(data.decode("utf-8", "replace"), seconds)))
            return pieces
        if mode == HEX:
            return [(d, True, row) for d, row in hex_assembler.feed(kind, data, seconds, when)]
        return [(kind, starts, text) for starts, text in assembler.feed(kind, data, seconds)]

    def _write(self, records: Iterable[Record]) -> None:
        pieces: list[Piece] = []
        for record in records:
            pieces += self._pieces(record, self._timestamps, self._mode, self._assembler, self._hex)
            self._shown_until = record[2]
        if self._hex.pending():
            self._tail_since = self.clock()
            if not self._flush_timer.isActive():
                self._flush_timer.start()  # shown if no more bytes come for it
        self._emit(pieces)

    def _emit(self, pieces: list[Piece]) -> None:
        if not pieces:
            return
        document = self.view.document()
        first = document.isEmpty()
        runs: list[tuple[str, list[str]]] = []  # consecutive pieces of one colour, as one string
        for kind, starts_line, text in pieces:
            if not runs or runs[-1][0] != kind:
                runs.append((kind, []))
            runs[-1][1].append(text if first or not starts_line else "\n" + text)
            first = False
        cursor = QTextCursor(document)
        cursor.movePosition(QTextCursor.MoveOperation.End)
        scroll = self.view.verticalScrollBar()
        self._writing = True
        try:
            cursor.beginEditBlock()
            for kind, texts in runs:
                cursor.insertText("".join(texts), self._formats[kind])  # "\n" starts a block
            cursor.endEditBlock()
            if self._follow:
                scroll.setValue(scroll.maximum())
        finally:
            self._writing = False

    def _reset_view(self) -> None:
        self._pending.clear()
        self._skipped = 0
        self._assembler = fmt.TextAssembler()
        self._hex = fmt.HexAssembler()
        self._shown_until = None
        self.view.clear()

    def _rerender(self) -> None:
        self._reset_view()
        count = self.view.maximumBlockCount()
        recent = list(self._records)[-count:] if count > 0 else list(self._records)
        if recent:
            self._write(recent)

    def _scrolled(self, value: int) -> None:
        if self._writing:
            return
        self._follow = value >= self.view.verticalScrollBar().maximum()
        self.paused_label.setVisible(not self._follow)

    def is_following(self) -> bool:
        """Whether new lines scroll the view (False while the user has scrolled up)."""
        return self._follow

    def display_mode(self) -> str:
        """`"text"` or `"hex"`."""
        return self._mode

    def set_display_mode(self, mode: str) -> None:
        """Show the traffic as escaped text (`"text"`) or as a hexdump (`"hex"`)."""
        if mode not in (TEXT, HEX):
            raise ValueError(f"display mode must be 'text' or 'hex', not {mode!r}")
        if mode != self._mode:
            self._mode = mode
            self.mode_combo.setCurrentText(mode)
            self._rerender()

    def timestamps(self) -> bool:
        """Whether timestamps are shown."""
        return self._timestamps

    def set_timestamps(self, shown: bool) -> None:
        """Show or hide the timestamps."""
        if shown != self._timestamps:
            self._timestamps = shown
            self.timestamps_check.setChecked(shown)
            self._rerender()

    def text(self) -> str:
        """The text in the view (what has been flushed)."""
        return self.view.toPlainText()

    def clear(self) -> None:
        """Forget all records and empty the view."""
        self._records.clear()
        self._reset_view()
        self._follow = True
        self.paused_label.setVisible(False)

    def export(self, path: str | Path) -> int:
        """Write every retained record as text, with timestamps, in the display mode; lines."""
        lines: list[str] = []
        assembler, hex_assembler = fmt.TextAssembler(), fmt.HexAssembler()
        for record in self._records:
            for _, starts_line, text in self._pieces(
                record, True, self._mode, assembler, hex_assembler
            ):
                if starts_line or not lines:
                    lines.append(text)
                else:
                    lines[-1] += text
        lines += [row for _, row in hex_assembler.close()]
        Path(path).write_text("".join(line + "\n" for line in lines), encoding="utf-8")
        return len(lines)

    def export_interactively(self) -> None:
        """Ask for a file and export the log to it, saying how it went."""
        path = self.ask_export_path()
        if not path:
            return
        try:
            count = self.export(path)
        except OSError as exc:
            log.warning("export to %s failed: %s", path, exc)
            self.show_error(f"export failed: {exc}")
        else:
            self.show_error("")
            self.append_note(f"exported {count} lines to {path}")

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
