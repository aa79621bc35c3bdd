"""Watching the system's serial ports, so the connection bar notices ports coming and going."""

from __future__ import annotations

import logging

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

log = logging.getLogger(__name__)

REFRESH_MS = 2000


def list_serial_ports() -> list[tuple[str, str]]:
    """(device, description) of every serial port the system reports; opens none of them."""
    from serial.tools import list_ports  # when first listed, after the window has painted

    ports = []
    for info in sorted(list_ports.comports(), key=lambda p: p.device):
        description = info.description
        if description in ("", "n/a"):
            description = QCoreApplication.translate("PortWatcher", "serial port")
        ports.append((info.device, description))
    return ports


class PortWatcher(QObject):
    """Lists ports every REFRESH_MS; emits `ports_changed` when the list differs, and on refresh."""

    ports_changed = Signal(list)
    port_added = Signal(str)
    port_removed = Signal(str)

    def __init__(self, parent: QObject | None = None, list_now: bool = True) -> None:
        """`list_now`: list the ports as soon as the event loop runs (else at the first
        `refresh()` or timer tick)."""
        super().__init__(parent)
        self._known: list[tuple[str, str]] | None = None
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self._check)
        self._timer.start()
        if list_now:
            QTimer.singleShot(0, self, self.refresh)

    def refresh(self) -> None:
        """List the ports now and always emit the list."""
        self._known = None
        self._check()

    def stop(self) -> None:
        """Stop watching."""
        self._timer.stop()

    def _check(self) -> None:
        try:
            ports = list_serial_ports()
        except OSError as exc:
            log.warning("listing serial ports failed: %s", exc)
            return
        if ports == self._known:
            return
        if self._known is not None:
            before = {p for p, _ in self._known}
            after = {p for p, _ in ports}
            for port in sorted(after - before):
                self.port_added.emit(port)
            for port in sorted(before - after):
                self.port_removed.emit(port)
        self._known = ports
        self.ports_changed.emit(ports)
