"""The position readout and views while bridging: what another program's traffic with the device
told (a reply that reported the position, the target of a move it sent), marked as observed."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject

if TYPE_CHECKING:
    from app.window.device.bridge_session import BridgeSession
    from app.window.device.machine_state import MachineState
    from drivers.bridge.watch import Observed


class BridgeReadout(QObject):
    """Shows, for the life of a bridge, where the bridged traffic says the stage is."""

    def __init__(self, machine: MachineState, session: BridgeSession) -> None:
        super().__init__(session)  # goes with the session
        self.machine = machine
        self.seen = False  # a position was observed on this bridge
        session.observed.connect(self.show)
        session.ended.connect(self.end)  # before the window's own end of the bridge is said
        self.start()

    def start(self) -> None:
        """A bridge began: the panel asks nothing, so nothing is known until the traffic says."""
        machine, window = self.machine, self.machine.window
        machine.bridging, self.seen = True, False
        machine.show_target(None)
        window.buffer.break_trail()  # the other program's moves: a segment of their own
        window.readout.clear()
        window.readout.set_status("bridged")

    def show(self, seen: Observed) -> None:
        """A position the traffic told: shown, drawn, and its target marked if it is one."""
        from drivers.bridge.watch import COMMANDED

        machine, window = self.machine, self.machine.window
        if not machine.bridging:
            return
        self.seen = True
        commanded = seen.source == COMMANDED
        machine.last_position = seen.point
        window.readout.set_position(*seen.point)
        window.readout.set_status("observed-target" if commanded else "observed")
        machine.show_target(seen.point if commanded else None)
        window.buffer.append(time.monotonic() - machine.t0, *seen.point)
        machine.show_outside()

    def end(self, _error: str = "") -> None:
        """The bridge ended: what was observed last is the last known position."""
        machine = self.machine
        machine.bridging = False
        machine.show_target(None)
        machine.window.readout.set_status("stale" if self.seen else "live")
