"""The position counted for a device that cannot be asked where it is (Visiomex, Firmata).

Visiomex and the Firmata stepper have no position feedback and move only by relative packets
or step counts, so where the stage is comes from the moves counted since a Home or Set Home.
The count is kept between runs (by the panel and motionctl alike); where none is kept, what
needs it is refused, never reckoned from an assumed origin. A move packet is counted as the
firmware reads it: on the seed firmware (@902bd4d, PROTOCOLS.md §2b "Move packet") the type
letter is never read, so the digits are µm whether the packet says linear, rotational or steps.
"""

from __future__ import annotations

from drivers.capabilities import Capabilities
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.base import Point, Protocol

COUNTED_PROTOCOLS = frozenset({"visiomex", "firmata"})
# The commands that start from the counted position (a relative-only device sends the
# distance from it); `home` too where the device has no home move of its own.
_NEEDS_COUNT = frozenset({"move", "position", "run"})
# Packet variants whose move digits this firmware reads as µm whatever the type letter.
_MICROMETRE_VARIANTS = frozenset({"seed", "prefixed"})
_PACKET_LENGTH = 18
_DIGITS = 7


class NoCount(BadInput):
    """A command that needs the counted position, where no count is kept."""


def keeps_count(protocol: Protocol) -> bool:
    """Whether the position of this protocol's devices is counted and kept between runs."""
    return counts_position(protocol.name, protocol.capabilities)


def counts_position(protocol: str, caps: Capabilities) -> bool:
    """Whether the position of the devices of the protocol named `protocol` is counted (from a
    Home or Set Home: unknown until then) and kept between runs."""
    return protocol in COUNTED_PROTOCOLS and not caps.position_feedback


def needs_count(command: str, caps: Capabilities) -> bool:
    """Whether `command` starts from the counted position (and is refused without one)."""
    return command in _NEEDS_COUNT or (command == "home" and not caps.homing)


def starts_count(command: str, caps: Capabilities) -> bool:
    """Whether `command` puts the stage at a known place: (0, 0, 0) once it has succeeded."""
    return command == "set-home" or (command == "home" and caps.homing)


def _how_to_count(caps: Capabilities) -> str:
    """How a count is started on this device."""
    if caps.homing:
        return Message(
            "Home or Set Home (in the panel, or motionctl home / set-home) to start counting"
        )
    return Message(
        "Set Home where the stage stands (in the panel, or motionctl set-home) to start "
        "counting; with no home move of its own, Home needs a count too"
    )


def no_count(command: str, protocol: Protocol) -> NoCount:
    """The refusal of a command that needs a count, where none is kept for the port."""
    return NoCount(
        Message(
            "{command} refused: position unknown: {protocol} cannot be asked where it is and no "
            "position is counted for this port; {how}",
            command=command,
            protocol=protocol.name,
            how=_how_to_count(protocol.capabilities),
        )
    )


def unknown_note(protocol: Protocol) -> str:
    """What is said after a move made without a count: where the stage is stays unknown."""
    return Message(
        "position unknown: {protocol} cannot be asked where it is and no position is counted "
        "for this port; {how}",
        protocol=protocol.name,
        how=_how_to_count(protocol.capabilities),
    )


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


def kind_note(kind: str, moved: Point) -> str:
    """What a rotational or steps move really does on this firmware."""
    return Message(
        "this firmware reads the digits as µm whatever the type letter ({kind} is not "
        "read): the stage moves X {x:.3f} mm, Y {y:.3f} mm",
        kind=kind,
        x=moved[0],
        y=moved[1],
    )


def no_identity(protocol: Protocol) -> str:
    """What `id` says of a device that cannot be asked who it is."""
    return Message(
        "{protocol} has no identity query: the device cannot be asked what it is",
        protocol=protocol.name,
    )
