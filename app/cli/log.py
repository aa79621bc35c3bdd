"""`motionctl log decode FILE [--protocol P] [--filter REGEX] [--json]`: a traffic log, decoded by
the protocol its connection notes name (a session log's), else by the one given."""

from __future__ import annotations

import re
from typing import Any

from drivers.decoding import DecodedFrame, connection_protocol, decode_records
from drivers.errors import BadInput, MotionError
from drivers.log_reader import LogRecord, read_any_log
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.registry import create_protocol

USAGE = "log decode FILE [--filter REGEX]"


def _parse(args: list[str]) -> tuple[str, re.Pattern[str] | None]:
    if len(args) < 2 or args[0] != "decode":
        raise BadInput(f"usage: {USAGE}")
    path, rest = args[1], args[2:]
    pattern: re.Pattern[str] | None = None
    if rest:
        if len(rest) != 2 or rest[0] != "--filter":
            raise BadInput(f"usage: {USAGE}")
        try:
            pattern = re.compile(rest[1], re.IGNORECASE)
        except re.error as exc:
            raise BadInput(f"--filter {rest[1]!r} is not a regular expression: {exc}") from None
    return path, pattern


def check_log_offline(args: list[str]) -> None:
    """Refuse a wrong `log` command line (BadInput)."""
    _parse(args)


class NothingDecoded(BadInput):
    """A log in which nothing is a frame of the protocol it was decoded with (exit 2)."""


def _named(records: list[LogRecord]) -> tuple[str, str] | None:
    """(protocol, variant) named by the log's first connection note; None: no such note."""
    for record in records:
        named = connection_protocol(record.note) if record.note else None
        if named is not None:
            return named
    return None


def _protocol_of(path: str, records: list[LogRecord]) -> Protocol:
    """The protocol the log's first connection note names (BadInput: it names none)."""
    named = _named(records)
    if named is None:
        raise BadInput(
            Message(
                "{file} names no protocol (no connection note: a motionctl --log file or a "
                "spy:// capture has none): give --protocol",
                file=path,
            )
        )
    try:
        return create_protocol(named[0], named[1] or None)
    except MotionError as exc:
        raise BadInput(
            Message("{file}: its connection note: {error}", file=path, error=exc)
        ) from None


def _check_decoded(
    path: str, protocol: Protocol, frames: list[DecodedFrame], named: str, traffic: int
) -> None:
    """Refuse (NothingDecoded) a decoding in which no frame is the protocol's."""
    if any(frame.kind in ("frame", "text") for frame in frames):
        return
    hint = (
        Message("its connection notes name {named}", named=named)
        if named and named != protocol.name
        else Message("try another --protocol")
    )
    raise NothingDecoded(
        Message(
            "nothing in {file} decodes as {protocol} ({count} records of traffic, none a "
            "{protocol} frame); {hint}",
            file=path,
            protocol=protocol.name,
            count=traffic,
            hint=hint,
        )
    )


def decode_log(protocol: Protocol | None, args: list[str]) -> dict[str, Any]:
    """The log's frames decoded (those the filter matches, in their line form): by `protocol`
    until a connection note names another, by the notes' protocol where None is given.
    NothingDecoded where none of its traffic is a frame of the protocol."""
    path, pattern = _parse(args)
    log_format, records = read_any_log(path)
    named = _named(records)
    chosen = protocol if protocol is not None else _protocol_of(path, records)
    frames = decode_records(chosen, records)
    traffic = sum(1 for record in records if record.data)
    _check_decoded(path, chosen, frames, named[0] if named is not None else "", traffic)
    lines = [(frame, frame.line()) for frame in frames]
    if pattern is not None:
        lines = [(frame, text) for frame, text in lines if pattern.search(text)]
    return {
        "format": log_format,
        "frames": [frame.as_dict() for frame, _ in lines],
        "text": [text for _, text in lines],
    }
