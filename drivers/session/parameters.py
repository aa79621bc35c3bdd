"""A session's device parameters: the ones the protocol declares, the values known to be on the
device, and writing them (one, several, a profile file), each confirmed by the device.

Public and stable: `DeviceParameters` (its methods and properties without a leading underscore),
`WriteProgress`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from contextlib import AbstractContextManager
from pathlib import Path

from drivers.device.motion import Motion, MoveStart
from drivers.device.param_profile import read_profile
from drivers.protocols.parameters import Parameter, ParameterWritten

__all__ = ["DeviceParameters", "WriteProgress"]

WriteProgress = Callable[[int, int, ParameterWritten], None]
"""Told (number, count, what the device confirmed) after each parameter written."""


class DeviceParameters:
    """The parameters of one device, written through its Motion (Visiomex: 1 s a packet)."""

    def __init__(
        self,
        motion: Motion,
        kept: Mapping[str, float] | None = None,
        operation: Callable[[], AbstractContextManager[None]] | None = None,
    ) -> None:
        """Parameters written through `motion`; `kept`: values written earlier, by name."""
        self._motion = motion
        self._kept: dict[str, float] = dict(kept or {})
        self._operation = operation
        motion.parameter_listeners.append(self._keep)
        motion.move_listeners.append(self._moved)

    @property
    def all(self) -> tuple[Parameter, ...]:
        """Every parameter the protocol declares (empty where the device has none)."""
        return self._motion.client.protocol.parameters

    def kept(self) -> dict[str, float]:
        """The values known to be on the device, by name: those given when it was opened
        (written earlier), those written since (the device cannot be asked for them), and those
        its firmware recomputed by itself after a set or at a move (Visiomex 15, 16, 19, 20)."""
        return dict(self._kept)

    def set(self, key: str | int, value: float) -> ParameterWritten:
        """Write one parameter (by name or id) and wait until the device confirms it."""
        if self._operation is None:
            return self._motion.set_parameter(key, value)
        with self._operation():
            return self._motion.set_parameter(key, value)

    def write(
        self, values: Mapping[str, float], progress: WriteProgress | None = None
    ) -> list[ParameterWritten]:
        """Write several parameters in turn, every value checked before the first is sent."""
        protocol = self._motion.client.protocol
        for name, value in values.items():
            protocol.parameter(name).to_wire(value)  # BadInput: nothing sent
        written = []
        for number, (name, value) in enumerate(values.items(), start=1):
            item = self.set(name, value)
            written.append(item)
            if progress is not None:
                progress(number, len(values), item)
        return written

    def write_profile(
        self, path: str | Path, progress: WriteProgress | None = None
    ) -> list[ParameterWritten]:
        """Write a profile file's values (firmware outputs left out); the file is read whole
        and checked first (ProfileError: nothing sent)."""
        protocol = self._motion.client.protocol
        return self.write(read_profile(path, protocol.parameters, protocol.name), progress)

    def _keep(self, written: ParameterWritten) -> None:
        self._kept[written.parameter.name] = written.value
        self._kept.update(written.device_values)

    def _moved(self, move: MoveStart) -> None:
        self._kept.update(move.recomputed)
