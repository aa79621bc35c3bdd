"""The window's bridge mode: a Bridge in a thread of its own, its traffic handed to the GUI.

The tap runs in the bridge's thread: it writes the session log (before the bytes go on) and
queues the record; a timer in the GUI thread takes the queue to the console, and reads it with
the protocol's decoders for the positions it tells (`observed`: a reply that reports the
position, the target of a move the other program sent). The end of the bridge (stopped, or the
device gone) reaches the GUI as a queued signal.
"""

from __future__ import annotations

import logging
import threading
from collections import deque
from pathlib import Path

from PySide6.QtCore import QObject, QTimer, Signal, Slot

from app.common.messages import localized
from drivers.bridge.snoop import Bridge
from drivers.bridge.watch import BridgeWatch
from drivers.errors import MotionError
from drivers.link.records import Traffic, TrafficLogWriter
from drivers.protocols.base import Protocol
from widgets._i18n import fill

log = logging.getLogger(__name__)

DRAIN_INTERVAL_MS = 20


class BridgeSession(QObject):
    """One bridge between a device's port and a pty, for the life of the bridge mode."""

    traffic = Signal(object)  # list[Traffic], in the GUI thread
    observed = Signal(object)  # drivers.bridge.watch.Observed, the last a drain found
    ended = Signal(str)  # "" when stopped, else what went wrong

    def __init__(
        self,
        device: str,
        baud: int,
        log_path: Path | None = None,
        log_start: float | None = None,
        parent: QObject | None = None,
        *,
        protocol: Protocol | None = None,
    ) -> None:
        super().__init__(parent)
        self._queue: deque[Traffic] = deque()
        self._protocol = protocol  # named in the log's bridge note
        self.watch = BridgeWatch(protocol) if protocol is not None else None
        self._log = None
        if log_path is not None:
            self._log = TrafficLogWriter(log_path.open("a", encoding="utf-8"), log_start)
        self.bridge = Bridge(device, baud, self._tap, protocol=protocol)
        self._thread: threading.Thread | None = None
        self._timer = QTimer(self)
        self._timer.setInterval(DRAIN_INTERVAL_MS)
        self._timer.timeout.connect(self.drain)
        self._stopped = False
        self._done.connect(self._on_done)

    _done = Signal(str, str)  # (for the log, for the operator), from the bridge's thread; queued

    def start(self) -> str:
        """Open the device and the pty, start forwarding; the pty's path (PortError if not)."""
        self.bridge.open()
        if self._log is not None:
            named = f" ({self._protocol.name})" if self._protocol is not None else ""
            self._log.note(f"bridge {self.bridge.device} <-> {self.bridge.path}{named}")
        self._thread = threading.Thread(target=self._serve, name="bridge", daemon=True)
        self._thread.start()
        self._timer.start()
        return self.bridge.path

    def _tap(self, record: Traffic) -> None:
        """In the bridge's thread: log, then queue for the GUI."""
        if self._log is not None:
            self._log(record)
        self._queue.append(record)

    def _serve(self) -> None:
        """In the bridge's thread: forward until stopped, close the ports, say how it ended."""
        error = shown = ""
        try:
            self.bridge.serve_forever()
        except MotionError as exc:
            error, shown = str(exc), localized(exc)  # the log keeps English
        except Exception as exc:  # the thread's last word must reach the window
            log.exception("the bridge failed")
            error = f"the bridge failed: {exc}"  # the log's words stay English
            shown = fill(self.tr("the bridge failed: %1"), localized(exc))
        finally:
            self.bridge.close()
        self._done.emit(error, shown)

    @Slot()
    def drain(self) -> None:
        """Hand the records queued since the last look to `traffic` (GUI thread)."""
        records = []
        while self._queue:
            records.append(self._queue.popleft())
        if records:
            self.traffic.emit(records)
            self._observe(records)

    def _observe(self, records: list[Traffic]) -> None:
        """The last position the records tell, to `observed` (GUI thread)."""
        watch, last = self.watch, None
        if watch is None:
            return
        for record in records:
            try:
                seen = watch.feed(record)
            except Exception:  # what the traffic says must never stop the bridge's display
                log.exception("reading the bridged traffic for positions failed")
                self.watch = None
                return
            if seen:
                last = seen[-1]
        if last is not None:
            self.observed.emit(last)

    def stop(self) -> None:
        """Stop forwarding; the bridge's thread closes the ports, then `ended("")` comes."""
        self._stopped = True
        self.bridge.stop()

    @Slot(str, str)
    def _on_done(self, error: str, shown: str) -> None:
        self._timer.stop()
        self.drain()
        if self._log is not None:
            self._log.note(f"bridge ended: {error}" if error else "bridge ended")
            self._log.stream.close()
            self._log = None
        self.ended.emit("" if self._stopped else shown or self.tr("the bridge stopped"))
