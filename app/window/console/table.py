"""The console's table: the lines of a TrafficIndex that pass the filters, read on demand."""

from __future__ import annotations

import math
import re
import time
from datetime import datetime
from operator import methodcaller

import numpy as np
from PySide6.QtCore import (
    QT_TRANSLATE_NOOP,
    QAbstractTableModel,
    QCoreApplication,
    QModelIndex,
    QObject,
    QPersistentModelIndex,
    QRect,
    Qt,
)
from PySide6.QtGui import (
    QBrush,
    QColor,
    QFont,
    QFontDatabase,
    QFontInfo,
    QFontMetrics,
    QPainter,
    QPaintEvent,
    QPalette,
)
from PySide6.QtWidgets import QHeaderView, QStyle, QTableView

from drivers.traffic.index import TrafficIndex
from drivers.traffic.lines import TrafficLine, escape
from widgets._i18n import fill
from widgets.table_columns import FittedColumns

TEXT, HEX, MIXED = "text", "hex", "mixed"
DISPLAY_MODES = (TEXT, HEX, MIXED)
RELATIVE, ABSOLUTE, DELTA = "relative", "absolute", "delta"
TIME_MODES = (RELATIVE, ABSOLUTE, DELTA)
COLUMNS = (  # the headers, translated at use (TrafficModel context)
    QT_TRANSLATE_NOOP("TrafficModel", "Line"),
    QT_TRANSLATE_NOOP("TrafficModel", "Time"),
    QT_TRANSLATE_NOOP("TrafficModel", "Dir"),
    QT_TRANSLATE_NOOP("TrafficModel", "Bytes"),
    QT_TRANSLATE_NOOP("TrafficModel", "Meaning"),
    QT_TRANSLATE_NOOP("TrafficModel", "Reply"),
)
CSV_COLUMNS = (
    "line", "time_s", "direction", "kind", "hex", "text", "meaning", "pair", "latency_ms",
    "first_copy", "time_iso",
)  # fmt: skip
LINE, TIME, DIRECTION, BYTES, MEANING, REPLY = range(len(COLUMNS))
REPLY_CHARS = 20  # "↩ #123456 1234.5 ms"
LEAST_CHARS = 16  # Bytes and Meaning never narrower (the console scrolls sideways instead)
KIND_NAMES = {  # the kinds' names shown (RawConsole context); the keys stay as they are
    "motion": QT_TRANSLATE_NOOP("RawConsole", "motion"),
    "query": QT_TRANSLATE_NOOP("RawConsole", "query"),
    "poll": QT_TRANSLATE_NOOP("RawConsole", "poll"),
    "setting": QT_TRANSLATE_NOOP("RawConsole", "setting"),
    "error": QT_TRANSLATE_NOOP("RawConsole", "error"),
    "debug": QT_TRANSLATE_NOOP("RawConsole", "debug"),
    "note": QT_TRANSLATE_NOOP("RawConsole", "note"),
}
SHOWN_BYTES = 96  # bytes shown in a cell; the tooltip and the export have them all
COLOURS = {"tx": "#1565c0", "rx": "#2e7d32", "": "#757575"}
ERROR_BACKGROUND = QColor("#ffd7d7")
MATCH_BACKGROUND = QColor("#fff59d")
_MIXED_TABLE = {b: chr(b) if 0x20 <= b < 0x7F else f"<{b:02X}>" for b in range(256)}
# str.translate by another name: the translation checks take .translate() for Qt's
_to_mixed = methodcaller("translate", _MIXED_TABLE)
Index = QModelIndex | QPersistentModelIndex
_DISPLAY = Qt.ItemDataRole.DisplayRole.value
_TOOLTIP = Qt.ItemDataRole.ToolTipRole.value
_FOREGROUND = Qt.ItemDataRole.ForegroundRole.value  # roles as ints: comparing enum members
_BACKGROUND = Qt.ItemDataRole.BackgroundRole.value  # costs more than the rest of a call
_FONT = Qt.ItemDataRole.FontRole.value


def shown_bytes(data: bytes, mode: str) -> str:
    """Bytes as text (escapes), hex (`47 45 54`) or mixed (printable as is, others `<0A>`)."""
    if mode == HEX:
        return data.hex(" ").upper()
    if mode == MIXED:
        return _to_mixed(data.decode("latin-1"))
    return escape(data)


ELLIPSIS = "…"
_UNITS = {  # what a shown byte is in each mode (the cell's "…" of bytes not shown is one too)
    HEX: re.compile(r"[0-9A-F]{2} ?|…"),
    MIXED: re.compile(r"<[0-9A-F]{2}>|.", re.DOTALL),
    TEXT: re.compile(r"\\x[0-9A-Fa-f]{2}|\\.|.", re.DOTALL),
}


def byte_units(text: str, mode: str) -> list[str]:
    """The shown bytes `text` (as shown_bytes gives them) cut into one piece a byte."""
    return _UNITS[mode].findall(text)


def elide_bytes(text: str, mode: str, room: int) -> str:
    """`text` (shown bytes) in at most `room` characters: cut between two bytes, never inside
    one (`41 42 …`, not `41 4`), with "…" where bytes are left out."""
    if len(text) <= room:
        return text
    kept, used = [], 0
    for unit in byte_units(text, mode):
        if used + len(unit) + len(ELLIPSIS) > room:
            break
        kept.append(unit)
        used += len(unit)
    return "".join(kept) + ELLIPSIS if room >= len(ELLIPSIS) else ""


def stamp(
    when: float, mode: str, origin: float, wall_offset: float | None, previous: float | None
) -> str:
    """A record time `when` as seconds since `origin`, as the wall-clock time (`when` plus
    `wall_offset`: the record clock's own times, not times since the origin), or as the gap
    since the record time `previous`."""
    if mode == ABSOLUTE and wall_offset is not None:
        return wall_text(when + wall_offset)
    if mode == DELTA:
        return "+0.000" if previous is None else f"+{when - previous:.3f}"
    return f"{when - origin:010.3f}"


def wall_text(wall: float) -> str:
    """A wall-clock time (epoch seconds) as local `HH:MM:SS.mmm`."""
    return time.strftime("%H:%M:%S", time.localtime(wall)) + f".{int(wall * 1000) % 1000:03d}"


def iso_text(wall: float) -> str:
    """A wall-clock time (epoch seconds) as local ISO 8601 with milliseconds and the offset."""
    return datetime.fromtimestamp(wall).astimezone().isoformat(timespec="milliseconds")


def reply_text(line: TrafficLine) -> str:
    """The pairing in words: `→ #12`, `↩ #11  3.2 ms`, `↻ copy of #9`."""
    return pairing_text(line.direction, line.pair, line.latency_ms, line.first_copy)


def pairing_text(direction: str, pair: int, latency_ms: float, first_copy: int) -> str:
    """As reply_text, from the fields (TrafficIndex.pairing)."""
    parts = []
    if first_copy >= 0:
        parts.append(f"↻ copy of #{first_copy}")
    if pair >= 0:
        if direction == "tx":
            parts.append(f"→ #{pair}")
        elif not math.isnan(latency_ms):
            parts.append(f"↩ #{pair}  {latency_ms:.1f} ms")
        else:
            parts.append(f"↩ #{pair}")
    return "  ".join(parts)


# What a row shows but its reply, built once: (cells' text, direction, background, italic).
# A plain tuple of strings and numbers: the garbage collector stops tracking those, so a
# screenful kept for each repaint adds nothing to its full collections.
RowView = tuple[tuple[str, ...], str, int, bool]
CELLS, ROW_DIRECTION, ROW_BACKGROUND, ROW_ITALIC = range(4)
BACKGROUNDS = (None, MATCH_BACKGROUND, ERROR_BACKGROUND)  # ROW_BACKGROUND's codes


class TrafficModel(QAbstractTableModel):
    """Rows are line numbers of the index (numpy array); cells are read from the spool."""

    def __init__(self, index: TrafficIndex, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.index_ = index
        self._rows = np.zeros(1024, dtype=np.int64)  # grown by half again when full
        self._count = 0
        self.mode = TEXT
        self.time_mode = RELATIVE
        self.origin = 0.0
        self.matches = np.zeros(0, dtype=np.int64)  # search hits (line numbers), sorted
        self._views: dict[int, RowView] = {}  # row → what it shows, while rows and modes stay
        self._italic = QFont()
        self._italic.setItalic(True)
        self.colours = {d: QColor(c) for d, c in COLOURS.items()}  # by direction
        self._brushes = {d: QBrush(c) for d, c in self.colours.items()}

    # -- rows ------------------------------------------------------------------------------

    @property
    def rows(self) -> np.ndarray:
        """The line numbers shown, in order (a view: do not keep it past a change)."""
        return self._rows[: self._count]

    def set_index(self, index: TrafficIndex) -> None:
        """Show another session's lines (none selected yet)."""
        self._views.clear()
        self.beginResetModel()
        self.index_ = index
        self._count = 0
        self.matches = np.zeros(0, dtype=np.int64)
        self.endResetModel()

    def set_rows(self, rows: np.ndarray) -> None:
        """Show these lines (a new filter)."""
        self._views.clear()
        self.beginResetModel()
        self._rows = np.array(rows, dtype=np.int64)
        self._count = len(rows)
        self.endResetModel()

    def append_rows(self, rows: np.ndarray) -> None:
        """Show more lines at the end (new traffic that passes the filter)."""
        if not len(rows):
            return
        first, end = self._count, self._count + len(rows)
        if end > len(self._rows):
            grown = np.empty(max(end, len(self._rows) * 3 // 2), dtype=np.int64)
            grown[:first] = self._rows[:first]
            self._rows = grown
        self.beginInsertRows(QModelIndex(), first, end - 1)
        self._rows[first:end] = rows
        self._count = end
        self.endInsertRows()

    def drop_before(self, line: int) -> int:
        """Stop showing the lines before `line` (dropped by the index); returns the rows gone.
        Rows are removed, not reset: the view keeps its selection and current row on the rows
        that stay."""
        self.matches = self.matches[int(np.searchsorted(self.matches, line)) :]
        gone = int(np.searchsorted(self.rows, line))
        if not gone:
            return 0
        self.beginRemoveRows(QModelIndex(), 0, gone - 1)
        count = self._count
        self._rows[: count - gone] = self._rows[gone:count]  # (numpy copies overlaps safely)
        self._count = count - gone
        self._views.clear()
        self.endRemoveRows()
        return gone

    def set_matches(self, matches: np.ndarray) -> None:
        """Highlight these lines (the search's hits)."""
        self.matches = matches
        self._views.clear()
        if self._count:
            self.dataChanged.emit(self.index(0, 0), self.index(self._count - 1, REPLY - 1))

    def shown_matches(self) -> int:
        """How many of the search's hits are shown (the others are in lines the filters hide)."""
        rows, matches = self.rows, self.matches
        if not len(rows) or not len(matches):
            return 0
        at = np.minimum(np.searchsorted(rows, matches), len(rows) - 1)
        return int(np.count_nonzero(rows[at] == matches))

    def add_matches(self, matches: np.ndarray) -> None:
        """Highlight these lines too (hits among new lines, after every line shown so far)."""
        if len(matches):
            self.matches = np.concatenate((self.matches, matches))

    def refresh(self) -> None:
        """Repaint every cell (a display or time mode changed)."""
        self._views.clear()
        if self._count:
            self.dataChanged.emit(self.index(0, 0), self.index(self._count - 1, REPLY))

    def line_at(self, row: int) -> TrafficLine:
        """The line shown at `row`."""
        return self.index_.line(int(self._rows[row]))

    def row_of(self, line: int) -> int:
        """The row showing `line`, or the nearest row after it (len(rows) if none)."""
        return int(np.searchsorted(self.rows, line))

    # -- Qt --------------------------------------------------------------------------------

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Lines shown."""
        return 0 if parent.isValid() else self._count

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Line, time, direction, bytes, meaning, reply."""
        return 0 if parent.isValid() else len(COLUMNS)

    def headerData(self, section: int, orientation: Qt.Orientation, role: int = 0) -> object:
        """Column titles."""
        if orientation == Qt.Orientation.Horizontal and role == Qt.ItemDataRole.DisplayRole:
            return self.tr(COLUMNS[section])
        return None

    def row_view(self, row: int) -> RowView:
        """What `row` shows but its reply (remembered until the rows or the modes change)."""
        view = self._views.get(row)
        if view is not None:
            return view
        if len(self._views) > 4096:
            self._views.clear()
        number, when, direction, kind, data, meaning, *_ = self.index_.read(int(self._rows[row]))
        if self.time_mode == DELTA:
            previous = self.index_.time(int(self._rows[row - 1])) if row > 0 else None
        else:
            previous = None
        shown = shown_bytes(data[:SHOWN_BYTES], self.mode)
        cells = (
            str(number),
            stamp(when, self.time_mode, self.origin, self.index_.wall_offset, previous),
            direction.upper() or "--",
            shown + ("…" if len(data) > SHOWN_BYTES else ""),
            meaning,
        )
        hit = np.searchsorted(self.matches, number)
        matched = hit < len(self.matches) and self.matches[hit] == number
        background = 1 if matched else 2 if kind == "error" else 0
        view = self._views[row] = (cells, direction, background, kind in ("note", "debug"))
        return view

    def reply(self, row: int) -> str:
        """The reply cell's text (read each time: a request's reply may come later)."""
        return pairing_text(*self.index_.pairing(int(self._rows[row])))

    def cell(self, row: int, column: int) -> str:
        """A cell's text."""
        if column == REPLY:
            return self.reply(row)
        return self.row_view(row)[CELLS][column]

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
        line, wall_offset = self.line_at(row), self.index_.wall_offset
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
            "" if wall_offset is None else iso_text(line.time + wall_offset),
        ]

    def tooltip(self, row: int) -> str:
        """Everything about a line: kind, hex, text, meaning, pairing."""
        line = self.line_at(row)
        name = KIND_NAMES.get(line.kind, line.kind)
        kind = QCoreApplication.translate("RawConsole", name)
        lines = [fill(self.tr("line %1: %2"), line.number, kind)]
        if line.data:
            lines += [
                fill(self.tr("hex: %1"), line.data.hex(" ").upper()),
                fill(self.tr("text: %1"), escape(line.data)),
            ]
        if line.meaning:
            lines.append(line.meaning)
        if reply_text(line):
            lines.append(fill(self.tr("%1 (double-click to go there)"), reply_text(line)))
        return "\n".join(lines)

    def data(self, index: Index, role: int = _DISPLAY) -> object:
        """Text, colours and tooltips of a cell (the console's view paints from `row_view`;
        this serves tests, tooltips and accessibility)."""
        if role == _DISPLAY:
            return self.cell(index.row(), index.column())
        if role == _FOREGROUND:
            return self._brushes[self.row_view(index.row())[ROW_DIRECTION]]
        if role == _BACKGROUND:
            return BACKGROUNDS[self.row_view(index.row())[ROW_BACKGROUND]]
        if role == _FONT:
            return self._italic if self.row_view(index.row())[ROW_ITALIC] else None
        if role == _TOOLTIP:
            return self.tooltip(index.row())
        return None


class TrafficView(QTableView):
    """The console's table. It paints the rows on screen itself, from the model's RowView of
    each (colours, italics, the reply): a few Python calls a row instead of a delegate and
    some five data() calls a cell, and Qt's plain text drawing instead of the item view's
    layout of each cell. Rows are one fixed height (the vertical header's default size)."""

    def __init__(self, model: TrafficModel) -> None:
        super().__init__()
        self.setModel(model)
        self._model = model
        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        font.setStyleStrategy(QFont.StyleStrategy.PreferNoShaping)  # Latin text: no shaping
        self.setFont(font)
        self.setWordWrap(False)
        self.setShowGrid(False)
        rows = self.verticalHeader()
        rows.setVisible(False)
        rows.setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
        rows.setDefaultSectionSize(self.fontMetrics().height() + 4)
        # The Reply ("↩ #1234 12.3 ms") as wide as it needs; Bytes and Meaning share the rest,
        # not the Reply, mostly empty, as the last section stretched did.
        digit = self.fontMetrics().horizontalAdvance("0")
        self.horizontalHeader().resizeSection(REPLY, digit * REPLY_CHARS + 12)
        self.columns = FittedColumns(self, (), {BYTES: 1.0, MEANING: 1.0}, digit * LEAST_CHARS)

    def fit_bytes(
        self, text: str, room: int, metrics: QFontMetrics | None = None, fixed: bool | None = None
    ) -> str:
        """A bytes cell's text as it fits in `room` pixels: whole, or cut between two bytes
        with "…" (the tooltip has them all); `fixed`: whether the font is fixed-pitch."""
        metrics = metrics or self.fontMetrics()
        mode = self._model.mode
        if fixed is None:
            fixed = QFontInfo(self.font()).fixedPitch()
        if fixed:
            return elide_bytes(text, mode, room // max(metrics.horizontalAdvance("0"), 1))
        if metrics.horizontalAdvance(text) <= room:
            return text
        kept, used = [], metrics.horizontalAdvance(ELLIPSIS)
        for unit in byte_units(text, mode):
            used += metrics.horizontalAdvance(unit)
            if used > room:
                break
            kept.append(unit)
        return "".join(kept) + ELLIPSIS

    def _selected(self, first: int, last: int) -> set[int]:
        """Rows first..last that are selected."""
        chosen: set[int] = set()
        for span in self.selectionModel().selection():
            chosen.update(range(max(span.top(), first), min(span.bottom(), last) + 1))
        return chosen

    def paintEvent(self, event: QPaintEvent) -> None:
        """Paint the rows in the exposed rectangle: backgrounds, then each column's text."""
        model = self._model
        count = model.rowCount()
        area = event.rect()
        height = self.verticalHeader().defaultSectionSize()
        offset = self.verticalOffset()
        first = max(0, (area.top() + offset) // height)
        last = min(count - 1, (area.bottom() + offset) // height)
        if first > last:
            return
        views = [model.row_view(row) for row in range(first, last + 1)]
        top = first * height - offset
        selected = self._selected(first, last)
        palette = self.palette()
        group = QPalette.ColorGroup.Active if self.hasFocus() else QPalette.ColorGroup.Inactive
        highlight = palette.brush(group, QPalette.ColorRole.Highlight)
        highlighted = palette.color(group, QPalette.ColorRole.HighlightedText)
        width = self.viewport().width()
        painter = QPainter(self.viewport())
        y = top
        for row, (_, _, background, _) in enumerate(views, first):
            if row in selected:
                painter.fillRect(0, y, width, height, highlight)
            elif background:
                painter.fillRect(0, y, width, height, BACKGROUNDS[background])
            y += height
        plain = self.font()
        italic = QFont(plain)
        italic.setItalic(True)
        metrics = self.fontMetrics()
        baseline = top + (height - metrics.height()) // 2 + metrics.ascent()
        margin = self.style().pixelMetric(QStyle.PixelMetric.PM_FocusFrameHMargin, None, self) + 1
        colours = model.colours
        fixed = QFontInfo(plain).fixedPitch()
        for column in range(len(COLUMNS)):
            if self.isColumnHidden(column):
                continue
            x = self.columnViewportPosition(column)
            room = self.columnWidth(column) - 2 * margin
            clip = QRect(x + margin, area.top(), room, area.height())
            clip &= area
            if clip.isEmpty():
                continue
            painter.setClipRect(clip)
            shown_italic = None
            colour = None
            y = baseline
            for row, (cells, direction, _, slanted) in enumerate(views, first):
                text = cells[column] if column != REPLY else model.reply(row)
                if column == BYTES:
                    text = self.fit_bytes(text, room, metrics, fixed)
                elif column >= MEANING and text:  # cut with "…" (the tooltip has it whole)
                    text = metrics.elidedText(text, Qt.TextElideMode.ElideRight, room)
                if text:
                    if slanted is not shown_italic:
                        shown_italic = slanted
                        painter.setFont(italic if slanted else plain)
                    wanted = highlighted if row in selected else colours[direction]
                    if wanted is not colour:
                        colour = wanted
                        painter.setPen(colour)
                    painter.drawText(x + margin, y, text)
                y += height
        painter.end()
