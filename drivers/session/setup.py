"""Setting a device up: its protocol made and configured, its port opened as the protocol needs.

The one place where this is done; `drivers.session.device_session.open_device` (and through it
motionctl, the
panel's worker and the benchmarks) and the bridge's device side use it. Public and stable:
`make_protocol`, `device_url`, `open_device_link`, `travel_limits`, `LogTarget`.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import TextIO

from drivers.device.travel import TravelLimits, parse_travel
from drivers.errors import BadInput
from drivers.link.records import TrafficLogWriter
from drivers.link.transport import Link, open_link
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.registry import create_protocol
from drivers.sim.urlhandler.protocol_sim import with_sim_variant

__all__ = ["LogTarget", "device_url", "make_protocol", "open_device_link", "travel_limits"]

LogTarget = str | os.PathLike[str] | TextIO | TrafficLogWriter
"""Where a session writes its traffic: a file path (appended to), an open text stream, or a
TrafficLogWriter (shared, e.g. the panel's session log)."""


def make_protocol(
    protocol: str | Protocol,
    variant: str | None = None,
    settings: Mapping[str, float] | None = None,
    parameters: Mapping[str, float] | None = None,
) -> Protocol:
    """The protocol named (or given), in `variant`, with its settings and kept parameter values."""
    if isinstance(protocol, Protocol):
        chosen = protocol.variant.name if protocol.variant else ""
        if variant and variant != chosen:
            raise BadInput(
                Message(
                    "variant {variant!r} asked for a protocol made as {chosen!r}",
                    variant=variant,
                    chosen=chosen,
                )
            )
        made = protocol
    else:
        made = create_protocol(protocol, variant or None)
    if parameters:
        made.assume_parameters(dict(parameters))
    if settings:
        made.configure(dict(settings))
    return made


def device_url(port: str, protocol: Protocol) -> str:
    """The URL to open: a `sim://` device made to speak the protocol's wire variant; any other
    port (and a `sim://` URL naming a variant already) as it is."""
    return with_sim_variant(port, protocol.variant.name if protocol.variant else "")


def open_device_link(
    port: str,
    protocol: Protocol | None = None,
    *,
    baud: int | None = None,
    dtr: bool | None = None,
    rts: bool | None = None,
) -> Link:
    """Open `port` for `protocol`: at its default baud unless given, DTR as the device needs
    unless given, a `sim://` device in the protocol's variant; PortError if it cannot open."""
    if baud is not None and baud <= 0:
        raise BadInput(
            Message("baud {baud} refused: a positive number of bits per second", baud=baud)
        )
    if protocol is None:
        return open_link(port, baud or 115200, dtr=dtr, rts=rts)
    capabilities = protocol.capabilities
    return open_link(
        device_url(port, protocol),
        baud or capabilities.default_baud,
        dtr=capabilities.dtr if dtr is None else dtr,
        rts=rts,
    )


def travel_limits(travel: TravelLimits | str | None, clamp: bool = False) -> TravelLimits | None:
    """The travel box: as given, or read from `X0:X1,Y0:Y1,Z0:Z1` in mm (`none`: no box);
    `clamp`: a move beyond it goes to its edge instead of being refused."""
    limits = parse_travel(travel) if isinstance(travel, str) else travel
    if limits is not None and clamp and not limits.clamp:
        limits = TravelLimits(limits.box, clamp=True)
    return limits
