"""Every protocol declared once (class, simulator, names, help, variants), imported only when
asked for; installed packages add theirs through the `motionpanel.protocols` entry points.
One protocol's problem never breaks another."""

from __future__ import annotations

import importlib
import logging
import os
import sys
from dataclasses import dataclass
from functools import cache
from typing import TYPE_CHECKING

from drivers.errors import UnknownProtocol
from drivers.messages import Message

if TYPE_CHECKING:
    from drivers.protocols.base import Protocol

log = logging.getLogger(__name__)

ENTRY_POINT_GROUP = "motionpanel.protocols"


@dataclass(frozen=True)
class ProtocolEntry:
    """One protocol as every front end lists it: the window, motionctl, motionsim, the sniffer.

    `protocol` and `simulator` are `module:Class` paths, imported only when used, so that a
    list of protocols costs no protocol module. `variants` names the wire variants
    (`Protocol.variants`, the first the default) without importing the class.
    """

    name: str  # the registry key, the CLI's `--protocol` value and the `sim://` name
    display_name: str  # how a sentence names its devices ("a Visiomex controller")
    protocol: str  # "package.module:ProtocolClass"
    simulator: str | None = None  # "package.module:SimulatedDeviceClass"; None: no simulator
    description: str = ""  # one line for motionctl/motionsim --help
    variants: tuple[str, ...] = ()
    sniff: bool = True  # a candidate when bytes from a device are read as another protocol's

    @property
    def has_variants(self) -> bool:
        """Whether the protocol has wire variants (imports nothing)."""
        return bool(self.variants)


BUILT_IN: tuple[ProtocolEntry, ...] = (
    ProtocolEntry(
        "coxiris",
        "COXIRIS",
        "drivers.protocols.coxiris:CoxirisProtocol",
        "drivers.sim.coxiris_device:CoxirisDevice",
        "COXIRIS ASCII lines: CMD args -> ACK CMD ... DONE CMD",
    ),
    ProtocolEntry(
        "visiomex",
        "Visiomex",
        "drivers.protocols.visiomex.protocol:VisiomexProtocol",
        "drivers.sim.visiomex_device:VisiomexDevice",
        "Visiomex VMR2P0R0001 packets, ended by a silence; FS/FP/FA feedback lines",
        variants=("seed", "prefixed", "board12"),
    ),
    ProtocolEntry(
        "pi-frame",
        "pi-frame",
        "drivers.protocols.piframe:PiFrameProtocol",
        "drivers.sim.piframe_device:PiFrameDevice",
        "Raspberry Pi motion frames: 25 binary bytes, write-only",
    ),
    ProtocolEntry(
        "firmata",
        "Firmata",
        "drivers.protocols.firmata:FirmataProtocol",
        "drivers.sim.firmata_device:FirmataDevice",
        "Firmata with the FirmataPlus stepper extension on an Arduino, one motor as X",
    ),
    ProtocolEntry(
        "laser-frame",
        "laser-frame",
        "drivers.protocols.laser.protocol:LaserProtocol",
        "drivers.sim.laser_device:LaserDevice",
        "the laser robot's stuffed binary frames, acknowledged, with a command queue",
    ),
)


def load_object(target: str) -> object:
    """What a `module:attribute` path names, its module imported now."""
    module_name, _, attribute = target.partition(":")
    obj: object = importlib.import_module(module_name)
    for part in attribute.split(".") if attribute else ():
        obj = getattr(obj, part)
    return obj


def _may_have_plugins() -> bool:
    """Whether any installed distribution may declare the entry-point group: a look at the
    `entry_points.txt` files on sys.path, far cheaper than importing importlib.metadata (which
    costs the window's first paint about 30 ms). A zip on the path counts as a maybe."""
    marker = ENTRY_POINT_GROUP.encode()
    for folder in sys.path:
        try:
            names = os.listdir(folder or ".")
        except NotADirectoryError:
            return True  # a zip archive: only importlib.metadata reads it
        except OSError:
            continue
        for name in names:
            if not name.endswith((".dist-info", ".egg-info")):
                continue
            try:
                with open(os.path.join(folder, name, "entry_points.txt"), "rb") as file:
                    if marker in file.read():
                        return True
            except OSError:
                continue
    return False


def _checked_plugin(value: object, where: str) -> ProtocolEntry | None:
    entry = value() if callable(value) and not isinstance(value, ProtocolEntry) else value
    if not isinstance(entry, ProtocolEntry):
        log.warning("protocol plugin %s is not a ProtocolEntry (%r): skipped", where, entry)
        return None
    return entry


@cache
def plugin_entries() -> tuple[ProtocolEntry, ...]:
    """The protocols installed packages declare, read once; a broken one is logged, skipped."""
    if not _may_have_plugins():
        return ()
    from importlib.metadata import entry_points

    try:
        points = list(entry_points(group=ENTRY_POINT_GROUP))
    except Exception:  # a distribution's metadata unreadable: the built-in protocols remain
        log.warning("protocol plugins cannot be listed", exc_info=True)
        return ()
    found: list[ProtocolEntry] = []
    taken = {entry.name for entry in BUILT_IN}
    for point in points:
        where = f"{point.name} ({point.value})"
        try:
            entry = _checked_plugin(point.load(), where)
        except Exception:  # any error of someone else's code: that plugin only is lost
            log.warning("protocol plugin %s cannot be loaded: skipped", where, exc_info=True)
            continue
        if entry is None:
            continue
        if entry.name in taken:
            log.warning("protocol plugin %s: the name %r is taken: skipped", where, entry.name)
            continue
        taken.add(entry.name)
        found.append(entry)
    return tuple(found)


def entries() -> tuple[ProtocolEntry, ...]:
    """Every protocol that can be used now: the built-in ones, then the installed plugins'."""
    return BUILT_IN + plugin_entries()


def find_entry(name: str) -> ProtocolEntry:
    """The declaration of the protocol `name`; UnknownProtocol naming those known."""
    for entry in entries():
        if entry.name == name:
            return entry
    known = ", ".join(protocol_names())
    raise UnknownProtocol(
        Message("unknown protocol {name!r} (known: {known})", name=name, known=known)
    )


def protocol_names() -> list[str]:
    """Names of the protocols that can be used now."""
    return [entry.name for entry in entries()]


def has_variants(name: str) -> bool:
    """Whether the protocol registered as `name` has wire variants (imports no protocol)."""
    return any(entry.name == name and entry.has_variants for entry in entries())


def get_protocol_class(name: str) -> type[Protocol]:
    """The protocol class registered as `name`; UnknownProtocol where it cannot be loaded."""
    from drivers.protocols.base import Protocol

    target = find_entry(name).protocol
    try:
        loaded = load_object(target)
    except Exception as exc:  # a plugin's broken module: that protocol only is lost
        log.warning("protocol %s: %s cannot be loaded", name, target, exc_info=True)
        raise UnknownProtocol(
            Message("protocol {name!r} cannot be loaded: {error}", name=name, error=str(exc))
        ) from exc
    if not (isinstance(loaded, type) and issubclass(loaded, Protocol)):
        raise UnknownProtocol(
            Message("protocol {name!r}: {target} is not a protocol class", name=name, target=target)
        )
    return loaded


def create_protocol(name: str, variant: str | None = None) -> Protocol:
    """A new instance of the protocol registered as `name`, in one of its wire variants."""
    return get_protocol_class(name)(variant)
