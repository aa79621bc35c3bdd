"""The COXIRIS device as its CommandParser firmware behaves on the wire (drivers/protocols/README.md
§1)."""

from __future__ import annotations

import re

from drivers.sim.arduino import print_float, to_float32
from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice
from drivers.sim.stage import Stage

DEVICE_ID = "CX25F7TK9P"
BUFFER_SIZE = 64  # the parser keeps 63 characters; the 64th before a terminator overflows
# Only CR or LF ends a line. A NUL is stored like any other character (it counts toward the 63),
# but the parser reads the line as a C string: the command ends at the first NUL
# (drivers/protocols/README.md §1).
LINE_ENDS = frozenset(b"\r\n")
_NUMBER = re.compile(rb"[+-]?(?:\d+\.?\d*|\.\d+)")

HELP_LINES = (
    "HELP - Displays this help message",
    "SET_HOME - Sets current position as home (0,0,0)",
    "GO_HOME - Moves to home position (0,0,0)",
    "ABSOLUTE_MOVE x y z - Moves to absolute position x, y, z",
    "DELTA_MOVE dx dy dz - Moves relative to current position by dx, dy, dz",
    "GET_POSITION - Returns current position",
    "SET_SPEED speed - Sets movement speed to speed in mm/s",
    "GET_SPEED - Returns current movement speed in mm/s",
    "GET_MIN_SPEED - Returns minimum allowed movement speed in mm/s",
    "GET_MAX_SPEED - Returns maximum allowed movement speed in mm/s",
    "GET_ID - Returns the unique device identifier",
    "CHECK_ERRORS - Performs system diagnostics and reports any errors",
)
_HELP_BLOCK = "Available commands:\r\n" + "".join(line + "\r\n" for line in HELP_LINES)

_MOVE_USAGE = {
    b"ABSOLUTE_MOVE": ("ABSOLUTE_MOVE x y z", "x, y, z"),
    b"DELTA_MOVE": ("DELTA_MOVE dx dy dz", "dx, dy, dz"),
}


class CoxirisDevice(SimulatedDevice):
    """CommandParser firmware plus a sketch driving a 3-axis stage.

    `blocking=True` (the default) reproduces a sketch whose move callback blocks: `DONE` comes
    when the move ends and nothing else is read meanwhile. `blocking=False` answers `DONE` at once
    and moves in the background, so `GET_POSITION` reports positions along the way.
    `faults` are reported by CHECK_ERRORS; `mute` makes a device that never answers.
    """

    protocol = "coxiris"
    default_baud = 115200

    def __init__(
        self,
        clock: Clock = monotonic,
        baud: int | None = None,
        *,
        blocking: bool = True,
        instant: bool = False,
        speed: float = 10.0,
        min_speed: float = 1.0,
        max_speed: float = 100.0,
        faults: tuple[str, ...] = (),
        mute: bool = False,
        chatter: float = 0.0,
    ) -> None:
        super().__init__(clock, baud)
        if not 0.0 <= chatter <= 100_000.0:
            raise ValueError(f"chatter={chatter}: 0 to 100000 debug lines a second")
        self.chatter = chatter  # lines/s of debug output, as a sketch with its prints left on
        self._chatter_next: float | None = None
        self._chatter_count = 0
        self.blocking = blocking
        self.stage = Stage(3, speed=to_float32(speed), instant=instant)
        self.min_speed = min_speed
        self.max_speed = max_speed
        self.faults = list(faults)
        self.mute = mute
        self._line = bytearray()

    def boot(self) -> None:
        """Start the debug chatter, if any."""
        super().boot()
        if self.chatter:
            self._chatter_next = self.clock() + 1.0 / self.chatter

    def wake_at(self) -> float | None:
        """When the next debug line is due."""
        return self._chatter_next

    def tick(self, now: float) -> None:
        """Print the debug lines due by `now` (one write, like a burst of Serial.print)."""
        if self._chatter_next is None:
            return
        period, lines = 1.0 / self.chatter, []
        while self._chatter_next <= now:
            self._chatter_count += 1
            lines.append(f"dbg {self._chatter_count} loop ok\r\n")
            self._chatter_next += period
        self.emit("".join(lines).encode("ascii"), now)

    # -- the parser ----------------------------------------------------------------------
    def handle_byte(self, byte: int, t: float) -> None:
        """CommandParser.read(): collect a line (a NUL too); CR or LF ends it."""
        if self.mute:
            return
        if byte in LINE_ENDS:
            line, self._line = bytes(self._line), bytearray()
            self._execute(line, t)
            return
        if len(self._line) >= BUFFER_SIZE - 1:
            self._line.clear()
            self._say("ERROR: Command too long", t)
            # The parser then drops what has arrived of this line, up to its line end; what
            # arrives later starts a new command (drivers/protocols/README.md §1), as does a next
            # line already received (issue 11).
            self.discard_available(t, until=LINE_ENDS)
            return
        self._line.append(byte)

    def _say(self, text: str, t: float) -> None:
        self.emit(text.encode("latin-1") + b"\r\n", t)

    def _execute(self, raw: bytes, t: float) -> None:
        line = raw.split(b"\0", 1)[0].strip(b" \t\r\n\v\f").upper()
        if not line:
            return
        name, _, rest = line.partition(b" ")
        params = [p for p in rest.split(b" ") if p]
        handler = _HANDLERS.get(name)
        if handler is None:
            text = "ERROR: Unknown command - \r\n" + name.decode("latin-1") + "\r\n" + _HELP_BLOCK
            self.emit(text.encode("latin-1"), t)
            return
        command = name.decode("ascii")
        self._say(f"ACK {command}", t)
        done_at, data = handler(self, params, t)
        self._say(f"DONE {command}" + (f": {data}" if data is not None else ""), done_at)

    # -- the sketch's callbacks -------------------------------------------------------------
    def _position_text(self, t: float) -> str:
        return " ".join(print_float(to_float32(v), 2) for v in self.stage.position(t))

    def _move(self, name: bytes, params: list[bytes], t: float) -> float:
        usage, names = _MOVE_USAGE[name]
        if len(params) < 3:
            self._say(f"ERROR: Missing parameters - Usage: {usage}", t)
            return t
        if not all(_NUMBER.fullmatch(p) for p in params[:3]):
            self._say(
                f"ERROR: Invalid number format - Usage: {usage} (where {names} are numbers)", t
            )
            return t
        values = [to_float32(float(p)) for p in params[:3]]
        if name == b"DELTA_MOVE":
            here = self.stage.target() if self.blocking else self.stage.position(t)
            values = [to_float32(a + b) for a, b in zip(here, values, strict=True)]
        return self._go(tuple(values), t)

    def _go(self, target: tuple[float, ...], t: float) -> float:
        duration = self.stage.move_to(target, t)
        if self.blocking:
            self.busy_until = t + duration
            return t + duration
        return t

    def cmd_help(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """HELP: the command list between ACK and DONE."""
        self.emit(_HELP_BLOCK.encode("latin-1"), t)
        return t, None

    def cmd_set_home(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """SET_HOME: the current position becomes (0, 0, 0)."""
        self.stage.set_position((0.0, 0.0, 0.0), t)
        return t, None

    def cmd_go_home(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """GO_HOME: a move to (0, 0, 0)."""
        return self._go((0.0, 0.0, 0.0), t), None

    def cmd_absolute_move(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """ABSOLUTE_MOVE x y z."""
        return self._move(b"ABSOLUTE_MOVE", params, t), None

    def cmd_delta_move(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """DELTA_MOVE dx dy dz."""
        return self._move(b"DELTA_MOVE", params, t), None

    def cmd_get_position(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """GET_POSITION: three numbers with two decimals."""
        return t, self._position_text(t)

    def cmd_set_speed(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """SET_SPEED s: positive number; this sketch also keeps it within its min/max."""
        if not params:
            self._say("ERROR: Missing parameter - Usage: SET_SPEED speed", t)
        elif not _NUMBER.fullmatch(params[0]):
            self._say(
                "ERROR: Invalid number format - Usage: SET_SPEED speed (where speed is a number)",
                t,
            )
        else:
            speed = to_float32(float(params[0]))
            if speed <= 0:
                self._say(
                    "ERROR: Speed must be positive - Usage: SET_SPEED speed (where speed > 0)", t
                )
            elif not self.min_speed <= speed <= self.max_speed:
                low, high = print_float(self.min_speed, 0), print_float(self.max_speed, 0)
                self._say(f"ERROR: Speed out of range ({low} to {high} mm/s)", t)
            else:
                self.stage.speed = speed
        return t, None

    def cmd_get_speed(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """GET_SPEED: printed with no decimals, so 12.5 reads 13."""
        return t, print_float(self.stage.speed, 0)

    def cmd_get_min_speed(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """GET_MIN_SPEED."""
        return t, print_float(self.min_speed, 0)

    def cmd_get_max_speed(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """GET_MAX_SPEED."""
        return t, print_float(self.max_speed, 0)

    def cmd_get_id(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """GET_ID."""
        return t, DEVICE_ID

    def cmd_check_errors(self, params: list[bytes], t: float) -> tuple[float, str | None]:
        """CHECK_ERRORS: one ERROR line per injected fault."""
        for fault in self.faults:
            self._say(f"ERROR: {fault}", t)
        return t, None


_HANDLERS = {
    b"HELP": CoxirisDevice.cmd_help,
    b"SET_HOME": CoxirisDevice.cmd_set_home,
    b"GO_HOME": CoxirisDevice.cmd_go_home,
    b"ABSOLUTE_MOVE": CoxirisDevice.cmd_absolute_move,
    b"DELTA_MOVE": CoxirisDevice.cmd_delta_move,
    b"GET_POSITION": CoxirisDevice.cmd_get_position,
    b"SET_SPEED": CoxirisDevice.cmd_set_speed,
    b"GET_SPEED": CoxirisDevice.cmd_get_speed,
    b"GET_MIN_SPEED": CoxirisDevice.cmd_get_min_speed,
    b"GET_MAX_SPEED": CoxirisDevice.cmd_get_max_speed,
    b"GET_ID": CoxirisDevice.cmd_get_id,
    b"CHECK_ERRORS": CoxirisDevice.cmd_check_errors,
}
