"""`motionctl macro ...` in one process against motionsim in another, through a real pty."""

from __future__ import annotations

import json
import os
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.common import macros
from app.common.macros import Macro
from tests.support.e2e import device_received, motionctl
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60)]

PROBE = Macro("home and probe", "coxiris", ("home", "move 10 5 0", "jog 0 0 -2", "position"))


@pytest.fixture
def record(tmp_path: Path) -> Path:
    return tmp_path / "device.log"


@pytest.fixture
def sim(record: Path) -> Iterator[SimProcess]:
    process = SimProcess("coxiris", "--record", str(record), "--instant", control=True)
    yield process
    if process.proc.poll() is None:
        assert process.stop() == 0


def write(path: Path, *items: Macro) -> Path:
    macros.write_macro_file(path, items)
    return path


def test_import_list_and_run_a_homing_and_probe_macro(
    sim: SimProcess, record: Path, tmp_path: Path
) -> None:
    file = write(tmp_path / "m.json", PROBE, Macro("other", "visiomex", ("home",)))
    imported = motionctl("coxiris", "none", "macro", "import", str(file))
    assert imported.returncode == 0, imported.stderr
    assert imported.stdout.strip() == f"imported from {file}: home and probe"
    listed = motionctl("coxiris", "none", "--json", "macro", "list")
    assert json.loads(listed.stdout) == {
        "macros": [{"name": "home and probe", "steps": list(PROBE.steps)}]
    }
    assert motionctl("visiomex", "none", "macro", "list").stdout.strip() == (
        "no macros saved for this protocol"
    )
    run = motionctl("coxiris", sim.path, "macro", "run", "home and probe")
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines() == [
        "home: 0.00 0.00 0.00",
        "move 10 5 0: 10.00 5.00 0.00",
        "jog 0 0 -2: 10.00 5.00 -2.00 (commanded, not measured)",
        "position: 10.00 5.00 -2.00",
    ]
    assert [line for line in run.stderr.splitlines() if "step" in line] == [
        "motionctl: step 1/4: home",
        "motionctl: step 2/4: move 10 5 0",
        "motionctl: step 3/4: jog 0 0 -2",
        "motionctl: step 4/4: position",
    ]
    sent = device_received(record)
    assert sent.index(b"GO_HOME") < sent.index(b"ABSOLUTE_MOVE") < sent.index(b"DELTA_MOVE")
    assert sent.rindex(b"DELTA_MOVE") < sent.rindex(b"GET_POSITION")
    again = motionctl("coxiris", sim.path, "--json", "position")
    assert json.loads(again.stdout) == {"position": [10.0, 5.0, -2.0]}


def test_export_writes_what_import_reads(tmp_path: Path) -> None:
    file = write(tmp_path / "in.json", PROBE)
    assert motionctl("coxiris", "none", "macro", "import", str(file)).returncode == 0
    out = tmp_path / "out.json"
    exported = motionctl("coxiris", "none", "macro", "export", str(out))
    assert exported.returncode == 0, exported.stderr
    assert macros.read_macro_file(out) == [PROBE]


def test_an_unknown_macro_exits_2_with_nothing_sent(sim: SimProcess, record: Path) -> None:
    run = motionctl("coxiris", sim.path, "macro", "run", "nope")
    assert run.returncode == 2
    assert run.stderr.strip() == "motionctl: no coxiris macro named 'nope' (saved: none)"
    assert device_received(record) == b""


def test_a_saved_macro_with_a_bad_step_exits_2_with_nothing_sent(
    sim: SimProcess, record: Path, settings_file: Path
) -> None:
    from app.common.settings import open_settings

    macros.save(open_settings(), "coxiris", [Macro("m", "coxiris", ("home", "move 1 two"))])
    run = motionctl("coxiris", sim.path, "macro", "run", "m")
    assert run.returncode == 2
    assert "macro m, step 2 ('move 1 two')" in run.stderr
    assert device_received(record) == b""


def test_a_file_with_one_bad_macro_imports_none(tmp_path: Path) -> None:
    file = write(tmp_path / "m.json", PROBE, Macro("bad", "coxiris", ("home", "fly 3")))
    imported = motionctl("coxiris", "none", "macro", "import", str(file))
    assert imported.returncode == 2
    assert "macro bad, step 2 ('fly 3'): unknown command 'fly'" in imported.stderr
    assert "no macros saved" in motionctl("coxiris", "none", "macro", "list").stdout


@pytest.mark.parametrize("kind", ["fifo", "garbage", "directory"])
def test_a_hostile_file_is_refused(tmp_path: Path, kind: str) -> None:
    path = tmp_path / "m.json"
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "garbage":
        path.write_bytes(b"\xff\xfe{\x00")
    else:
        path.mkdir()
    imported = motionctl("coxiris", "none", "macro", "import", str(path))
    assert imported.returncode == 2
    assert str(path) in imported.stderr
    assert len(imported.stderr.splitlines()) == 1


def test_a_device_that_stops_answering_mid_macro_exits_3(sim: SimProcess, tmp_path: Path) -> None:
    file = write(tmp_path / "m.json", Macro("m", "coxiris", ("home", "position", "position")))
    assert motionctl("coxiris", "none", "macro", "import", str(file)).returncode == 0
    sim.fault("hang")
    run = motionctl("coxiris", sim.path, "--timeout", "0.5", "macro", "run", "m")
    assert run.returncode == 3
    assert run.seconds < 10
    assert "did not answer" in run.stderr


def test_usage_errors_exit_2() -> None:
    for args in (("macro",), ("macro", "run"), ("macro", "list", "x"), ("macro", "delete", "x")):
        run = motionctl("coxiris", "none", *args)
        assert run.returncode == 2, args
        assert "usage: macro list | macro run NAME" in run.stderr, args
