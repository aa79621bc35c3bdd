"""The driver layer's messages with the positions they state in the operator's units and to the
device's resolution: "stopped at (19.72, 5, 0) mm", or "(0.7765, 0.1969, 0) in", never the raw
"(19.7228, 5, 0) mm". The drivers keep saying mm (motionctl prints them as they are); the window
says them this way. Safe from any thread (no widget is touched)."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.common.messages import localized
from drivers.messages import CONTEXT, Message, fill, message_of
from widgets._i18n import number_text
from widgets._units import INCH, MM_PER_INCH, unit_text

# A position in a message's template: "({x:g}, {y:g}, {z:g}) mm" (the names may be any).
POSITION = re.compile(r"\(\{(\w+):g\}, \{(\w+):g\}, \{(\w+):g\}\) mm")
DEFAULT_DECIMALS = 3  # of a mm, for a device that does not say its resolution


@dataclass(frozen=True)
class Lengths:
    """How lengths are shown: "mm" or "in", and the device's resolution (mm; None: unknown)."""

    units: str = "mm"
    resolution: float | None = None

    def decimals(self) -> int:
        """The decimals shown: the resolution's in mm, two more in inches (at most 4)."""
        mm = DEFAULT_DECIMALS
        if self.resolution is not None and self.resolution > 0:
            mm = max(0, math.ceil(-math.log10(self.resolution) - 1e-9))
        return mm if self.units != INCH else max(0, min(4, mm + 2))

    def text(self, mm: float) -> str:
        """`mm` in the units shown, to their decimals (trailing zeros dropped)."""
        value = mm / MM_PER_INCH if self.units == INCH else mm
        return number_text(value, self.decimals())


def position_localized(value: object, lengths: Lengths) -> str:
    """`value` as `localized` says it, the positions in it in `lengths` (nested messages too);
    a translation that writes the position otherwise is said in mm as the driver wrote it."""
    said = message_of(value)
    if said is None or not said.values:
        return localized(value)
    template = QCoreApplication.translate(CONTEXT, said.template)
    values: dict[str, object] = {
        name: position_localized(item, lengths)
        if isinstance(item, (Message, BaseException))
        else item
        for name, item in said.values.items()
    }
    found = POSITION.search(template)
    if found is not None and all(isinstance(values.get(n), (int, float)) for n in found.groups()):
        names = found.groups()
        for name in names:
            values[name] = lengths.text(float(values[name]))  # type: ignore[arg-type]
        shown = "(" + ", ".join("{" + name + "}" for name in names) + ") "
        shown += unit_text(lengths.units)
        template = template[: found.start()] + shown + template[found.end() :]
    try:
        return fill(template, values)
    except (KeyError, IndexError, ValueError):  # a translation that does not fit: as localized
        return localized(value)
