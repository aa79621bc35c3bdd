"""Text forms of raw serial traffic for the console: escapes, hexdump lines, and parsing input."""

from __future__ import annotations

import re

HEX_WIDTH = 16  # bytes per hexdump line
TEXT_WIDTH = 256  # bytes per line in text mode; longer records continue on the next line
HEX_IDLE = 0.2  # s without bytes after which an unterminated hexdump block ends

_ESCAPES = {0x0D: "\\r", 0x0A: "\\n", 0x09: "\\t", 0x5C: "\\\\"}
# str.translate tables over latin-1 text: one C-level pass per record instead of a Python loop
_ESCAPE_TABLE = {
    b: _ESCAPES.get(b, chr(b) if 0x20 <= b < 0x7F else f"\\x{b:02x}") for b in range(256)
}
_DOTS_TABLE = bytes(b if 0x20 <= b < 0x7F else 0x2E for b in range(256))
_UNESCAPES = {"r": b"\r", "n": b"\n", "t": b"\t", "\\": b"\\", "0": b"\0"}
_HEX_SEPARATORS = re.compile(r"[\s,:;-]+")
_HEX_DIGITS = re.compile(r"[0-9a-fA-F]+")


def escape(data: bytes) -> str:
    """Printable ASCII as is; CR, LF, tab and backslash as \\r \\n \\t \\\\; others as \\xNN."""
    return data.decode("latin-1").translate(_ESCAPE_TABLE)


def unescape(text: str) -> bytes:
    """The bytes of a send line in text mode: UTF-8, with \\r \\n \\t \\0 \\\\ and \\xNN escapes.

    Raises ValueError naming the bad escape.
    """
    out = bytearray()
    i = 0
    while i < len(text):
        char = text[i]
        if char != "\\":
            out += char.encode("utf-8")
            i += 1
            continue
        code = text[i + 1 : i + 2]
        if code in _UNESCAPES:
            out += _UNESCAPES[code]
            i += 2
        elif code == "x":
            digits = text[i + 2 : i + 4]
            if len(digits) != 2 or not _HEX_DIGITS.fullmatch(digits):
                raise ValueError(f"\\x needs two hex digits at column {i + 1}: {text[i : i + 4]!r}")
            out.append(int(digits, 16))
            i += 4
        elif not code:
            raise ValueError("a lone backslash ends the line: write \\\\ for a backslash")
        else:
            raise ValueError(
                f"unknown escape \\{code} at column {i + 1} (use \\r \\n \\t \\0 \\\\ \\xNN)"
            )
    return bytes(out)


def parse_hex(text: str) -> bytes:
    """Bytes from hex like "48 45 4c", "48454C", "0x48,0x45" or "48:45"; raises ValueError."""
    out = bytearray()
    for token in _HEX_SEPARATORS.split(text.strip()):
        if not token:
            continue
        digits = token[2:] if token[:2].lower() == "0x" else token
        if not digits or not _HEX_DIGITS.fullmatch(digits):
            raise ValueError(f"not hex: {token!r}")
        if len(digits) % 2:
            raise ValueError(f"odd number of hex digits in {token!r}: write 0{digits} or pairs")
        out += bytes.fromhex(digits)
    return bytes(out)


def stamp(seconds: float) -> str:
    """A relative time like `000003.001`."""
    return f"{seconds:010.3f}"


def _prefix(direction: str, seconds: float | None) -> str:
    label = direction.upper() if direction in ("tx", "rx") else "--"
    return label if seconds is None else f"{stamp(seconds)} {label}"


class TextAssembler:
    """Cuts traffic into text lines at LF: a line goes on across reads of the same direction.

    A serial read returns whatever has arrived (`A`, `CK GET_POS`, `ITION\\r\\n`); shown one read
    per line that is unreadable. `feed` returns pieces `(starts_line, text)`: a piece that starts
    a line carries the timestamp and direction, one that does not continues the previous line.
    A line ends at LF, when the other direction or a note comes, or after TEXT_WIDTH bytes.
    """

    def __init__(self) -> None:
        self.open_direction: str | None = None  # direction of the unterminated last line
        self._open_bytes = 0

    def feed(self, direction: str, data: bytes, seconds: float | None) -> list[tuple[bool, str]]:
        """The pieces of one record ("tx" or "rx")."""
        pieces: list[tuple[bool, str]] = []
        if not data:
            return pieces
        prefix = _prefix(direction, seconds)
        *complete, rest = data.split(b"\n")
        for part in [line + b"\n" for line in complete] + ([rest] if rest else []):
            while part:
                if self.open_direction == direction and self._open_bytes < TEXT_WIDTH:
                    room = TEXT_WIDTH - self._open_bytes
                    chunk, part = part[:room], part[room:]
                    pieces.append((False, escape(chunk)))
                else:
                    chunk, part = part[:TEXT_WIDTH], part[TEXT_WIDTH:]
                    pieces.append((True, f"{prefix}  {escape(chunk)}"))
                    self.open_direction, self._open_bytes = direction, 0
                self._open_bytes += len(chunk)
                if chunk.endswith(b"\n"):
                    self.open_direction = None
        return pieces

    def close(self) -> None:
        """End the open line (a note, or a re-render, comes next)."""
        self.open_direction = None


def hex_row(prefix: str, chunk: bytes) -> str:
    """One hexdump row: `prefix  48 45 4C ...  HEL` for up to HEX_WIDTH bytes."""
    hexes = chunk.hex(" ").upper()
    text = chunk.translate(_DOTS_TABLE).decode("ascii")
    return f"{prefix}  {hexes:<{HEX_WIDTH * 3 - 1}}  {text}"


def hex_lines(direction: str, data: bytes, seconds: float | None) -> list[str]:
    """`000003.001 TX  48 45 4C 4C 4F ...  HELLO`: HEX_WIDTH bytes per line."""
    prefix = _prefix(direction, seconds)
    return [
        hex_row(prefix, data[i : i + HEX_WIDTH]) for i in range(0, max(len(data), 1), HEX_WIDTH)
    ]


class HexAssembler:
    """Cuts traffic into hexdump blocks at LF: a block goes on across reads of one direction.

    A reply that arrives in several reads is one block of HEX_WIDTH-byte rows, every row carrying
    the time and direction of the block's first byte. A block ends after an LF, when the other
    direction comes, when `close` is called (a note), or before bytes that come HEX_IDLE s or
    more after the previous ones (binary frames without LF). `feed` returns the finished rows as
    (direction, row); the unfinished last row is held (see `pending`) until the block goes on or
    ends.
    """

    def __init__(self) -> None:
        self.open_direction: str | None = None  # direction of the unterminated last block
        self._prefix = ""
        self._row = b""  # bytes of the unfinished last row
        self._last: float | None = None  # time of the last bytes fed

    def pending(self) -> bool:
        """Whether an unfinished row is held back (shown by the next `close`)."""
        return bool(self._row)

    def feed(
        self, direction: str, data: bytes, seconds: float | None, at: float | None = None
    ) -> list[tuple[str, str]]:
        """(direction, row) finished by one record ("tx" or "rx"); `at`: its time, for HEX_IDLE."""
        rows: list[tuple[str, str]] = []
        if not data:
            return rows
        idle = at is not None and self._last is not None and at - self._last >= HEX_IDLE
        if self.open_direction is not None and (direction != self.open_direction or idle):
            rows += self.close()
        self._last = at
        prefix = _prefix(direction, seconds)
        position = 0
        while position < len(data):
            if self.open_direction is None:
                self.open_direction, self._prefix = direction, prefix
            lf = data.find(b"\n", position)
            end = len(data) if lf < 0 else lf + 1
            row = self._row + data[position:end]
            position = end
            full = len(row) - len(row) % HEX_WIDTH
            for i in range(0, full, HEX_WIDTH):
                rows.append((direction, hex_row(self._prefix, row[i : i + HEX_WIDTH])))
            self._row = row[full:]
            if lf >= 0:
                rows += self.close()
        return rows

    def close(self) -> list[tuple[str, str]]:
        """End the open block: (direction, its unfinished row), if any (e.g. a note comes)."""
        rows = []
        if self._row and self.open_direction is not None:
            rows.append((self.open_direction, hex_row(self._prefix, self._row)))
        self.open_direction, self._row = None, b""
        return rows


def note_line(text: str, seconds: float | None) -> str:
    """An information line such as `000000.000 --  connected`."""
    return f"{_prefix('note', seconds)}  {text}"
