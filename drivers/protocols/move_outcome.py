"""What a move will really do on its device, by the device's own arithmetic, known before it is
sent: where it leaves the stage, what to say when that is not what was asked, and the parameter
values the device recomputes as it moves (Visiomex 15, 16, 19, 20)."""

from __future__ import annotations

from dataclasses import dataclass, field

Point = tuple[float, float, float]


@dataclass(frozen=True)
class MoveOutcome:
    """Where a move leaves the stage, and what comes with it."""

    end: Point
    warning: str = ""
    """Said before the move is sent where it will not go as asked (a Message); "" otherwise."""
    recomputed: dict[str, float] = field(default_factory=dict)
    """Parameters (by name, in interface units) the device holds once the move has run."""
