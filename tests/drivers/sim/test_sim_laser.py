"""The simulated laser-processing robot (drivers/protocols/README.md §3), on a manual clock."""

from __future__ import annotations

import struct
import time

import pytest
import serial

import drivers.link.transport  # noqa: F401  (registers the sim:// handler)
from app.simcli import build_parser
from drivers.framers.stuffed import StuffedFramer
from drivers.sim.clock import ManualClock
from drivers.sim.laser_device import DEVICE_ID, FRAME_TIMEOUT, REPLY_DELAY, LaserDevice
from drivers.sim.registry import create_device
from drivers.sim.urlhandler.protocol_sim import parse_sim_url

FRAMER = StuffedFramer()
MOVE_LINEAR, DWELL, GO_HOME = 0x01, 0x02, 0x03
GET_POSITION, GET_STATUS, SET_HOME, STOP, GET_ID = b"\x10", b"\x11", b"\x12", b"\x13", b"\x14"
HOME = b"\x03"


def move(x: float, y: float, z: float, speed: float) -> bytes:
    """MOVE_LINEAR: F0 04 x y z speed."""
    return b"\x01\xf0\x04" + struct.pack("<4f", x, y, z, speed)


def dwell(ms: int) -> bytes:
    """DWELL: F1 01 ms."""
    return b"\x02\xf1\x01" + struct.pack("<h", ms)


def seq(number: int) -> bytes:
    """SEQUENCE: F1 01 number."""
    return b"\x20\xf1\x01" + struct.pack("<H", number)


def ack(number: int) -> bytes:
    """The acknowledgement of a queued frame."""
    return seq(number)


def error(word: int, code: int) -> bytes:
    """An error reply's data."""
    return bytes((0x7F, 0xF2, 0x02, word, code))


def _device(**options: object) -> tuple[LaserDevice, ManualClock]:
    clock = ManualClock()
    return LaserDevice(clock, **options), clock  # type: ignore[arg-type]


def send(device: LaserDevice, data: bytes) -> None:
    """One frame holding `data`."""
    device.receive(FRAMER.encode(data))


def replies(device: LaserDevice) -> list[bytes]:
    """The data of every reply frame sent by now."""
    frames, rest = StuffedFramer().split(device.read_output())
    assert rest == b""
    return frames


def ask(device: LaserDevice, data: bytes) -> bytes:
    """Send a frame and take its one reply."""
    send(device, data)
    out = replies(device)
    assert len(out) == 1, out
    return out[0]


def position_of(reply: bytes) -> tuple[float, ...]:
    """The three floats of a GET_POSITION reply."""
    assert reply[:3] == b"\x10\xf0\x03"
    return struct.unpack("<3f", reply[3:])


# -- framing -----------------------------------------------------------------------------------
def test_get_position_from_the_brief() -> None:
    device, _ = _device()
    device.receive(bytes.fromhex("EB 90 82 F0 10 90 82 10"))
    out = device.read_output()
    assert out == bytes.fromhex("EB 90 82 F0 10 F0 03") + bytes(12) + bytes.fromhex("90 82 03")
    assert device.frames_ok == 1


def test_a_90_byte_is_stuffed_both_ways() -> None:
    device, _ = _device(instant=True)
    frame = FRAMER.encode(seq(0x9090) + move(18.0, 0.0, 0.0, 10.0))  # 18.0f = 00 00 90 41
    assert frame.count(b"\x90\x90") >= 3
    device.receive(frame)
    assert replies(device) == [ack(0x9090)]
    send(device, GET_POSITION)
    out = device.read_output()
    assert b"\x00\x00\x90\x90\x41" in out
    assert position_of(FRAMER.decode(out)[1] or b"") == (18.0, 0.0, 0.0)


def test_checksum_error_is_code_2_for_the_first_data_byte() -> None:
    device, _ = _device()
    device.receive(bytes.fromhex("EB 90 82 F0 10 90 82 11"))
    assert replies(device) == [error(0x10, 2)]
    assert (device.frames_ok, device.frames_bad) == (0, 1)


def test_bad_flag_is_a_framing_error_answered_once() -> None:
    device, clock = _device()
    device.receive(bytes.fromhex("EB 90 82 F1 10 90 82 10"))
    clock.advance(FRAME_TIMEOUT * 2)
    assert replies(device) == [error(0x00, 1)]
    assert device.frames_bad == 1
    assert ask(device, GET_STATUS) == b"\x11\xf2\x02\x00\x00"


def test_lone_90_in_the_data_is_a_framing_error_answered_once() -> None:
    device, clock = _device()
    device.receive(bytes.fromhex("EB 90 82 F0 10 90 41 90 82 51"))
    clock.advance(FRAME_TIMEOUT * 2)
    assert replies(device) == [error(0x10, 1)]
    assert device.frames_bad == 1


def test_a_stuffed_90_is_the_failed_word_of_a_damaged_frame() -> None:
    device, _ = _device()
    device.receive(bytes.fromhex("EB 90 82 F0 90 90 90 82 00"))  # data 90, checksum wrong
    assert replies(device) == [error(0x90, 2)]
    device.receive(bytes.fromhex("EB 90 82 F0 90 82 01"))  # no data, checksum wrong
    assert replies(device) == [error(0x00, 2)]


def test_stray_bytes_get_a_framing_error_after_a_pause() -> None:
    device, clock = _device()
    device.receive(b"\x01\x02\x03")
    assert replies(device) == []
    clock.advance(FRAME_TIMEOUT)
    assert replies(device) == [error(0x00, 1)]


def test_a_frame_cut_short_gets_a_framing_error_after_a_pause() -> None:
    device, clock = _device()
    device.receive(bytes.fromhex("EB 90 82 F0 11"))
    clock.advance(FRAME_TIMEOUT)
    assert replies(device) == [error(0x11, 1)]


def test_noise_before_a_frame_is_skipped_silently() -> None:
    device, clock = _device()
    device.receive(b"\x00\x55\xeb" + FRAMER.encode(GET_ID))
    clock.advance(1.0)
    assert replies(device) == [b"\x14\xf3\x0a" + DEVICE_ID.encode()]


# -- instructions ------------------------------------------------------------------------------
def test_unknown_command_is_code_3() -> None:
    device, _ = _device()
    assert ask(device, b"\x55") == error(0x55, 3)
    assert ask(device, b"\x00") == error(0x00, 3)
    assert ask(device, b"") == error(0x00, 3)


@pytest.mark.parametrize(
    ("data", "failed"),
    [
        (b"\x01\xf0\x03" + struct.pack("<3f", 1, 2, 3), 0x01),  # three floats, not four
        (b"\x02\xf0\x01" + struct.pack("<f", 5), 0x02),  # DWELL with a float
        (move(1, 2, 3, 0.0), 0x01),  # speed 0
        (move(1, 2, 3, -5.0), 0x01),
        (move(float("nan"), 2, 3, 5.0), 0x01),
        (dwell(-1), 0x02),
        (b"\x03\xf2\x01\x00", 0x03),  # GO_HOME takes no field
        (b"\x01\xf0\x04" + struct.pack("<3f", 1, 2, 3), 0x01),  # values run past the data
        (b"\x10\xf2", 0x10),  # a field without its count
        (GET_POSITION + GET_STATUS, 0x10),  # immediates go alone
        (move(1, 2, 3, 5) + GET_POSITION, 0x10),
        (seq(1) + STOP, 0x13),
        (HOME + seq(1), 0x20),  # SEQUENCE not first
        (seq(1), 0x20),  # SEQUENCE with nothing to queue
        (HOME + b"\x99", 0x03),  # a byte that is neither a word nor a field marker
    ],
)
def test_bad_arguments_are_code_4(data: bytes, failed: int) -> None:
    device, clock = _device()
    assert ask(device, data) == error(failed, 4)
    clock.advance(10)
    assert device.executed == []
    assert device.last_sequence is None


def test_get_id() -> None:
    device, _ = _device()
    assert ask(device, GET_ID) == b"\x14\xf3\x0a" + b"LZR-SIM-01"


def test_queued_frame_is_acknowledged_and_runs_in_order_over_time() -> None:
    device, clock = _device()
    frame = seq(1) + move(10, 0, 0, 10) + move(10, 10, 0, 5) + dwell(500) + HOME
    assert ask(device, frame) == ack(1)
    assert device.executed == [(MOVE_LINEAR, (10.0, 0.0, 0.0, 10.0))]
    clock.advance(0.5)
    assert device.position() == pytest.approx((5.0, 0.0, 0.0))
    clock.advance(0.5)
    assert device.position() == pytest.approx((10.0, 0.0, 0.0))
    clock.advance(1.0)
    assert device.position() == pytest.approx((10.0, 5.0, 0.0))
    clock.advance(1.0)  # t=3: second move done, the dwell runs until 3.5
    assert device.position() == pytest.approx((10.0, 10.0, 0.0))
    assert device.is_running()
    clock.advance(0.5 + 2**0.5 * 10 / 5 / 2)  # half way home at the last speed
    assert device.position() == pytest.approx((5.0, 5.0, 0.0))
    clock.advance(10)
    assert device.position() == pytest.approx((0.0, 0.0, 0.0))
    assert [word for word, _ in device.executed] == [MOVE_LINEAR, MOVE_LINEAR, DWELL, GO_HOME]
    assert device.executed[2] == (DWELL, (500,))
    assert device.executed_at == pytest.approx([0.0, 1.0, 3.0, 3.5])
    assert device.next_due() is None


def test_go_home_uses_10_mm_s_before_any_move() -> None:
    device, _ = _device()
    assert ask(device, HOME) == HOME
    assert device.executed == [(GO_HOME, ())]
    assert not device.is_running()  # already there


def test_a_retransmission_is_acknowledged_but_not_run_twice() -> None:
    device, _ = _device(instant=True)
    frame = seq(7) + move(1, 0, 0, 10)
    assert ask(device, frame) == ack(7)
    assert ask(device, frame) == ack(7)
    assert device.duplicates == 1
    assert device.executed == [(MOVE_LINEAR, (1.0, 0.0, 0.0, 10.0))]
    assert ask(device, seq(8) + move(2, 0, 0, 10)) == ack(8)
    assert len(device.executed) == 2
    assert device.last_sequence == 8


def test_queued_instruction_without_sequence_is_acked_with_its_word_and_unprotected() -> None:
    device, _ = _device(instant=True)
    assert ask(device, move(1, 0, 0, 10) + dwell(0)) == b"\x01"
    assert ask(device, move(1, 0, 0, 10) + dwell(0)) == b"\x01"
    assert len(device.executed) == 4
    assert device.duplicates == 0


def test_seven_instructions_a_frame_but_not_eight() -> None:
    device, _ = _device()
    assert ask(device, seq(1) + dwell(10) * 7) == ack(1)
    assert ask(device, seq(2) + dwell(10) * 8) == error(0x20, 4)
    assert ask(device, dwell(10) * 8) == error(0x02, 4)
    assert device.queue_length() == 6


def test_queue_full_is_code_5_and_queues_nothing() -> None:
    device, clock = _device(queue=4)
    assert ask(device, seq(1) + dwell(1000) * 5) == error(0x20, 5)
    assert device.executed == [] and device.last_sequence is None
    assert ask(device, seq(1) + dwell(1000) * 4) == ack(1)  # the first starts at once
    assert device.queue_length() == 3
    assert ask(device, seq(2) + dwell(1000) * 2) == error(0x20, 5)
    assert ask(device, dwell(1000) * 2) == error(0x02, 5)
    assert device.queue_length() == 3 and device.last_sequence == 1
    clock.advance(1.0)
    assert ask(device, seq(2) + dwell(1000) * 2) == ack(2)
    assert device.queue_length() == 4


def test_stop_halts_the_move_and_flushes_the_queue() -> None:
    device, clock = _device()
    ask(device, seq(1) + move(10, 0, 0, 10) + move(10, 10, 0, 10) + HOME)
    clock.advance(0.4)
    assert ask(device, STOP) == STOP
    assert device.position() == pytest.approx((4.0, 0.0, 0.0))
    assert ask(device, GET_STATUS) == b"\x11\xf2\x02\x00\x00"
    clock.advance(10)
    assert device.position() == pytest.approx((4.0, 0.0, 0.0))
    assert len(device.executed) == 1


def test_set_home_makes_here_zero() -> None:
    device, _ = _device(instant=True)
    ask(device, seq(1) + move(5, 6, 7, 10))
    assert ask(device, SET_HOME) == SET_HOME
    assert position_of(ask(device, GET_POSITION)) == (0.0, 0.0, 0.0)
    ask(device, seq(2) + move(1, 1, 1, 10))
    assert position_of(ask(device, GET_POSITION)) == (1.0, 1.0, 1.0)


def test_set_home_during_a_move_keeps_the_stage_going_to_the_same_place() -> None:
    device, clock = _device()
    ask(device, seq(1) + move(10, 0, 0, 10))
    clock.advance(0.4)
    assert ask(device, SET_HOME) == SET_HOME
    clock.advance(1.0)
    assert device.position() == pytest.approx((6.0, 0.0, 0.0))
    assert not device.is_running()


def test_get_status_reports_depth_and_state_while_moving() -> None:
    device, clock = _device()
    assert ask(device, GET_STATUS) == b"\x11\xf2\x02\x00\x00"
    ask(device, seq(1) + move(10, 0, 0, 10) + dwell(500) + HOME)
    clock.advance(0.5)
    assert ask(device, GET_STATUS) == b"\x11\xf2\x02\x02\x01"
    assert position_of(ask(device, GET_POSITION)) == pytest.approx((5.0, 0.0, 0.0))
    clock.advance(0.7)  # in the dwell
    assert ask(device, GET_STATUS) == b"\x11\xf2\x02\x01\x01"
    clock.advance(10)
    assert ask(device, GET_STATUS) == b"\x11\xf2\x02\x00\x00"


def test_replies_are_paced_at_the_baud_rate() -> None:
    device, clock = _device(baud=115200)
    frame = FRAMER.encode(GET_ID)
    device.receive(frame)
    byte_time = 10 / 115200
    reply = FRAMER.encode(b"\x14\xf3\x0a" + DEVICE_ID.encode())
    done = (len(frame) + len(reply)) * byte_time
    clock.advance(done - byte_time / 2)
    assert device.read_output() == reply[:-1]
    clock.advance(byte_time)
    assert device.read_output() == reply[-1:]


def test_mute_never_answers() -> None:
    device, clock = _device(mute=True)
    send(device, GET_ID)
    send(device, seq(1) + HOME)
    clock.advance(1.0)
    assert device.read_output() == b""
    assert device.executed == []


# -- faults ------------------------------------------------------------------------------------
def test_corrupt_gives_a_checksum_or_framing_error() -> None:
    device, clock = _device(corrupt=1.0, seed=1)
    send(device, seq(1) + move(1, 2, 3, 4))
    clock.advance(FRAME_TIMEOUT * 2)
    out = replies(device)
    assert len(out) == 1
    assert out[0][:3] == b"\x7f\xf2\x02" and out[0][4] in (1, 2)
    assert device.executed == []
    assert device.frames_bad == 1


def test_drop_gives_no_reply_and_does_nothing() -> None:
    device, clock = _device(drop=1.0, seed=1)
    send(device, seq(1) + HOME)
    send(device, GET_ID)
    clock.advance(1.0)
    assert device.read_output() == b""
    assert device.executed == []
    assert device.frames_dropped == 2 and device.frames_ok == 0


def test_drop_reply_acts_on_the_frame_but_sends_nothing() -> None:
    device, clock = _device(drop_reply=1.0, seed=1, instant=True)
    send(device, seq(1) + move(1, 2, 3, 4))
    clock.advance(1.0)
    assert device.read_output() == b""
    assert device.executed == [(MOVE_LINEAR, (1.0, 2.0, 3.0, 4.0))]
    assert device.replies_dropped == 1 and device.frames_ok == 1


def test_drop_reply_then_retransmission_runs_once() -> None:
    device, _ = _device(drop_reply=0.5, seed=3, instant=True)
    frame = seq(1) + move(1, 2, 3, 4)
    for _ in range(20):
        send(device, frame)
        if replies(device):
            break
    assert len(device.executed) == 1
    assert device.duplicates == device.frames_ok - 1 >= 1


def test_delay_reply_sends_half_a_second_late() -> None:
    device, clock = _device(delay_reply=1.0, seed=1)
    send(device, GET_ID)
    assert device.next_due() == pytest.approx(REPLY_DELAY)
    clock.advance(REPLY_DELAY - 0.01)
    assert device.read_output() == b""
    clock.advance(0.01)
    assert replies(device) == [b"\x14\xf3\x0a" + DEVICE_ID.encode()]


def test_garbage_precedes_the_reply_which_still_decodes() -> None:
    device, _ = _device(garbage=1.0, seed=1)
    for _ in range(20):
        send(device, GET_ID)
        out = device.read_output()
        start = out.index(b"\xeb\x90\x82")
        assert 1 <= start <= 16
        frames, rest = StuffedFramer().split(out)
        assert frames == [b"\x14\xf3\x0a" + DEVICE_ID.encode()] and rest == b""


def _session(seed: int) -> tuple[bytes, tuple[int, ...], list[tuple[int, tuple]]]:
    device, clock = _device(
        corrupt=0.02, drop=0.1, drop_reply=0.1, delay_reply=0.1, garbage=0.3, seed=seed
    )
    out = bytearray()
    for n in range(40):
        send(device, seq(n) + move(n, 0, 0, 100))
        clock.advance(0.2)
        send(device, GET_POSITION)
        clock.advance(0.6)
        out += device.read_output()
    counters = (
        device.frames_ok,
        device.frames_bad,
        device.frames_dropped,
        device.replies_dropped,
        device.duplicates,
    )
    return bytes(out), counters, device.executed


def test_same_seed_same_output() -> None:
    first = _session(11)
    assert first == _session(11)
    assert first[1][2] > 0 and first[1][3] > 0  # the faults happened
    assert first != _session(12)


def test_fault_rates_are_probabilities() -> None:
    with pytest.raises(ValueError):
        LaserDevice(ManualClock(), corrupt=1.5)  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        LaserDevice(ManualClock(), queue=0)  # type: ignore[arg-type]


# -- wiring ------------------------------------------------------------------------------------
def test_registry_creates_it() -> None:
    device = create_device("laser-frame", ManualClock(), None, queue=8, seed=2)
    assert isinstance(device, LaserDevice)
    assert device.queue_depth == 8
    assert device.default_baud == 115200


def test_sim_url_options() -> None:
    name, options, timing = parse_sim_url(
        "sim://laser-frame?corrupt=0.1&drop=0.2&drop_reply=0.3&delay_reply=0.4&garbage=0.5"
        "&seed=3&queue=16"
    )
    assert name == "laser-frame" and timing
    assert options == {
        "corrupt": 0.1,
        "drop": 0.2,
        "drop_reply": 0.3,
        "delay_reply": 0.4,
        "garbage": 0.5,
        "seed": 3,
        "queue": 16,
    }
    with pytest.raises(serial.SerialException):
        serial.serial_for_url("sim://laser-frame?seed=x", 115200)
    with pytest.raises(serial.SerialException):
        serial.serial_for_url("sim://laser-frame?corrupt=2", 115200)


@pytest.mark.timeout(10)
def test_sim_url_answers_in_real_time() -> None:
    port = serial.serial_for_url("sim://laser-frame?corrupt=0.1&seed=3", 115200, timeout=0.5)
    try:
        answered = 0
        for _ in range(30):
            port.reset_input_buffer()
            port.write(FRAMER.encode(GET_ID))
            deadline = time.monotonic() + 1.0
            buffer = b""
            frames: list[bytes] = []
            while not frames and time.monotonic() < deadline:
                buffer += port.read(port.in_waiting or 1)
                frames, _ = StuffedFramer().split(buffer)
            if frames == [b"\x14\xf3\x0a" + DEVICE_ID.encode()]:
                answered += 1
                if answered == 2:
                    break
            else:
                time.sleep(FRAME_TIMEOUT * 2)  # let the device give up on a damaged frame
        assert answered == 2
        assert port.device.frames_ok >= answered
    finally:
        port.close()


def test_motionsim_accepts_the_fault_options() -> None:
    options = build_parser().parse_args(["laser-frame", "--corrupt", "0.01", "--drop", "0.005"])
    assert (options.corrupt, options.drop) == (0.01, 0.005)
    options = build_parser().parse_args(
        ["laser-frame", "--corrupt", "0.01", "--drop", "0.005", "--seed", "7"]
    )
    assert (options.corrupt, options.drop, options.seed) == (0.01, 0.005, 7)
    options = build_parser().parse_args(
        [
            *("laser-frame", "--drop-reply", "0.1", "--delay-reply", "0.2"),
            *("--garbage", "0.3", "--queue", "9"),
        ]
    )
    assert (options.drop_reply, options.delay_reply, options.garbage, options.queue) == (
        0.1,
        0.2,
        0.3,
        9,
    )
    assert build_parser().parse_args(["laser-frame"]).corrupt is None
