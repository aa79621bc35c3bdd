"""Reading traffic logs back: ours (`motionctl --log`, the session log) as records with times.

Our format: `SSSSSS.mmm TX   48 45 4C 4C 4F   HELLO`, one line per 16 bytes, a record's lines
sharing their stamp and direction; `#` lines are notes. A file that is not such a log is refused
with the line that gave it away. `read_any_log` also reads pyserial spy:// captures (spy_log).
A log may be hundreds of MiB: it is read a chunk at a time (drivers/files.py: at most
`LOG_MAX_BYTES`, lines of at most `LOG_MAX_LINE` characters), and `open_any_log` hands its
records over as they are read, for a caller that keeps them more compactly than a list.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterable, Iterator
from pathlib import Path

from drivers.files import LOG_MAX_BYTES, LOG_MAX_LINE, read_lines
from drivers.messages import Message
from drivers.traffic import spy_log
from drivers.traffic.log_records import LogError, LogRecord

__all__ = [
    "LogError",
    "LogRecord",
    "log_records",
    "open_any_log",
    "parse_log",
    "read_any_log",
    "read_log",
]

_LINE = re.compile(r"^(\d{6,}\.\d{3}) (TX|RX)   ((?:[0-9A-F]{2} ){0,15}[0-9A-F]{2})(.*)$")
_HEX_FIELD = 47  # 16 bytes as hex; shorter rows are padded to it before the text column
_NOTE = re.compile(r"^(?:(\d{6,}\.\d{3}) )?# ?(.*)$")


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
    return list(log_records(text.splitlines(), source))


def log_records(lines: Iterable[str], source: str) -> Iterator[LogRecord]:
    """The records of a log's lines, each as soon as it is complete; LogError naming the line
    for one that is not a traffic log's, or at the end for a log without traffic."""
    parts: list[bytes] = []  # the open record's lines, joined when it ends
    key: tuple[float, str] | None = None
    full = False  # the open record's last line had 16 bytes: the next may continue it
    last = 0.0  # the time of the latest record, which a note without its own takes
    traffic = False
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        hit = _LINE.match(line)
        if hit is None or not _text_column_fits(hit.group(3), hit.group(4)):
            note = _NOTE.match(line)
            if note is None:
                raise LogError(
                    Message(
                        "{source} line {number}: not a traffic log line: {line!r}",
                        source=source,
                        number=number,
                        line=line[:60],
                    )
                )
            if key is not None:
                yield LogRecord(key[0], key[1], b"".join(parts))
            key, parts, full = None, [], False
            last = float(note.group(1)) if note.group(1) else last
            yield LogRecord(last, "", b"", note.group(2))
            continue
        stamp, direction = float(hit.group(1)), hit.group(2).lower()
        data = bytes.fromhex(hit.group(3))
        if not (full and key == (stamp, direction)):  # else: the record's next line
            if key is not None:
                yield LogRecord(key[0], key[1], b"".join(parts))
            key, parts, last, traffic = (stamp, direction), [], stamp, True
        parts.append(data)
        full = len(data) == 16
    if key is not None:
        yield LogRecord(key[0], key[1], b"".join(parts))
    if not traffic:
        raise LogError(
            Message("{source}: no traffic in it (not a Motion Panel log)", source=source)
        )


def _lines(file: Path) -> Iterator[str]:
    return read_lines(file, LOG_MAX_BYTES, LOG_MAX_LINE, Message("traffic log"), LogError)


def read_log(path: str | Path) -> list[LogRecord]:
    """A log file's records; LogError for a missing, special, binary, huge or foreign file."""
    file = Path(path)
    return list(log_records(_lines(file), str(file)))


def read_any_log(path: str | Path) -> tuple[str, list[LogRecord]]:
    """A log's format (`motionpanel` or `pyserial-spy`, told by its content) and its records."""
    log_format, records = open_any_log(path)
    return log_format, list(records)


def open_any_log(path: str | Path) -> tuple[str, Iterator[LogRecord]]:
    """A log's format, told by its first line that is not blank, and its records as the file is
    read on (LogError where the reading reaches a line that is wrong)."""
    file = Path(path)
    lines = _lines(file)
    for blanks, line in enumerate(lines):
        if not line.strip():
            continue
        again = itertools.chain(itertools.repeat("", blanks), (line,), lines)
        if spy_log.is_spy_line(line):  # first: our line pattern would take spy's offsets as bytes
            return "pyserial-spy", spy_log.spy_records(again, str(file))
        if _LINE.match(line) or _NOTE.match(line):
            return "motionpanel", log_records(again, str(file))
        raise LogError(
            Message(
                "{file}: not a Motion Panel log nor a pyserial spy:// capture: line {number} is "
                "not a traffic log line: {line!r}; for spy://, {hint}",
                file=file,
                number=blanks + 1,
                line=line[:60],
                hint=spy_log.HEXDUMP_HINT,
            )
        )
    raise LogError(
        Message(
            "{file}: empty, not a Motion Panel log nor a pyserial spy:// capture "
            "(spy's raw format leaves its file empty); {hint}",
            file=file,
            hint=spy_log.HEXDUMP_HINT,
        )
    )
