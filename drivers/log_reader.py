"""Reading traffic logs back: ours (`motionctl --log`, the session log) as records with times.

Our format: `SSSSSS.mmm TX   48 45 4C 4C 4F   HELLO`, one line per 16 bytes, a record's lines
sharing their stamp and direction; `#` lines are notes. A file that is not such a log is refused
with the line that gave it away.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from drivers.errors import BadInput
from drivers.files import read_text

MAX_BYTES = 512 * 1024 * 1024
_LINE = re.compile(r"^(\d{6,}\.\d{3}) (TX|RX)   ((?:[0-9A-F]{2} ?){1,16})")
_NOTE = re.compile(r"^(?:(\d{6,}\.\d{3}) )?# ?(.*)$")


class LogError(BadInput):
    """A file that cannot be read as a traffic log (which file, which line, why)."""


@dataclass(frozen=True)
class LogRecord:
    """Bytes that crossed (direction `tx`/`rx`) at `time` seconds, or a note (`data` empty)."""

    time: float
    direction: str
    data: bytes
    note: str = ""


def parse_log(text: str, source: str = "log") -> list[LogRecord]:
    """The records of a log's text; LogError for text that is not a traffic log."""
    records: list[LogRecord] = []
    matched = 0
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        hit = _LINE.match(line)
        if hit is None:
            note = _NOTE.match(line)
            if note is None:
                raise LogError(f"{source} line {number}: not a traffic log line: {line[:60]!r}")
            stamp = (
                float(note.group(1)) if note.group(1) else (records[-1].time if records else 0.0)
            )
            records.append(LogRecord(stamp, "", b"", note.group(2)))
            continue
        matched += 1
        stamp, direction = float(hit.group(1)), hit.group(2).lower()
        data = bytes.fromhex(hit.group(3))
        last = records[-1] if records else None
        if (
            last is not None
            and last.direction == direction
            and last.time == stamp
            and not last.note
            and len(last.data) % 16 == 0
        ):
            records[-1] = LogRecord(stamp, direction, last.data + data)  # the record's next line
        else:
            records.append(LogRecord(stamp, direction, data))
    if not matched:
        raise LogError(f"{source}: no traffic in it (not a Motion Panel log)")
    return records


def read_log(path: str | Path) -> list[LogRecord]:
    """A log file's records; LogError for a missing, binary, huge or foreign file."""
    file = Path(path)
    text = read_text(file, MAX_BYTES, "traffic log", LogError)
    return parse_log(text, str(file))
