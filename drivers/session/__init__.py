"""One connected device as every front end drives it: `DeviceSession` and its parts (internal:
import `DeviceSession` and `open_device` from `drivers`)."""

from __future__ import annotations

import importlib
import warnings
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from drivers.session.device_session import DeviceSession as DeviceSession
    from drivers.session.device_session import open_device as open_device

_OLD = ("DeviceSession", "open_device")


def __getattr__(name: str) -> Any:
    """`from drivers.session import DeviceSession`, the old spelling: deprecated."""
    if name not in _OLD:
        raise AttributeError(f"module 'drivers.session' has no attribute {name!r}")
    warnings.warn(
        f"drivers.session.{name} is deprecated and will be removed in release 0.3.0: "
        f"use drivers.{name}",
        DeprecationWarning,
        stacklevel=2,
    )
    return getattr(importlib.import_module("drivers.session.device_session"), name)
