"""The steps of a point program as the device stack runs and checks them: points and dwells.

Read from CSV and JSON by drivers/toolpath/point_program.py, which names them too.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class ProgramPoint:
    """One point of a program."""

    x: float
    y: float
    z: float
    speed: float


@dataclass(frozen=True)
class ProgramDwell:
    """A pause of `ms` milliseconds in a streamed program (the device's queue waits)."""

    ms: int
