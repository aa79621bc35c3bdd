"""The 27 Visiomex VMR2P0R0001 parameters (drivers/protocols/README.md §2, seed `001_*`).

Scaling: the seed gives only the pulley diameter (mm×10: 38.2 mm -> `000382`); every other value
is a whole number of its unit on the wire (project decision). Defaults are what the firmware
holds at power-on after its boot recalculation (drivers/protocols/README.md §2b,
`visiomex_model.POWER_ON`): a move of 10 mm is 400 steps (10 mm thread, 400 full steps, ×1
microstepping), 4000 µs delays.
"""

from __future__ import annotations

from typing import TypedDict, Unpack

from drivers.messages import Message, message_template
from drivers.protocols.parameters import Parameter
from drivers.protocols.visiomex.model import POWER_ON

DRIVING_MECHANISM_ID = 27
SPEED_IDS = (21, 22)
_AXIS_WORD = {"x": "X", "y": "Y"}


class _Options(TypedDict, total=False):
    """Parameter's fields a pair may set besides its default."""

    scale: int
    digits: int
    output: bool
    maximum_value: float | None


def _pair(
    first_id: int, name: str, unit: str, text: str, default: float, **options: Unpack[_Options]
) -> tuple[Parameter, Parameter]:
    """The X and Y parameters of one kind: ids `first_id` and `first_id + 1`; `text` is a
    message_template whose `{axis}` each gets its axis in."""
    x, y = (
        Parameter(
            first_id + index,
            f"{name}_{axis}",
            unit,
            Message(text, axis=_AXIS_WORD[axis]),
            default=default,
            **options,
        )
        for index, axis in enumerate("xy")
    )
    return x, y


PARAMETERS: tuple[Parameter, ...] = (
    *_pair(
        1,
        "thread_distance",
        "mm",
        message_template("Lead-screw pitch of the {axis} axis (mm per turn)"),
        POWER_ON[1],
    ),
    *_pair(
        3,
        "pulley_diameter",
        "mm",
        message_template(
            "Belt pulley diameter of the {axis} axis; sent as mm×10 (38.2 mm -> 000382)"
        ),
        POWER_ON[3],
        scale=10,
    ),
    *_pair(
        5,
        "motor_fullcycle_step",
        "steps",
        message_template("Full steps per motor turn, {axis} axis"),
        POWER_ON[5],
    ),
    *_pair(
        7,
        "microstep_coeff",
        "×",
        message_template("Microstepping factor of the {axis} driver"),
        POWER_ON[7],
    ),
    *_pair(
        9,
        "max_speed",
        "mm/s",
        message_template("Highest speed allowed on the {axis} axis"),
        POWER_ON[9],
    ),
    *_pair(
        11,
        "step_delay_speed_steady",
        "µs",
        message_template("Step delay at the steady speed, {axis} axis (computed by the firmware)"),
        POWER_ON[11],
        output=True,
    ),
    *_pair(
        13,
        "step_delay_speed_min",
        "µs",
        message_template("Step delay at the lowest speed, {axis} axis"),
        POWER_ON[13],
    ),
    *_pair(
        15,
        "step_delay_instantaneous",
        "µs",
        message_template(
            "Current step delay, {axis} axis (left by the firmware's ramps; this revision times "
            "an X step as 15 high plus 16 low, a Y step as 16 twice)"
        ),
        POWER_ON[15],
    ),
    *_pair(
        17,
        "step_delay_acceleration_avg",
        "µs",
        message_template(
            "Mean step delay while accelerating, {axis} axis (computed by the firmware)"
        ),
        POWER_ON[17],
        output=True,
    ),
    *_pair(
        19,
        "step_count_acceleration",
        "steps",
        message_template("Steps spent accelerating, {axis} axis (computed by the firmware)"),
        POWER_ON[19],
        output=True,
    ),
    *_pair(
        21,
        "input_speed_steady",
        "mm/s",
        message_template("Requested steady speed of the {axis} axis"),
        POWER_ON[21],
    ),
    *_pair(
        23,
        "input_acceleration",
        "mm/s²",
        message_template("Requested acceleration of the {axis} axis"),
        POWER_ON[23],
    ),
    *_pair(
        25,
        "delta_t",
        "s",
        message_template("Duration of the last move, {axis} axis (computed by the firmware)"),
        POWER_ON[25],
        output=True,
    ),
    Parameter(
        DRIVING_MECHANISM_ID,
        "driving_mechanism",
        "",
        Message("0 belt pulley, 1 lead screw (this firmware forces 1 after every set)"),
        default=1,
        maximum_value=1,
    ),
)
assert [p.id for p in PARAMETERS] == list(range(1, 28))

BY_ID = {p.id: p for p in PARAMETERS}
DEFAULTS: dict[int, float] = {p.id: p.default for p in PARAMETERS}
