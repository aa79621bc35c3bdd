"""What a Visiomex move does with its parameters: steps, mm per step, and how long it takes.

The seed-revision firmware (PROTOCOLS.md §2) computes the cycle length (thread pitch, or the
pulley's circumference) once at boot; the steps per cycle (05 × 07) and the step delay (15) are
read at every move; one step is twice the delay plus about 575 µs of loop overhead (the recording:
400 steps end 4.43 s after the write, 100 steps 1.86 s); the Y loop runs param 20's count.
"""

from __future__ import annotations

import math

from drivers.messages import Message
from drivers.protocols.visiomex_params import DEFAULTS

SILENCE = 1.0  # Serial.readString() ends a packet after 1 s without bytes
STEP_OVERHEAD = 0.000575  # s per step beyond the two delays, measured on the recording
_IDS = {
    "x": {"thread": 1, "pulley": 3, "full": 5, "micro": 7, "delay": 15, "accel_steps": 19},
    "y": {"thread": 2, "pulley": 4, "full": 6, "micro": 8, "delay": 16, "accel_steps": 20},
}


def cycle_mm(values: dict[int, float], axis: str) -> float:
    """Millimetres per motor turn: the thread pitch (lead screw), else the pulley's perimeter."""
    ids = _IDS[axis]
    if values.get(27, 1) == 1:
        return values[ids["thread"]]
    return math.pi * values[ids["pulley"]]


def steps_per_cycle(values: dict[int, float], axis: str) -> float:
    """Microsteps per motor turn: full steps × microstepping."""
    ids = _IDS[axis]
    return values[ids["full"]] * values[ids["micro"]]


def step_seconds(values: dict[int, float], axis: str) -> float:
    """One step's time: high and low for the step delay each, plus the loop's overhead."""
    return 2 * values[_IDS[axis]["delay"]] * 1e-6 + STEP_OVERHEAD


def firmware_steps(values: dict[int, float], axis: str, distance_mm: float) -> int:
    """Steps the firmware makes for a distance: from the boot-time cycle, truncated."""
    cycle = cycle_mm(DEFAULTS, axis)
    if cycle <= 0:
        return 0
    return int(abs(distance_mm) / cycle * steps_per_cycle(values, axis))


def move_seconds(values: dict[int, float], dx_mm: float, dy_mm: float) -> float:
    """Stepping time after `FP0001`: X's steps, then Y's.

    The seed revision's Y loop runs param 20's count (0 by default), not Y's steps; counting
    both (the documented behaviour) makes this an upper bound either way.
    """
    x = firmware_steps(values, "x", dx_mm) * step_seconds(values, "x")
    y_steps = max(firmware_steps(values, "y", dy_mm), values[_IDS["y"]["accel_steps"]])
    return x + y_steps * step_seconds(values, "y")


def derived_values(values: dict[int, float]) -> list[tuple[str, str]]:
    """What the technician sees beside the table: steps per turn, mm per step, steps per mm, and
    how long a 10 mm move takes, for X and Y."""
    per_axis: dict[str, list[str]] = {"turn": [], "mm_step": [], "step_mm": [], "ten": []}
    for axis in "xy":
        cycle = cycle_mm(values, axis)
        steps = steps_per_cycle(values, axis)
        if cycle <= 0 or steps <= 0:
            raise ValueError(
                Message(
                    "{axis}: the cycle ({cycle:g} mm) and the steps per turn ({steps:g}) "
                    "must both be above 0",
                    axis=axis.upper(),
                    cycle=cycle,
                    steps=steps,
                )
            )
        name = axis.upper()
        ten_mm = int(10 / cycle * steps) * step_seconds(values, axis) + SILENCE
        per_axis["turn"].append(f"{name} {steps:g}")
        per_axis["mm_step"].append(f"{name} {cycle / steps:.4f} mm")
        per_axis["step_mm"].append(f"{name} {steps / cycle:.3f}")
        per_axis["ten"].append(f"{name} {ten_mm:.2f} s")
    ten = Message("{times} (1 s silence included)", times=" · ".join(per_axis["ten"]))
    return [
        (Message("Microsteps per turn"), " · ".join(per_axis["turn"])),
        (Message("Per step"), " · ".join(per_axis["mm_step"])),
        (Message("Steps per mm"), " · ".join(per_axis["step_mm"])),
        (Message("A 10 mm move"), ten),
    ]
