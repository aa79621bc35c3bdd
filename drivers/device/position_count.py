"""The position kept for a device that cannot be asked where it is (Visiomex, Firmata,
pi-frame).

Visiomex and the Firmata stepper have no position feedback and move only by relative packets
or step counts, so where the stage is comes from the moves counted since a Home or Set Home.
The pi-frame has no feedback either and its frames carry absolute targets, so a relative move
is sent as a target reckoned from the position commanded last. Either is kept between runs
(by the panel and motionctl alike); where none is kept, what needs it is refused, never
reckoned from an assumed origin. A move packet is counted as the
firmware reads it: on the seed firmware (@902bd4d, drivers/protocols/README.md §2b "Move packet")
the type letter is never read, so the digits are µm whether the packet says linear, rotational or
steps.
"""

from __future__ import annotations

from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.base import Point, Protocol
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.commands import MoveTo
from drivers.protocols.visiomex.move_digits import firmware_move_mm as firmware_move_mm

COUNTED_PROTOCOLS = frozenset({"visiomex", "firmata"})
# The commands that start from the position kept whatever the device: a program (its first
# move, its arcs), an arc (its start and Z); `move` too where the device moves only by relative
# distances, `jog` where it moves only to absolute targets (pi-frame), `home` where it has
# neither a home move nor absolute moves.
_NEEDS_COUNT = frozenset({"position", "run", "arc"})
# Packet variants whose move digits this firmware reads as µm whatever the type letter.


class NoCount(BadInput):
    """A command that needs the counted position, where no count is kept."""


def keeps_count(protocol: Protocol) -> bool:
    """Whether the position of this protocol's devices is kept between runs (counted or
    commanded: they cannot be asked)."""
    return keeps_position(protocol.capabilities)


def keeps_position(caps: Capabilities) -> bool:
    """Whether a device's position is kept between runs: it cannot be asked where it is, so
    it is counted (relative moves) or commanded (absolute targets) from a known place."""
    return not caps.position_feedback


def counts_position(protocol: str, caps: Capabilities) -> bool:
    """Whether the position of the devices of the protocol named `protocol` is counted (from a
    Home or Set Home: unknown until then) and kept between runs."""
    return protocol in COUNTED_PROTOCOLS and not caps.position_feedback


def needs_count(command: str, caps: Capabilities) -> bool:
    """Whether `command` starts from the position kept (and is refused without one)."""
    return (
        command in _NEEDS_COUNT
        or (command == "move" and not caps.absolute_moves)
        or (command == "jog" and not caps.relative_moves)
        or (command == "home" and not caps.homing and not caps.absolute_moves)
    )


def starts_count(command: str, caps: Capabilities) -> bool:
    """Whether `command` puts the stage at a known place once it has succeeded: (0, 0, 0), or
    the absolute target of a move."""
    absolute = caps.absolute_moves
    return (
        command == "set-home"
        or (command == "home" and (caps.homing or absolute))
        or (command == "move" and absolute)
    )


def commanded(caps: Capabilities) -> bool:
    """Whether the position kept is the one commanded last (absolute targets), not counted."""
    return caps.absolute_moves and not caps.relative_moves


def resume(protocol: Protocol, here: Point) -> None:
    """The protocol goes on from the position kept (a pi-frame's per-axis speeds and move
    times follow from the position commanded last); BadInput where it cannot be sent from."""
    if commanded(protocol.capabilities):
        protocol.encode(MoveTo(*here))  # on the device's grid, within its range
        protocol.on_sent(MoveTo(*here))


def _how_to_count(caps: Capabilities) -> str:
    """How a count is started on this device."""
    if commanded(caps):
        return Message(
            "its frames carry absolute targets, so a relative move needs the position: Set Home "
            "where the stage stands, Home, or move to an absolute point first (in the panel, or "
            "motionctl set-home, home or move X Y Z)"
        )
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
    how = _how_to_count(protocol.capabilities)
    if commanded(protocol.capabilities):
        return NoCount(
            Message(
                "{command} refused: position unknown: {protocol} cannot be asked where it is "
                "and no commanded position is kept for this port; {how}",
                command=command,
                protocol=protocol.name,
                how=how,
            )
        )
    return NoCount(
        Message(
            "{command} refused: position unknown: {protocol} cannot be asked where it is and no "
            "position is counted for this port; {how}",
            command=command,
            protocol=protocol.name,
            how=how,
        )
    )


def unknown_note(protocol: Protocol) -> str:
    """What is said after a move made without a count: where the stage is stays unknown."""
    how = _how_to_count(protocol.capabilities)
    if commanded(protocol.capabilities):
        return Message(
            "position unknown: {protocol} cannot be asked where it is and no commanded "
            "position is kept for this port; {how}",
            protocol=protocol.name,
            how=how,
        )
    return Message(
        "position unknown: {protocol} cannot be asked where it is and no position is counted "
        "for this port; {how}",
        protocol=protocol.name,
        how=how,
    )


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
