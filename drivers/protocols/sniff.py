"""Which protocol bytes from a device read as: a device that answers in another protocol's way
is named ("this looks like a Visiomex controller, not COXIRIS")."""

from __future__ import annotations

import logging

from drivers.errors import MotionError
from drivers.framers.splitter import FrameSplitter
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.events import Event, TextLine, Undecodable
from drivers.protocols.registry import create_protocol, entries

log = logging.getLogger(__name__)


def device_name(protocol: str) -> str:
    """`Visiomex` for "visiomex": the protocol's devices as a sentence names them (its
    declaration's display name; the protocol's name if it has none)."""
    names = {entry.name: entry.display_name for entry in entries()}
    return names.get(protocol) or protocol


def recognised(protocol: Protocol, data: bytes) -> int:
    """How many frames in `data` the protocol reads as something of its own: a reply, a report,
    its boot banner; plain text lines and undecodable frames do not count."""
    try:
        splitter = FrameSplitter(protocol.new_framer())
        # A line the device was still printing when the wait gave up counts too: a Visiomex
        # banner's `Checkpoint 2` can come a few ms before its CR LF.
        frames = splitter.feed(data) + splitter.end()
    except MotionError:
        return 0
    count = 0
    for frame in frames:
        try:
            events: list[Event] = protocol.decode(frame)
        except MotionError:
            continue
        for event in events:
            if protocol.is_restart(event) or not isinstance(event, TextLine | Undecodable):
                count += 1
    return count


def recognised_sent(protocol: Protocol, data: bytes) -> int:
    """How many frames in bytes a host sent the protocol reads as moves its device makes (a
    device that never answers, such as pi-frame's, is known by what it is sent)."""
    try:
        frames = FrameSplitter(protocol.new_tx_framer()).whole(data)[0]
    except MotionError:
        return 0
    count = 0
    for frame in frames:
        try:
            command = protocol.sent_command(frame)
        except MotionError:
            continue
        count += command is not None
    return count


def sniff(data: bytes, expected: str) -> str | None:
    """The protocol, other than `expected`, that reads `data` best, when it reads more of it as
    its own than `expected` does; None when none does (or nothing came)."""
    if not data:
        return None
    scores: dict[str, int] = {}
    for name in (entry.name for entry in entries() if entry.sniff):
        try:
            scores[name] = recognised(create_protocol(name), data)
        except MotionError as exc:  # a protocol that cannot be made is no candidate
            log.debug("sniffing as %s: %s", name, exc)
    own = scores.pop(expected, 0)
    best = max(scores, key=lambda name: scores[name], default=None)
    if best is None or scores[best] <= own:
        return None
    return best


def looks_like(data: bytes, expected: str) -> Message | None:
    """ "this looks like a Visiomex controller, not COXIRIS" when `data` reads as another
    protocol's; None otherwise."""
    found = sniff(data, expected)
    if found is None:
        return None
    return Message(
        "this looks like a {found} controller, not {expected}",
        found=device_name(found),
        expected=device_name(expected),
    )
