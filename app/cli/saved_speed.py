"""motionctl and the speed of a device whose moves carry it (pi-frame, Firmata, laser-frame):
`speed V` sends nothing there, so it is kept per device and the moves of later runs use it."""

from __future__ import annotations

import logging

from PySide6.QtCore import QSettings

from app.common.settings import read_speed, write_speed
from drivers.errors import BadInput
from drivers.protocols.base import Protocol
from drivers.session.device_session import DeviceSession

log = logging.getLogger(__name__)


class SavedSpeed:
    """The speed kept for one device; inactive where the device itself keeps its speed."""

    def __init__(self, settings: QSettings, protocol: Protocol, port: str) -> None:
        self.settings, self.protocol, self.port = settings, protocol, port
        self.active = protocol.capabilities.speed_in_moves
        self.saved = read_speed(settings, protocol.name, port) if self.active else None

    def begin(self, session: DeviceSession) -> None:
        """The run's moves go at the speed kept (one outside today's range is left unused)."""
        if self.saved is None:
            return
        try:
            session.speed(self.saved)  # nothing is sent: the speed goes with each move
        except BadInput as exc:
            log.info("the speed kept for this port is not used: %s", exc)
            self.saved = None

    def done(self, session: DeviceSession) -> None:
        """After a run that succeeded: keep the speed it set (`speed V`, a macro's step)."""
        if not self.active:
            return
        speed = session.speed()  # as set, else the one kept, else the default: nothing sent
        if speed != (self.saved if self.saved is not None else session.capabilities.default_speed):
            write_speed(self.settings, self.protocol.name, self.port, speed)
