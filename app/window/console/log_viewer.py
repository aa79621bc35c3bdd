"""File → Open log: a traffic log (ours or a pyserial spy:// capture) browsed decoded, offline.

Decoded by the protocol chosen, else by the one the log's note names, else by the one its
traffic reads as (drivers/traffic/log_origin.py); a simulator's record is shown as the host saw it.

The file is read and decoded in a background thread (no Qt there); the window gets the finished
index through a queued signal and shows it in a console with every filter, and a timeline. A log
may be hundreds of MiB: it is read a chunk at a time and its records go straight to the index
(a few dozen bytes a line in memory); the reader's checks and limits are drivers/files.py's.
"""

from __future__ import annotations

import logging
import threading
from itertools import chain, islice
from pathlib import Path

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Qt, Signal, Slot
from PySide6.QtGui import QCloseEvent, QKeySequence, QShortcut
from PySide6.QtWidgets import (
    QComboBox,
    QFileDialog,
    QHBoxLayout,
    QLabel,
    QMainWindow,
    QPushButton,
    QSplitter,
    QVBoxLayout,
    QWidget,
)

from app.common.messages import localized
from app.window.console.feed import TimelineFeed
from app.window.console.traffic_console import RawConsole, localized_index
from app.window.layout.screen_fit import fit_new_window
from drivers.errors import MotionError
from drivers.protocols.registry import create_protocol, protocol_names
from drivers.traffic.decoding import PartProtocols, connection_protocol
from drivers.traffic.index import TrafficIndex
from drivers.traffic.log_origin import DEVICE_SIDE, host_view, origin_of
from drivers.traffic.log_reader import LogRecord, open_any_log
from widgets._i18n import fill
from widgets.traffic_timeline import TrafficTimeline

log = logging.getLogger(__name__)

RAW = QT_TRANSLATE_NOOP("LogViewer", "(undecoded)")  # the key; shown translated
LOOKAHEAD = 10_000  # records searched for the connection note (a session log's second line)
BATCH = 65_536  # records handed to the index at a time


def detect_protocol(records: list[LogRecord]) -> tuple[str, str] | None:
    """(protocol, variant) named by a log's first connection note, e.g. `connected to …
    (coxiris, …)`."""
    for record in records:
        if record.note:
            named = connection_protocol(record.note)
            if named is not None:
                return named
    return None


def ask_open_path(parent: QWidget) -> str:
    """Ask for a log file; "" when cancelled."""
    path, _ = QFileDialog.getOpenFileName(
        parent,
        QCoreApplication.translate("LogViewer", "Open traffic log"),
        "",
        QCoreApplication.translate("LogViewer", "Logs (*.log *.txt);;All files (*)"),
    )
    return path


class LogViewer(QMainWindow):
    """A log's frames, decoded by the protocol chosen (or named in the log), with every filter."""

    _loaded = Signal(object)  # (path, format, protocol, variant, index) or an error message

    def __init__(self, parent: QWidget | None = None, protocol: str = "") -> None:
        super().__init__(parent)
        self.setObjectName("logViewer")
        self.setWindowTitle(self.tr("Traffic log"))
        self.path: Path | None = None
        self._default_protocol = protocol
        self._busy = False
        self.protocol_combo = QComboBox()
        self.protocol_combo.setObjectName("logViewerProtocol")
        self.protocol_combo.addItem(self.tr(RAW), RAW)
        for name in protocol_names():
            self.protocol_combo.addItem(name, name)
        self.protocol_combo.setToolTip(
            self.tr(
                "Decode with this protocol (chosen from the log's connection note when it has one)"
            )
        )
        self.protocol_combo.activated.connect(self._protocol_chosen)
        open_button = QPushButton(self.tr("Open…"))
        open_button.setObjectName("logViewerOpen")
        open_button.setToolTip(self.tr("Open a Motion Panel log or a pyserial spy:// capture"))
        open_button.clicked.connect(self.open_interactively)
        self.status = QLabel(self.tr("no log open"))
        self.status.setObjectName("logViewerStatus")
        self.status.setWordWrap(True)
        # Closed from the window itself too: without a window manager there is no title bar.
        close_button = QPushButton(self.tr("Close"))
        close_button.setObjectName("logViewerClose")
        close_button.setToolTip(self.tr("Close this log's window (Ctrl+W, Esc)"))
        close_button.clicked.connect(self.close)
        keys = [QKeySequence("Ctrl+W"), QKeySequence(Qt.Key.Key_Escape)]
        standard = QKeySequence.keyBindings(QKeySequence.StandardKey.Close)  # Ctrl+F4 …
        keys += [k for k in standard if k not in keys]
        self.close_shortcuts = [QShortcut(k, self, self.close) for k in keys]
        top = QHBoxLayout()
        top.addWidget(QLabel(self.tr("Protocol:")))
        top.addWidget(self.protocol_combo)
        top.addWidget(open_button)
        top.addWidget(self.status, 1)
        top.addWidget(close_button)
        self.console = RawConsole(self, sending=False)
        self.timeline = TrafficTimeline(self)
        self.feed = TimelineFeed(self.console, self.timeline)
        splitter = QSplitter(Qt.Orientation.Vertical)
        splitter.addWidget(self.console)
        splitter.addWidget(self.timeline)
        splitter.setSizes([600, 250])
        body = QWidget()
        layout = QVBoxLayout(body)
        layout.addLayout(top)
        layout.addWidget(splitter, 1)
        self.setCentralWidget(body)
        self.ask_path = lambda: ask_open_path(self)
        self._loaded.connect(self._on_loaded)
        fit_new_window(self, 1200, 800)  # or what the screen has room for

    def open_interactively(self) -> None:
        """Ask for a file and open it."""
        path = self.ask_path()
        if path:
            self.open(path)

    def open(self, path: str | Path, protocol: str | None = None) -> None:
        """Read and decode `path` in the background (protocol None: the log's own, else chosen)."""
        self.path = Path(path)
        self._busy = True
        self._show(fill(self.tr("reading %1…"), self.path.name), error=False)
        chosen = protocol if protocol is not None else None
        threading.Thread(
            target=self._read, args=(self.path, chosen), name="log-reader", daemon=True
        ).start()

    def busy(self) -> bool:
        """Whether a log is being read."""
        return self._busy

    def _read(self, path: Path, chosen: str | None) -> None:
        """In the reader thread: the records, the protocol, the decoded index (no Qt here)."""
        index: TrafficIndex | None = None
        try:
            kind, read = open_any_log(path)
            batch = list(islice(read, LOOKAHEAD))
            given = create_protocol(chosen) if chosen not in (None, RAW) else None
            origin = origin_of(batch, given) if chosen != RAW else None
            name, variant = (chosen, "") if chosen is not None else (self._default_protocol, "")
            if chosen is None and origin is not None:  # named by its note, or its traffic's
                name, variant = origin.protocol, origin.variant
            flipped = any(r.note and DEVICE_SIDE in r.note for r in batch)  # a simulator's
            records = host_view(chain(batch, read))
            batch = list(islice(records, LOOKAHEAD))
            protocol = create_protocol(name, variant or None) if name and name != RAW else None
            index = localized_index(protocol)
            parts = PartProtocols(protocol)
            follow = chosen != RAW  # undecoded when chosen so; else each part by its note's
            while batch:
                start = 0
                for at, record in enumerate(batch):
                    if follow and record.note and parts.follow(record):
                        index.add_records(batch[start:at])
                        index.set_protocol(parts.current)
                        start = at
                index.add_records(batch[start:] if start else batch)
                batch = list(islice(records, BATCH))
        except (MotionError, LookupError, OSError) as exc:
            if index is not None:
                index.close()
            self._loaded.emit(localized(exc))
            return
        used = ", ".join(f"{n} {v}".strip() for n, v in parts.used)
        how = origin.how if origin is not None and chosen is None else ""
        self._loaded.emit((path, kind, name or RAW, used, index, how, flipped))

    @Slot(object)
    def _on_loaded(self, result: object) -> None:
        self._busy = False
        if isinstance(result, str):
            self._show(result, error=True)
            return
        path, kind, name, used, index, how, flipped = result
        found = self.protocol_combo.findData(name or RAW)
        if found >= 0:
            self.protocol_combo.setCurrentIndex(found)
        self.console.load(index)
        self.setWindowTitle(fill(self.tr("%1 — traffic log"), path.name))
        shown = used or self.tr(RAW)
        text = fill(
            self.tr("%1 (%2): %3 lines, decoded as %4"), path, kind, f"{len(index):,}", shown
        )
        if how == "recognised":
            text += self.tr(", recognised from its traffic (the log names no protocol)")
        if flipped:
            text += self.tr("; a simulator's record: TX and RX shown as the host saw them")
        self._show(text, error=False)

    def _protocol_chosen(self) -> None:
        if self.path is not None:
            self.open(self.path, str(self.protocol_combo.currentData()))

    def _show(self, text: str, error: bool) -> None:
        self.status.setText(text)
        self.status.setStyleSheet("color: #c62828;" if error else "")

    def closeEvent(self, event: QCloseEvent) -> None:
        """Release the log's spool."""
        self.console.index.close()
        super().closeEvent(event)

    def status_text(self) -> str:
        """What the window says about the log (or the error)."""
        return self.status.text()
