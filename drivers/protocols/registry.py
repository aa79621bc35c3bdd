"""Protocols by name, imported only when asked for: one protocol's problem never breaks another."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

from drivers.errors import UnknownProtocol
from drivers.messages import Message

if TYPE_CHECKING:
    from drivers.protocols.base import Protocol

PROTOCOLS: dict[str, tuple[str, str]] = {
    "coxiris": ("drivers.protocols.coxiris", "CoxirisProtocol"),
    "visiomex": ("drivers.protocols.visiomex.protocol", "VisiomexProtocol"),
    "pi-frame": ("drivers.protocols.piframe", "PiFrameProtocol"),
    "firmata": ("drivers.protocols.firmata", "FirmataProtocol"),
    "laser-frame": ("drivers.protocols.laser.protocol", "LaserProtocol"),
}
PLANNED: tuple[str, ...] = ()
# The protocols that have wire variants (`Protocol.variants`), known without importing them: the
# panel's first paint needs no protocol module, and most protocols have none (a test holds this
# to the classes).
WITH_VARIANTS: frozenset[str] = frozenset({"visiomex"})


def protocol_names() -> list[str]:
    """Names of the protocols that can be used now."""
    return list(PROTOCOLS)


def has_variants(name: str) -> bool:
    """Whether the protocol registered as `name` has wire variants (imports no protocol)."""
    return name in WITH_VARIANTS


def get_protocol_class(name: str) -> type[Protocol]:
    """The protocol class registered as `name`."""
    try:
        module_name, class_name = PROTOCOLS[name]
    except KeyError:
        if name in PLANNED:
            raise UnknownProtocol(
                Message("protocol {name!r} is not implemented yet", name=name)
            ) from None
        known = ", ".join(protocol_names())
        raise UnknownProtocol(
            Message("unknown protocol {name!r} (known: {known})", name=name, known=known)
        ) from None
    protocol_class: type[Protocol] = getattr(importlib.import_module(module_name), class_name)
    return protocol_class


def create_protocol(name: str, variant: str | None = None) -> Protocol:
    """A new instance of the protocol registered as `name`, in one of its wire variants."""
    return get_protocol_class(name)(variant)
