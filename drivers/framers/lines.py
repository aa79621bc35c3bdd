"""Line framer: frames end at CR or LF (COXIRIS replies, Visiomex feedback lines)."""

from __future__ import annotations

from drivers.framers.base import Framer


class LineFramer(Framer):
    """Lines ended by `\\r\\n`, `\\n` or `\\r`; the terminator is not part of the frame.

    Empty lines are skipped. `max_length` bounds a line without a terminator: past it the bytes
    are returned as a frame of their own so a device that never ends its line cannot grow memory.
    A lone `\\r` at the end of the buffer waits, since a `\\n` may follow it.
    """

    def __init__(self, terminator: bytes = b"\n", max_length: int = 4096) -> None:
        self.terminator = terminator
        self.max_length = max_length

    def decode(self, buffer: bytes) -> tuple[int, bytes | None]:
        """Take one line from the front of `buffer`."""
        skipped = len(buffer) - len(buffer.lstrip(b"\r\n"))
        if skipped:
            if skipped == len(buffer) and buffer.endswith(b"\r"):
                # Keep a trailing CR: it may be the first half of CRLF, then is skipped next time.
                return (skipped - 1, None) if skipped > 1 else (0, None)
            return skipped, None
        cr, lf = buffer.find(b"\r", 0, self.max_length), buffer.find(b"\n", 0, self.max_length)
        end = cr if lf < 0 else lf if cr < 0 else min(cr, lf)
        if end >= 0:
            return end, buffer[:end]
        if len(buffer) >= self.max_length:
            return self.max_length, buffer[: self.max_length]
        return 0, None

    def split(self, buffer: bytes) -> tuple[list[bytes], bytes]:
        """Every complete line in `buffer` and the rest, in one pass (as `decode` repeated, but
        without copying the rest after each line: a flood's big reads stay linear)."""
        frames: list[bytes] = []
        position, size, limit = 0, len(buffer), self.max_length
        while position < size:
            start = position
            while position < size and buffer[position] in b"\r\n":
                position += 1
            if position == size:
                if buffer.endswith(b"\r"):  # maybe the first half of CRLF: wait for what follows
                    position = max(size - 1, start)
                break
            cr = buffer.find(b"\r", position, position + limit)
            lf = buffer.find(b"\n", position, position + limit)
            end = cr if lf < 0 else lf if cr < 0 else min(cr, lf)
            if end >= 0:
                frames.append(buffer[position:end])
                position = end
            elif size - position >= limit:
                frames.append(buffer[position : position + limit])
                position += limit
            else:
                break
        return frames, buffer[position:]

    def split_wired(self, buffer: bytes) -> tuple[list[bytes], list[bytes], bytes] | None:
        """As `split`, with each line's bytes as they crossed: its line end and the empty lines
        after it (empty lines before the first are dropped). None where a line is too long for
        this fast path (`split` handles it); `bytes.splitlines` does the scanning."""
        parts = buffer.splitlines(True)
        rest = b""
        if parts:
            last = parts[-1]
            if last[-1] == 0x0D:  # a CR at the very end may be the first half of CRLF: it waits
                rest = b"\r"
                if len(last) > 1:
                    parts[-1] = last[:-1]
                else:
                    parts.pop()
            elif last[-1] != 0x0A:
                rest = parts.pop()
        limit = self.max_length
        if len(rest) >= limit or (parts and max(map(len, parts)) > limit):
            return None
        frames = [part.rstrip(b"\r\n") for part in parts]
        if b"" not in frames:
            return frames, parts, rest
        lines: list[bytes] = []
        wires: list[bytes] = []
        for frame, part in zip(frames, parts, strict=True):
            if frame:
                lines.append(frame)
                wires.append(part)
            elif wires:  # an empty line: its end crossed with the line before
                wires[-1] += part
        return lines, wires, rest

    def encode(self, payload: bytes) -> bytes:
        """Append the terminator."""
        return payload + self.terminator
