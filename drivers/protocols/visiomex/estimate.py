"""How long a Visiomex move takes on the wire, from the firmware model (drivers/protocols/README.md
§2b): the 1 s of silence, the debug lines and `FP0001` going out while stepping starts, then
`FA0001`."""

from __future__ import annotations

from drivers.protocols.visiomex.model import SILENCE, FirmwareState, debug_lines
from drivers.protocols.visiomex.timing import REPLY_LATENCY, move_reply_seconds

FEEDBACK_BYTES = len("FP0001\r\n")


def reply_bytes(state: FirmwareState, x_um: float, y_um: float, bad_directions: int = 0) -> int:
    """Bytes a move prints up to and including `FP0001`: EP0003s, nine debug lines, FP0001."""
    lines = debug_lines(state, x_um, y_um)
    return sum(len(line) + 2 for line in lines) + FEEDBACK_BYTES * (1 + bad_directions)


def after_packet_seconds(reply: int, stepping: float) -> float:
    """Seconds from a move packet's last byte to the end of `FA0001`: the silence, the firmware
    noticing it, `reply` bytes going out while stepping runs, then `FA0001`."""
    return SILENCE + REPLY_LATENCY + move_reply_seconds(reply, stepping)


def move_seconds(state: FirmwareState, x_um: float, y_um: float, bad_directions: int = 0) -> float:
    """Seconds from a move packet's last byte to the end of `FA0001`, without advancing `state`."""
    count = reply_bytes(state, x_um, y_um, bad_directions)
    plan = state.copy().move(x_um, y_um)
    return after_packet_seconds(count, plan.seconds)
