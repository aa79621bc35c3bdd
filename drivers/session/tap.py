"""A session's traffic tap: listeners on its link, and the logs it writes the traffic to.

Public and stable: `TrafficTap` (its methods without a leading underscore).
"""

from __future__ import annotations

import os
from typing import TextIO

from drivers.link.records import TrafficLogWriter
from drivers.link.transport import Link, TrafficListener
from drivers.session.setup import LogTarget

__all__ = ["TrafficTap"]


class TrafficTap:
    """Every byte of one link, handed to listeners and written to logs as it crosses."""

    def __init__(self, link: Link) -> None:
        """A tap on `link` (listeners are called in the thread that reads or writes it)."""
        self.link = link
        self.logs: list[TrafficLogWriter] = []
        """The logs written to, in the order they were added."""
        self._owned: list[TextIO] = []

    def add_listener(self, listener: TrafficListener) -> None:
        """Call `listener` with every Traffic record (bytes sent or received) from now on."""
        self.link.listeners.append(listener)

    def remove_listener(self, listener: TrafficListener) -> None:
        """Stop calling `listener` (ValueError if it was not added)."""
        self.link.listeners.remove(listener)

    def log_to(self, target: LogTarget) -> TrafficLogWriter:
        """Write every byte from now on to a log (the hexdump of `motionctl --log`): a path is
        appended to and closed with the tap; a stream or a writer stays the caller's."""
        if isinstance(target, TrafficLogWriter):
            writer = target
        elif isinstance(target, str | os.PathLike):
            stream = open(target, "a", encoding="utf-8")  # noqa: SIM115 (closed by close())
            self._owned.append(stream)
            writer = TrafficLogWriter(stream)
        else:
            writer = TrafficLogWriter(target)
        self.logs.append(writer)
        self.link.listeners.append(writer)
        return writer

    def stop_log(self, writer: TrafficLogWriter) -> None:
        """Stop writing to `writer` (a log added by `log_to`; nothing if it was not)."""
        if writer in self.logs:
            self.logs.remove(writer)
        if writer in self.link.listeners:
            self.link.listeners.remove(writer)

    def note(self, text: str) -> None:
        """A `#` line with its time in each log (a connection, a change of settings)."""
        for writer in self.logs:
            writer.note(text)

    def close(self) -> None:
        """Close the log files the tap opened itself (idempotent)."""
        for stream in self._owned:
            stream.close()
        self._owned.clear()
