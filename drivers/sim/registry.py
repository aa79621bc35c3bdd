"""Simulated devices by protocol name, read from the protocols' declarations and imported lazily."""

from __future__ import annotations

from typing import Any

from drivers.errors import UnknownProtocol
from drivers.protocols.registry import ProtocolEntry, entries, load_object
from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice


def _simulated() -> dict[str, ProtocolEntry]:
    return {entry.name: entry for entry in entries() if entry.simulator}


def simulator_names() -> list[str]:
    """Protocols that have a simulated device."""
    return sorted(_simulated())


def simulator_class(name: str) -> type[SimulatedDevice]:
    """The simulated device class of protocol `name`; UnknownProtocol where there is none or it
    cannot be loaded."""
    entry = _simulated().get(name)
    if entry is None or entry.simulator is None:
        known = ", ".join(simulator_names())
        raise UnknownProtocol(f"no simulator for {name!r} (simulators: {known})")
    try:
        loaded = load_object(entry.simulator)
    except Exception as exc:  # a plugin's broken module: that simulator only is lost
        raise UnknownProtocol(f"the {name} simulator cannot be loaded: {exc}") from exc
    if not (isinstance(loaded, type) and issubclass(loaded, SimulatedDevice)):
        raise UnknownProtocol(f"the {name} simulator {entry.simulator} is not a SimulatedDevice")
    return loaded


def create_device(
    name: str, clock: Clock = monotonic, baud: int | None = None, **options: Any
) -> SimulatedDevice:
    """A simulated device for protocol `name`; `options` go to its constructor."""
    return simulator_class(name)(clock, baud, **options)
