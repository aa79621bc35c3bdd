"""The bridge: a device on one side, a pseudo-terminal for another program on the other.

`drivers.bridge.Bridge` (the module before the bridge became a package) still works, with a
DeprecationWarning: it is drivers.bridge.snoop.Bridge now, removed in release 0.3.0.
"""

from __future__ import annotations

import warnings
from typing import Any


def __getattr__(name: str) -> Any:
    """The old module's names, from drivers.bridge.snoop, with a warning."""
    if name.startswith("__"):
        raise AttributeError(name)
    from drivers.bridge import snoop

    if not hasattr(snoop, name):
        raise AttributeError(f"module 'drivers.bridge' has no attribute {name!r}")
    warnings.warn(
        f"drivers.bridge.{name} is deprecated and will be removed in release 0.3.0: it is "
        f"drivers.bridge.snoop.{name} now",
        DeprecationWarning,
        stacklevel=2,
    )
    return getattr(snoop, name)
