"""Typed events: what a decoder makes of the frames a device sends.

An event's str() is what it says to a person: a Message (drivers/messages.py) where it has words
to translate, built only when asked, so that decoding stays cheap; the protocol's own words (ACK,
DONE, a command's name, a code) are its values.
"""

from __future__ import annotations

from dataclasses import dataclass

from drivers.messages import Message


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
    """The device's own words, or what its code means (a Message where the protocol's
    documents give the meaning)."""
    code: str | None = None

    def __str__(self) -> str:
        if self.code:
            return Message("error {code}: {message}", code=self.code, message=self.message)
        return Message("error: {message}", message=self.message)


@dataclass(frozen=True)
class PositionReport(Event):
    """A position; `measured` is False when it is only what was commanded."""

    x: float
    y: float
    z: float
    measured: bool = True
    confirmed: bool = False
    """For a commanded position: the device said the move to it has ended (Visiomex FA0001)."""
    known: bool = True
    """False for a device that cannot be asked, counted from where the session began rather
    than from a known place (Home, Set Home, an absolute target, a position kept from an
    earlier run): where the stage is, is then unknown."""

    def __str__(self) -> str:
        x, y, z = self.x, self.y, self.z
        if not self.known:
            return Message(
                "position unknown (({x:g}, {y:g}, {z:g}) mm counted from where the session "
                "began; Home or Set Home to know it)",
                x=x,
                y=y,
                z=z,
            )
        if self.measured:
            return Message("position ({x:g}, {y:g}, {z:g}) mm", x=x, y=y, z=z)
        if self.confirmed:
            return Message(
                "position ({x:g}, {y:g}, {z:g}) mm (commanded, confirmed)", x=x, y=y, z=z
            )
        return Message("position ({x:g}, {y:g}, {z:g}) mm (commanded)", x=x, y=y, z=z)


@dataclass(frozen=True)
class Feedback(Event):
    """A feedback packet such as Visiomex `FP0001`, or an acknowledged command word."""

    code: str
    value: bytes = b""
    meaning: str = ""
    """What the packet means, for people (a Message where it has words to translate)."""

    def __str__(self) -> str:
        if self.meaning:  # the bytes are shown beside it where they matter
            return Message("feedback {code} ({meaning})", code=self.code, meaning=self.meaning)
        if self.value:
            return Message(
                "feedback {code} {bytes}", code=self.code, bytes=self.value.hex(" ").upper()
            )
        return Message("feedback {code}", code=self.code)


@dataclass(frozen=True)
class TextLine(Event):
    """A line that is not part of the protocol's grammar: help text, debug output, echo."""

    text: str

    def __str__(self) -> str:
        return Message("the line {text!r}", text=self.text)


@dataclass(frozen=True)
class Undecodable(Event):
    """A frame the decoder could not read; kept so the console can show it."""

    data: bytes
    reason: str
    """Why it could not be read (a Message, as the FrameError that said it carried)."""

    def __str__(self) -> str:
        return Message(
            "an unreadable frame ({reason}): {bytes}",
            reason=self.reason,
            bytes=self.data.hex(" ").upper(),
        )
