"""How the Visiomex firmware reads a move packet's digits: as µm, whatever its type letter.

The seed and prefixed revisions never read the letter after `M` (drivers/protocols/README.md §2b),
so `MR` and `MS` packets move their digits as µm like `ML`; the driver counts what they really do.
"""

from __future__ import annotations

from drivers.protocols.base import Point, Protocol

_MICROMETRE_VARIANTS = frozenset({"seed", "prefixed"})
_PACKET_LENGTH = 18
_DIGITS = 7


def reads_micrometres(protocol: Protocol) -> bool:
    """Whether this firmware reads a move packet's digits as µm whatever its type letter."""
    variant = protocol.variant.name if protocol.variant is not None else ""
    return protocol.name == "visiomex" and variant in _MICROMETRE_VARIANTS


def firmware_move_mm(protocol: Protocol, packet: bytes) -> Point | None:
    """The distances in mm a move packet makes the firmware go, the type letter ignored as the
    firmware ignores it (None: not a move packet this firmware is known to read so)."""
    if not reads_micrometres(protocol):
        return None
    text = packet.decode("latin-1")
    if len(text) != _PACKET_LENGTH or not text.startswith("M"):
        return None
    distances = []
    for sign_at in (2, 3 + _DIGITS):
        sign, digits = text[sign_at], text[sign_at + 1 : sign_at + 1 + _DIGITS]
        if sign not in "PN" or not digits.isdigit():
            return None
        distances.append((-1 if sign == "N" else 1) * int(digits) / 1000)
    return (distances[0], distances[1], 0.0)
