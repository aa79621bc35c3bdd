"""Reading traffic logs back: ours (`motionctl --log`, the session log) as records with times.

Our format: `SSSSSS.mmm TX   48 45 4C 4C 4F   HELLO`, one line per 16 bytes, a record's lines
sharing their stamp and direction; `#` lines are notes. A file that is not such a log is refused
with the line that gave it away. `read_any_log` also reads pyserial spy:// captures (spy_log).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from drivers.errors import BadInput
from drivers.files import read_text

MAX_BYTES = 512 * 1024 * 1024
_LINE = re.compile(r"^(\d{6,}\.\d{3}) (TX|RX)   ((?:[0-9A-F]{2} ){0,15}[0-9A-F]{2})(.*)$")
_HEX_FIELD = 47  # 16 bytes as hex; shorter rows are padded to it before the text column
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


def _text_column_fits(hexes: str, rest: str) -> bool:
    """Whether what follows the hex is the padding and a text column of as many characters."""
    if not rest:
        return True
    if not rest.startswith("   "):
        return False
    gap = " " * (_HEX_FIELD - len(hexes) + 3)
    count = (len(hexes) + 1) // 3
    exact = rest.startswith(gap) and len(rest) - len(gap) <= count
    return exact or len(rest.lstrip(" ")) <= count  # or hand-made padding


def parse_log(text: str, source: str = "log") -> list[LogRecord]:
    """The records of a log's text; LogError for text that is not a traffic log."""
    records: list[LogRecord] = []
    parts: list[bytes] = []  # the open record's lines, joined when it ends
    key: tuple[float, str] | None = None
    full = False  # the open record's last line had 16 bytes: the next may continue it

    def close() -> None:
        if key is not None:
            records.append(LogRecord(key[0], key[1], b"".join(parts)))

    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        hit = _LINE.match(line)
        if hit is None or not _text_column_fits(hit.group(3), hit.group(4)):
            note = _NOTE.match(line)
            if note is None:
                raise LogError(f"{source} line {number}: not a traffic log line: {line[:60]!r}")
            close()
            key, parts, full = None, [], False
            stamp = (
                float(note.group(1)) if note.group(1) else (records[-1].time if records else 0.0)
            )
            records.append(LogRecord(stamp, "", b"", note.group(2)))
            continue
        stamp, direction = float(hit.group(1)), hit.group(2).lower()
        data = bytes.fromhex(hit.group(3))
        if not (full and key == (stamp, direction)):  # else: the record's next line
            close()
            key, parts = (stamp, direction), []
        parts.append(data)
        full = len(data) == 16
    close()
    if not any(record.direction for record in records):
        raise LogError(f"{source}: no traffic in it (not a Motion Panel log)")
    return records


def read_log(path: str | Path) -> list[LogRecord]:
    """A log file's records; LogError for a missing, binary, huge or foreign file."""
    file = Path(path)
    text = read_text(file, MAX_BYTES, "traffic log", LogError)
    return parse_log(text, str(file))


def read_any_log(path: str | Path) -> tuple[str, list[LogRecord]]:
    """A log's format (`motionpanel` or `pyserial-spy`, told by its content) and its records."""
    from drivers import spy_log  # spy_log builds on this module's records and errors

    file = Path(path)
    text = read_text(file, MAX_BYTES, "traffic log", LogError)
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        if spy_log.is_spy_line(line):  # first: our line pattern would take spy's offsets as bytes
            return "pyserial-spy", spy_log.parse_spy(text, str(file))
        if _LINE.match(line) or _NOTE.match(line):
            return "motionpanel", parse_log(text, str(file))
        raise LogError(
            f"{file}: not a Motion Panel log nor a pyserial spy:// capture: line {number} is not "
            f"a traffic log line: {line[:60]!r}; for spy://, {spy_log.HEXDUMP_HINT}"
        )
    raise LogError(
        f"{file}: empty, not a Motion Panel log nor a pyserial spy:// capture "
        f"(spy's raw format leaves its file empty); {spy_log.HEXDUMP_HINT}"
    )
