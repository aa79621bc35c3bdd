"""motionctl against `motionsim laser-frame`, in another process, over a pty.

The laser link answers every frame, so unlike the write-only devices of test_cli_binary_e2e.py
nothing here waits on an estimate: motionctl waits for replies, and the tests for motionctl. What
went on the wire is read back from motionctl's `--log` hexdump and from the device's `--record`
(whose RX is what the host wrote, before the simulator's own fault injection), split into frames
with the link's own StuffedFramer and decoded with `decode_instructions`; the reference bytes are
written out here independently of the driver.
"""

from __future__ import annotations

import itertools
import json
import math
import re
import struct
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

import pytest

from drivers.framers.stuffed import StuffedFramer
from drivers.protocols.laser.codec import FLOAT, INT16, crc16, decode_instructions
from tests.support import e2e as e2e_support
from tests.support.e2e import Record, Run, stream, traffic
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.usefixtures("settings_file")  # motionctl reads and writes the settings

MOVE_LINEAR, GO_HOME = 0x01, 0x03
GET_POSITION, GET_STATUS, SET_HOME, STOP, GET_ID = 0x10, 0x11, 0x12, 0x13, 0x14
SEQUENCE, ERROR = 0x20, 0x7F

STAMP = 0.001  # the log's resolution


def hexes(text: str) -> bytes:
    return bytes.fromhex(text)


def frame_of(data: bytes) -> bytes:
    """drivers/protocols/README.md §3 framing, written out: `EB 90 82 F0`, data with 90 doubled,
    `90 82`, sum."""
    return (
        hexes("EB 90 82 F0")
        + data.replace(b"\x90", b"\x90\x90")
        + hexes("90 82")
        + bytes((sum(data) & 0xFF,))
    )


GET_POSITION_FRAME = hexes("EB 90 82 F0 10 90 82 10")
GET_STATUS_FRAME = frame_of(bytes((GET_STATUS,)))
SET_HOME_FRAME = frame_of(bytes((SET_HOME,)))
STOP_FRAME = frame_of(bytes((STOP,)))
GET_ID_FRAME = frame_of(bytes((GET_ID,)))
assert frame_of(bytes((GET_POSITION,))) == GET_POSITION_FRAME


def dump_lines(log: Path) -> list[Record]:
    """The log's records (once read line by line: the same here, where every write is a frame
    shorter than a 16-byte hexdump line)."""
    return traffic(log)


def frames(data: bytes) -> list[bytes]:
    """The frames' unstuffed data; every byte must belong to a good frame."""
    framer = StuffedFramer()
    found: list[bytes] = []
    while data:
        used, frame = framer.decode(data)
        assert used, f"an incomplete frame at the end: {data.hex(' ')}"
        assert frame is not None, f"not a good frame ({framer.last_error}): {data[:used].hex(' ')}"
        found.append(frame)
        data = data[used:]
    return found


def wire_frames(data: bytes) -> list[bytes]:
    """The frames as they went on the wire (to compare with the reference bytes)."""
    framer = StuffedFramer()
    return [framer.encode(frame) for frame in frames(data)]


def float32(value: float) -> float:
    return struct.unpack("<f", struct.pack("<f", value))[0]


def sequence_of(frame: bytes) -> tuple[int, int]:
    """(frame number, CRC field) of a queued frame's data; its CRC checked over the raw bytes."""
    assert frame[:3] == hexes("20 F1 02"), frame.hex(" ")
    number, check = struct.unpack("<hh", frame[3:7])
    assert check & 0xFFFF == crc16(frame[7:]), f"frame {number}: CRC-16 differs"
    return number, check


def moves_of(frame: bytes) -> list[tuple[float, ...]]:
    """The MOVE_LINEAR values (x, y, z, speed) of a queued frame's data."""
    instructions = decode_instructions(frame)[1:]
    assert all(i.word == MOVE_LINEAR for i in instructions), instructions
    return [tuple(float(v) for v in i.values(FLOAT)) for i in instructions]


def motionctl(port: str, *args: str, log: Path | None = None, timeout: float = 60) -> Run:
    """Run `motionctl --port PORT --protocol laser-frame [--log LOG] ARGS`; how long it took."""
    return e2e_support.motionctl("laser-frame", port, *args, log=log, timeout=timeout)


def ok(run: Run) -> Run:
    assert run.returncode == 0, (run.returncode, run.stdout, run.stderr)
    return run


Point = tuple[float, float, float, float]


def write_program(path: Path, points: Sequence[Point]) -> Path:
    lines = ["x,y,z,speed", *(f"{x:.3f},{y:.3f},{z:.3f},{s:g}" for x, y, z, s in points)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def spiral(count: int, speed: float) -> list[Point]:
    """Distinct points on a rising spiral, each a short move from the last."""
    points = []
    for i in range(count):
        angle, radius = i * 0.05, 1.0 + i * 0.01
        x, y, z = radius * math.cos(angle), radius * math.sin(angle), i * 0.001
        points.append((round(x, 3), round(y, 3), round(z, 3), speed))
    return points


# -- fixtures ---------------------------------------------------------------------------------
@pytest.fixture
def host_log(tmp_path: Path) -> Path:
    return tmp_path / "host.log"


@pytest.fixture
def start_sim(tmp_path: Path) -> Iterator[Callable[..., tuple[SimProcess, Path]]]:
    """Starts `motionsim laser-frame ARGS --record FILE`; each is stopped (and must exit 0)."""
    started: list[SimProcess] = []

    def start(*args: str) -> tuple[SimProcess, Path]:
        record = tmp_path / f"device{len(started)}.log"
        process = SimProcess("laser-frame", "--record", str(record), *args)
        started.append(process)
        return process, record

    yield start
    for process in started:
        if process.proc.poll() is None:
            assert process.stop() == 0


@pytest.fixture(scope="module")
def idle_laser(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[SimProcess, Path]]:
    """One device for the refusal tests: none of them may send it anything."""
    record = tmp_path_factory.mktemp("idle_laser") / "device.log"
    process = SimProcess("laser-frame", "--instant", "--record", str(record))
    yield process, record
    assert process.stop() == 0
    assert stream(record, "RX") == b""


# -- 1. position: one exact frame ---------------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_position_sends_exactly_one_get_position_frame(start_sim, host_log: Path) -> None:
    sim, record = start_sim()
    result = ok(motionctl(sim.path, "position", log=host_log))
    assert result.stdout == "0.00 0.00 0.00\n"
    assert [line.data for line in dump_lines(host_log) if line.direction == "TX"] == [
        hexes("EB 90 82 F0 10 90 82 10")
    ]
    assert stream(record, "RX") == GET_POSITION_FRAME
    [reply] = frames(stream(host_log, "RX"))
    [answer] = decode_instructions(reply)
    assert answer.word == GET_POSITION and answer.values(FLOAT) == (0.0, 0.0, 0.0)


# -- 2. id, a queued move, set-home, status, stop ---------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(30)
def test_id_move_set_home_status_stop(start_sim, tmp_path: Path) -> None:
    sim, record = start_sim()  # moves take their time: 10 mm/s
    logs = {name: tmp_path / f"{name}.log" for name in ("id", "move", "home", "status", "stop")}

    identified = ok(motionctl(sim.path, "id", log=logs["id"]))
    assert identified.stdout == "LZR-SIM-01\n"
    assert wire_frames(stream(logs["id"], "TX")) == [GET_ID_FRAME]

    moved = ok(motionctl(sim.path, "move", "10", "5", "0", log=logs["move"]))
    assert moved.stdout == "10.00 5.00 0.00\n"
    sent = frames(stream(logs["move"], "TX"))
    queued = [f for f in sent if f[0] == SEQUENCE]
    assert len(queued) == 1, [f.hex(" ") for f in sent]
    # Where it was first, then the one queued frame, then position polls until it got there.
    index = sent.index(queued[0])
    assert index >= 1
    assert all(f == bytes((GET_POSITION,)) for f in sent[:index] + sent[index + 1 :])
    assert len(sent) - index - 1 >= 2  # polled while the stage moved
    number, check = sequence_of(queued[0])
    assert 1 <= number <= 32767
    sequence, move = decode_instructions(queued[0])
    assert sequence.word == SEQUENCE and sequence.values(INT16) == (number, check)
    move_bytes = hexes("01 F0 04") + struct.pack("<4f", 10.0, 5.0, 0.0, 10.0)
    assert queued[0][7:] == move_bytes
    assert move.word == MOVE_LINEAR
    assert move.values(FLOAT) == (10.0, 5.0, 0.0, 10.0)  # the default 10 mm/s
    assert moved.seconds >= math.hypot(10, 5) / 10 - 0.05  # it returned once the move had ended
    replies = [decode_instructions(f)[0] for f in frames(stream(logs["move"], "RX"))]
    assert replies[index].word == SEQUENCE and replies[index].values(INT16) == (number,)
    assert replies[-1].word == GET_POSITION
    assert replies[-1].values(FLOAT) == (10.0, 5.0, 0.0)

    homed = ok(motionctl(sim.path, "set-home", log=logs["home"]))
    assert homed.stdout == "ok\n"
    assert wire_frames(stream(logs["home"], "TX")) == [SET_HOME_FRAME]
    assert ok(motionctl(sim.path, "position")).stdout == "0.00 0.00 0.00\n"

    status = ok(motionctl(sim.path, "status", log=logs["status"]))
    assert status.stdout == "queue 0, idle\n"
    assert wire_frames(stream(logs["status"], "TX")) == [GET_STATUS_FRAME]
    as_json = ok(motionctl(sim.path, "--json", "status"))
    assert json.loads(as_json.stdout) == {"status": {"queue": 0, "moving": False}}

    stopped = ok(motionctl(sim.path, "stop", log=logs["stop"]))
    assert stopped.stdout == "ok\n"
    assert wire_frames(stream(logs["stop"], "TX")) == [STOP_FRAME]
    assert frames(stream(logs["stop"], "RX")) == [bytes((STOP,))]

    assert frames(stream(record, "RX")).count(queued[0]) == 1  # the move went once


@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_jog_moves_by_the_distance(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("--instant")
    jogged = ok(motionctl(sim.path, "jog", "1", "0", "0", log=host_log))
    assert jogged.stdout == "1.00 0.00 0.00\n"
    queued = [f for f in frames(stream(host_log, "TX")) if f[0] == SEQUENCE]
    assert [moves_of(f) for f in queued] == [[(1.0, 0.0, 0.0, 10.0)]]


@pytest.mark.e2e
@pytest.mark.timeout(20)
@pytest.mark.parametrize(
    "follow_up",
    [
        pytest.param("home"),
        pytest.param("move"),
        pytest.param("run"),
    ],
)
def test_a_second_run_queued_command_is_executed(start_sim, tmp_path: Path, follow_up: str) -> None:
    sim, _ = start_sim("--instant")
    assert ok(motionctl(sim.path, "move", "10", "5", "0")).stdout == "10.00 5.00 0.00\n"
    if follow_up == "home":
        assert ok(motionctl(sim.path, "home")).stdout == "0.00 0.00 0.00\n"
    elif follow_up == "move":
        assert ok(motionctl(sim.path, "move", "20", "0", "0")).stdout == "20.00 0.00 0.00\n"
    else:
        program = write_program(tmp_path / "one.csv", [(3.0, 4.0, 0.0, 100.0)])
        ran = ok(motionctl(sim.path, "--json", "run", str(program)))
        assert json.loads(ran.stdout)["executed"] == 1
        assert ok(motionctl(sim.path, "position")).stdout == "3.00 4.00 0.00\n"


# -- 3. a 1,000-point program over a line that corrupts 1 % of the bytes ---------------------------
SUMMARY = re.compile(
    r"(\d+)/(\d+) instructions executed in (\d+) frames, (\d+) retransmission\(s\), "
    r"(\d+\.\d) s"
)
PROGRESS = re.compile(r"motionctl: (\d+)/(\d+) sent, (\d+) acknowledged, (\d+) executed, \d+/s")


@pytest.mark.e2e
@pytest.mark.timeout(60)
def test_run_a_thousand_points_over_a_corrupting_line(
    start_sim, tmp_path: Path, host_log: Path
) -> None:
    sim, record = start_sim("--corrupt", "0.01", "--seed", "7", "--instant")
    points = spiral(1000, 1000.0)
    assert len(set(points)) == 1000
    program = write_program(tmp_path / "spiral.csv", points)

    result = ok(motionctl(sim.path, "run", str(program), log=host_log))
    [summary] = result.stdout.splitlines()
    match = SUMMARY.fullmatch(summary)
    assert match, summary
    executed, total, frame_count, retransmissions = (int(match[i]) for i in range(1, 5))
    assert (executed, total) == (1000, 1000)
    assert retransmissions > 0
    assert math.ceil(1000 / 7) <= frame_count <= 1000
    assert float(match[5]) <= result.seconds
    progress = [PROGRESS.match(line) for line in result.stderr.splitlines()]
    assert progress and all(progress), result.stderr
    assert [int(p[1]) for p in progress if p] == sorted(int(p[1]) for p in progress if p)
    assert progress[-1] and progress[-1].group(1, 2, 3, 4) == ("1000", "1000", "1000", "1000")

    # The device's port saw exactly what motionctl wrote (its faults are injected after).
    host_tx = stream(host_log, "TX")
    assert stream(record, "RX") == host_tx
    sent = frames(host_tx)
    queued = [f for f in sent if f[0] == SEQUENCE]
    others = [f for f in sent if f[0] != SEQUENCE]
    # Queue depths while it runs; once it has run, where the stage is (the result's position).
    while others and others[-1] == bytes((GET_POSITION,)):
        others.pop()
    assert others and all(f == bytes((GET_STATUS,)) for f in others)
    by_number: dict[int, set[bytes]] = {}
    for frame in queued:
        by_number.setdefault(sequence_of(frame)[0], set()).add(frame)
    # One number per frame; a retransmission is the kept copy, byte for byte.
    assert len(by_number) <= frame_count
    assert len(by_number) == frame_count
    assert all(len(copies) == 1 for copies in by_number.values())
    assert len(queued) - frame_count <= retransmissions

    # Every frame was acknowledged with its number (its CRC checked above); together the
    # acknowledged frames hold each move once, in the program's order.
    replies = [decode_instructions(f)[0] for f in frames(stream(host_log, "RX"))]
    assert {r.word for r in replies} <= {SEQUENCE, ERROR, GET_STATUS, GET_POSITION}
    acked = {int(r.values(INT16)[0]) for r in replies if r.word == SEQUENCE}
    assert acked == set(by_number)
    # In the order first sent: numbers start anywhere and wrap, so sorting them is no order.
    first_sent = list(dict.fromkeys(sequence_of(frame)[0] for frame in queued))
    moves = [m for n in first_sent if n in acked for m in moves_of(next(iter(by_number[n])))]
    assert len(moves) == 1000
    assert len(set(moves)) == 1000
    assert moves == [tuple(float32(v) for v in p) for p in points]

    status = ok(motionctl(sim.path, "status"))
    assert status.stdout == "queue 0, idle\n"


# -- 4. bad programs: refused naming the line, nothing sent ------------------------------------
BAD_PROGRAMS = [
    pytest.param(
        "nohead.csv",
        b"1,2,3,10\n4,5,6,10\n",
        ("line 1", "header must name x, y, z and speed"),
        id="missing header",
    ),
    pytest.param(
        "word.csv",
        b"x,y,z,speed\n1,2,3,10\n\n1,abc,3,10\n",
        ("line 4", "y 'abc' is not a number"),
        id="not a number",
    ),
    pytest.param(
        "zero.csv",
        b"x,y,z,speed\n1,2,3,10\n4,5,6,0\n",
        ("line 3", "speed 0 mm/s"),
        id="speed 0",
    ),
    pytest.param(
        "image.csv",
        b"\x89PNG\r\n\x1a\n" + bytes(range(256)),
        ("image.csv", "not UTF-8 text"),
        id="binary",
    ),
    pytest.param(None, b"", ("cannot read the program", "absent.csv"), id="missing file"),
    pytest.param("empty.csv", b"", ("empty.csv", "no header line"), id="empty"),
    pytest.param(
        "huge.csv",
        b"x,y,z,speed\n1,2,3,10\n1e39,2,3,10\n",
        ("line 3", "float32"),
        id="beyond float32",
    ),
]


@pytest.mark.e2e
@pytest.mark.timeout(15)
@pytest.mark.parametrize(("name", "content", "expected"), BAD_PROGRAMS)
def test_bad_program_is_refused_before_sending(
    idle_laser, tmp_path: Path, host_log: Path, name: str | None, content: bytes, expected: tuple
) -> None:
    sim, record = idle_laser
    path = tmp_path / (name or "absent.csv")
    if name is not None:
        path.write_bytes(content)
    before = stream(record, "RX")
    result = motionctl(sim.path, "run", str(path), log=host_log)
    assert result.returncode == 2, (result.stdout, result.stderr)
    assert result.stdout == ""
    [line] = result.stderr.splitlines()
    assert line.startswith("motionctl: "), line
    for fragment in expected:
        assert fragment in line, (fragment, line)
    assert stream(host_log, "TX") == b""
    assert stream(record, "RX") == before


@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_program_saved_with_a_byte_order_mark_runs(start_sim, tmp_path: Path) -> None:
    sim, _ = start_sim("--instant")
    program = tmp_path / "excel.csv"
    program.write_bytes(b"\xef\xbb\xbfx,y,z,speed\r\n3,4,0,100\r\n")
    ran = ok(motionctl(sim.path, "--json", "run", str(program)))
    assert json.loads(ran.stdout)["executed"] == 1


# -- 5. a device that never answers -------------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_silent_device_position_exits_3_after_three_tries(start_sim, host_log: Path) -> None:
    sim, record = start_sim("--drop", "1.0")
    result = motionctl(sim.path, "position", log=host_log)
    assert result.returncode == 3, (result.stdout, result.stderr)
    assert result.seconds < 3.0
    assert result.stdout == ""
    [line] = result.stderr.splitlines()
    assert line.startswith("motionctl: "), line
    assert "GET_POSITION" in line and "3 tries" in line, line
    tx = [entry for entry in dump_lines(host_log) if entry.direction == "TX"]
    assert [entry.data for entry in tx] == [GET_POSITION_FRAME] * 3
    assert all(b.time - a.time >= 0.25 - STAMP for a, b in itertools.pairwise(tx))
    assert stream(host_log, "RX") == b""
    assert stream(record, "RX") == GET_POSITION_FRAME * 3
    assert stream(record, "TX") == b""


# -- 6. a clean line: full frames, no retransmission -----------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_json_run_on_a_clean_line_sends_full_frames(
    start_sim, tmp_path: Path, host_log: Path
) -> None:
    sim, record = start_sim("--instant")
    points = spiral(70, 1000.0)
    program = write_program(tmp_path / "seventy.csv", points)
    result = ok(motionctl(sim.path, "--json", "run", str(program), log=host_log))
    [line] = result.stdout.splitlines()
    summary = json.loads(line)
    # The keys scripts read since the first release stay; a program's name, where it ended
    # and its last line were added with issue 23.
    assert set(summary) == {
        *("instructions", "executed", "frames", "retransmissions", "seconds"),
        *("program", "finished", "position", "measured", "last_line"),
    }
    assert summary["finished"] is True
    assert summary["instructions"] == summary["executed"] == 70
    assert summary["frames"] == 10
    assert summary["retransmissions"] == 0
    assert 0 < summary["seconds"] <= result.seconds
    assert PROGRESS.match(result.stderr.splitlines()[-1]), result.stderr

    queued = [f for f in frames(stream(record, "RX")) if f[0] == SEQUENCE]
    assert len(queued) == 10
    numbers = [sequence_of(f)[0] for f in queued]
    assert len(set(numbers)) == 10
    assert [len(moves_of(f)) for f in queued] == [7] * 10
    moves = [m for f in queued for m in moves_of(f)]
    assert moves == [tuple(float32(v) for v in p) for p in points]
    acks = [decode_instructions(f)[0] for f in frames(stream(host_log, "RX"))]
    assert [int(a.values(INT16)[0]) for a in acks if a.word == SEQUENCE] == numbers
    assert ERROR not in {a.word for a in acks}
