"""Where a traffic log came from: the protocol and port its notes name and whose side of the link
it was written on; for a file that names none, the protocol its traffic reads as.

Every log the product writes opens with a connection note the readers parse
(drivers/traffic/decoding.py
`connection_protocol`): `connected to PORT (PROTOCOL [VARIANT], N baud)`. A simulator's record
(`motionsim --record`) is the device's side of the link, its TX what the device sent: its note
says so (`DEVICE_SIDE`), and `host_view` turns such records round, so that they decode as the
host's (TX sent to the device, RX its replies). A file that names no protocol (a spy:// capture,
a log of an older version) is read by each protocol in turn (drivers/protocols/sniff.py) and
taken as the host's side (a record of an older motionsim, without its note, decodes turned round).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass

from drivers.errors import MotionError
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.registry import create_protocol, get_protocol_class, protocol_names
from drivers.protocols.sniff import recognised, recognised_sent
from drivers.traffic.decoding import connection_protocol
from drivers.traffic.log_records import LogRecord

__all__ = [
    "DEVICE_SIDE",
    "Origin",
    "connection_note",
    "device_side_note",
    "host_view",
    "origin_of",
    "sniff_log",
]

DEVICE_SIDE = "the device's side of the link"
"""What a record's connection note says when its TX is what the device sent."""
SNIFF_BYTES = 65_536  # of each direction, from the start of the log, read by every protocol
_FLIPPED = {"tx": "rx", "rx": "tx"}


@dataclass(frozen=True)
class Origin:
    """The protocol (and variant, "" for the first) a log is decoded with; `how`: "named" (by
    its note), "recognised" (from its traffic) or "given"; `device_side`: its TX is what the
    device sent; `frames`: how many frames the protocol recognised (when recognised)."""

    protocol: str
    variant: str = ""
    how: str = "named"
    device_side: bool = False
    frames: int = 0

    def shown(self) -> str:
        """`visiomex seed`, `firmata`: the protocol as the connection note writes it."""
        return f"{self.protocol} {self.variant}".strip()

    def describe(self, source: str) -> Message:
        """What was chosen for a log that names no protocol, said to the user."""
        return Message(
            "{source} names no protocol: decoded as {protocol}, which its traffic reads as "
            "({frames} frames recognised)",
            source=source,
            protocol=self.shown(),
            frames=self.frames,
        )


def _shown(protocol: Protocol) -> str:
    return f"{protocol.name} {protocol.variant.name}" if protocol.variant else protocol.name


def connection_note(port: str, protocol: Protocol, baud: int) -> str:
    """`connected to sim://firmata (firmata, 57600 baud)`: the note that names a log's protocol."""
    return f"connected to {port} ({_shown(protocol)}, {baud} baud)"


def device_side_note(port: str, protocol: Protocol, baud: int) -> str:
    """A simulator's record's note: its connection, and that TX is what the device sent."""
    return (
        f"{connection_note(port, protocol, baud)}, {DEVICE_SIDE}: TX is what the device sent, "
        "RX what it read"
    )


def _named(note: str) -> Origin | None:
    named = connection_protocol(note) if note else None
    if named is None:
        return None
    return Origin(named[0], named[1], "named", DEVICE_SIDE in note)


def host_view(records: Iterable[LogRecord]) -> Iterator[LogRecord]:
    """The records as the host saw them: after a connection note of the device's side, each
    direction turned round, until a connection note of the host's side."""
    flipped = False
    for record in records:
        named = _named(record.note)
        if named is not None:
            flipped = named.device_side
        if flipped and record.direction:
            record = LogRecord(record.time, _FLIPPED[record.direction], record.data, record.note)
        yield record


def _candidates(names: Sequence[str]) -> Iterator[tuple[str, str]]:
    """(protocol, variant) for each protocol named and each of its wire variants."""
    for name in names:
        try:
            variants = [v.name for v in get_protocol_class(name).variants] or [""]
        except MotionError:
            continue
        yield from ((name, variant) for variant in variants)


def sniff_log(records: Iterable[LogRecord], names: Sequence[str] = ()) -> Origin | None:
    """The protocol (of `names`, default all) whose decoder recognises most of the frames the
    log received (then of the moves it sent); None when no protocol recognises any."""
    streams = {"tx": bytearray(), "rx": bytearray()}
    for record in records:
        stream = streams.get(record.direction)
        if stream is not None and len(stream) < SNIFF_BYTES:
            stream += record.data[: SNIFF_BYTES - len(stream)]
        if all(len(s) >= SNIFF_BYTES for s in streams.values()):
            break
    best: Origin | None = None
    best_score = (0, 0)
    for name, variant in _candidates(list(names) or protocol_names()):
        try:
            protocol = create_protocol(name, variant or None)
        except MotionError:
            continue
        score = (
            recognised(protocol, bytes(streams["rx"])),
            recognised_sent(protocol, bytes(streams["tx"])),
        )
        if score > best_score:
            best, best_score = Origin(name, variant, "recognised", False, sum(score)), score
    return best


def origin_of(records: Sequence[LogRecord], given: Protocol | None = None) -> Origin | None:
    """How the log is to be decoded: by the protocol given, else by its first connection note's,
    else by the one its traffic reads as (the side it was written on told by its notes: a log
    that names none is the host's); None: it names none and no protocol recognises it."""
    named = next((o for o in map(_named, (r.note for r in records)) if o is not None), None)
    if given is not None:
        variant = given.variant.name if given.variant else ""
        return Origin(given.name, variant, "given", named is not None and named.device_side)
    return named if named is not None else sniff_log(records)
