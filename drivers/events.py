"""Typed events: what a decoder makes of the frames a device sends."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Event:
    """Base of every decoded event."""


@dataclass(frozen=True)
class Ack(Event):
    """The device accepted a command and started on it."""

    command: str

    def __str__(self) -> str:
        return f"ACK {self.command}"


@dataclass(frozen=True)
class Done(Event):
    """The device finished a command; `data` is what followed the colon, if anything."""

    command: str
    data: str | None = None

    def __str__(self) -> str:
        return f"DONE {self.command}" + (f": {self.data}" if self.data is not None else "")


@dataclass(frozen=True)
class ErrorReport(Event):
    """The device reported an error."""

    message: str
    code: str | None = None

    def __str__(self) -> str:
        return f"error {self.code}: {self.message}" if self.code else f"error: {self.message}"


@dataclass(frozen=True)
class PositionReport(Event):
    """A position; `measured` is False when it is only what was commanded."""

    x: float
    y: float
    z: float
    measured: bool = True
    confirmed: bool = False
    """For a commanded position: the device said the move to it has ended (Visiomex FA0001)."""

    def __str__(self) -> str:
        kind = ""
        if not self.measured:
            kind = " (commanded, confirmed)" if self.confirmed else " (commanded)"
        return f"position ({self.x:g}, {self.y:g}, {self.z:g}) mm{kind}"


@dataclass(frozen=True)
class Feedback(Event):
    """A feedback packet such as Visiomex `FP0001`, or an acknowledged command word."""

    code: str
    value: bytes = b""
    meaning: str = ""

    def __str__(self) -> str:
        if self.meaning:  # the bytes are shown beside it where they matter
            return f"feedback {self.code} ({self.meaning})"
        return f"feedback {self.code}" + (f" {self.value.hex(' ').upper()}" if self.value else "")


@dataclass(frozen=True)
class TextLine(Event):
    """A line that is not part of the protocol's grammar: help text, debug output, echo."""

    text: str

    def __str__(self) -> str:
        return f"the line {self.text!r}"


@dataclass(frozen=True)
class Undecodable(Event):
    """A frame the decoder could not read; kept so the console can show it."""

    data: bytes
    reason: str

    def __str__(self) -> str:
        return f"an unreadable frame ({self.reason}): {self.data.hex(' ').upper()}"
