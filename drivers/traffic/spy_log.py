"""Reading pyserial `spy://PORT?file=F` captures (its hexdump format) as traffic log records.

A data line is `SSSSSS.mmm TX   0010  48 45 4C 4C 4F ...  HELLO`: the byte offset in the write (or
read) it belongs to, up to 16 bytes in hex and their ASCII column; one call's lines continue
each other by offset, and may carry the call's colour escape (`&color`) in front of the first.
Spy's TX is what the program wrote (our `tx`), its RX what it read. Control-line and buffer
events (`RTS  active`, `Q-RX reset_input_buffer`, `RX   <empty>` with `&all`) become notes.
Spy's `&raw` format runs the bytes of both directions together (and pyserial 3.5 cannot even
write it to a file), so it is refused. Records are handed over as the capture is read (a call
as soon as no later line can continue it), so a long capture needs no list of them.
"""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from drivers.messages import Message
from drivers.traffic.log_records import LogError, LogRecord

HEXDUMP_HINT = Message(
    "capture with spy's default hexdump format: spy://PORT?file=FILE, without raw"
)
_ESCAPE = re.compile(r"\x1b\[[0-9;]*m")
_DATA = re.compile(r"^(-?\d+\.\d{3}) (TX|RX)   ([0-9A-F]{4,})  (.*)$")
_EVENT = re.compile(r"^(-?\d+\.\d{3}) (Q-RX|Q-TX|BRK|RTS|DTR|CTS|DSR|RI|CD|RX) +(\S.*)$")
_STAMPED = re.compile(r"^-?\d+\.\d{3} ")
_HEX_WIDTH = 16 * 3 + 1  # 16 cells of `XX ` and the space after the eighth
_SHOWN = {n: "." for n in (*range(0x20), *range(0x7F, 0x100))}  # the ASCII column's dots
_WAITING_MAX = 4096  # entries kept behind a call still open before that call is taken as ended


@dataclass
class _Call:
    """The bytes of one write or read, gathered line by line (16 bytes per full line)."""

    time: float
    direction: str
    data: bytearray


def _row(data: bytes) -> str:
    """How spy shows up to 16 bytes after the offset: hex cells, then their ASCII column."""
    first, second = data[:8].hex(" ").upper(), data[8:16].hex(" ").upper()
    text = data.decode("latin-1").translate(_SHOWN)
    return f"{first:<24} {second:<24} {text:<16}"


def _row_bytes(row: str) -> bytes | None:
    """The bytes of a data line's row, or None when it is not exactly as spy writes them."""
    try:
        data = bytes.fromhex(row[:_HEX_WIDTH])
    except ValueError:
        return None
    if not 1 <= len(data) <= 16 or _row(data).rstrip() != row.rstrip():
        return None
    return data


def _clean(line: str) -> str:
    """The line without colour escapes (`&color`) or trailing blanks."""
    return _ESCAPE.sub("", line).rstrip()


def _is_event(hit: re.Match[str] | None) -> bool:
    """Whether an `_EVENT` match is one spy writes: an RX event is only `RX   <empty>` (any
    other `RX` line is bytes, ours or spy's)."""
    return hit is not None and (hit.group(2) != "RX" or hit.group(3) == "<empty>")


def is_spy_line(line: str) -> bool:
    """Whether a line can only come from a pyserial spy:// capture (a data or an event line);
    our own `000002.000 RX   F9   .` is not one, though it starts alike."""
    if _ESCAPE.match(line):
        return True
    clean = _clean(line)
    return bool(_DATA.match(clean)) or _is_event(_EVENT.match(clean))


def _refusal(source: str, number: int, line: str) -> LogError:
    """The error for a line that is not one spy writes in its hexdump format."""
    clean = _clean(line)
    if _ESCAPE.match(line) and not _STAMPED.match(clean):
        why = Message("both directions run together, nothing tells TX from RX")
        return LogError(
            Message(
                "{source} line {number}: spy's raw format is refused ({why}); {hint}",
                source=source,
                number=number,
                why=why,
                hint=HEXDUMP_HINT,
            )
        )
    return LogError(
        Message(
            "{source} line {number}: not a pyserial spy:// hexdump line: {line!r}",
            source=source,
            number=number,
            line=line[:60],
        )
    )


def parse_spy(text: str, source: str) -> list[LogRecord]:
    """The records of a spy:// hexdump capture; LogError naming the line for anything else."""
    return list(spy_records(text.splitlines(), source))


def _record(entry: _Call | LogRecord) -> LogRecord:
    if isinstance(entry, _Call):
        return LogRecord(entry.time, entry.direction, bytes(entry.data))
    return entry


def _is_open(entry: _Call | LogRecord, calls: dict[str, _Call]) -> bool:
    return isinstance(entry, _Call) and calls.get(entry.direction) is entry


def spy_records(lines: Iterable[str], source: str) -> Iterator[LogRecord]:
    """The records of a capture's lines, in the order their first lines come, each as soon as it
    is complete; LogError naming the line for one spy does not write."""
    waiting: deque[_Call | LogRecord] = deque()  # in order; the first a call still open
    calls: dict[str, _Call] = {}  # each direction's open call: its next lines may continue it
    entries = traffic = False
    for number, line in enumerate(lines, start=1):
        clean = _clean(line)
        if not clean:
            continue
        hit = _DATA.match(clean)
        if hit is not None:
            stamp, direction = float(hit.group(1)), hit.group(2).lower()
            offset, data = int(hit.group(3), 16), _row_bytes(hit.group(4))
            if data is None:
                raise _refusal(source, number, line)
            call: _Call | None  # the open call these bytes continue, checked below
            if offset == 0:
                call = calls[direction] = _Call(stamp, direction, bytearray(data))
                waiting.append(call)
            else:
                call = calls.get(direction)
                if call is None or offset % 16 or len(call.data) != offset:
                    raise LogError(
                        Message(
                            "{source} line {number}: bytes at offset {offset:#06x} of a "
                            "{direction} call whose earlier lines are missing",
                            source=source,
                            number=number,
                            offset=offset,
                            direction=direction.upper(),
                        )
                    )
                call.data += data
            if len(call.data) % 16:  # a short line ends its call
                del calls[direction]
            traffic = True
        else:
            event = _EVENT.match(clean)
            if event is None or not _is_event(event):
                raise _refusal(source, number, line)
            stamp_text, label, value = event.groups()
            waiting.append(LogRecord(float(stamp_text), "", b"", f"{label} {value}"))
        entries = True
        if len(waiting) > _WAITING_MAX and _is_open(waiting[0], calls):
            del calls[waiting[0].direction]
        while waiting and not _is_open(waiting[0], calls):
            yield _record(waiting.popleft())
    if entries and not traffic:
        raise LogError(
            Message("{source}: no traffic in it, only control-line events", source=source)
        )
    if not traffic:  # e.g. the colour code alone that `raw&color` leaves
        raise LogError(
            Message(
                "{source}: no traffic in it (nor spy's raw format); {hint}",
                source=source,
                hint=HEXDUMP_HINT,
            )
        )
    yield from map(_record, waiting)
