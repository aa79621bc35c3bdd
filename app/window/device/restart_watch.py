"""A device with no boot banner shows a restart only by its idle position: it stood still
(where the last job left it, or for two readings), nothing was sent meanwhile, and now it is at
the power-on origin."""

from __future__ import annotations

from drivers.errors import DeviceRestarted
from drivers.messages import Message

POSITION_TOLERANCE = 1e-6  # mm: readings closer than this are the same position

Point = tuple[float, float, float]


def same(a: Point, b: Point) -> bool:
    """Whether two readings are the same position."""
    return all(abs(p - q) <= POSITION_TOLERANCE for p, q in zip(a, b, strict=True))


class RestartWatch:
    """The idle readings, and the restart they show."""

    def __init__(self) -> None:
        self._position: Point | None = None
        self._stable: Point | None = None  # the reading before

    def forget(self) -> None:
        """Something was sent (a job) or the device was lost: earlier readings prove nothing."""
        self._position = self._stable = None

    def rest_at(self, here: Point) -> None:
        """Where the last job left the stage, as the position it stands still at."""
        self._position = self._stable = here

    def reading(self, here: Point) -> None:
        """An idle reading; DeviceRestarted when it shows the device restarted."""
        before, self._position = self._position, here
        if before is None or self._stable is None:
            self._stable = before
            return
        stood_still = same(before, self._stable)
        self._stable = before
        if stood_still and not same(here, before) and same(here, (0.0, 0.0, 0.0)):
            shown = ", ".join(f"{v:g}" for v in before)
            raise DeviceRestarted(
                Message(
                    "the position went from ({position}) to (0, 0, 0) mm while nothing was sent: "
                    "the device restarted",
                    position=shown,
                )
            )
