"""The speed moves go at: as the device reports it, set only within the device's limits."""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable

from drivers.device.client import Client
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.protocols.capabilities import Capabilities

log = logging.getLogger(__name__)


class Speed:
    """A device's speed: read back where it can be, else as last set; limits as it allows."""

    def __init__(
        self,
        client: Client,
        set_parameter: Callable[[str | int, float], object],
        notify: Callable[[str], None],
    ) -> None:
        self.client = client
        self._set_parameter = set_parameter
        self._notify = notify
        self.last: float | None = None
        """The speed last set or read back (None: neither yet)."""
        self._limits: tuple[float, float] | None = None

    @property
    def capabilities(self) -> Capabilities:
        """The protocol's capabilities as they are now (settings may change them)."""
        return self.client.protocol.capabilities

    def read(self) -> float:
        """The speed as the device reports it (or as last set, where it cannot be read back)."""
        if not self.capabilities.speed_readback:
            real = self.client.protocol.moving_speed()  # Visiomex: its step delays' speed
            if real is not None:
                return real
            return self.last if self.last is not None else self.capabilities.default_speed
        value = self._number(cmd.GetSpeed())
        self.last = value
        return value

    def current(self) -> float:
        """The speed last set or read back, else as the device reports it now."""
        return self.last if self.last is not None else self.read()

    def _number(self, command: cmd.Command) -> float:
        """A query's reply value, as a float (float's error where it is not a number)."""
        # Reply.value is an object: which query gets a number is each protocol's to say.
        return float(self.client.execute(command).value)  # type: ignore[arg-type]

    def limits(self) -> tuple[float, float]:
        """The lowest and highest speed the device allows."""
        if self._limits is None:
            if self.capabilities.speed_limits_queryable:
                low = self._number(cmd.GetMinSpeed())
                high = self._number(cmd.GetMaxSpeed())
                self._limits = (low, high)
            elif self.capabilities.speed_range is not None:
                return self.capabilities.speed_range  # not kept: settings may change it
            else:
                raise BadInput(
                    Message(
                        "{protocol} has no speed limits to report",
                        protocol=self.client.protocol.name,
                    )
                )
        return self._limits

    def set(self, speed: float) -> float:
        """Set the speed, refused outside the device's limits; returns what the device reports.

        The limits are asked of the device first where the protocol can (COXIRIS: two queries),
        so an out-of-range speed is refused without SET_SPEED being sent. Where the protocol
        sets the speed as parameters (Visiomex 21 and 22), each is written and reported.
        """
        if not math.isfinite(speed) or speed <= 0:
            raise BadInput(
                Message("speed {speed:g} refused: the speed must be a positive number", speed=speed)
            )
        low, high = self.limits()
        unit = self.capabilities.speed_unit
        if not low <= speed <= high:
            raise BadInput(
                Message(
                    "speed {speed:g} {unit} refused: the device allows {low:g} to {high:g} {unit}",
                    speed=speed,
                    unit=unit,
                    low=low,
                    high=high,
                )
            )
        fixed = self.client.protocol.moving_speed()
        if fixed is not None and math.isclose(speed, fixed):
            return fixed  # the device moves so already (a program's end setting it back)
        # Where the speed goes with every move (pi-frame, Firmata), nothing is sent now.
        speed_in_moves = self.capabilities.speed_in_moves
        parts = [] if speed_in_moves else self.client.protocol.expand(cmd.SetSpeed(speed))
        for part in parts:
            self.client.protocol.encode(part)  # every packet checked before the first is sent
        for part in parts:
            if isinstance(part, cmd.SetParameter):
                self._set_parameter(part.param_id, part.value)
            else:
                self.client.execute(part)
        self.last = speed
        if fixed is not None:  # Visiomex: 21/22 are written, its step delays time the steps
            real = self.client.protocol.moving_speed()
            assert real is not None
            self._notify(
                Message(
                    "speed {speed:g} {unit} written, but this firmware times its steps from its "
                    "step delays (15, 16) alone: moves go at {real:.3f} {unit}",
                    speed=speed,
                    unit=unit,
                    real=real,
                )
            )
            return real
        if self.capabilities.speed_readback:
            reported = self.read()
            if reported != speed:
                log.debug(
                    "speed %g %s reads back as %g (the device rounds it)", speed, unit, reported
                )
            return reported
        return speed

    def filled_in(self, command: cmd.Command) -> cmd.Command:
        """Where the speed goes with every move (pi-frame, Firmata): the speed set, filled in."""
        if not self.capabilities.speed_in_moves:
            return command
        if isinstance(command, cmd.MoveTo | cmd.MoveBy | cmd.Arc) and command.speed is None:
            return dataclasses.replace(command, speed=self.current())
        return command
