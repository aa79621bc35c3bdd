"""motionctl and the position kept for a device that cannot be asked where it is (counted on
Visiomex and Firmata, commanded on the pi-frame): read from the settings the panel keeps,
checked before anything is sent, kept after the run."""

from __future__ import annotations

import logging
from typing import Any

from PySide6.QtCore import QSettings

from app.common.settings import read_counted_position, write_counted_position
from drivers.device.position_count import (
    commanded,
    keeps_count,
    needs_count,
    no_count,
    resume,
    starts_count,
    unknown_note,
)
from drivers.errors import BadInput, FrameError
from drivers.protocols import commands as cmd
from drivers.protocols.base import Point, Protocol
from drivers.session.device_session import DeviceSession

log = logging.getLogger(__name__)
_MOVING = frozenset({"move", "jog", "home", "raw", "macro", "run"})


class CliCount:
    """The count for one run: None where the protocol keeps none (it is measured, or asked)."""

    def __init__(self, settings: QSettings, protocol: Protocol, port: str) -> None:
        self.settings, self.protocol, self.port = settings, protocol, port
        self.active = keeps_count(protocol)
        self.before: Point | None = None
        if self.active:
            self.before = read_counted_position(settings, protocol.name, port)
        if self.before is not None:
            try:
                resume(protocol, self.before)
            except BadInput as exc:  # e.g. off the grid of ticks per mm changed since
                log.warning("the position kept for this port is not used: %s", exc)
                self.before = None

    def check(self, command: str, steps: tuple[str, ...] = ()) -> None:
        """Refuse (NoCount) a command, or a macro's step, that needs a count none is kept of."""
        if not self.active or self.before is not None:
            return
        caps = self.protocol.capabilities
        for name in (command, *(step.split(" ", 1)[0].lower() for step in steps)):
            if needs_count(name, caps):
                raise no_count(name, self.protocol)

    def begin(self, session: DeviceSession) -> None:
        """Start the run's session from the count kept."""
        if self.before is not None:
            session.resume_from(self.before)

    def done(
        self, session: DeviceSession, command: str, args: list[str], result: dict[str, Any]
    ) -> None:
        """After a command that succeeded: keep the new count, and say how it is known."""
        if not self.active:
            return
        caps = self.protocol.capabilities
        known = self.before is not None or starts_count(command, caps)
        after: Point | None = None
        if command == "raw":
            after = self._after_raw(session, args[0]) if known else None
            known = known and after is not None
        elif known and session.last_position is not None:
            here = session.last_position
            after = (here.x, here.y, here.z)
        if known and after is not None:
            if after != self.before:
                write_counted_position(self.settings, self.protocol.name, self.port, after)
            if "position" in result or command == "set-home":
                result["position"] = list(after)
                result["measured"] = False
                result["commanded" if commanded(caps) else "counted"] = True
        elif command in _MOVING:
            if self.before is not None:  # raw bytes sent unread: where they went is not known
                write_counted_position(self.settings, self.protocol.name, self.port, None)
            result["position"], result["measured"] = None, False
            result["position_note"] = unknown_note(self.protocol)

    def failed(self, moved: bool) -> None:
        """A command failed: after a move was sent, where the stage is is no longer known."""
        if self.active and moved and self.before is not None:
            write_counted_position(self.settings, self.protocol.name, self.port, None)

    def _after_raw(self, session: DeviceSession, text: str) -> Point | None:
        """The count after raw bytes: moved as the firmware makes the move, unchanged by a
        packet that moves nothing, None where they could not be read."""
        assert self.before is not None
        frame = self.protocol.encode(cmd.Raw(text.encode("utf-8")))
        try:
            commands = self.protocol.sent_commands(frame)
        except FrameError:
            return None
        if not any(c is not None for c in commands):
            return self.before
        # The move was followed as the firmware makes it (Motion: the protocol's move_outcome).
        here = session.last_position
        return (here.x, here.y, here.z) if here is not None else None
