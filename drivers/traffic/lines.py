"""What a line of the traffic is: its kinds and directions, its fields, its bytes as text.

Kinds: `motion`, `query`, `poll` (the position query and its reply), `setting`, `error`,
`debug` (the device's own text) and `note`. A line's code, one byte in the index, is its
direction's number << 4 | its kind's number.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from drivers.link.records import DIRECTIONS

KINDS = ("motion", "query", "poll", "setting", "error", "debug", "note")
KIND_CODE = {kind: code for code, kind in enumerate(KINDS)}
DIRECTION_CODE = {direction: code for code, direction in enumerate(DIRECTIONS)}
_ESCAPES = {0x0D: "\\r", 0x0A: "\\n", 0x09: "\\t", 0x5C: "\\\\"}
_ESCAPE_TABLE = {
    b: _ESCAPES.get(b, chr(b) if 0x20 <= b < 0x7F else f"\\x{b:02x}") for b in range(256)
}
_TAILS = {"\r\n": "\\r\\n", "\n": "\\n", "\r": "\\r"}


def escape(data: bytes) -> str:
    """Printable ASCII as is; CR, LF, tab and backslash as \\r \\n \\t \\\\; others as \\xNN."""
    text = data.decode("latin-1")
    if text.isascii():  # the common cases, fast: printable text, then a line end
        if text.isprintable():
            return text.replace("\\", "\\\\") if "\\" in text else text
        core = text.rstrip("\r\n")
        if core.isprintable() and "\\" not in core:
            tail = text[len(core) :]
            return core + (_TAILS.get(tail) or tail.replace("\r", "\\r").replace("\n", "\\n"))
    return text.translate(_ESCAPE_TABLE)


@dataclass(frozen=True)
class TrafficLine:
    """One line of the session: a frame or a note, with its pairing."""

    number: int
    time: float  # seconds, on the clock of the records (monotonic or log time)
    direction: str  # "tx", "rx", or "" for a note
    kind: str
    data: bytes  # as they crossed, terminator included, where known
    meaning: str
    pair: int = -1  # the reply of a request, the request of a reply (-1: none)
    latency_ms: float = math.nan  # on a reply: time since its request
    first_copy: int = -1  # on a retransmission: the line of the frame's first copy
