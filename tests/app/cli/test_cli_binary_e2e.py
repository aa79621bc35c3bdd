"""motionctl against `motionsim pi-frame` and `motionsim firmata`, in other processes, over a pty.

Both devices are write-only: nothing ends a move but motionctl's own estimate, so moves are short
or fast. What went on the wire is read back from motionctl's `--log` hexdump (the hex columns) and
from the device's `--record`. The Firmata board announces itself `--reset-delay` seconds after it
boots; motionctl waits up to 2.5 s for it after opening the port, so each Firmata run costs ~2.3 s.
"""

from __future__ import annotations

import json
import math
import struct
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from tests.support.e2e import (
    Run,
    device_received,
    device_sent,
    motionctl,
    received,
    sent,
    traffic,
)
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.usefixtures("settings_file")  # motionctl writes the settings

STAMP = 0.001  # the log's resolution


def pi(port: str, *args: str, log: Path | None = None) -> Run:
    return motionctl("pi-frame", port, *args, log=log)


def firmata(port: str, *args: str, log: Path | None = None) -> Run:
    return motionctl("firmata", port, *args, log=log)


# -- reference bytes, written out independently of the drivers ---------------------------------
def pi_frame(
    action: int,
    x: int = 0,
    y: int = 0,
    z: int = 0,
    speeds: tuple[int, int, int] = (0, 0, 0),
    radius: int = 0,
    angular: int = 0,
    start: int = 0,
    end: int = 0,
    direction: int = 0,
) -> bytes:
    """drivers/protocols/README.md §4: `7B 7D`, action, X Y Z signed, seven unsigned fields,
    direction, `2A`."""
    fields = struct.pack(">hhh", x, y, z) + struct.pack(">7H", *speeds, radius, angular, start, end)
    return b"\x7b\x7d" + bytes([action]) + fields + bytes([direction]) + b"\x2a"


def hexes(text: str) -> bytes:
    return bytes.fromhex(text)


CONFIG_200 = hexes("F0 72 00 48 01 08 09 F7")
CONFIG_4096 = hexes("F0 72 00 00 20 08 09 0A 0B F7")
STEP_300_500 = hexes("F0 72 01 2C 02 00 74 03 01 F7")
VERSION_REQUEST = hexes("F0 72 02 F7")
VERSION_REPLY = hexes("F0 72 05 00 F7")
ID_REQUEST = hexes("F9 F0 79 F7")  # REPORT_VERSION, then the REPORT_FIRMWARE query


def messages(data: bytes) -> list[bytes]:
    """Firmata messages: SysEx from F0 to F7, any other byte on its own (F9 has no data here)."""
    out: list[bytes] = []
    index = 0
    while index < len(data):
        if data[index] == 0xF0:
            end = data.index(0xF7, index) + 1
            out.append(data[index:end])
            index = end
        else:
            out.append(data[index : index + 1])
            index += 1
    return out


def tx_messages(log: Path) -> list[bytes]:
    return messages(b"".join(r.data for r in sent(log)))


def decode_step(message: bytes) -> tuple[int, int]:
    """(rpm, signed steps) of a STEPPER_STEP message: speed on 3, steps on 2 7-bit bytes."""
    assert message[:3] == hexes("F0 72 01") and message[-1] == 0xF7 and len(message) == 10
    rpm = message[3] | message[4] << 7 | message[5] << 14
    steps = message[6] | message[7] << 7
    assert message[8] in (0, 1)
    return rpm, steps if message[8] == 1 else -steps


def tx_time_of(log: Path, data: bytes) -> float:
    """The stamp of the first write that holds `data`."""
    return next(r.time for r in sent(log) if data in r.data)


# -- fixtures ---------------------------------------------------------------------------------
@pytest.fixture
def host_log(tmp_path: Path) -> Path:
    return tmp_path / "host.log"


@pytest.fixture
def start_sim(tmp_path: Path) -> Iterator[Callable[..., tuple[SimProcess, Path]]]:
    """Starts `motionsim KIND ARGS --record FILE`; each is stopped (and must exit 0) after."""
    started: list[SimProcess] = []

    def start(kind: str, *args: str) -> tuple[SimProcess, Path]:
        record = tmp_path / f"device{len(started)}.log"
        process = SimProcess(kind, "--record", str(record), *args)
        started.append(process)
        return process, record

    yield start
    for process in started:
        if process.proc.poll() is None:
            assert process.stop() == 0


@pytest.fixture(scope="module")
def idle_pi(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[SimProcess, Path]]:
    """One pi-frame device for the refusal tests: none of them may send it anything."""
    record = tmp_path_factory.mktemp("idle_pi") / "device.log"
    process = SimProcess("pi-frame", "--record", str(record))
    yield process, record
    assert process.stop() == 0
    assert device_received(record) == b""


@pytest.fixture(scope="module")
def idle_firmata(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[SimProcess, Path]]:
    """One Firmata board for the refusal tests: none of them may send it anything."""
    record = tmp_path_factory.mktemp("idle_firmata") / "device.log"
    process = SimProcess("firmata", "--reset-delay", "0.2", "--record", str(record))
    yield process, record
    assert process.stop() == 0
    assert device_received(record) == b""


def refused_before_sending(
    protocol: str, idle: tuple[SimProcess, Path], host_log: Path, *args: str
) -> Run:
    """Run motionctl on an idle device; it must exit 2 with one line, having written nothing."""
    sim, record = idle
    before = device_received(record)
    result = motionctl(protocol, sim.path, *args, log=host_log)
    assert result.returncode == 2, (result.stdout, result.stderr)
    assert result.stdout == ""
    assert result.stderr.startswith("motionctl: ")
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert sent(host_log) == []
    assert device_received(record) == before
    return result


# == pi-frame ===================================================================================
# -- 1. a linear move: one exact frame, speeds split over X and Y -----------------------------
@pytest.mark.e2e
@pytest.mark.timeout(30)
def test_pi_move_sends_one_frame_with_split_speeds(start_sim, host_log: Path) -> None:
    sim, record = start_sim("pi-frame", "--instant")
    # 100 x 50 ticks at 1 tick/mm and the default 10 mm/s: motionctl waits ~11 s (the slow axis).
    result = pi(sim.path, "--ticks-per-mm", "1", "move", "100", "50", "0", log=host_log)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "100.00 50.00 0.00 (commanded, not measured)"
    [tx] = sent(host_log)
    assert len(tx.data) == 25
    assert tx.data.startswith(hexes("7B 7D 01 00 64 00 32 00 00"))
    assert tx.data.endswith(hexes("2A"))
    # Each axis gets its share of 10 mm/s (ticks/s, rounded up) so that both arrive together.
    length = math.hypot(100, 50)
    speed_x, speed_y = math.ceil(10 * 100 / length), math.ceil(10 * 50 / length)
    assert (speed_x, speed_y) == (9, 5)
    assert tx.data == pi_frame(1, 100, 50, 0, (speed_x, speed_y, 0))
    assert received(host_log) == []
    assert device_received(record) == tx.data
    assert result.seconds >= 100 / speed_x  # it waited for the estimated end of the move


# -- 2. refused before sending ----------------------------------------------------------------
PI_BAD = [
    (("--ticks-per-mm", "1", "move", "40000", "0", "0"), ("X 40000 mm", "16 bits")),
    (("dwell", "70000"), ("dwell 70000", "0 to 65535")),
    (("--ticks-per-mm", "1", "arc", "0", "0", "70000", "0", "90", "--ccw"), ("radius 70000",)),
    (("--ticks-per-mm", "0", "move", "1", "0", "0"), ("ticks_per_mm 0",)),
    (("arc", "0", "0", "10", "0", "90", "--cw", "--ccw"), ("usage: arc",)),
    (("arc", "0", "0", "10", "0", "90"), ("usage: arc",)),
    (("arc", "0", "0", "0", "0", "90", "--ccw"), ("radius 0 mm",)),
]


@pytest.mark.e2e
@pytest.mark.timeout(15)
@pytest.mark.parametrize(
    ("args", "expected"), [pytest.param(a, e, id=" ".join(a)) for a, e in PI_BAD]
)
def test_pi_out_of_range_is_refused_before_sending(
    idle_pi, host_log: Path, args: tuple[str, ...], expected: tuple[str, ...]
) -> None:
    result = refused_before_sending("pi-frame", idle_pi, host_log, *args)
    for fragment in expected:
        assert fragment in result.stderr, (fragment, result.stderr)


# -- 3. dwell and set-home --------------------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_pi_dwell_and_set_home_frames(start_sim, tmp_path: Path) -> None:
    sim, record = start_sim("pi-frame", "--instant")
    dwell_log, home_log = tmp_path / "dwell.log", tmp_path / "home.log"
    dwelt = pi(sim.path, "dwell", "250", log=dwell_log)
    assert dwelt.returncode == 0, dwelt.stderr
    dwell = hexes("7B 7D 00 00 FA") + bytes(19) + hexes("2A")
    assert dwell == pi_frame(0, 250)
    assert [r.data for r in sent(dwell_log)] == [dwell]
    assert dwelt.seconds >= 0.25  # motionctl waits the dwell out
    homed = pi(sim.path, "set-home", log=home_log)
    assert homed.returncode == 0, homed.stderr
    set_home = hexes("7B 7D 03") + bytes(21) + hexes("2A")
    assert [r.data for r in sent(home_log)] == [set_home]
    assert device_received(record) == dwell + set_home


# -- 4. arcs: a Linear frame to the start point, then the Circular frame -----------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_pi_arc_moves_to_its_start_then_sends_the_circular_frame(start_sim, tmp_path: Path) -> None:
    sim, record = start_sim("pi-frame", "--instant")
    ccw_log, cw_log = tmp_path / "ccw.log", tmp_path / "cw.log"
    assert pi(sim.path, "set-home").returncode == 0  # an arc starts from the position kept
    # Default 100 ticks/mm, 10 mm/s: 1000 ticks to the start at 1000 ticks/s, then 90° at
    # 10 mm/s on a 10 mm radius = 1 rad/s = 5729.6 -> 5730 hundredths of a degree per second.
    ccw = pi(sim.path, "arc", "0", "0", "10", "0", "90", "--ccw", log=ccw_log)
    assert ccw.returncode == 0, ccw.stderr
    assert ccw.stdout.strip() == "0.00 10.00 0.00 (commanded, not measured)"
    angular = round(math.degrees(10 / 10) * 100)
    approach = pi_frame(1, 1000, 0, 0, (1000, 0, 0))
    circle = pi_frame(2, 0, 0, 0, radius=1000, angular=angular, start=0, end=9000, direction=1)
    first, second = sent(ccw_log)
    assert (first.data, second.data) == (approach, circle)
    assert second.time - first.time >= 1.0 - STAMP  # the approach's estimated time first
    assert circle[15:17] == hexes("03 E8") and circle[23] == 0x01

    # Clockwise (a 1 mm radius keeps it short: from (0, 10) kept by the run before, to the
    # start at (1, 0) at 10 mm/s along the line, then 270° at 572.96°/s).
    cw = pi(sim.path, "arc", "0", "0", "1", "0", "90", "--cw", log=cw_log)
    assert cw.returncode == 0, cw.stderr
    assert cw.stdout.strip() == "0.00 1.00 0.00 (commanded, not measured)"
    angular = round(math.degrees(10 / 1) * 100)
    cw_approach = pi_frame(1, 100, 0, 0, (100, 996, 0))  # 1000 ticks/s · (100, 1000) / 1005
    cw_circle = pi_frame(2, radius=100, angular=angular, start=0, end=9000, direction=0)
    assert [r.data for r in sent(cw_log)] == [cw_approach, cw_circle]
    home = pi_frame(3)
    assert device_received(record) == home + approach + circle + cw_approach + cw_circle


# -- 5. garbage on the line, then a frame --------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_pi_garbage_then_a_frame_both_reach_the_device(start_sim, tmp_path: Path) -> None:
    sim, record = start_sim("pi-frame", "--instant", "-v")
    raw_log, move_log = tmp_path / "raw.log", tmp_path / "move.log"
    garbage = pi(sim.path, "raw", "xyz", log=raw_log)
    assert garbage.returncode == 0, garbage.stderr
    assert [r.data for r in sent(raw_log)] == [hexes("78 79 7A")]
    moved = pi(sim.path, "move", "1", "0", log=move_log)  # 100 ticks at 1000 ticks/s
    assert moved.returncode == 0, moved.stderr
    assert moved.stdout.strip() == "1.00 0.00 0.00 (commanded, not measured)"
    frame = pi_frame(1, 100, 0, 0, (1000, 0, 0))
    assert [r.data for r in sent(move_log)] == [frame]
    assert device_received(record) == b"xyz" + frame
    # The device skipped the garbage and ran the frame (its -v log names what it executes).
    assert sim.stop() == 0
    assert sim.proc.stderr is not None
    log = sim.proc.stderr.read()
    assert "executing (1, (100, 0, 0, 1000, 0, 0, 0, 0, 0, 0, 0))" in log, log


# == Firmata ===================================================================================
# -- 6. a saved config is sent again after the reset, then the step ----------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_step_after_the_saved_config(start_sim, tmp_path: Path) -> None:
    sim, record = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    config_log, step_log = tmp_path / "config.log", tmp_path / "step.log"
    configured = firmata(
        sim.path, "config", "--steps-per-rev", "200", "--pins", "8", "9", log=config_log
    )
    assert configured.returncode == 0, configured.stderr
    assert configured.stdout.strip() == "configured: 200 steps/rev on pins 8 9 (library 5)"
    assert tx_messages(config_log)[0] == CONFIG_200

    stepped = firmata(sim.path, "step", "300", "500", log=step_log)
    assert stepped.returncode == 0, stepped.stderr
    assert stepped.stdout.strip() == "500 steps in 1 message(s), about 0.5 s"
    sent_messages = tx_messages(step_log)
    assert [m for m in sent_messages if m[:3] == hexes("F0 72 01")] == [STEP_300_500]
    assert sent_messages[-1] == STEP_300_500
    step_at = sent_messages.index(STEP_300_500)
    assert sent_messages.index(CONFIG_200) < sent_messages.index(VERSION_REQUEST) < step_at
    assert decode_step(STEP_300_500) == (300, 500)
    # The step went once the board had answered the version request (the config confirmed).
    replies = [r for r in received(step_log) if r.time <= tx_time_of(step_log, STEP_300_500)]
    assert VERSION_REPLY in b"".join(r.data for r in replies)
    assert STEP_300_500 in device_received(record)
    assert stepped.seconds >= 0.5  # 500 steps at 300 rpm x 200 steps/rev = 1000 steps/s


@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_firmata_config_asks_the_library_version_once(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    result = firmata(sim.path, "config", "--steps-per-rev", "200", "--pins", "8", "9", log=host_log)
    assert result.returncode == 0, result.stderr
    assert tx_messages(host_log) == [CONFIG_200, VERSION_REQUEST]


@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_step_beyond_the_travel_box_is_refused_before_any_is_sent(
    start_sim, tmp_path: Path
) -> None:
    sim, record = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    config = firmata(sim.path, "config", "--steps-per-rev", "200", "--pins", "8", "9")
    assert config.returncode == 0, config.stderr
    box = ("--travel", "-10:10,-10:10,-10:10")
    # 20000 steps at 80 steps/mm: 250 mm, in two messages, the first alone already 204.8 mm.
    refused = motionctl("firmata", sim.path, "step", "6000", "20000", options=box)
    assert refused.returncode == 2, refused.stderr
    assert "outside -10..10 mm" in refused.stderr
    assert STEP_300_500[:3] not in device_received(record)[len(CONFIG_200) :]
    within = motionctl("firmata", sim.path, "step", "300", "500", options=box)  # 6.25 mm
    assert within.returncode == 0, within.stderr
    assert STEP_300_500 in device_received(record)


# -- 7. a long move is split into messages of at most 16383 steps -------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_long_step_is_split(start_sim, tmp_path: Path) -> None:
    sim, record = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    config = firmata(sim.path, "config", "--steps-per-rev", "200", "--pins", "8", "9")
    assert config.returncode == 0, config.stderr
    log = tmp_path / "step.log"
    # 6000 rpm x 200 steps/rev = 20000 steps/s: 20000 steps take ~1 s of waiting.
    result = firmata(sim.path, "step", "6000", "20000", log=log)
    assert result.returncode == 0, result.stderr
    steps = [m for m in tx_messages(log) if m[:3] == hexes("F0 72 01")]
    decoded = [decode_step(m) for m in steps]
    assert len(decoded) >= 2
    assert all(rpm == 6000 for rpm, _ in decoded)
    assert all(0 < count <= 16383 for _, count in decoded)
    assert sum(count for _, count in decoded) == 20000
    assert [count for _, count in decoded] == [16383, 3617]
    # Each message once the previous one should have ended: 16383 steps at 20000 steps/s.
    first, second = (tx_time_of(log, m) for m in steps)
    assert second - first >= 16383 / 20000 - STAMP
    assert result.stdout.strip() == "20000 steps in 2 message(s), about 1.0 s"
    progress = [line for line in result.stderr.splitlines() if "message" in line]
    assert progress == [
        "motionctl: message 1/2: 16383 steps",
        "motionctl: message 2/2: 3617 steps",
    ]
    assert b"".join(steps) in device_received(record)


# -- 8. a 4-pin config; the library version -------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_four_pin_config_and_version(start_sim, tmp_path: Path) -> None:
    sim, _ = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    config_log, version_log = tmp_path / "config.log", tmp_path / "version.log"
    args = ("config", "--steps-per-rev", "4096", "--pins", "8", "9", "10", "11")
    configured = firmata(sim.path, *args, log=config_log)
    assert configured.returncode == 0, configured.stderr
    assert configured.stdout.strip() == "configured: 4096 steps/rev on pins 8 9 10 11 (library 5)"
    assert tx_messages(config_log)[0] == CONFIG_4096
    assert b"".join(r.data for r in sent(config_log)).startswith(CONFIG_4096)

    version = firmata(sim.path, "version", log=version_log)
    assert version.returncode == 0, version.stderr
    assert version.stdout.strip() == "stepper library version 5"
    assert tx_messages(version_log)[0] == CONFIG_4096  # the saved config, sent after the reset
    assert tx_messages(version_log)[-1] == VERSION_REQUEST
    assert VERSION_REPLY in b"".join(r.data for r in received(version_log))

    as_json = firmata(sim.path, "--json", "version")
    assert as_json.returncode == 0, as_json.stderr
    assert json.loads(as_json.stdout) == {"version": 5}


# -- 9. refused before sending ------------------------------------------------------------------
FIRMATA_BAD = [
    (("config", "--steps-per-rev", "200", "--pins", "8", "9", "10"), ("3 pins", "2 or 4")),
    (("step", "0", "10"), ("speed (rpm) 0",)),
    (("step", "300", "abc"), ("steps 'abc'",)),
    (("move", "1", "2"), ("one axis",)),
    (("--steps-per-mm", "80", "move", "0.001"), ("0.001 mm", "0.0125 mm")),
    (("step", "3000000", "1"), ("speed (rpm) 3000000", "2097151")),
]


@pytest.mark.e2e
@pytest.mark.timeout(15)
@pytest.mark.parametrize(
    ("args", "expected"), [pytest.param(a, e, id=" ".join(a)) for a, e in FIRMATA_BAD]
)
def test_firmata_bad_input_is_refused_before_sending(
    idle_firmata, host_log: Path, args: tuple[str, ...], expected: tuple[str, ...]
) -> None:
    result = refused_before_sending("firmata", idle_firmata, host_log, *args)
    for fragment in expected:
        assert fragment in result.stderr, (fragment, result.stderr)


# -- 10. no board; a board that resets when the port opens --------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_no_board_answers_exits_3(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("firmata", "--mute")
    result = firmata(sim.path, "id", log=host_log)
    assert result.returncode == 3, (result.stdout, result.stderr)
    assert result.seconds < 8.0
    assert result.stdout == ""
    [line] = result.stderr.strip().splitlines()
    assert line.startswith("motionctl: the device did not answer"), line
    assert "Firmata board" in line, line
    assert [r.data for r in sent(host_log)] == [ID_REQUEST]
    assert received(host_log) == []


@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_id_waits_for_the_board_after_its_reset(start_sim, host_log: Path) -> None:
    sim, record = start_sim("firmata")  # the default 2 s bootloader, from the simulator's start
    result = firmata(sim.path, "id", log=host_log)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "FirmataPlus.ino 2.5"
    first_tx = sent(host_log)[0]
    first_rx = received(host_log)[0] if received(host_log) else None
    waited_until = min(first_rx.time if first_rx else 2.0, 2.0)
    assert first_tx.time >= waited_until - STAMP, traffic(host_log)
    assert first_tx.data == ID_REQUEST
    # On the board's side: the request came after it announced itself, not into the bootloader.
    # (its bytes leave at the line's pace: on a busy machine a record may hold one byte)
    board = device_sent(record)
    assert b"".join(r.data for r in board).startswith(hexes("F9 02 05"))
    host_first = next(r for r in traffic(record) if r.direction == "RX")
    assert host_first.time >= board[0].time


@pytest.mark.e2e
@pytest.mark.timeout(20)
def test_firmata_simulated_board_announces_itself_after_each_open(
    start_sim, host_log: Path
) -> None:
    sim, _ = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    for _ in range(2):  # every open resets the board, which then announces itself
        host_log.unlink(missing_ok=True)
        result = firmata(sim.path, "id", log=host_log)
        assert result.returncode == 0, result.stderr
        rx = received(host_log)
        # A board reset by this open speaks 0.2 s after it; motionctl then need not wait 2 s.
        assert rx and rx[0].time <= sent(host_log)[0].time < 1.5, traffic(host_log)


# -- 11. identity ---------------------------------------------------------------------------------
@pytest.mark.e2e
@pytest.mark.timeout(15)
def test_firmata_id_prints_firmware_name_and_version(start_sim, host_log: Path) -> None:
    sim, _ = start_sim("firmata", "--reset-delay", "0.2", "--instant")
    result = firmata(sim.path, "--json", "id", log=host_log)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == {"id": "FirmataPlus.ino 2.5"}
    assert [r.data for r in sent(host_log)] == [ID_REQUEST]
    answer = b"".join(r.data for r in received(host_log))
    name = b"".join(bytes((c, 0)) for c in b"FirmataPlus.ino")
    assert hexes("F0 79 02 05") + name + hexes("F7") in answer
