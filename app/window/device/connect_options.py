"""What the window asks a connection for, and what it learns of the device once connected."""

from __future__ import annotations

from dataclasses import dataclass, field

from drivers.device.position_truth import Whereabouts
from drivers.protocols.base import Setting
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.parameters import Parameter


@dataclass(frozen=True)
class DeviceInfo:
    """What the window needs to adapt to a connected device."""

    port: str
    protocol: str
    identity: str
    capabilities: Capabilities
    variant: str = ""
    parameters: tuple[Parameter, ...] = ()
    settings: tuple[Setting, ...] = ()
    """The protocol's settings (ticks per mm...), with their values at connection."""
    values: dict[str, float] = field(default_factory=dict)
    whereabouts: Whereabouts | None = None
    """What the session knows of the position once the device is ready."""


@dataclass(frozen=True)
class ConnectOptions:
    """How to talk to the device beyond port, protocol and baud."""

    variant: str = ""  # the protocol's wire variant ("": its default)
    settings: dict[str, float] = field(default_factory=dict)
    """The protocol's settings kept by the panel (ticks per mm...)."""
    parameters: dict[str, float] = field(default_factory=dict)
    """Values written earlier and kept by the panel (the device may have no read-back)."""
    dtr: bool | None = None  # DTR when the port opens (None: the protocol's default)
    rts: bool | None = None  # RTS when the port opens (None: as the port opens it, asserted)
    position: tuple[float, float, float] | None = None
    """Where a device that cannot be asked was left, as kept (None: not known)."""
    after_loss: bool = False  # the device was lost with its link before (the session knows)
