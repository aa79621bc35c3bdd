"""The serial port's control lines: the outputs the host drives, the inputs the device drives."""

from __future__ import annotations

from dataclasses import dataclass, fields

from drivers.messages import Message

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
            return Message("no modem control lines")
        return Message(
            "{dtr}, {rts}, {cts}, {dsr}, {cd}, {ri}",
            **{name: _state(name, getattr(self, name)) for name in _NAMES},
        )

    def unknown(self) -> bool:
        """Whether the port can tell nothing (no line is known)."""
        return all(getattr(self, name) is None for name in _NAMES)

    def changes(self, before: ControlLines) -> list[str]:
        """What differs from `before`, line by line: `["CTS off", "DSR ?"]`."""
        return [
            _state(name, getattr(self, name))
            for name in _NAMES
            if getattr(self, name) != getattr(before, name)
        ]


_NAMES = tuple(f.name for f in fields(ControlLines))


def _state(name: str, value: bool | None) -> Message:
    """`CTS on`, `CTS off`, `CTS ?` (unknown)."""
    if value is None:
        return Message("{line} ?", line=name.upper())
    if value:
        return Message("{line} on", line=name.upper())
    return Message("{line} off", line=name.upper())
