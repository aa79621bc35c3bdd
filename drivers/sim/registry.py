"""Simulated devices by protocol name, imported lazily."""

from __future__ import annotations

import importlib
from typing import Any

from drivers.errors import UnknownProtocol
from drivers.sim.clock import Clock, monotonic
from drivers.sim.device import SimulatedDevice

SIMULATORS: dict[str, tuple[str, str]] = {
    "coxiris": ("drivers.sim.coxiris_device", "CoxirisDevice"),
    "visiomex": ("drivers.sim.visiomex_device", "VisiomexDevice"),
    "pi-frame": ("drivers.sim.piframe_device", "PiFrameDevice"),
    "firmata": ("drivers.sim.firmata_device", "FirmataDevice"),
    "laser-frame": ("drivers.sim.laser_device", "LaserDevice"),
}


def simulator_names() -> list[str]:
    """Protocols that have a simulated device."""
    return sorted(SIMULATORS)


def create_device(
    name: str, clock: Clock = monotonic, baud: int | None = None, **options: Any
) -> SimulatedDevice:
    """A simulated device for protocol `name`; `options` go to its constructor."""
    try:
        module_name, class_name = SIMULATORS[name]
    except KeyError:
        known = ", ".join(simulator_names())
        raise UnknownProtocol(f"no simulator for {name!r} (simulators: {known})") from None
    device_class: type[SimulatedDevice] = getattr(importlib.import_module(module_name), class_name)
    return device_class(clock, baud, **options)
