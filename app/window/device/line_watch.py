"""The port's modem lines as a worker follows them: read every CONTROL_POLL_S while idle, each
change an input made by itself told as a note, the whole set told to the window."""

from __future__ import annotations

import time
from collections.abc import Callable

from drivers.link.control_lines import ControlLines
from drivers.session.device_session import DeviceSession

CONTROL_POLL_S = 0.25  # s between reads of the modem lines (CTS, DSR, CD, RI) while idle


class LineWatch:
    """The lines last told, and when they are read next."""

    def __init__(
        self,
        changed: Callable[[ControlLines], object],
        note: Callable[[str], object],
        log: Callable[[str], object],
    ) -> None:
        self._changed, self._note, self._log = changed, note, log
        self.lines: ControlLines | None = None  # as last told
        self._next_read = 0.0

    def forget(self) -> None:
        """A new connection: nothing told yet."""
        self.lines = None

    def due(self) -> bool:
        """Whether the lines are to be read now."""
        return time.monotonic() >= self._next_read

    def report(self, session: DeviceSession, force: bool = False, note: bool = False) -> None:
        """Read the lines; tell them if they changed (or `force`), noting the inputs that
        changed by themselves; `note`: write them all to the session log (at connection)."""
        self._next_read = time.monotonic() + CONTROL_POLL_S
        lines = session.control_lines()
        before, self.lines = self.lines, lines
        if note:
            self._log(f"control lines: {lines.describe()}")
        elif before is not None and not force:
            for change in lines.changes(before):
                self._note(change)
        if force or lines != before:
            self._changed(lines)
