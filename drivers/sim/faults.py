"""Faults injected into any simulated device, at run time: hang, slow, garbage, wrong reply, reboot.

`FaultyDevice` wraps a device (it has the methods a `PtyServer` calls) and changes what crosses
the line, for every protocol alike. `control(line)` applies one fault command; it may be called
from another thread (motionsim reads them on stdin). A reboot replaces the device by a fresh one,
as a power cycle loses everything in RAM, and the new one boots (its banner, if any, is printed).
"""

from __future__ import annotations

import random
import threading
import time
from collections import deque
from collections.abc import Callable

from drivers.framers.base import Framer
from drivers.link.control_lines import ControlLines
from drivers.sim.device import SimulatedDevice

FAULT_COMMANDS = {
    "hang": "stop reading and answering (a firmware stuck in a loop)",
    "resume": "read and answer again",
    "slow S": "deliver every byte S seconds late (0 to end)",
    "garbage N": "send N bytes of noise now",
    "wrong": "answer the next reply frame with an earlier, different frame",
    "reboot": "power-cycle: state lost, banner printed again",
    "where": "tell where the simulated axes really are, in the device's own units",
}
MAX_GARBAGE = 1_000_000
MAX_DELAY_S = 60.0
HISTORY = 8  # frames kept to answer with a wrong one


def true_position(device: SimulatedDevice) -> tuple[float, ...]:
    """Where a simulated device's axes are now, in its own units (mm; pi-frame: ticks;
    Firmata: steps), whatever the host was told."""
    steps = getattr(device, "steps", None)
    if callable(steps):  # the Firmata board's one motor
        return (float(steps()),)
    position = getattr(device, "position", None)
    if callable(position):
        return tuple(float(v) for v in position())
    stage = device.stage  # type: ignore[attr-defined]  # COXIRIS
    return tuple(float(v) for v in stage.position(device.clock()))


class FaultError(ValueError):
    """A fault command that is not understood or out of range."""


class FaultyDevice:
    """A simulated device whose line can be made to misbehave while it runs."""

    def __init__(
        self,
        factory: Callable[[], SimulatedDevice],
        framer: Framer | None = None,
        seed: int = 0,
    ) -> None:
        self._factory = factory
        self.device = factory()
        self._framer = framer
        self._random = random.Random(seed)
        self._lock = threading.RLock()
        self.hung = False
        self.delay = 0.0
        self._wrong = False
        self._delayed: deque[tuple[float, bytes]] = deque()
        self._noise = bytearray()
        self._out = b""  # output not yet framed (only while a wrong reply is armed)
        self._history: deque[bytes] = deque(maxlen=HISTORY)
        self.reboots = 0

    @property
    def resets_on_open(self) -> bool:
        """Whether the wrapped board resets when its port opens."""
        return self.device.resets_on_open

    @property
    def default_baud(self) -> int:
        """The wrapped device's line rate."""
        return self.device.default_baud

    # -- what a server calls -----------------------------------------------------------------
    def boot(self) -> None:
        """Power-on of the wrapped device."""
        with self._lock:
            self.device.boot()

    def power_cycle(self) -> None:
        """A reset of the wrapped device (its port opened)."""
        with self._lock:
            self.device.power_cycle()

    def receive(self, data: bytes) -> None:
        """Bytes from the host; a hung device never reads them."""
        with self._lock:
            if not self.hung:
                self.device.receive(data)

    def set_lines(self, dtr: bool, rts: bool) -> None:
        """The host's DTR and RTS reach the wrapped device even when it hangs (a DTR reset is
        hardware; like `reboot`, it leaves the injected faults as they are)."""
        with self._lock:
            resets = self.device.resets
            self.device.set_lines(dtr, rts)
            if self.device.resets != resets:
                self._out = b""  # a frame cut by the reset is never completed

    def modem_inputs(self) -> ControlLines:
        """The wrapped device's modem lines."""
        with self._lock:
            return self.device.modem_inputs()

    def receive_break(self) -> None:
        """A break from the host; a hung device never reads it."""
        with self._lock:
            if not self.hung:
                self.device.receive_break()

    def read_output(self) -> bytes:
        """What the device has sent by now, after the faults."""
        with self._lock:
            out = self.device.read_output()
            if self.hung:
                out = b""
            if self._framer is not None:
                out = self._frames(out)
            if self._noise:
                out, self._noise = bytes(self._noise) + out, bytearray()
            if self.delay or self._delayed:
                return self._late(out)
            return out

    def next_due(self) -> float | None:
        """When something is next due, the delayed bytes and noise included."""
        with self._lock:
            times = [t for t in (self.device.next_due(),) if t is not None]
            if self._delayed:
                times.append(self._delayed[0][0])
            if self._noise:
                times.append(time.monotonic())
            return min(times) if times else None

    # -- control -----------------------------------------------------------------------------
    def control(self, line: str) -> str:
        """Apply one fault command (see FAULT_COMMANDS); returns what was done."""
        words = line.split()
        if not words:
            raise FaultError("empty fault command")
        name, args = words[0].lower(), words[1:]
        with self._lock:
            if name == "hang":
                self.hung = True
            elif name == "resume":
                self.hung = False
            elif name == "slow":
                self.delay = _number(args, 0.0, MAX_DELAY_S, "slow S: seconds")
            elif name == "garbage":
                count = int(_number(args, 1, MAX_GARBAGE, "garbage N: bytes"))
                self._noise += self._random.randbytes(count)
            elif name == "wrong":
                if self._framer is None:
                    raise FaultError("wrong: this device sends no frames to mix up")
                self._wrong = True
            elif name == "reboot":
                lines = self.device.dtr, self.device.rts
                self.device = self._factory()
                self.device.dtr, self.device.rts = lines  # the host's lines stay as they are
                self.device.boot()
                self._out = b""
                self.reboots += 1
            elif name == "where":
                return "where " + " ".join(f"{v:.6g}" for v in true_position(self.device))
            else:
                raise FaultError(f"unknown fault {name!r}; one of: {', '.join(FAULT_COMMANDS)}")
        return " ".join(words)

    # -- helpers -----------------------------------------------------------------------------
    def _frames(self, out: bytes) -> bytes:
        """Keep the last frames sent (as wire bytes); with a wrong reply armed, swap the next."""
        assert self._framer is not None
        buffer, sent = self._out + out, bytearray()
        while buffer:
            used, frame = self._framer.decode(buffer)
            if used == 0:
                break
            wire, buffer = buffer[:used], buffer[used:]
            if frame is not None and self._wrong:
                earlier = next((f for f in reversed(self._history) if f != wire), None)
                if earlier is not None:
                    self._wrong = False
                    sent += earlier
                    continue
            if frame is not None:
                self._history.append(wire)
            sent += wire
        self._out = buffer
        return bytes(sent)

    def _late(self, out: bytes) -> bytes:
        now = time.monotonic()
        if out:
            self._delayed.append((now + self.delay, out))
        due = bytearray()
        while self._delayed and self._delayed[0][0] <= now:
            due += self._delayed.popleft()[1]
        return bytes(due)


def _number(args: list[str], low: float, high: float, usage: str) -> float:
    if len(args) != 1:
        raise FaultError(f"usage: {usage}")
    try:
        value = float(args[0])
    except ValueError:
        raise FaultError(f"{args[0]!r} is not a number ({usage})") from None
    if not low <= value <= high:
        raise FaultError(f"{args[0]} is out of range {low:g} to {high:g} ({usage})")
    return value
