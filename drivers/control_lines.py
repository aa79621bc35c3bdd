"""The serial port's control lines: the outputs the host drives, the inputs the device drives."""

from __future__ import annotations

from dataclasses import dataclass, fields

OUTPUTS = ("dtr", "rts")  # driven by the host
INPUTS = ("cts", "dsr", "cd", "ri")  # driven by the device (or its adapter)
BREAK_S = 0.25  # seconds a break holds the transmit line low (pyserial's default)


@dataclass(frozen=True)
class ControlLines:
    """The state of the six modem lines (True: asserted); None where the port cannot tell.

    DTR and RTS are what the host drives (as last set, or as the port reads them back); CTS,
    DSR, CD (carrier detect) and RI (ring indicator) are what the other end drives.
    """

    dtr: bool | None = None
    rts: bool | None = None
    cts: bool | None = None
    dsr: bool | None = None
    cd: bool | None = None
    ri: bool | None = None

    def describe(self) -> str:
        """`DTR on, RTS off, CTS on, DSR on, CD off, RI off` (`CTS ?` where unknown)."""
        if self.unknown():
            return "no modem control lines"
        return ", ".join(f"{name.upper()} {_word(getattr(self, name))}" for name in _NAMES)

    def unknown(self) -> bool:
        """Whether the port can tell nothing (no line is known)."""
        return all(getattr(self, name) is None for name in _NAMES)

    def changes(self, before: ControlLines) -> list[str]:
        """What differs from `before`, line by line: `["CTS off", "DSR ?"]`."""
        return [
            f"{name.upper()} {_word(getattr(self, name))}"
            for name in _NAMES
            if getattr(self, name) != getattr(before, name)
        ]


_NAMES = tuple(f.name for f in fields(ControlLines))


def _word(value: bool | None) -> str:
    return "?" if value is None else "on" if value else "off"
