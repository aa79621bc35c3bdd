"""The stable names at the root of `drivers`, imported lazily, and the old spellings that still
work with a DeprecationWarning until release 0.3.0."""

from __future__ import annotations

import importlib
import json
import subprocess
import sys

import pytest

import drivers
from drivers._moved import MOVED
from tests.support.simproc import ROOT

pytestmark = pytest.mark.timeout(60)


def _fresh(name: str) -> None:
    """Forget an old name's import, so that importing it again goes through the finder."""
    sys.modules.pop(name, None)
    parent, _, child = name.rpartition(".")
    if parent in sys.modules and child in vars(sys.modules[parent]):
        delattr(sys.modules[parent], child)


@pytest.mark.parametrize("old", sorted(MOVED))
def test_an_old_module_path_warns_and_gives_the_module_now(old: str) -> None:
    _fresh(old)
    with pytest.warns(DeprecationWarning, match=r"release 0\.3\.0") as caught:
        exec(compile(f"import {old}", __file__, "exec"), {})  # an import statement, as scripts
    module = sys.modules[old]
    assert module is importlib.import_module(MOVED[old])
    assert module.__name__ == module.__spec__.name == MOVED[old]  # its own spec kept
    assert MOVED[old] in str(caught[0].message)
    assert caught[0].filename == __file__  # the warning points at the importer


def test_the_old_paths_are_no_modules_of_their_own() -> None:
    for old in MOVED:
        path = ROOT.joinpath(*old.split("."))
        assert not path.is_dir() and not path.with_suffix(".py").exists(), old


def test_a_submodule_of_a_moved_package_is_the_same_object() -> None:
    for name in ("drivers.urlhandler.protocol_sim", "drivers.urlhandler"):
        _fresh(name)
    with pytest.warns(DeprecationWarning):
        old = importlib.import_module("drivers.urlhandler.protocol_sim")
    assert old is importlib.import_module("drivers.sim.urlhandler.protocol_sim")


def test_from_drivers_session_import_is_deprecated() -> None:
    from drivers.session.device_session import DeviceSession, open_device

    with pytest.warns(DeprecationWarning, match=r"use drivers\.DeviceSession"):
        from drivers.session import DeviceSession as OldSession
    with pytest.warns(DeprecationWarning, match=r"release 0\.3\.0"):
        from drivers.session import open_device as old_open
    assert OldSession is DeviceSession and old_open is open_device
    with pytest.raises(AttributeError):
        drivers.session.nothing_here  # noqa: B018


def test_every_public_name_resolves_to_its_home() -> None:
    assert len(drivers.__all__) == len(set(drivers.__all__))
    for name in drivers.__all__:
        value = getattr(drivers, name)
        assert getattr(value, "__name__", name) == name
    assert drivers.DeviceSession.__module__ == "drivers.session.device_session"
    assert issubclass(drivers.PortBusy, drivers.MotionError)
    with pytest.raises(AttributeError):
        drivers.Motion  # noqa: B018  (internal: not a root name)


def test_the_root_names_what_a_script_needs() -> None:
    wanted = {
        "DeviceSession", "open_device", "PositionReport", "Whereabouts", "TravelLimits",
        "ProgramPoint", "ProgramDwell", "Toolpath", "load_toolpath", "StreamProgress", "Traffic",
        "Capabilities", "MotionError", "BadInput", "DeviceError", "CommunicationError",
    }  # fmt: skip
    assert wanted <= set(drivers.__all__)


def test_import_drivers_imports_no_module_below_it() -> None:
    code = (
        "import json, sys, drivers; "
        "print(json.dumps(sorted(m for m in sys.modules if m.startswith('drivers.'))))"
    )
    run = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=30
    )
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout) == ["drivers._moved"]  # the finder of the old paths alone


def test_a_script_runs_on_the_public_names_alone() -> None:
    from drivers import ProgramPoint, open_device

    with open_device("sim://coxiris?instant=1", "coxiris", travel="-10:10,-10:10,0:5") as stage:
        state = stage.run_program([ProgramPoint(1, 2, 0, 10), ProgramPoint(3, 4, 0, 10)])
        assert isinstance(state, drivers.StreamProgress) and state.finished
        assert isinstance(stage.position(), drivers.PositionReport)
        assert isinstance(stage.travel, drivers.TravelLimits)
        assert isinstance(stage.where(), drivers.Whereabouts)
