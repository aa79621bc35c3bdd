"""Where a Visiomex move packet leaves the stage, by the firmware's own arithmetic
(drivers/protocols/README.md §2b): the step counts truncated in 32-bit floats, X stepping them all,
the Y loop stepping the ramp count R_y (none at power-on), each step a cycle length ÷ (full steps ×
microstepping) long. Also what the move leaves in 15, 16, 19 and 20, and the speed the axes really
step at.
"""

from __future__ import annotations

from dataclasses import dataclass

from drivers.messages import Message
from drivers.protocols.visiomex.model import (
    FULLCYCLE,
    INSTANT,
    MICROSTEP,
    RAMP_COUNT,
    FirmwareState,
)

TOLERANCE = 1e-9  # mm: a distance the steps make exactly


@dataclass(frozen=True)
class FirmwareMove:
    """One move as the firmware makes it: the distances asked and moved (mm, signed), the step
    counts it computed and the steps its loops make, and 15/16/19/20 as it leaves them."""

    asked: tuple[float, float]
    moved: tuple[float, float]
    steps: tuple[int, int]
    loops: tuple[int, int]
    left: dict[int, float]


def step_mm(state: FirmwareState, axis: int) -> float:
    """The length of one step (mm): the boot-time cycle ÷ (full steps × microstepping); 0 where
    the firmware holds no steps per turn."""
    per_turn = int(state.values[FULLCYCLE[axis]]) * int(state.values[MICROSTEP[axis]])
    return state.cycle[axis] / per_turn if per_turn else 0.0


def firmware_move(
    state: FirmwareState, x_um: float, y_um: float, signs: tuple[int, int]
) -> FirmwareMove:
    """A move packet's distances (µm as `atof` read them, unsigned) and directions (+1/-1),
    made from `state` as it is now (not advanced)."""
    trial = state.copy()
    plan = trial.move(x_um, y_um)
    moved = tuple(signs[axis] * plan.loops[axis] * step_mm(state, axis) for axis in (0, 1))
    asked = (signs[0] * x_um / 1000, signs[1] * y_um / 1000)
    left = {i: trial.values[i] for i in (*INSTANT, *RAMP_COUNT)}
    return FirmwareMove(asked, (moved[0], moved[1]), plan.steps, plan.loops, left)


def move_warning(move: FirmwareMove) -> str:
    """What the firmware will not do as asked, said before the packet is sent ("" if it moves
    as asked), e.g. "Y will not move: ...", "X moves 0.975 mm, whole steps"."""
    parts = []
    for axis, name in enumerate("XY"):
        asked, moved = move.asked[axis], move.moved[axis]
        if abs(asked - moved) <= TOLERANCE:
            continue
        if axis == 1 and move.loops[1] == 0:
            parts.append(
                Message(
                    "Y will not move: at these parameters the firmware's Y loop makes no step "
                    "(it runs the ramp count, 0; set 22 and 24 so that the ramp length is above 0)"
                )
            )
        elif axis == 1 and move.loops[1] < move.steps[1]:
            parts.append(
                Message(
                    "Y moves {moved:.3f} mm, not {asked:.3f}: the firmware's Y loop runs the "
                    "ramp count ({loops} of {steps} steps)",
                    moved=moved,
                    asked=asked,
                    loops=move.loops[1],
                    steps=move.steps[1],
                )
            )
        else:
            parts.append(
                Message(
                    "{axis} moves {moved:.3f} mm, not {asked:.3f}: whole steps ({steps}), "
                    "truncated as the firmware counts",
                    axis=name,
                    moved=moved,
                    asked=asked,
                    steps=move.loops[axis],
                )
            )
    return "; ".join(parts) if len(parts) > 1 else (parts[0] if parts else "")


def stepping_speeds(state: FirmwareState) -> tuple[float, float]:
    """The speeds (mm/s) X and Y step at now, outside ramps: an X step is 15 high plus 16 low,
    a Y step 16 twice (0: the delays hold no time)."""
    d15, d16 = state.delays
    x_time, y_time = (d15 + d16) * 1e-6, 2 * d16 * 1e-6
    x = step_mm(state, 0) / x_time if x_time > 0 else 0.0
    y = step_mm(state, 1) / y_time if y_time > 0 else 0.0
    return x, y
