"""A traffic log's records and the error for a file that is not a log, shared by its readers
(drivers/traffic/log_reader.py for ours, drivers/traffic/spy_log.py for pyserial spy://
captures)."""

from __future__ import annotations

from dataclasses import dataclass

from drivers.errors import BadFile


class LogError(BadFile):
    """A file that cannot be read as a traffic log (which file, which line, why)."""


@dataclass(frozen=True)
class LogRecord:
    """Bytes that crossed (direction `tx`/`rx`) at `time` seconds, or a note (`data` empty)."""

    time: float
    direction: str
    data: bytes
    note: str = ""
