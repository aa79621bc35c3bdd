"""The console's table: the lines of a TrafficIndex that pass the filters, read on demand."""

from __future__ import annotations

import math
import time

import numpy as np
from PySide6.QtCore import QAbstractTableModel, QModelIndex, QObject, QPersistentModelIndex, Qt
from PySide6.QtGui import QBrush, QColor, QFont

from drivers.traffic_index import TrafficIndex, TrafficLine, escape

TEXT, HEX, MIXED = "text", "hex", "mixed"
DISPLAY_MODES = (TEXT, HEX, MIXED)
RELATIVE, ABSOLUTE, DELTA = "relative", "absolute", "delta"
TIME_MODES = (RELATIVE, ABSOLUTE, DELTA)
COLUMNS = ("Line", "Time", "Dir", "Bytes", "Meaning", "Reply")
CSV_COLUMNS = (
    "line", "time_s", "direction", "kind", "hex", "text", "meaning", "pair", "latency_ms",
    "first_copy",
)  # fmt: skip
LINE, TIME, DIRECTION, BYTES, MEANING, REPLY = range(len(COLUMNS))
SHOWN_BYTES = 96  # bytes shown in a cell; the tooltip and the export have them all
COLOURS = {"tx": "#1565c0", "rx": "#2e7d32", "": "#757575"}
ERROR_BACKGROUND = QColor("#ffd7d7")
MATCH_BACKGROUND = QColor("#fff59d")
_MIXED_TABLE = {b: chr(b) if 0x20 <= b < 0x7F else f"<{b:02X}>" for b in range(256)}
Index = QModelIndex | QPersistentModelIndex
_DISPLAY = Qt.ItemDataRole.DisplayRole.value
_TOOLTIP = Qt.ItemDataRole.ToolTipRole.value
_STYLE_SLOTS = {
    Qt.ItemDataRole.ForegroundRole.value: 0,
    Qt.ItemDataRole.BackgroundRole.value: 1,
    Qt.ItemDataRole.FontRole.value: 2,
}  # roles as ints: comparing enum members costs more than the rest of a call


def shown_bytes(data: bytes, mode: str) -> str:
    """Bytes as text (escapes), hex (`47 45 54`) or mixed (printable as is, others `<0A>`)."""
    if mode == HEX:
        return data.hex(" ").upper()
    if mode == MIXED:
        return data.decode("latin-1").translate(_MIXED_TABLE)
    return escape(data)


def stamp(seconds: float, mode: str, wall_offset: float | None, previous: float | None) -> str:
    """A time as seconds since the origin, a wall-clock time, or the gap since `previous`."""
    if mode == ABSOLUTE and wall_offset is not None:
        wall = seconds + wall_offset
        return time.strftime("%H:%M:%S", time.localtime(wall)) + f".{int(wall * 1000) % 1000:03d}"
    if mode == DELTA:
        return "+0.000" if previous is None else f"+{seconds - previous:.3f}"
    return f"{seconds:010.3f}"


def reply_text(line: TrafficLine) -> str:
    """The pairing in words: `→ #12`, `↩ #11  3.2 ms`, `↻ copy of #9`."""
    parts = []
    if line.first_copy >= 0:
        parts.append(f"↻ copy of #{line.first_copy}")
    if line.pair >= 0:
        if line.direction == "tx":
            parts.append(f"→ #{line.pair}")
        elif not math.isnan(line.latency_ms):
            parts.append(f"↩ #{line.pair}  {line.latency_ms:.1f} ms")
        else:
            parts.append(f"↩ #{line.pair}")
    return "  ".join(parts)


class TrafficModel(QAbstractTableModel):
    """Rows are line numbers of the index (numpy array); cells are read from the spool."""

    def __init__(self, index: TrafficIndex, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.index_ = index
        self.rows = np.zeros(0, dtype=np.int64)
        self.mode = TEXT
        self.time_mode = RELATIVE
        self.origin = 0.0
        self.matches = np.zeros(0, dtype=np.int64)  # search hits (line numbers), sorted
        self._cells: dict[tuple[int, int], str] = {}  # (row, column) → text, while rows stay
        self._styles: dict[int, tuple[QBrush, QColor | None, QFont | None]] = {}
        self._italic = QFont()
        self._italic.setItalic(True)
        self._brushes = {d: QBrush(QColor(c)) for d, c in COLOURS.items()}

    # -- rows ------------------------------------------------------------------------------

    def set_index(self, index: TrafficIndex) -> None:
        """Show another session's lines (none selected yet)."""
        self._cells.clear()
        self._styles.clear()
        self.beginResetModel()
        self.index_ = index
        self.rows = np.zeros(0, dtype=np.int64)
        self.matches = np.zeros(0, dtype=np.int64)
        self.endResetModel()

    def set_rows(self, rows: np.ndarray) -> None:
        """Show these lines (a new filter)."""
        self._cells.clear()
        self._styles.clear()
        self.beginResetModel()
        self.rows = rows
        self.endResetModel()

    def append_rows(self, rows: np.ndarray) -> None:
        """Show more lines at the end (new traffic that passes the filter)."""
        if not len(rows):
            return
        first = len(self.rows)
        self.beginInsertRows(QModelIndex(), first, first + len(rows) - 1)
        self.rows = np.concatenate((self.rows, rows))
        self.endInsertRows()

    def set_matches(self, matches: np.ndarray) -> None:
        """Highlight these lines (the search's hits)."""
        self.matches = matches
        self._styles.clear()
        if len(self.rows):
            self.dataChanged.emit(self.index(0, 0), self.index(len(self.rows) - 1, REPLY - 1))

    def refresh(self) -> None:
        """Repaint every cell (a display or time mode changed)."""
        self._cells.clear()
        self._styles.clear()
        if len(self.rows):
            self.dataChanged.emit(self.index(0, 0), self.index(len(self.rows) - 1, REPLY))

    def line_at(self, row: int) -> TrafficLine:
        """The line shown at `row`."""
        return self.index_.line(int(self.rows[row]))

    def row_of(self, line: int) -> int:
        """The row showing `line`, or the nearest row after it (len(rows) if none)."""
        return int(np.searchsorted(self.rows, line))

    # -- Qt --------------------------------------------------------------------------------

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Lines shown."""
        return 0 if parent.isValid() else len(self.rows)

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Line, time, direction, bytes, meaning, reply."""
        return 0 if parent.isValid() else len(COLUMNS)

    def headerData(self, section: int, orientation: Qt.Orientation, role: int = 0) -> object:
        """Column titles."""
        if orientation == Qt.Orientation.Horizontal and role == Qt.ItemDataRole.DisplayRole:
            return COLUMNS[section]
        return None

    def cell(self, row: int, column: int) -> str:
        """A cell's text (remembered until the rows or the modes change)."""
        if column == REPLY:
            return reply_text(self.line_at(row))  # a request's reply may come later
        key = (row, column)
        text = self._cells.get(key)
        if text is None:
            if len(self._cells) > 20_000:
                self._cells.clear()
                self._styles.clear()
            text = self._cells[key] = self._cell(row, column)
        return text

    def _cell(self, row: int, column: int) -> str:
        line = self.line_at(row)
        if column == LINE:
            return str(line.number)
        if column == TIME:
            previous = self.index_.time(int(self.rows[row - 1])) if row > 0 else None
            offset = self.index_.wall_offset
            return stamp(line.time - self.origin, self.time_mode, offset, previous)
        if column == DIRECTION:
            return line.direction.upper() or "--"
        if column == BYTES:
            shown = shown_bytes(line.data[:SHOWN_BYTES], self.mode)
            return shown + ("…" if len(line.data) > SHOWN_BYTES else "")
        if column == MEANING:
            return line.meaning
        return reply_text(line)

    def row_text(self, row: int, with_time: bool = True) -> str:
        """A shown line as text: `time DIR  bytes  meaning  [reply]`; the meaning is left out
        where it only repeats the bytes (a text protocol's line, the device's own text)."""
        line = self.line_at(row)
        if line.direction == "":
            text = "--  " + line.meaning
        else:
            text = f"{line.direction.upper()}  {shown_bytes(line.data, self.mode)}"
            plain = line.data.decode("latin-1").strip()
            if line.meaning and line.meaning != plain and line.kind != "debug":
                text += f"  {line.meaning}"
        reply = reply_text(line)
        if reply:
            text += f"  [{reply}]"
        return f"{self.cell(row, TIME)} {text}" if with_time else text

    def csv_row(self, row: int) -> list[object]:
        """A shown line's CSV fields, as CSV_COLUMNS names them."""
        line = self.line_at(row)
        return [
            line.number,
            f"{line.time - self.origin:.3f}",
            line.direction,
            line.kind,
            line.data.hex(" ").upper(),
            shown_bytes(line.data, TEXT),
            line.meaning,
            line.pair if line.pair >= 0 else "",
            "" if math.isnan(line.latency_ms) else f"{line.latency_ms:.1f}",
            line.first_copy if line.first_copy >= 0 else "",
        ]

    def _style(self, row: int) -> tuple[QBrush, QColor | None, QFont | None]:
        """A row's foreground, background and font (remembered with its cells)."""
        style = self._styles.get(row)
        if style is None:
            line = self.line_at(row)
            hit = np.searchsorted(self.matches, line.number)
            background = (
                MATCH_BACKGROUND
                if hit < len(self.matches) and self.matches[hit] == line.number
                else ERROR_BACKGROUND
                if line.kind == "error"
                else None
            )
            font = self._italic if line.kind in ("note", "debug") else None
            style = self._styles[row] = (self._brushes[line.direction], background, font)
        return style

    def tooltip(self, row: int) -> str:
        """Everything about a line: kind, hex, text, meaning, pairing."""
        line = self.line_at(row)
        lines = [f"line {line.number}: {line.kind}"]
        if line.data:
            lines += [f"hex: {line.data.hex(' ').upper()}", f"text: {escape(line.data)}"]
        if line.meaning:
            lines.append(line.meaning)
        if reply_text(line):
            lines.append(reply_text(line) + " (double-click to go there)")
        return "\n".join(lines)

    def data(self, index: Index, role: int = _DISPLAY) -> object:
        """Text, colours and tooltips of a cell (called hundreds of times a repaint: kept lean)."""
        if role == _DISPLAY:
            return self.cell(index.row(), index.column())
        slot = _STYLE_SLOTS.get(role)
        if slot is not None:
            return self._style(index.row())[slot]
        if role == _TOOLTIP:
            return self.tooltip(index.row())
        return None
