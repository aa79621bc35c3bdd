"""`motionctl log decode FILE --protocol P [--filter REGEX] [--json]`: a traffic log, decoded."""

from __future__ import annotations

import re
from typing import Any

from drivers.decoding import decode_records
from drivers.errors import BadInput
from drivers.log_reader import read_any_log
from drivers.protocols.base import Protocol

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


def decode_log(protocol: Protocol, args: list[str]) -> dict[str, Any]:
    """The log's frames decoded (those the filter matches, in their line form)."""
    path, pattern = _parse(args)
    log_format, records = read_any_log(path)
    frames = decode_records(protocol, records)
    lines = [(frame, frame.line()) for frame in frames]
    if pattern is not None:
        lines = [(frame, text) for frame, text in lines if pattern.search(text)]
    return {
        "format": log_format,
        "frames": [frame.as_dict() for frame, _ in lines],
        "text": [text for _, text in lines],
    }
