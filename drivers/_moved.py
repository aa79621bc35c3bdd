"""The module paths that moved when drivers/ was regrouped: the old dotted names still import,
with a DeprecationWarning, and give the module now at the new one (the same object).

Removed in release 0.3.0: import the public names from `drivers` itself.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import warnings
from types import ModuleType

REMOVAL = "0.3.0"
MOVED = {
    "drivers.bridge_watch": "drivers.bridge.watch",
    "drivers.capabilities": "drivers.protocols.capabilities",
    "drivers.client": "drivers.device.client",
    "drivers.commands": "drivers.protocols.commands",
    "drivers.control_lines": "drivers.link.control_lines",
    "drivers.decoding": "drivers.traffic.decoding",
    "drivers.events": "drivers.protocols.events",
    "drivers.log_origin": "drivers.traffic.log_origin",
    "drivers.log_reader": "drivers.traffic.log_reader",
    "drivers.log_records": "drivers.traffic.log_records",
    "drivers.motion": "drivers.device.motion",
    "drivers.motion_guard": "drivers.device.guard",
    "drivers.move_outcome": "drivers.protocols.move_outcome",
    "drivers.numbers": "drivers.protocols.numbers",
    "drivers.param_profile": "drivers.device.param_profile",
    "drivers.parameters": "drivers.protocols.parameters",
    "drivers.position_count": "drivers.device.position_count",
    "drivers.position_truth": "drivers.device.position_truth",
    "drivers.program": "drivers.toolpath.point_program",
    "drivers.protocol_sniff": "drivers.protocols.sniff",
    "drivers.protocols.laser_codec": "drivers.protocols.laser.codec",
    "drivers.protocols.visiomex_advice": "drivers.protocols.visiomex.advice",
    "drivers.protocols.visiomex_estimate": "drivers.protocols.visiomex.estimate",
    "drivers.protocols.visiomex_model": "drivers.protocols.visiomex.model",
    "drivers.protocols.visiomex_params": "drivers.protocols.visiomex.params",
    "drivers.protocols.visiomex_timing": "drivers.protocols.visiomex.timing",
    "drivers.protocols.visiomex_where": "drivers.protocols.visiomex.where",
    "drivers.registry": "drivers.protocols.registry",
    "drivers.session_parameters": "drivers.session.parameters",
    "drivers.session_setup": "drivers.session.setup",
    "drivers.session_tap": "drivers.session.tap",
    "drivers.spy_log": "drivers.traffic.spy_log",
    "drivers.streaming": "drivers.toolpath.streaming",
    "drivers.traffic_index": "drivers.traffic.index",
    "drivers.traffic_lines": "drivers.traffic.lines",
    "drivers.traffic_pairing": "drivers.traffic.pairing",
    "drivers.traffic_search": "drivers.traffic.search",
    "drivers.traffic_spool": "drivers.traffic.spool",
    "drivers.transport": "drivers.link.transport",
    "drivers.travel": "drivers.device.travel",
    "drivers.urlhandler": "drivers.sim.urlhandler",
    "drivers.urlhandler.protocol_sim": "drivers.sim.urlhandler.protocol_sim",
    "drivers.urlhandler.rfc2217_port": "drivers.link.rfc2217_port",
    "drivers.work_zero": "drivers.device.work_zero",
}
"""Old dotted name -> the module's name now. The old modules that are packages now
(drivers.session, drivers.traffic, drivers.bridge, drivers.protocols.laser,
drivers.protocols.visiomex) are not here: they import as the packages."""


class _Alias(importlib.abc.Loader):
    """Gives the module at its new name for the old one (nothing is loaded twice)."""

    def __init__(self, new: str) -> None:
        self.new = new
        self._spec: importlib.machinery.ModuleSpec | None = None

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        """The module at the new name, imported there."""
        module = importlib.import_module(self.new)
        self._spec = module.__spec__
        return module

    def exec_module(self, module: ModuleType) -> None:
        """Nothing to run: give the module its own spec back (the import set the alias's)."""
        module.__spec__ = self._spec


class MovedFinder(importlib.abc.MetaPathFinder):
    """Finds the old dotted names of MOVED, warning that they go in release 0.3.0."""

    def find_spec(
        self, fullname: str, path: object = None, target: object = None
    ) -> importlib.machinery.ModuleSpec | None:
        """A spec for an old name (None: not one of them)."""
        new = MOVED.get(fullname)
        if new is None:
            return None
        warnings.warn(
            f"{fullname} is deprecated and will be removed in release {REMOVAL}: it is {new} "
            "now, and the stable names are those of `drivers` itself (drivers.__all__)",
            DeprecationWarning,
            stacklevel=2,  # the importer: warnings skips the import system's frames
        )
        return importlib.machinery.ModuleSpec(fullname, _Alias(new))


def install() -> None:
    """Put the finder first on sys.meta_path, once (an old package's submodules are found
    there too, before the path finder would load them a second time under the old name)."""
    if not any(isinstance(finder, MovedFinder) for finder in sys.meta_path):
        sys.meta_path.insert(0, MovedFinder())
