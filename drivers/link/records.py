"""Traffic records from the tap, and their hexdump form for log files."""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field
from typing import ClassVar, TextIO

TX = "tx"
RX = "rx"
NOTE = ""  # a note's direction: it crossed no wire
DIRECTIONS = (TX, RX, NOTE)
"""Every direction a record has, in the order the traffic index numbers them."""
_wall_clock = time.time  # `time` is also a field name below, which hides the module in the class


@dataclass(frozen=True)
class Traffic:
    """Bytes that crossed the port: direction (`tx`/`rx`), data, and monotonic + wall-clock time
    (None: not known, as in a log read back)."""

    direction: str
    data: bytes
    time: float
    wall: float | None = field(default_factory=_wall_clock)


@dataclass(frozen=True)
class Note:
    """A line among the traffic that crossed no wire (connected, a line changed, a program
    loaded): its text, and monotonic + wall-clock time (None: not known)."""

    text: str
    time: float
    wall: float | None = field(default_factory=_wall_clock)
    direction: ClassVar[str] = NOTE

    @property
    def data(self) -> bytes:
        """The text as UTF-8 (for code that treats every record as bytes)."""
        return self.text.encode("utf-8")


Record = Traffic | Note
"""What travels from the tap to the console's index, unchanged."""


def hexdump_lines(record: Traffic, start: float, width: int = 16) -> list[str]:
    """Lines like pyserial's spy: `000003.001 TX   48 45 4C 4C 4F   HELLO`."""
    lines = []
    for offset in range(0, len(record.data), width):
        chunk = record.data[offset : offset + width]
        hexes = " ".join(f"{b:02X}" for b in chunk)
        text = "".join(chr(b) if 0x20 <= b < 0x7F else "." for b in chunk)
        stamp = f"{record.time - start:010.3f}"
        lines.append(f"{stamp} {record.direction.upper()}   {hexes:<{width * 3 - 1}}   {text}")
    return lines


class TrafficLogWriter:
    """Writes every record to a text file as it happens, flushed, so a crash loses nothing;
    from any thread (a note never lands inside a record's lines)."""

    def __init__(self, stream: TextIO, start: float | None = None) -> None:
        self.stream = stream
        self.start = time.monotonic() if start is None else start
        self._lock = threading.Lock()

    def note(self, text: str) -> None:
        """A `#` line (a connection, a disconnection) with its time, flushed; none once the
        stream is closed (a note from another thread as the log is turned off)."""
        with self._lock:
            if not self.stream.closed:
                self.stream.write(f"{time.monotonic() - self.start:010.3f} # {text}\n")
                self.stream.flush()

    def __call__(self, record: Traffic) -> None:
        """Append one record as hexdump lines with their text column."""
        with self._lock:
            for line in hexdump_lines(record, self.start):
                self.stream.write(line + "\n")
            self.stream.flush()
