"""Every log the product writes opens in `motionctl log decode`, on all five protocols, in other
processes: motionctl's `--log` (naming its protocol and port, even where the device speaks
first), motionsim's `--record` (the device's side, decoded as the host's), a pyserial spy://
capture (naming nothing: the protocol is recognised from its traffic, and said); and a decode
cut short by `| head` ends quietly."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.support.e2e import motionctl
from tests.support.simproc import ROOT, SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(90), pytest.mark.usefixtures("settings_file")]

# A command with traffic each (Firmata's board speaks first: its log begins with what it sent).
COMMANDS = {
    "coxiris": ("id",),
    "visiomex": ("param", "set", "21", "100"),
    "laser-frame": ("id",),
    "pi-frame": ("home",),
    "firmata": ("id",),
}


def _decode(log: Path, *options: str) -> tuple[int, dict[str, object], str]:
    done = subprocess.run(
        [sys.executable, "-m", "app.cli", *options, "--json", "log", "decode", str(log)],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )
    return done.returncode, json.loads(done.stdout) if done.stdout else {}, done.stderr


def _sent(result: dict[str, object]) -> list[str]:
    frames = result["frames"]
    assert isinstance(frames, list)
    return [f["hex"] for f in frames if f["direction"] == "tx"]


@pytest.fixture(scope="module", params=list(COMMANDS))
def logs(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Iterator:
    """One run of the protocol's command on motionsim over a pty, logged three ways."""
    protocol = request.param
    folder = tmp_path_factory.mktemp(protocol)
    record, log, spy = folder / "device.log", folder / "motionctl.log", folder / "spy.txt"
    sim = SimProcess(protocol, "--instant", "--record", str(record))
    with pytest.MonkeyPatch.context() as patch:  # the runs' settings: the module's own
        patch.setenv("MOTIONPANEL_SETTINGS", str(folder / "settings.ini"))
        try:
            for port, extra in ((sim.path, log), (f"spy://{sim.path}?file={spy}", None)):
                run = motionctl(protocol, port, *COMMANDS[protocol], log=extra, timeout=60)
                assert run.returncode == 0, run.stderr
        finally:
            assert sim.stop() == 0
    yield protocol, record, log, spy


def test_motionctl_s_log_names_its_protocol_and_port_and_decodes(logs) -> None:
    protocol, _record, log, _spy = logs
    first = log.read_text(encoding="utf-8").splitlines()[0]
    assert "# connected to /dev/" in first and f"({protocol}" in first
    status, result, stderr = _decode(log)  # no --protocol: the log's note names it
    assert status == 0, stderr
    assert result["protocol"].split()[0] == protocol and result["chosen_by"] == "named"
    assert _sent(result) and all(f["kind"] != "error" for f in result["frames"])


def test_the_simulator_s_record_decodes_as_the_host_s_side(logs) -> None:
    protocol, record, log, _spy = logs
    status, result, stderr = _decode(record)
    assert status == 0, stderr
    assert result["device_side"] is True and result["protocol"].split()[0] == protocol
    _, host, _ = _decode(log)
    # What motionctl sent is what the device read: the record's RX, shown as TX.
    assert _sent(result)[: len(_sent(host))] == _sent(host)


def test_a_spy_capture_naming_nothing_is_recognised_and_said(logs) -> None:
    protocol, _record, log, spy = logs
    status, result, stderr = _decode(spy)
    assert status == 0, stderr
    assert result["chosen_by"] == "recognised" and result["protocol"].split()[0] == protocol
    assert f"names no protocol: decoded as {protocol}" in stderr
    _, host, _ = _decode(log)
    assert _sent(result) == _sent(host)


def test_a_decode_cut_short_by_head_ends_quietly(logs, tmp_path: Path) -> None:
    protocol, _record, log, _spy = logs
    lines = log.read_text(encoding="utf-8").splitlines()
    big = tmp_path / "big.log"  # far more output than a pipe holds
    big.write_text("\n".join([line for line in lines if "#" not in line] * 3000))
    head = subprocess.run(
        f"{sys.executable} -m app.cli --protocol {protocol} log decode {big} | head -n 1",
        shell=True,
        capture_output=True,
        text=True,
        timeout=60,
        cwd=ROOT,
        executable="/bin/bash",
    )
    assert head.stdout.count("\n") == 1 and head.stdout.split()[1] in ("TX", "RX")
    assert head.stderr == "", f"{protocol}: {head.stderr}"
