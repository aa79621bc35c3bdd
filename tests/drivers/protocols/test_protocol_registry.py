"""Protocols declared once (drivers/protocols/registry.py): every list reads the declarations,
each passes the conformance suite, and plugins come in by entry point without breaking the rest."""

from __future__ import annotations

import sys
import types
from importlib import metadata

import pytest

from app.cli.command_line import PROTOCOL_CHOICES
from app.simcli import build_parser
from drivers.conformance import check_entry
from drivers.errors import UnknownProtocol
from drivers.protocols import registry
from drivers.protocols.registry import BUILT_IN, ProtocolEntry, entries, protocol_names
from drivers.protocols.sniff import device_name
from drivers.sim.registry import create_device, simulator_names

pytestmark = pytest.mark.timeout(60)

SETTINGS = {"firmata": {"pin1": 8.0, "pin2": 9.0}}  # its board moves only once configured


@pytest.mark.parametrize("entry", entries(), ids=lambda e: e.name)
def test_every_registered_protocol_conforms(entry: ProtocolEntry) -> None:
    assert check_entry(entry, SETTINGS.get(entry.name)) == []


def test_the_front_ends_list_the_declarations() -> None:
    names = [entry.name for entry in entries()]
    assert names == protocol_names() == list(PROTOCOL_CHOICES)
    assert simulator_names() == sorted(e.name for e in entries() if e.simulator)
    help_text = " ".join(build_parser().format_help().split())
    for entry in entries():
        assert f"{entry.name} ({' '.join(entry.description.split())})" in help_text
    assert device_name("visiomex") == "Visiomex" and device_name("nonesuch") == "nonesuch"


BAD = (
    ProtocolEntry(
        "misnamed", "Misnamed", "drivers.protocols.coxiris:CoxirisProtocol", None, "one line"
    ),
    ProtocolEntry(
        "novariants",
        "No variants",
        "drivers.protocols.coxiris:CoxirisProtocol",
        description="declares variants its class does not have",
        variants=("fast",),
    ),
    ProtocolEntry("Bad Name", "x", "drivers.protocols.coxiris:CoxirisProtocol", None, "two\nlines"),
    ProtocolEntry("nomodule", "x", "no.such.module:Nothing", None, "a module that is not there"),
)


@pytest.mark.parametrize("entry", BAD, ids=lambda e: e.name)
def test_the_conformance_suite_finds_a_broken_declaration(monkeypatch, entry) -> None:
    monkeypatch.setattr(registry, "plugin_entries", lambda: (entry,))
    assert check_entry(entry) != []


def test_a_simulator_without_the_options_motionsim_gives_is_refused(monkeypatch) -> None:
    entry = ProtocolEntry(
        "bare-sim",
        "bare",
        "drivers.protocols.coxiris:CoxirisProtocol",
        "drivers.sim.device:SimulatedDevice",  # abstract: cannot be made
        "a simulator that cannot be made",
    )
    monkeypatch.setattr(registry, "plugin_entries", lambda: (entry,))
    problems = check_entry(entry)
    assert any("simulator" in p for p in problems), problems


# -- plugins by entry point -------------------------------------------------------------------


@pytest.fixture
def plugins(monkeypatch):
    """Entry points served from a module of this test: `install(name=value, ...)`."""
    module = types.ModuleType("fake_protocol_plugins")
    module.GOOD = ProtocolEntry(
        "plug-good",
        "Plug",
        "drivers.protocols.coxiris:CoxirisProtocol",
        "drivers.sim.coxiris_device:CoxirisDevice",
        "a plugin",
    )
    module.made = lambda: ProtocolEntry(
        "plug-made", "Made", "drivers.protocols.coxiris:CoxirisProtocol", None, "made by a call"
    )
    module.CLASH = ProtocolEntry(
        "coxiris", "Clash", "drivers.protocols.coxiris:CoxirisProtocol", None, "a taken name"
    )
    module.NOT_AN_ENTRY = 42

    def raises():
        raise RuntimeError("the plugin's own bug")

    module.raises = raises
    monkeypatch.setitem(sys.modules, module.__name__, module)
    monkeypatch.setattr(registry, "_may_have_plugins", lambda: True)

    def install(*targets: str) -> None:
        points = [
            metadata.EntryPoint(f"p{i}", f"{module.__name__}:{target}", registry.ENTRY_POINT_GROUP)
            for i, target in enumerate(targets)
        ]
        monkeypatch.setattr(metadata, "entry_points", lambda group: points)
        registry.plugin_entries.cache_clear()

    yield install
    registry.plugin_entries.cache_clear()


def test_a_plugin_entry_or_a_callable_returning_one_is_listed(plugins) -> None:
    plugins("GOOD", "made")
    assert protocol_names() == [*(e.name for e in BUILT_IN), "plug-good", "plug-made"]
    assert "plug-good" in simulator_names() and "plug-made" not in simulator_names()
    assert create_device("plug-good", instant=True).protocol == "coxiris"


def test_a_broken_plugin_is_logged_and_skipped_the_others_stay(plugins, caplog) -> None:
    plugins("raises", "NOT_AN_ENTRY", "CLASH", "missing_attribute", "GOOD")
    assert protocol_names() == [*(e.name for e in BUILT_IN), "plug-good"]
    said = caplog.text
    assert "the plugin's own bug" in said and "is not a ProtocolEntry" in said
    assert "'coxiris' is taken" in said and "missing_attribute" in said


def test_a_plugin_whose_module_is_broken_loses_only_itself(monkeypatch) -> None:
    entry = ProtocolEntry("plug-broken", "Broken", "no.such.module:Nothing", None, "broken")
    monkeypatch.setattr(registry, "plugin_entries", lambda: (entry,))
    with pytest.raises(UnknownProtocol, match="cannot be loaded"):
        registry.create_protocol("plug-broken")
    from drivers.protocols.sniff import sniff

    assert sniff(b"DONE GET_POSITION: 1.00 2.00 3.00\r\n", "laser-frame") == "coxiris"


def test_the_plugins_are_read_once(plugins, monkeypatch) -> None:
    plugins("GOOD")
    calls = []
    real = metadata.entry_points
    monkeypatch.setattr(metadata, "entry_points", lambda group: calls.append(group) or real(group))
    protocol_names(), protocol_names(), simulator_names()
    assert calls == [registry.ENTRY_POINT_GROUP]


def test_no_plugin_installed_costs_no_importlib_metadata(tmp_path) -> None:
    """Without a plugin, listing the protocols reads no metadata module (about 30 ms of the
    window's first paint)."""
    import subprocess

    code = (
        "import sys; from drivers.protocols.registry import protocol_names; protocol_names(); "
        "print('importlib.metadata' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
