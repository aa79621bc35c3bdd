"""What the Visiomex firmware will really do with a set of parameter values, in the technician's
words: steps per move, how long a move steps, whether Y moves at all, and which written values it
overwrites or never reads (drivers/protocols/README.md §2b).

Every figure comes from the firmware model (visiomex_model.FirmwareState): the values are set on a
freshly booted model in id order, as "Write changed" would send them, and a move is tried on a
copy of it.
"""

from __future__ import annotations

from drivers.messages import Message
from drivers.protocols.visiomex.estimate import after_packet_seconds
from drivers.protocols.visiomex.model import (
    BOOT_ONLY,
    NEVER_READ,
    OVERWRITTEN_AFTER_SET,
    OVERWRITTEN_AT_MOVE,
    POWER_ON,
    FirmwareState,
    debug_lines,
    format_float,
)
from drivers.protocols.visiomex.params import BY_ID
from drivers.protocols.visiomex.timing import MovePlan

OUTPUTS = OVERWRITTEN_AFTER_SET | OVERWRITTEN_AT_MOVE
RAMPED = frozenset({15, 16})  # the current step delays: a ramp leaves them changed
FEEDBACK_LINE = len("FP0001\r\n")
MM_UM, TEN_MM_UM = 1_000, 10_000


def _ids(ids: frozenset[int]) -> str:
    return ", ".join(f"{i:02d}" for i in sorted(ids))


def firmware_after_writing(values: dict[int, float]) -> FirmwareState:
    """The firmware as it would be after power-on and a set of every given input that differs
    from its power-on value (interface units by id, in id order); outputs are not sent."""
    state = FirmwareState.boot()
    for param_id in sorted(values):
        if param_id in OUTPUTS or param_id not in BY_ID:
            continue
        value = values[param_id]
        if value == POWER_ON.get(param_id):
            continue
        state.set(param_id, round(value * BY_ID[param_id].scale))  # the wire's integer
    return state


def timed_move(state: FirmwareState, x_um: float, y_um: float) -> tuple[MovePlan, float]:
    """A move's plan, and the seconds from the packet's last byte to `FA0001`'s last byte
    (1 s of silence, the debug lines and `FP0001`, stepping meanwhile); the state advances."""
    reply = sum(len(line) + 2 for line in debug_lines(state, x_um, y_um)) + FEEDBACK_LINE
    plan = state.move(x_um, y_um)
    return plan, after_packet_seconds(reply, plan.seconds)


def _steps_row(state: FirmwareState) -> tuple[str, str]:
    return Message("Steps per move"), Message(
        "X: 1 mm = {x1}, 10 mm = {x10} · Y: 1 mm = {y1}, 10 mm = {y10} (truncated: the "
        "firmware counts in 32-bit floats)",
        x1=state.steps("x", MM_UM),
        x10=state.steps("x", TEN_MM_UM),
        y1=state.steps("y", MM_UM),
        y10=state.steps("y", TEN_MM_UM),
    )


def _x_row(state: FirmwareState) -> tuple[str, str]:
    trial = state.copy()
    first, total = timed_move(trial, TEN_MM_UM, 0)
    text = Message(
        "{steps} steps, {stepping} s of stepping; FA0001 about {total} s after the packet",
        steps=first.steps[0],
        stepping=format_float(first.seconds),
        total=format_float(total, 1),
    )
    later_state = state.copy()
    later_state.move(TEN_MM_UM, TEN_MM_UM)  # Y's ramp leaves D16, X's low phase, shorter
    later = later_state.move(TEN_MM_UM, 0)
    if abs(later.seconds - first.seconds) > 0.01 * first.seconds:
        text = Message(
            "{text}; after a move in which Y stepped, {later} s (X's low phase is Y's last "
            "delay, {delay} µs: the ramps do not restore the delays)",
            text=text,
            later=format_float(later.seconds),
            delay=later_state.delays[1],
        )
    return Message("A 10 mm X move"), text


def _y_row(state: FirmwareState) -> tuple[str, str]:
    plan = state.copy().move(0, TEN_MM_UM)
    asked, runs = plan.steps[1], plan.loops[1]
    if runs == 0:
        text = Message(
            "no: the firmware's Y loop runs the ramp count (R_y = 0 with these values), not "
            "the {asked} steps a 10 mm move asks for; set 22 and 24 so that the ramp length "
            "is above 0 (e.g. 22 = 6000, 24 = 1)",
            asked=asked,
        )
    else:
        text = Message(
            "{runs} of the {asked} steps of a 10 mm Y move, {seconds} s: the firmware's Y loop "
            "runs the ramp count R_y (at most the ramp length {ramp}), not the distance, and "
            "speeds up without slowing down",
            runs=runs,
            asked=asked,
            seconds=format_float(plan.y_seconds, 3),
            ramp=state.ramp[1],
        )
    return Message("Y moves"), text


def _ramp_row(state: FirmwareState) -> tuple[str, str]:
    ramp_x, ramp_y = state.ramp
    if not ramp_x and not ramp_y:
        text = Message(
            "none: the ramp length is 0 on both axes (it follows 21 ÷ 23 and 13 - 11); every "
            "X step takes 15 high plus 16 low"
        )
    else:
        text = Message(
            "X over {x} steps, Y over {y} steps, between 13/14 (slow) and 11/12 (fast)",
            x=ramp_x,
            y=ramp_y,
        )
    return Message("Ramps"), text


def _unused_row(values: dict[int, float]) -> tuple[str, str] | None:
    unused = [
        BY_ID[i].name
        for i in sorted(values)
        if i in NEVER_READ | BOOT_ONLY and i in POWER_ON and values[i] != POWER_ON[i]
    ]
    if not unused:
        return None
    return Message("Not used"), Message(
        "{names}: the values in the table differ from power-on, but this firmware does not "
        "use them",
        names=", ".join(unused),
    )


def derived_values(values: dict[int, float]) -> list[tuple[str, str]]:
    """What the technician sees under the parameter table: (label, text) pairs, as Messages."""
    state = firmware_after_writing(values)
    rows = [_steps_row(state), _x_row(state), _y_row(state), _ramp_row(state)]
    rows += [
        (
            Message("Overwritten after every set"),
            Message(
                "{ids}: the firmware recomputes them; a written value does not stay",
                ids=_ids(OVERWRITTEN_AFTER_SET),
            ),
        ),
        (
            Message("Overwritten at every move"),
            Message("{ids}: the ramp counts of the last move", ids=_ids(OVERWRITTEN_AT_MOVE)),
        ),
        (
            Message("Never read"),
            Message(
                "{ids}: writing them changes nothing (27 is forced to 1 after every set)",
                ids=_ids(NEVER_READ),
            ),
        ),
        (
            Message("Read only at boot"),
            Message(
                "{ids}: the cycle length ({cycle} mm) is taken from them at power-on, when they "
                "hold their power-on values again: writing them changes no move",
                ids=_ids(BOOT_ONLY),
                cycle=format_float(state.cycle[0]),
            ),
        ),
    ]
    if unused := _unused_row(values):
        rows.append(unused)
    return rows


def write_warning(param_id: int) -> str:
    """What writing this parameter will not do on this firmware ("" if it does what it says);
    a warning shown before sending, not a refusal."""
    if param_id in OVERWRITTEN_AFTER_SET:
        return Message(
            "the firmware recomputes {id} after every set: this value will not stay", id=param_id
        )
    if param_id in OVERWRITTEN_AT_MOVE:
        return Message(
            "the firmware recomputes {id} at every move: this value will not stay", id=param_id
        )
    if param_id == 27:
        return Message("the firmware forces 27 to 1 after every set: this value will not stay")
    if param_id in NEVER_READ:
        return Message(
            "this firmware never reads {id:02d}: writing it changes nothing", id=param_id
        )
    if param_id in RAMPED:
        return Message(
            "a move with ramps (ramp length above 0) leaves {id} at the ramp's last delay: "
            "this value stays only until then",
            id=param_id,
        )
    if param_id in BOOT_ONLY:
        return Message(
            "this firmware reads {id:02d} only at boot, when it holds {value} again: writing "
            "it changes no move",
            id=param_id,
            value=BY_ID[param_id].with_unit(POWER_ON[param_id]),
        )
    return ""
