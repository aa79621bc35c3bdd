"""motionctl in one process against motionsim in another, through a real pseudo-terminal."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import serial

from tests.support.e2e import device_received_text
from tests.support.simproc import ROOT, SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60)]

TRANSCRIPT = json.loads((Path(__file__).resolve().parents[2] / "data" / "coxiris.json").read_text())


def motionctl(port: str, *args: str, timeout: float = 2.0, log: Path | None = None):
    """Run motionctl and return the completed process."""
    options = ["--port", port, "--protocol", "coxiris", "--timeout", str(timeout)]
    if log is not None:
        options += ["--log", str(log)]
    return subprocess.run(
        [sys.executable, "-m", "app.cli", *options, *args],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )


@pytest.fixture(autouse=True)
def _own_settings(settings_file: Path) -> None:
    """motionctl reads and writes the panel's settings: a file of the test's own."""


def test_acceptance_move_then_position(sim: SimProcess) -> None:
    moved = motionctl(sim.path, "move", "10", "-5", "2.5")
    assert moved.returncode == 0, moved.stderr
    assert moved.stdout.strip() == "10.00 -5.00 2.50"
    position = motionctl(sim.path, "position")
    assert position.stdout.strip() == "10.00 -5.00 2.50"
    as_json = motionctl(sim.path, "--json", "position")
    assert json.loads(as_json.stdout) == {"position": [10.0, -5.0, 2.5]}
    assert as_json.stderr == ""


@pytest.mark.sim_args("--speed", "50")
def test_every_command(sim: SimProcess) -> None:
    def ok(*args: str) -> str:
        result = motionctl(sim.path, *args)
        assert result.returncode == 0, (args, result.stderr)
        return result.stdout.strip()

    assert ok("id") == "CX25F7TK9P"
    assert json.loads(ok("--json", "id")) == {"id": "CX25F7TK9P"}
    assert ok("position") == "0.00 0.00 0.00"
    assert ok("move", "1.5", "-2", "0.5") == "1.50 -2.00 0.50"
    assert ok("jog", "+.5", "1.", "-2") == "2.00 -1.00 -1.50"
    assert ok("jog", "1", "1") == "3.00 0.00 -1.50"
    assert ok("home") == "0.00 0.00 0.00"
    ok("move", "4", "4", "4")
    assert ok("set-home") == "ok"
    assert json.loads(ok("--json", "set-home")) == {"ok": True}
    assert ok("position") == "0.00 0.00 0.00"
    assert ok("speed") == "50 mm/s"
    assert json.loads(ok("--json", "speed", "12.5")) == {"speed": 13.0, "requested": 12.5}
    assert ok("speed") == "13 mm/s"
    assert ok("limits") == "min 1 mm/s, max 100 mm/s"
    assert json.loads(ok("--json", "limits")) == {"min_speed": 1.0, "max_speed": 100.0}
    assert ok("check") == "ok"
    assert json.loads(ok("--json", "check")) == {"errors": []}
    assert ok("raw", "get_id") == "ACK GET_ID\nDONE GET_ID: CX25F7TK9P"
    assert json.loads(ok("--json", "raw", "GET_SPEED")) == {
        "reply": ["ACK GET_SPEED", "DONE GET_SPEED: 13"]
    }


@pytest.mark.sim_args("--speed", "50", "--non-blocking")
def test_non_blocking_move_returns_when_the_target_is_reached(sim: SimProcess) -> None:
    moved = motionctl(sim.path, "move", "20", "0", "0")
    assert moved.returncode == 0, moved.stderr
    assert moved.stdout.strip() == "20.00 0.00 0.00"
    assert motionctl(sim.path, "position").stdout.strip() == "20.00 0.00 0.00"


@pytest.mark.sim_args("--fault", "Motor X stalled")
def test_device_error_exits_1(sim: SimProcess) -> None:
    result = motionctl(sim.path, "check")
    assert result.returncode == 1
    assert result.stderr.strip() == "motionctl: Motor X stalled"


def test_unknown_command_exits_1_at_once(sim: SimProcess) -> None:
    start = time.monotonic()
    result = motionctl(sim.path, "raw", "FOO", timeout=10.0)
    elapsed = time.monotonic() - start
    assert result.returncode == 1
    assert "does not know the command 'FOO'" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert elapsed < 10.0  # it did not wait for a DONE that never comes


@pytest.mark.parametrize(
    "args",
    [
        ("move", "1e3", "0"),
        ("move", ".", "0"),
        ("move", "nan", "0"),
        ("jog", "0x10", "0"),
        ("jog", "1,5", "0"),
        ("move", "inf", "0"),
        ("move", "1"),
        ("move", "1", "2", "3", "4"),
        ("id", "extra"),
        ("raw", "X" * 64),
        ("raw", "GET_€"),
        ("raw", "GET_ID\nHELP"),
        ("raw", "   "),
        ("raw",),
        ("speed", "0"),
        ("speed", "-5"),
        ("speed", "fast"),
        ("move", "99999999999", "0", "0"),
        ("move", "0.001", "0", "0"),
        ("jog", "0", "0.005"),
        ("--travel", "-50:50,-50:50,0:10", "move", "100000", "0", "0"),
        ("--travel", "1:2", "id"),
        ("teleport",),
    ],
)
def test_bad_input_exits_2_with_nothing_sent(sim: SimProcess, record: Path, args) -> None:
    result = motionctl(sim.path, *args)
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    assert len(result.stderr.strip().splitlines()) >= 1
    assert result.stderr.startswith(("motionctl: ", "usage: "))
    assert device_received_text(record) == ""


def test_bad_options_exit_2_with_nothing_sent(sim: SimProcess, record: Path) -> None:
    bad_options = (
        ["--timeout", "0"],
        ["--timeout", "-1"],
        ["--baud", "0"],
        ["--baud", "fast"],
        ["--log", "/nonexistent-dir/host.log"],
    )
    for options in bad_options:
        result = subprocess.run(
            [
                sys.executable,
                "-m",
                "app.cli.main",
                "--port",
                sim.path,
                "--protocol",
                "coxiris",
                *options,
                "id",
            ],
            capture_output=True,
            text=True,
            timeout=30,
            cwd=ROOT,
        )
        assert result.returncode == 2, result.stderr
    unknown = subprocess.run(
        [sys.executable, "-m", "app.cli", "--port", sim.path, "--protocol", "zmodem", "id"],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )
    assert unknown.returncode == 2
    assert device_received_text(record) == ""


def test_speed_above_the_maximum_never_sends_set_speed(sim: SimProcess, record: Path) -> None:
    result = motionctl(sim.path, "speed", "500")
    assert result.returncode == 2
    assert "the device allows 1 to 100 mm/s" in result.stderr
    sent = device_received_text(record)
    assert "GET_MAX_SPEED" in sent and "SET_SPEED" not in sent


@pytest.mark.sim_args("--mute")
def test_device_that_never_answers_exits_3(sim: SimProcess) -> None:
    start = time.monotonic()
    result = motionctl(sim.path, "id", timeout=0.5)
    assert result.returncode == 3
    assert "did not answer to GET_ID" in result.stderr
    assert "it may still be moving" in result.stderr
    assert time.monotonic() - start < 10
    as_json = motionctl(sim.path, "--json", "id", timeout=0.5)
    assert as_json.returncode == 3
    error = json.loads(as_json.stdout)
    assert error["exit"] == 3 and "did not answer" in error["error"]


def test_json_errors_are_one_object(sim: SimProcess) -> None:
    for args, status in (
        (("--json", "move", "1e3", "0"), 2),
        (("--json", "raw", "FOO"), 1),
        (("--json", "teleport"), 2),
    ):
        result = motionctl(sim.path, *args)
        assert result.returncode == status, result.stderr
        error = json.loads(result.stdout)
        assert set(error) == {"error", "exit"} and error["exit"] == status
        assert error["error"]


def test_travel_limits_refuse_a_jog_beyond_them(sim: SimProcess, record: Path) -> None:
    travel = ("--travel", "-50:50,-20:20,0:10")
    assert motionctl(sim.path, *travel, "move", "45", "0", "0").returncode == 0
    result = motionctl(sim.path, *travel, "jog", "10", "0")
    assert result.returncode == 2
    assert "X 55 mm is outside -50..50 mm" in result.stderr
    assert "DELTA_MOVE" not in device_received_text(record)


def test_travel_limits_clamp_when_asked(sim: SimProcess) -> None:
    result = motionctl(
        sim.path, "--travel", "-50:50,-20:20,0:10", "--clamp", "--json", "jog", "80", "0"
    )
    assert result.returncode == 0, result.stderr
    answer = json.loads(result.stdout)
    assert answer["position"] == [50.0, 0.0, 0.0]
    assert "clamped" in answer["notices"][0] and "clamped" in result.stderr


def test_travel_limits_saved_by_the_panel_apply(sim: SimProcess, settings_file: Path) -> None:
    from PySide6.QtCore import QSettings

    from app.common.settings import write_travel
    from drivers.device.travel import TravelLimits

    settings = QSettings(str(settings_file), QSettings.Format.IniFormat)
    write_travel(settings, "coxiris", sim.path, TravelLimits(((-5, 5), (-5, 5), (0, 1))))
    settings.sync()
    result = motionctl(sim.path, "move", "6", "0", "0")
    assert result.returncode == 2 and "travel limits" in result.stderr
    assert motionctl(sim.path, "--travel", "none", "move", "6", "0", "0").returncode == 0


def test_port_that_does_not_exist_exits_3() -> None:
    result = motionctl("/dev/ttyNOPE42", "id")
    assert result.returncode == 3
    assert result.stderr.count("\n") == 1 and "cannot open /dev/ttyNOPE42" in result.stderr


@pytest.mark.sim_args("--speed", "1")
def test_device_vanishing_mid_move(sim: SimProcess, tmp_path: Path) -> None:
    log = tmp_path / "host.log"
    proc = subprocess.Popen(
        [sys.executable, "-m", "app.cli", "--port", sim.path, "--protocol", "coxiris",
         "--timeout", "5", "--log", str(log), "move", "100", "0", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=ROOT,
    )  # fmt: skip
    deadline = time.monotonic() + 20
    while "ACK ABSOLUTE_MOVE" not in _hexdump_text(log):
        assert time.monotonic() < deadline, "the move was never acknowledged"
        assert proc.poll() is None
        time.sleep(0.02)  # polling a file for a condition, with a deadline
    sim.kill()
    _, stderr = proc.communicate(timeout=20)
    assert proc.returncode == 3
    assert len(stderr.strip().splitlines()) == 1
    assert "reading from" in stderr or "failed" in stderr
    assert "ACK ABSOLUTE_MOVE" in _hexdump_text(log)


def _hexdump_text(log: Path) -> str:
    if not log.exists():
        return ""
    return "".join(line.split("   ")[-1] for line in log.read_text().splitlines() if " RX " in line)


@pytest.mark.sim_args("--instant", "--no-line-timing")
def test_recorded_transcript_byte_for_byte_over_the_pty(sim: SimProcess) -> None:
    # The recording is of the firmware built for a host behind a pty: a whole line arrives at
    # once, so the too-long line's tail is flushed with it. With line timing emulated the tail
    # arrives later and is parsed as a new command, as on a slow line (test_sim_coxiris_behaviour).
    with serial.Serial(sim.path, 115200, timeout=0.05) as port:
        for exchange in TRANSCRIPT["exchanges"]:
            expected = exchange["received"].encode("latin-1")
            port.write(exchange["sent"].encode("latin-1"))
            got = b""
            deadline = time.monotonic() + (5 if expected else 0.3)
            while time.monotonic() < deadline and (len(got) < len(expected) or not expected):
                got += port.read(max(1, port.in_waiting))
            assert got == expected, exchange["sent"]


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_motionsim_exits_cleanly_on_signals(sig: int) -> None:
    sim = SimProcess("coxiris")
    assert re.fullmatch(r"/dev/pts/\d+", sim.path)
    assert os.path.exists(sim.path)
    assert sim.stop(sig) == 0
    assert sim.proc.stderr is not None and sim.proc.stderr.read() == ""
