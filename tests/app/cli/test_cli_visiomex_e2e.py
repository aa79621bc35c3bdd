"""motionctl against `motionsim visiomex` in another process, through a real pseudo-terminal.

The Visiomex firmware ends a packet after 1 s of silence, so every set costs about 1.03 s: moves
run on `--instant` devices where the stepping time does not matter, and the 27-parameter profile
is written once. What went on the wire is read back from motionctl's own `--log` hexdump (the hex
columns, not the text column) and, for "nothing sent", also from the device's `--record`.
"""

from __future__ import annotations

import itertools
import json
import re
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from drivers.device.param_profile import format_profile
from drivers.link.records import Traffic, hexdump_lines
from drivers.protocols.visiomex.params import PARAMETERS
from drivers.protocols.visiomex.protocol import VisiomexProtocol
from tests.support import e2e as e2e_support
from tests.support.e2e import Run, device_received, sent, stream, traffic
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.usefixtures("settings_file")  # motionctl writes the settings
SET_SECONDS = 1.0  # the firmware's silence window: no reply, and no second packet, sooner


def received(log: Path) -> bytes:
    """Everything motionctl read, as bytes (the binary tests' `received` gives records)."""
    return stream(log, "RX")


def motionctl(port: str, *args: str, log: Path | None = None, options: tuple[str, ...] = ()) -> Run:
    """Run `motionctl --port PORT --protocol visiomex [OPTIONS] ARGS`; how long it took too."""
    return e2e_support.motionctl("visiomex", port, *args, log=log, options=options, timeout=90)


def packet(parameter_id: int, wire: int) -> bytes:
    """A seed-variant set packet, written out independently of the driver."""
    return f"S{parameter_id:02d}{wire:06d}".ljust(18, "N").encode("ascii")


@pytest.fixture
def host_log(tmp_path: Path) -> Path:
    return tmp_path / "host.log"


@pytest.fixture
def start_sim(tmp_path: Path) -> Iterator[Callable[..., tuple[SimProcess, Path]]]:
    """Starts `motionsim visiomex ARGS --record FILE`; each is stopped (and must exit 0) after."""
    started: list[SimProcess] = []

    def start(*args: str) -> tuple[SimProcess, Path]:
        record = tmp_path / f"device{len(started)}.log"
        process = SimProcess("visiomex", "--record", str(record), *args)
        started.append(process)
        return process, record

    yield start
    for process in started:
        if process.proc.poll() is None:
            assert process.stop() == 0


@pytest.fixture(scope="module")
def idle_sim(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[SimProcess, Path]]:
    """One device for the refusal tests: none of them may send it anything."""
    record = tmp_path_factory.mktemp("idle") / "device.log"
    process = SimProcess("visiomex", "--record", str(record))
    yield process, record
    assert process.stop() == 0
    assert device_received(record) == b""


def refused_before_sending(idle_sim: tuple[SimProcess, Path], host_log: Path, *args: str) -> Run:
    """Run motionctl on the idle device; it must exit 2 having written nothing."""
    sim, record = idle_sim
    before = device_received(record)
    result = motionctl(sim.path, *args, log=host_log)
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    assert result.stderr.startswith("motionctl: ")
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert sent(host_log) == []
    assert device_received(record) == before
    return result


# -- 1. a set: exact packet, reply, remembered ------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_param_set_sends_one_packet_and_remembers_the_value(start_sim, host_log: Path) -> None:
    sim, _ = start_sim()
    result = motionctl(sim.path, "param", "set", "pulley_diameter_x", "38.2", log=host_log)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "pulley_diameter_x = 38.2 mm"
    [tx] = sent(host_log)
    assert tx.data == b"S03000382NNNNNNNNN"
    rx = [r for r in traffic(host_log) if r.direction == "RX"]
    assert b"FS0003\r" in received(host_log)
    assert rx[0].time - tx.time >= SET_SECONDS  # the firmware waited for the silence

    listed = motionctl(sim.path, "--json", "param", "list")
    assert listed.returncode == 0, listed.stderr
    rows = {row["name"]: row for row in json.loads(listed.stdout)["parameters"]}
    assert len(rows) == 27
    assert rows["pulley_diameter_x"]["last_written"] == 38.2
    assert rows["driving_mechanism"]["last_written"] == 1.0  # forced by the firmware's set
    assert all(
        row["last_written"] is None
        for name, row in rows.items()
        if name not in ("pulley_diameter_x", "driving_mechanism")
    )


# -- 2. a move: exact packet, debug lines, FA0001, commanded position -------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_move_sends_one_packet_and_ends_at_fa0001(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("--instant")
    assert motionctl(sim.path, "set-home").returncode == 0  # counting starts (nothing sent)
    result = motionctl(sim.path, "--json", "move", "10", "-2.5", log=host_log)
    assert result.returncode == 0, result.stderr
    assert [r.data for r in sent(host_log)] == [b"MLP0010000N0002500"]
    # At power-on the firmware's Y loop makes no step (issue 28): counted so, said first.
    assert json.loads(result.stdout) == {
        "position": [10.0, 0.0, 0.0],
        "measured": False,
        "counted": True,
        "notices": [
            "Y will not move: at these parameters the firmware's Y loop makes no step (it runs "
            "the ramp count, 0; set 22 and 24 so that the ramp length is above 0)"
        ],
    }
    # The firmware's 9 debug lines come before FP0001 and do not disturb the driver. Lines end
    # in CR LF; motionctl is done at the CR of FA0001 and never reads its LF.
    lines = re.split(r"\r\n?", received(host_log).decode("ascii"))
    assert lines.index("FP0001") == 9 and lines.index("FA0001") == 10
    assert lines[0] == "Driving Mechanism: 1" and lines[8] == "Step y: 100"


# -- 3. bad values: refused before anything is sent ------------------------------------------
RANGE_PULLEY = ("pulley_diameter_x", "mm", "0.0 mm to 99999.9 mm", "steps of 0.1 mm")


BAD_VALUES = [
    (("param", "set", "pulley_diameter_x", "38.25"), ("38.25 mm", *RANGE_PULLEY)),
    (("param", "set", "pulley_diameter_x", "-1"), ("-1 mm", *RANGE_PULLEY)),
    (("param", "set", "3", "100000"), ("100000 mm", *RANGE_PULLEY)),
    (("param", "set", "pulley_diameter_x", "1e7"), ("pulley_diameter_x", "'1e7'")),
    (("param", "set", "3", "nan"), ("pulley_diameter_x", "'nan'")),
    (("param", "set", "3", "abc"), ("pulley_diameter_x", "'abc'")),
    (("param", "set", "driving_mechanism", "2"), ("driving_mechanism", "2", "0 to 1")),
    (("param", "set", "nope", "1"), ("'nope'", "1..27", "param list")),
    (("param", "set", "28", "1"), ("'28'", "1..27")),
    (("param", "set", "0", "1"), ("'0'", "1..27")),
    (("move", "1", "2", "3"), ("Z 3 mm", "X and Y only")),
    (("move", "10000", "0"), ("X 10000 mm", "9999.999 mm", "7 digits")),
    (("jog", "0.0005", "0"), ("X 0.0005 mm", "1 µm")),
    (("speed", "12.5"), ("input_speed_steady_x", "12.5 mm/s", "whole numbers")),
]


@pytest.mark.e2e
@pytest.mark.timeout(15)
@pytest.mark.parametrize(
    ("args", "expected"), [pytest.param(a, e, id=" ".join(a)) for a, e in BAD_VALUES]
)
def test_bad_values_are_refused_before_anything_is_sent(
    idle_sim, host_log: Path, args: tuple[str, ...], expected: tuple[str, ...]
) -> None:
    result = refused_before_sending(idle_sim, host_log, *args)
    for fragment in expected:
        assert fragment in result.stderr, (fragment, result.stderr)


@pytest.mark.e2e
@pytest.mark.timeout(15)
@pytest.mark.parametrize("value", ["1e7", "nan", "abc"])
def test_a_value_that_is_not_a_number_is_refused_with_the_unit_and_range(
    idle_sim, host_log: Path, value: str
) -> None:
    result = refused_before_sending(idle_sim, host_log, "param", "set", "3", value)
    assert "0.0 mm to 99999.9 mm" in result.stderr, result.stderr


# -- 4. two sets in one run are two packets ---------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_two_sets_in_one_run_are_not_merged(start_sim, host_log: Path, tmp_path: Path) -> None:
    sim, record = start_sim()
    profile = tmp_path / "two.toml"
    profile.write_text(
        'protocol = "visiomex"\n\n[parameters]\npulley_diameter_x = 38.2\n'
        "input_speed_steady_x = 12\n",
        encoding="utf-8",
    )
    result = motionctl(sim.path, "--json", "param", "write", str(profile), log=host_log)
    assert result.returncode == 0, result.stderr
    first, second = sent(host_log)
    assert first.data == packet(3, 382) and second.data == packet(21, 12)
    assert second.time - first.time >= SET_SECONDS
    rx = received(host_log)
    assert b"FS0003\r" in rx and b"FS0021\r" in rx
    assert rx.index(b"FS0003") < rx.index(b"FS0021")
    assert device_received(record) == first.data + second.data
    written = json.loads(result.stdout)["written"]
    assert [(w["name"], w["value"]) for w in written] == [
        ("pulley_diameter_x", 38.2),
        ("input_speed_steady_x", 12.0),
    ]
    assert written[0]["device_values"] == {"driving_mechanism": 1.0}
    # 21 = 12 mm/s: the firmware recomputes delta_t_x (25 = 21 ÷ 23 = 12 ÷ 10, whole)
    assert written[1]["device_values"] == {"driving_mechanism": 1.0, "delta_t_x": 1.0}
    progress = [line for line in result.stderr.splitlines() if "confirmed" in line]
    assert progress[0].startswith("motionctl: 1/2 pulley_diameter_x = 38.2 mm confirmed")
    assert progress[1].startswith("motionctl: 2/2 input_speed_steady_x = 12 mm/s confirmed")
    assert len(progress) == 2


# -- 5. a device that never answers -------------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(30)
def test_a_device_that_never_answers_exits_3(start_sim) -> None:
    sim, _ = start_sim("--mute")
    result = motionctl(sim.path, "param", "set", "3", "38.2")
    assert result.returncode == 3
    assert result.seconds < 4.0
    assert result.stdout == ""
    [line] = result.stderr.strip().splitlines()
    assert line.startswith("motionctl: the device did not answer")
    assert "pulley_diameter_x" in line
    assert motionctl(sim.path, "set-home").returncode == 0  # a count: the move may go
    moved = motionctl(sim.path, "move", "1", "0")
    assert moved.returncode == 3
    assert moved.seconds < 10.0
    [line] = moved.stderr.strip().splitlines()
    assert "did not answer to MLP0001000P0000000" in line
    # The packet went and may have moved the stage: the count is gone.
    after = motionctl(sim.path, "position")
    assert after.returncode == 2 and "position unknown" in after.stderr, after.stderr


# -- 6. the firmware's debug noise (its move lines are checked in test 2) -----------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_an_error_code_exits_1_with_the_firmware_message(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("--instant")
    result = motionctl(sim.path, "raw", "X", log=host_log)
    assert result.returncode == 1
    assert [r.data for r in sent(host_log)] == [b"X"]
    assert b"EP0002" in received(host_log)
    assert result.stderr.strip() == (
        "motionctl: packet X: the device answered EP0002 (invalid command type)"
    )


@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_raw_packet_with_no_reply_exits_0_at_once(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("--instant")
    result = motionctl(sim.path, "raw", "G", log=host_log)
    assert result.returncode == 0, result.stderr
    assert [r.data for r in sent(host_log)] == [b"G"]
    assert result.seconds < 3.0


# -- 7. wire variants -------------------------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_prefixed_feedback_is_taken_only_by_the_prefixed_variant(start_sim) -> None:
    sim, _ = start_sim("--variant", "prefixed", "--instant")
    result = motionctl(sim.path, "param", "set", "3", "38.2", options=("--variant", "prefixed"))
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "pulley_diameter_x = 38.2 mm"
    seed = motionctl(sim.path, "param", "set", "3", "38.2")
    assert seed.returncode == 3
    assert "did not answer to S03000382NNNNNNNNN" in seed.stderr
    assert "'>FS0003'" in seed.stderr  # it came, and was not taken as the reply


@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_board12_packets(start_sim, tmp_path: Path) -> None:
    assert VisiomexProtocol("board12").capabilities.default_baud == 115200
    sim, _ = start_sim("--variant", "board12", "--baud", "115200", "--instant")
    options = ("--variant", "board12", "--baud", "115200")
    jog_log, home_log = tmp_path / "jog.log", tmp_path / "home.log"
    jogged = motionctl(sim.path, "jog", "3", "-2", log=jog_log, options=options)
    assert jogged.returncode == 0, jogged.stderr
    assert [r.data for r in sent(jog_log)] == [b"MLP0003N0002"]
    assert b"FA0001" in received(jog_log)
    homed = motionctl(sim.path, "home", log=home_log, options=options)
    assert homed.returncode == 0, homed.stderr
    assert [r.data for r in sent(home_log)] == [b"DNNNNNNNNNNN"]
    assert b"FA0001" in received(home_log)
    assert homed.stdout.strip() == "0.00 0.00 0.00 (counted, not measured)"


# -- 8. a whole profile, written and remembered -------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(60)
def test_full_profile_round_trip(start_sim, host_log: Path, tmp_path: Path) -> None:
    values = {p.name: p.default for p in PARAMETERS}
    inputs = [p for p in PARAMETERS if not p.output]  # a profile never holds firmware outputs
    profile = tmp_path / "all.toml"
    text = format_profile(values, PARAMETERS, "visiomex")
    output = next(p for p in PARAMETERS if p.output)  # one written by hand: left out, said so
    text += f"{output.name} = {output.default:g}\n"
    profile.write_text(text, encoding="utf-8")
    sim, _ = start_sim()
    result = motionctl(sim.path, "--json", "param", "write", str(profile), log=host_log)
    assert result.returncode == 0, result.stderr
    assert f"not written: {output.name} (computed by the firmware" in result.stderr
    written = json.loads(result.stdout)["written"]
    assert [w["name"] for w in written] == [p.name for p in inputs]
    assert [w["value"] for w in written] == [float(p.default) for p in inputs]
    packets = sent(host_log)
    assert [r.data for r in packets] == [packet(p.id, round(p.default * p.scale)) for p in inputs]
    assert all(b.time - a.time >= SET_SECONDS for a, b in itertools.pairwise(packets))
    assert sum("confirmed" in line for line in result.stderr.splitlines()) == len(inputs)

    listed = motionctl(sim.path, "--json", "param", "list")
    assert listed.returncode == 0, listed.stderr
    rows = json.loads(listed.stdout)["parameters"]
    last = {row["name"]: row["last_written"] for row in rows if row["last_written"] is not None}
    assert last == {p.name: float(p.default) for p in inputs}


# -- 9. malformed profile files -------------------------------------------------------------
HEAD = 'protocol = "visiomex"\n\n[parameters]\n'


@pytest.mark.e2e
@pytest.mark.timeout(15)
@pytest.mark.parametrize(
    ("content", "expected"),
    [
        ("this is = = not toml\n", ("not a parameter profile", "line 1")),
        (HEAD + "thread_distance_x = 10\nnope = 1\n", ("line 5", "unknown parameter 'nope'")),
        (HEAD + "pulley_diameter_x = 38.25\n", ("line 4", "pulley_diameter_x", "0.1 mm")),
        (HEAD + 'pulley_diameter_x = "38.2"\n', ("line 4", "pulley_diameter_x", "not a number")),
        ('protocol = "visiomex"\npulley_diameter_x = 38.2\n', ("line 2", "pulley_diameter_x")),
        ('protocol = "visiomex"\n', ("no [parameters] table",)),
        (HEAD + "# padding\n" * (100 * 1024 // 10), ("larger than 64 KiB",)),
        (bytes(range(256)) * 4, ("not UTF-8 text",)),
        ('protocol = "coxiris"\n\n[parameters]\nthread_distance_x = 10\n', ("'coxiris'",)),
        (None, ("cannot read the profile", "No such file")),
    ],
    ids=[
        "not-toml",
        "unknown-name",
        "out-of-range",
        "string-value",
        "top-level-values",
        "no-table",
        "100KiB",
        "binary",
        "coxiris",
        "missing",
    ],
)
def test_malformed_profiles_are_refused_naming_the_file(
    idle_sim, host_log: Path, tmp_path: Path, content: str | bytes | None, expected: tuple[str, ...]
) -> None:
    profile = tmp_path / "profile.toml"
    if isinstance(content, bytes):
        profile.write_bytes(content)
    elif content is not None:
        profile.write_text(content, encoding="utf-8")
        if "padding" in content:
            assert profile.stat().st_size >= 100 * 1024
    result = refused_before_sending(idle_sim, host_log, "param", "write", str(profile))
    assert str(profile) in result.stderr
    for fragment in expected:
        assert fragment in result.stderr, (fragment, result.stderr)


@pytest.mark.e2e
@pytest.mark.timeout(5)
def test_the_log_reader_rebuilds_records(tmp_path: Path) -> None:
    """The hexdump reader, on what drivers/link/records.py writes: records apart, long ones
    whole."""
    records = [
        Traffic("tx", b"S03000382NNNNNNNNN", 10.0),
        Traffic("rx", b"FS0003\r\n", 11.0),
        Traffic("tx", b"ABCDEFGHIJKLMNOP", 12.0),  # exactly one full line
        Traffic("tx", b"01 23   45", 12.0),  # same stamp, text that looks like hex
    ]
    log = tmp_path / "host.log"
    log.write_text("".join(line + "\n" for r in records for line in hexdump_lines(r, 10.0)))
    assert [(r.time, r.direction) for r in traffic(log)[:2]] == [(0.0, "TX"), (1.0, "RX")]
    assert traffic(log)[0].data == b"S03000382NNNNNNNNN"
    assert received(log) == b"FS0003\r\n"
    # Two writes in the same millisecond after a full line cannot be told apart; the bytes are.
    assert b"".join(r.data for r in sent(log)) == b"S03000382NNNNNNNNNABCDEFGHIJKLMNOP01 23   45"
