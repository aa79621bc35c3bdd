"""The simulated echo-stage: reads lines, moves a two-axis stage, answers when the move ends."""

from __future__ import annotations

from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice
from drivers.sim.stage import Stage
from echo_stage.protocol import MOVE

MAX_LINE = 80


class EchoStageDevice(SimulatedDevice):
    """`instant` moves take no time; `mute` never answers (motionsim passes both to every
    simulator); `speed` is in mm/s."""

    protocol = "echo-stage"
    default_baud = 115200

    def __init__(
        self,
        clock: Clock = monotonic,
        baud: int | None = None,
        *,
        instant: bool = False,
        mute: bool = False,
        speed: float = 20.0,
    ) -> None:
        super().__init__(clock, baud)
        self.stage = Stage(2, speed=speed, instant=instant)
        self.mute = mute
        self._line = bytearray()

    def handle_byte(self, byte: int, t: float) -> None:
        """Collect a line; LF ends it, a CR is ignored, an over-long line is dropped."""
        if self.mute or byte == 0x0D:
            return
        if byte != 0x0A:
            if len(self._line) < MAX_LINE:
                self._line.append(byte)
            return
        line, self._line = self._line.decode("latin-1").strip(), bytearray()
        if line:
            self._execute(line, t)

    def _execute(self, line: str, t: float) -> None:
        if line == "POS?":
            x, y = self.stage.position(t)
            self._say(f"POS {x:.3f} {y:.3f} 0.000", t)
        elif match := MOVE.match(line):
            target = (float(match[1]), float(match[2]))
            duration = self.stage.move_to(target, t)
            self._say(f"OK {target[0]:.3f} {target[1]:.3f}", t + duration)
        else:
            self._say(f"ERR unknown command {line[:20]}", t)

    def _say(self, text: str, t: float) -> None:
        self.emit(text.encode("ascii") + b"\n", t)
