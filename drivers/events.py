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


@dataclass(frozen=True)
class Done(Event):
    """The device finished a command; `data` is what followed the colon, if anything."""

    command: str
    data: str | None = None


@dataclass(frozen=True)
class ErrorReport(Event):
    """The device reported an error."""

    message: str
    code: str | None = None


@dataclass(frozen=True)
class PositionReport(Event):
    """A position; `measured` is False when it is only what was commanded."""

    x: float
    y: float
    z: float
    measured: bool = True


@dataclass(frozen=True)
class Feedback(Event):
    """A feedback packet such as Visiomex `FP0001`, or an acknowledged command word."""

    code: str
    value: bytes = b""


@dataclass(frozen=True)
class TextLine(Event):
    """A line that is not part of the protocol's grammar: help text, debug output, echo."""

    text: str


@dataclass(frozen=True)
class Undecodable(Event):
    """A frame the decoder could not read; kept so the console can show it."""

    data: bytes
    reason: str
