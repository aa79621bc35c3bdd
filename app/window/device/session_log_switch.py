"""The panel's session log as a worker keeps it: one writer, tapped into each session's traffic,
switched to another file (or off) while a connection goes on, each file naming the other."""

from __future__ import annotations

from typing import TextIO

from drivers.link.records import TrafficLogWriter
from drivers.session.device_session import DeviceSession


def file_name(stream: TextIO) -> str:
    """The path of a log's file, as far as the stream knows it."""
    return str(getattr(stream, "name", "another file"))


class SessionLog:
    """The session log's writer (None: off), and the session it is tapped into."""

    def __init__(self) -> None:
        self.writer: TrafficLogWriter | None = None
        self._session: DeviceSession | None = None

    def attach(self, session: DeviceSession | None) -> None:
        """Log `session`'s traffic from now on (None: the session ended)."""
        self._session = session
        if session is not None and self.writer is not None:
            session.log_to(self.writer)

    def switch(self, stream: TextIO | None) -> None:
        """Write to `stream` from now on (None: stop); the connection open now, if any, goes on
        in the new file, and each file says where the other is."""
        before = self.writer
        self.writer = TrafficLogWriter(stream) if stream is not None else None
        session = self._session
        if session is not None:
            if before is not None:
                session.tap.stop_log(before)
            if self.writer is not None:
                session.log_to(self.writer)
        if before is None:
            return
        if self.writer is not None:
            self.note(f"continued from {file_name(before.stream)}")
            before.note(f"the session log goes on in {file_name(self.writer.stream)}")
        else:
            before.note("the session log was turned off")
        before.stream.close()

    def note(self, text: str) -> None:
        """A `#` line in the log (English), in order with the traffic."""
        if self.writer is not None:
            self.writer.note(text)

    def end(self, text: str) -> None:
        """The last note, then the file closed (the panel quits)."""
        ending, self.writer = self.writer, None
        if ending is not None:
            ending.note(text)
            ending.stream.close()
