"""The work zero of the connected device: kept per device in the settings, set from the readout's
Zero buttons, shown by the readout and used by the coordinate entry; Set Home keeps it in place."""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import Any

from PySide6.QtCore import QObject

from app.common.messages import localized
from app.common.settings import device_key
from drivers.device.work_zero import WorkZero, format_work_zero, parse_work_zero
from drivers.errors import BadInput
from widgets._i18n import fill
from widgets.coordinate_entry import CoordinateEntry
from widgets.position_readout import PositionReadout

log = logging.getLogger(__name__)

Point = tuple[float, float, float]


class WorkFrame(QObject):
    """Owns the work zero; `say(text)` tells the operator what changed."""

    def __init__(
        self,
        settings: Any,
        readout: PositionReadout,
        entry: CoordinateEntry,
        say: Callable[[str], None],
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self.settings = settings
        self.readout = readout
        self.entry = entry
        self.say = say
        self.zero = WorkZero()
        self.key: str | None = None
        self.position: Point | None = None
        readout.zero_requested.connect(self.zero_axes)
        readout.clear_zero_requested.connect(self.clear)

    def device_ready(self, protocol: str, port: str) -> None:
        """Use the zero kept for this device (a malformed kept value: none, logged)."""
        self.key = f"{device_key(protocol, port)}/work_zero"
        text = self.settings.value(self.key)
        zero = WorkZero()
        if isinstance(text, str) and text:
            try:
                zero = parse_work_zero(text)
            except BadInput as exc:
                log.warning("the kept work zero is unreadable and was left out: %s", exc)
        self._set(zero, save=False)
        if not zero.is_machine():
            self.say(fill(self.tr("work coordinates: %1"), localized(zero.describe())))

    def set_position(self, position: Point | None) -> None:
        """The stage's machine position as last known (None: unknown); Zero needs one."""
        self.position = position
        self.readout.set_zero_enabled(position is not None and self.key is not None)

    def zero_axes(self, axes: str) -> None:
        """Make the current position the work zero on these axes ("x", "xyz")."""
        if self.position is None or self.key is None:
            self.say(self.tr("work zero not set: the position is unknown"))
            return
        self._set(self.zero.zeroed(axes, self.position))
        shown = ", ".join(
            f"{a.upper()} {self.readout.number_text(self.position['xyz'.index(a)])}" for a in axes
        )
        self.say(fill(self.tr("work zero set at %1 %2 (machine)"), shown, self.readout.units()))

    def clear(self) -> None:
        """Put the work zero back at the device's home."""
        self._set(WorkZero())
        self.say(self.tr("work zero cleared: work coordinates are machine coordinates"))

    def home_moved(self, old_home_at: Point) -> None:
        """Set Home made `old_home_at` (machine mm) the new origin: the zero stays in place."""
        if self.zero.is_machine():
            return
        self._set(self.zero.after_set_home(old_home_at))
        self.say(fill(self.tr("work zero kept in place: %1"), localized(self.zero.describe())))

    def disconnected(self) -> None:
        """No device: Zero is off until one is connected."""
        self.position = None
        self.readout.set_zero_enabled(False)

    def _set(self, zero: WorkZero, save: bool = True) -> None:
        self.zero = zero
        self.readout.set_work_zero(zero.point)
        self.entry.set_work_zero(zero.point)
        if save and self.key is not None:
            self.settings.setValue(self.key, format_work_zero(zero))
            self.settings.sync()
