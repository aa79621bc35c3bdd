"""Motion Panel driver layer: transports, framers, protocols and simulators (no Qt).

The stability promise covers exactly the names in this package's `__all__` (the scripting API:
`open_device`, `DeviceSession` and the nouns they take and return); every module below
`drivers` is internal and may change from one release to the next. The names are imported
when first used, so that `import drivers` loads none of the modules below it.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from drivers import _moved

if TYPE_CHECKING:
    from drivers.device.position_truth import Whereabouts
    from drivers.device.travel import TravelLimits
    from drivers.errors import (
        Aborted,
        BadFile,
        BadInput,
        CommunicationError,
        DeviceError,
        DeviceRestarted,
        DeviceTimeout,
        FrameError,
        GarbledReply,
        MotionError,
        NoControlLines,
        PortBusy,
        PortError,
        QueueFull,
        Retransmit,
        UnknownProtocol,
    )
    from drivers.link.records import Traffic
    from drivers.protocols.capabilities import Capabilities
    from drivers.protocols.events import PositionReport
    from drivers.session.bench import Bench, BenchDevice, BenchError, open_bench, read_bench
    from drivers.session.device_session import DeviceSession, open_device
    from drivers.toolpath.loader import load_toolpath
    from drivers.toolpath.model import Toolpath
    from drivers.toolpath.point_program import ProgramDwell, ProgramPoint
    from drivers.toolpath.streaming import StreamProgress

_ERRORS = (
    "Aborted", "BadFile", "BadInput", "CommunicationError", "DeviceError", "DeviceRestarted",
    "DeviceTimeout", "FrameError", "GarbledReply", "MotionError", "NoControlLines", "PortBusy",
    "PortError", "QueueFull", "Retransmit", "UnknownProtocol",
)  # fmt: skip
_HOMES = {
    "DeviceSession": "drivers.session.device_session",
    "open_device": "drivers.session.device_session",
    **dict.fromkeys(
        ("Bench", "BenchDevice", "BenchError", "open_bench", "read_bench"), "drivers.session.bench"
    ),
    "PositionReport": "drivers.protocols.events",
    "Whereabouts": "drivers.device.position_truth",
    "TravelLimits": "drivers.device.travel",
    "Capabilities": "drivers.protocols.capabilities",
    "ProgramPoint": "drivers.toolpath.point_program",
    "ProgramDwell": "drivers.toolpath.point_program",
    "Toolpath": "drivers.toolpath.model",
    "load_toolpath": "drivers.toolpath.loader",
    "StreamProgress": "drivers.toolpath.streaming",
    "Traffic": "drivers.link.records",
    **dict.fromkeys(_ERRORS, "drivers.errors"),
}
"""Where each public name lives (internal: the modules may move, the names stay)."""

__all__ = [
    "Aborted",
    "BadFile",
    "BadInput",
    "Bench",
    "BenchDevice",
    "BenchError",
    "Capabilities",
    "CommunicationError",
    "DeviceError",
    "DeviceRestarted",
    "DeviceSession",
    "DeviceTimeout",
    "FrameError",
    "GarbledReply",
    "MotionError",
    "NoControlLines",
    "PortBusy",
    "PortError",
    "PositionReport",
    "ProgramDwell",
    "ProgramPoint",
    "QueueFull",
    "Retransmit",
    "StreamProgress",
    "Toolpath",
    "Traffic",
    "TravelLimits",
    "UnknownProtocol",
    "Whereabouts",
    "load_toolpath",
    "open_bench",
    "open_device",
    "read_bench",
]

_moved.install()


def __getattr__(name: str) -> Any:
    """A public name, imported from its module on first use."""
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'drivers' has no attribute {name!r}")
    value = getattr(importlib.import_module(home), name)
    globals()[name] = value  # found at once from now on
    return value


def __dir__() -> list[str]:
    """The public names, with the module's own."""
    return sorted({*globals(), *__all__})
