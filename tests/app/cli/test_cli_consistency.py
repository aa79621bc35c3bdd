"""A consistent motionctl: no --port where no device is needed, options after the command, a log
that decodes as nothing refused, `speed` on every protocol (kept per port for the moves that
follow), one error prefix, numbers in plain digits, jogs reported in their own units."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest

from app.cli.arguments import parse_command_line
from app.cli.report import plain_error
from app.common import macros
from app.common.macros import Macro
from app.common.settings import open_settings, read_speed
from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.link.records import TrafficLogWriter
from drivers.link.transport import open_link
from drivers.messages import Message, plain_number
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.protocols.firmata import FirmataProtocol
from tests.support.e2e import motionctl_as_typed

pytestmark = pytest.mark.timeout(60)


def motionctl(*args: str) -> subprocess.CompletedProcess[str]:
    """`python -m app.cli ARGS`, exactly as given."""
    return motionctl_as_typed(*args, timeout=40)


def _coxiris_log(path: Path, note: str | None) -> Path:
    """A log of GET_ID on a simulated COXIRIS, with a connection note first if given."""
    link = open_link("sim://coxiris?instant=1", 115200)
    with path.open("a", encoding="utf-8") as stream:
        writer = TrafficLogWriter(stream)
        if note is not None:
            writer.note(note)
        link.listeners.append(writer)
        try:
            Motion(Client(link, CoxirisProtocol())).client.execute(cmd.GetId())
        finally:
            link.close()
    return path


# -- commands that need no device ----------------------------------------------------------------


def test_log_decode_takes_the_protocol_from_the_connection_note(tmp_path: Path) -> None:
    log = _coxiris_log(tmp_path / "session.log", "connected to /dev/ttyUSB0 (coxiris, 115200 baud)")
    done = motionctl("log", "decode", str(log), "--json")  # no --port, no --protocol
    assert done.returncode == 0, done.stderr
    meanings = [f["meaning"] for f in json.loads(done.stdout)["frames"]]
    assert meanings[1:] == ["GET_ID", "ACK GET_ID", "DONE GET_ID: CX25F7TK9P"]


def test_a_log_without_connection_notes_is_recognised_from_its_traffic(tmp_path: Path) -> None:
    log = _coxiris_log(tmp_path / "cli.log", None)
    told = motionctl("log", "decode", str(log), "--filter", "done")
    assert told.returncode == 0, told.stderr
    assert told.stdout.strip().endswith("DONE GET_ID: CX25F7TK9P")
    assert f"{log} names no protocol: decoded as coxiris" in told.stderr
    given = motionctl("log", "decode", str(log), "--protocol", "coxiris", "--filter", "done")
    assert given.returncode == 0 and given.stderr == "", given.stderr
    assert given.stdout.strip().endswith("DONE GET_ID: CX25F7TK9P")


def test_a_log_no_protocol_recognises_needs_protocol(tmp_path: Path) -> None:
    log = tmp_path / "noise.log"
    log.write_text("000000.001 RX   00 01 02                                          ...\n")
    refused = motionctl("log", "decode", str(log))
    assert refused.returncode == 2 and refused.stdout == ""
    assert refused.stderr.strip().endswith("recognises its traffic: give --protocol")


@pytest.mark.parametrize("protocol", ["laser-frame", "pi-frame", "firmata"])
def test_a_log_that_decodes_as_nothing_is_refused(tmp_path: Path, protocol: str) -> None:
    log = _coxiris_log(tmp_path / "cli.log", None)
    refused = motionctl("--protocol", protocol, "log", "decode", str(log))
    assert refused.returncode == 2 and refused.stdout == ""
    assert f"nothing in {log} decodes as {protocol}" in refused.stderr
    as_json = motionctl("--protocol", protocol, "log", "decode", str(log), "--json")
    assert json.loads(as_json.stdout)["exit"] == 2 and as_json.returncode == 2


def test_param_list_needs_no_port() -> None:
    listed = motionctl("param", "list", "--protocol", "visiomex", "--json")
    assert listed.returncode == 0, listed.stderr
    rows = json.loads(listed.stdout)["parameters"]
    assert rows[0]["name"] == "thread_distance_x" and rows[0]["last_written"] is None


def test_macro_list_needs_no_port_nor_protocol(tmp_path: Path) -> None:
    file = tmp_path / "m.json"
    macros.write_macro_file(
        file, [Macro("probe", "coxiris", ("home",)), Macro("out", "visiomex", ("jog 1 0",))]
    )
    for protocol in ("coxiris", "visiomex"):
        assert motionctl("--protocol", protocol, "macro", "import", str(file)).returncode == 0
    listed = motionctl("macro", "list", "--json")
    assert listed.returncode == 0, listed.stderr
    assert json.loads(listed.stdout)["macros"] == [
        {"name": "probe", "steps": ["home"], "protocol": "coxiris"},
        {"name": "out", "steps": ["jog 1 0"], "protocol": "visiomex"},
    ]
    assert motionctl("macro", "list").stdout.splitlines() == [
        "coxiris probe: home",
        "visiomex out: jog 1 0",
    ]
    one = motionctl("macro", "list", "--protocol", "visiomex", "--json")
    assert json.loads(one.stdout) == {"macros": [{"name": "out", "steps": ["jog 1 0"]}]}


@pytest.mark.parametrize(
    ("args", "why"),
    [
        (("--protocol", "coxiris", "position"), "position needs --port"),
        (("--protocol", "visiomex", "param", "set", "1", "2"), "param needs --port"),
        (("--protocol", "coxiris", "macro", "run", "probe"), "macro needs --port"),
        (("--port", "sim://coxiris", "position"), "position needs --protocol"),
    ],
)
def test_a_device_command_without_port_or_protocol_is_refused(args: tuple[str, ...], why: str):
    refused = motionctl(*args)
    assert refused.returncode == 2 and refused.stderr.startswith(f"motionctl: {why}")
    assert refused.stderr.count("\n") == 1 and refused.stdout == ""


# -- options before or after the command -----------------------------------------------------------


def test_options_after_the_command_are_motionctl_options() -> None:
    options = parse_command_line(
        ["move", "-5", "0.5", "--json", "--port", "p", "--protocol", "coxiris", "--travel", "none"]
    )
    assert options.args == ["-5", "0.5"]
    assert (options.json, options.port, options.protocol, options.travel) == (
        True,
        "p",
        "coxiris",
        "none",
    )
    arc = parse_command_line(["--protocol", "pi-frame", "arc", "0", "0", "5", "0", "90", "--ccw"])
    assert arc.args == ["0", "0", "5", "0", "90", "--ccw"] and not arc.json  # the command's own
    config = parse_command_line(["config", "--steps-per-rev", "200", "--pins", "2", "3", "-v"])
    assert config.args == ["--steps-per-rev", "200", "--pins", "2", "3"] and config.verbose
    assert parse_command_line(["log", "decode", "F", "--filter", "x"]).args[2:] == ["--filter", "x"]


def test_a_command_gives_the_same_answer_with_options_after_it() -> None:
    port = "sim://coxiris?instant=1"
    before = motionctl("--port", port, "--protocol", "coxiris", "--json", "id")
    after = motionctl("id", "--json", "--protocol", "coxiris", "--port", port)
    assert before.returncode == after.returncode == 0, after.stderr
    assert json.loads(before.stdout) == json.loads(after.stdout) == {"id": "CX25F7TK9P"}


# -- speed on every protocol ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("protocol", "sent"),
    [
        ("pi-frame", "Linear X=500 Y=0 Z=0 ticks at 1250/0/0 ticks/s"),  # 12.5 mm/s x 100/mm
        ("laser-frame", "MOVE_LINEAR [5.0, 0.0, 0.0, 12.5]"),
    ],
)
def test_speed_goes_with_the_moves_of_later_runs(tmp_path: Path, protocol: str, sent: str) -> None:
    port = f"sim://{protocol}?instant=1"
    base = ("--port", port, "--protocol", protocol)
    set_speed = motionctl(*base, "speed", "12.5", "--json")
    assert set_speed.returncode == 0, set_speed.stderr
    assert json.loads(set_speed.stdout) == {"speed": 12.5, "requested": 12.5, "in_moves": True}
    assert motionctl(*base, "speed").stdout == "12.5 mm/s (for the moves that follow)\n"
    log = tmp_path / "move.log"
    moved = motionctl(*base, "--log", str(log), "move", "5", "0", "0")
    assert moved.returncode == 0, moved.stderr
    decoded = motionctl("--protocol", protocol, "log", "decode", str(log))
    assert any(line.endswith(sent) for line in decoded.stdout.splitlines()), decoded.stdout


def test_firmata_speed_is_kept_for_the_port() -> None:
    base = ("--port", "sim://firmata?instant=1", "--protocol", "firmata")
    assert motionctl(*base, "speed", "3").returncode == 0
    kept = motionctl(*base, "--json", "speed")
    assert json.loads(kept.stdout) == {"speed": 3.0, "in_moves": True}
    settings = open_settings()
    assert read_speed(settings, "firmata", "sim://firmata?instant=1") == 3.0
    assert read_speed(settings, "firmata", "/dev/ttyUSB9") is None  # another port: its own
    assert FirmataProtocol().capabilities.default_speed != 3.0


@pytest.mark.parametrize(
    ("protocol", "allowed"),
    [
        ("pi-frame", "0.01 to 655.35 mm/s"),
        ("laser-frame", "0.1 to 1000 mm/s"),
        ("coxiris", "1 to 100 mm/s"),
    ],
)
def test_a_speed_out_of_range_is_refused_before_anything_is_sent(
    tmp_path: Path, protocol: str, allowed: str
) -> None:
    log = tmp_path / "never.log"
    refused = motionctl(
        "--port", f"sim://{protocol}?instant=1", "--protocol", protocol, "--log", str(log),
        "speed", "100000000",
    )  # fmt: skip
    assert refused.returncode == 2
    assert (
        refused.stderr == f"motionctl: speed 100000000 mm/s refused: the device allows {allowed}\n"
    )
    if protocol == "coxiris":  # its limits are asked of the device; SET_SPEED is never sent
        decoded = motionctl("--protocol", protocol, "log", "decode", str(log)).stdout
        assert "GET_MAX_SPEED" in decoded and "SET_SPEED" not in decoded
    else:
        assert not log.exists()  # the port was never opened


# -- one prefix, plain numbers, units of a jog ----------------------------------------------------


def test_a_port_that_cannot_open_is_said_once() -> None:
    failed = motionctl("--port", "/dev/ttyNOPE42", "--protocol", "coxiris", "id")
    assert failed.returncode == 3
    assert (
        failed.stderr
        == "motionctl: cannot open /dev/ttyNOPE42: [Errno 2] No such file or directory\n"
    )


def test_an_error_is_cleaned_of_a_second_prefix_and_errno() -> None:
    assert plain_error("motionctl: motionctl: the device did not answer") == (
        "the device did not answer"
    )
    pyserial = (
        "cannot open /dev/x: [Errno 13] could not open port /dev/x: [Errno 13] "
        "Permission denied: '/dev/x'"
    )
    assert plain_error(pyserial) == "cannot open /dev/x: [Errno 13] Permission denied"
    log = "cannot write the log /a/b.log: [Errno 2] No such file or directory: '/a/b.log'"
    assert plain_error(log) == "cannot write the log /a/b.log: [Errno 2] No such file or directory"
    assert plain_error("line one\nline two") == "line one line two"


def test_numbers_are_written_in_plain_digits() -> None:
    said = Message("speed {speed:g} mm/s, {small:g}, {short:.3g}, {whole:g}", speed=1e8,
                   small=1.5e-7, short=123456789.0, whole=25.0)  # fmt: skip
    assert said == "speed 100000000 mm/s, 0.00000015, 123000000, 25"
    assert said.template.startswith("speed {speed:g}")
    assert plain_number(123456789.0) == "123456789" and plain_number(0.1) == "0.1"
    assert Message("{x!r} {y:.2f} {n:g}", x=1e8, y=2.0, n=7) == "100000000.0 2.00 7"


def test_a_rotational_jog_is_reported_in_degrees(tmp_path: Path) -> None:
    base = ("--port", "sim://visiomex?instant=1", "--protocol", "visiomex", "--variant", "board12")
    assert motionctl(*base, "set-home").returncode == 0
    jogged = motionctl(*base, "jog", "90", "0", "--kind", "rotational")
    assert jogged.returncode == 0, jogged.stderr
    assert jogged.stdout.startswith("jog X 90 Y 0 degrees, packet MRP0090P0000")
    box = motionctl(*base, "--travel", "0:1,0:1,0:0", "--kind", "rotational", "jog", "90", "0")
    assert box.returncode == 2
    assert "jog by (90, 0, 0) degrees" in box.stderr and box.stderr.count("motionctl:") == 1
