"""Test doubles shared by several test files."""

from __future__ import annotations


class ScriptedPort:
    """A pyserial-like port that answers every write with `answer`; keeps what was written."""

    def __init__(self, answer: bytes = b"") -> None:
        self.answer = answer
        self.pending = b""
        self.written = b""
        self.port = "scripted"

    def write(self, data: bytes) -> int:
        """Keep the bytes and queue the scripted answer."""
        self.written += data
        self.pending += self.answer
        return len(data)

    def flush(self) -> None:
        """Nothing to flush."""

    @property
    def in_waiting(self) -> int:
        """Bytes of the answer not read yet."""
        return len(self.pending)

    def read(self, size: int) -> bytes:
        """Up to `size` bytes of the answer."""
        data, self.pending = self.pending[:size], self.pending[size:]
        return data

    def close(self) -> None:
        """Nothing to close."""
