"""Motion Panel driver layer: transports, framers, protocols and simulators (no Qt).

Public and stable: `open_device` and `DeviceSession` (drivers/session/device_session.py), the
scripting API;
imported when first used, so that importing one driver module loads no others.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from drivers.session.device_session import DeviceSession, open_device

__all__ = ["DeviceSession", "open_device"]


def __getattr__(name: str) -> Any:
    """`drivers.open_device` and `drivers.DeviceSession`, imported on first use."""
    if name in __all__:
        import drivers.session.device_session

        return getattr(drivers.session.device_session, name)
    raise AttributeError(f"module 'drivers' has no attribute {name!r}")
