"""What a protocol can do, so that the application adapts to it."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


class Completion(enum.Enum):
    """How the end of a move becomes known."""

    REPLY = "reply"  # the device's reply says the move ended (or a position poll confirms it)
    FEEDBACK = "feedback"  # a feedback packet arrives when the move ends
    ESTIMATE = "estimate"  # no message: estimated from distance and speed


@dataclass(frozen=True)
class Capabilities:
    """Static description of a protocol's abilities.

    Its texts for the operator (`speed_note`, `home_note`, `notes`) are Messages
    (drivers/messages.py), so that the window shows them in the operator's language.
    """

    axes: tuple[str, ...]
    length_unit: str = "mm"
    speed_unit: str = "mm/s"
    default_baud: int = 115200
    absolute_moves: bool = True
    relative_moves: bool = True
    homing: bool = True
    set_home: bool = True
    speed: bool = True
    speed_range: tuple[float, float] | None = None  # None: ask the device, or unknown
    speed_limits_queryable: bool = False
    speed_readback: bool = True  # False: the speed is only what was last set
    default_speed: float = 10.0  # assumed until set, where the speed cannot be read back
    identity_queryable: bool = True
    position_feedback: bool = True  # False: positions are commanded only
    completion: Completion = Completion.REPLY
    parameters: bool = False
    stop: bool = False  # True: Stop halts a move under way; False: Stop only drops the queue
    resolution: float | None = None  # the finest coordinate step the device represents (mm)
    travel: tuple[tuple[float, float], tuple[float, float], tuple[float, float]] | None = None
    """The travel box in mm where the protocol knows it (None: unknown, set by the user)."""
    busy_silent: bool = False  # the device answers nothing while a blocking move runs
    raw_text: bool = True  # a console send line takes text (True) or hex (False) by default
    raw_line_end: str = "\n"  # what the console appends to a text line by default
    move_kinds: tuple[str, ...] = ("linear",)  # MoveBy kinds: linear, rotational, steps
    speed_decimals: int = 2  # the decimals a speed may have (Visiomex: whole mm/s)
    speed_note: str = ""  # what setting the speed does on this device, where it is not obvious
    speed_fixed: bool = False  # setting the speed changes no move (speed_note says why)
    home_note: str = ""  # how Home is done, where the device has no homing of its own
    speed_in_moves: bool = False  # the speed goes with every move (MoveTo/MoveBy.speed)
    dtr: bool | None = None  # the DTR line the device needs when the port opens (None: as is)
    startup_wait: float = 0.0  # seconds the device needs after the port opens (Arduino reset)
    arcs: bool = False  # Arc moves
    dwell: bool = False  # Dwell on the device
    streaming: bool = False  # programs stream to a queue on the device (grouped, acknowledged)
    notes: tuple[str, ...] = field(default_factory=tuple)
