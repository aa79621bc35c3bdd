"""`motionctl log decode FILE [--protocol P] [--filter REGEX] [--json]`: a traffic log, decoded by
the protocol given, else by the one its connection notes name, else by the one its traffic reads
as (drivers/traffic/log_origin.py); a simulator's record as the host's side of the link."""

from __future__ import annotations

import logging
import re
from collections.abc import Callable
from typing import Any

from drivers.errors import BadInput, MotionError
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.registry import create_protocol
from drivers.traffic.decoding import DecodedFrame, decode_records
from drivers.traffic.log_origin import Origin, host_view, origin_of
from drivers.traffic.log_reader import LogRecord, read_any_log

log = logging.getLogger("motionctl")

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


def _origin(path: str, records: list[LogRecord], given: Protocol | None) -> Origin:
    """The protocol to decode with and the side the log was written on (BadInput: it names no
    protocol, none was given and no protocol recognises its traffic)."""
    origin = origin_of(records, given)
    if origin is None:
        raise BadInput(
            Message(
                "{file} names no protocol (no connection note) and no protocol recognises its "
                "traffic: give --protocol",
                file=path,
            )
        )
    return origin


def _protocol_of(path: str, origin: Origin, given: Protocol | None) -> Protocol:
    """The protocol given, else the one the log names or its traffic reads as."""
    if given is not None:
        return given
    try:
        return create_protocol(origin.protocol, origin.variant or None)
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


def _warn(text: object) -> None:
    log.warning("%s", text)


def decode_log(
    protocol: Protocol | None, args: list[str], notice: Callable[[object], None] | None = None
) -> dict[str, Any]:
    """The log's frames decoded (those the filter matches, in their line form): by `protocol`
    until a connection note names another, by the notes' protocol where None is given, by the
    one its traffic reads as where it names none (`notice` says which). A simulator's record
    is decoded as the host's side. NothingDecoded where none of its traffic is a frame of the
    protocol."""
    path, pattern = _parse(args)
    log_format, read = read_any_log(path)
    origin = _origin(path, read, protocol)
    if origin.how == "recognised":  # said on stderr, as motionctl's warnings are
        (notice or _warn)(origin.describe(path))
    records = list(host_view(read))
    chosen = _protocol_of(path, origin, protocol)
    frames = decode_records(chosen, records)
    traffic = sum(1 for record in records if record.data)
    named = origin.protocol if origin.how == "named" else ""
    _check_decoded(path, chosen, frames, named, traffic)
    lines = [(frame, frame.line()) for frame in frames]
    if pattern is not None:
        lines = [(frame, text) for frame, text in lines if pattern.search(text)]
    return {
        "format": log_format,
        "protocol": origin.shown() if protocol is None else chosen.name,
        "chosen_by": origin.how,
        "device_side": origin.device_side,
        "frames": [frame.as_dict() for frame, _ in lines],
        "text": [text for _, text in lines],
    }
