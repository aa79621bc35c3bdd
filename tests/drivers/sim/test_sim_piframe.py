"""The simulated pi-frame device (drivers/protocols/README.md §4), on a manual clock."""

from __future__ import annotations

import math
import struct
import time

import pytest
import serial

import drivers.link.transport  # noqa: F401  (registers the sim:// handler)
from drivers.sim.clock import ManualClock
from drivers.sim.piframe_device import (
    CIRCULAR,
    DEFAULT_SPEED,
    DWELL,
    LINEAR,
    SET_HOME,
    PiFrameDevice,
)
from drivers.sim.registry import create_device

SEED_LINEAR = bytes.fromhex("7B7D01 0064 0032 0000 0000 0000 0000 0000 0000 0000 0000 00 2A")
CW, CCW = 0, 1


def frame(
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
    """A 25-byte frame, big-endian, X/Y/Z signed."""
    body = struct.pack(
        ">BhhhHHHHHHHB", action, x, y, z, *speeds, radius, angular, start, end, direction
    )
    return b"\x7b\x7d" + body + b"\x2a"


def dwell(ms: int) -> bytes:
    """A dwell of `ms` milliseconds (X sent unsigned)."""
    return b"\x7b\x7d\x00" + struct.pack(">H", ms) + bytes(19) + b"\x2a"


def _device(**options: object) -> tuple[PiFrameDevice, ManualClock]:
    clock = ManualClock()
    return PiFrameDevice(clock, **options), clock  # type: ignore[arg-type]


def _approx(point: tuple[float, ...], expected: tuple[float, ...], abs_: float = 1e-6) -> bool:
    return point == pytest.approx(expected, abs=abs_)


def test_seed_frame_is_the_linear_example_in_big_endian() -> None:
    assert frame(LINEAR, 100, 50) == SEED_LINEAR
    assert len(SEED_LINEAR) == 25


def test_seed_linear_frame_moves_at_the_default_speed() -> None:
    device, clock = _device()
    device.receive(SEED_LINEAR)
    assert device.frames_ok == 1
    assert device.history == [(LINEAR, (100, 50, 0, 0, 0, 0, 0, 0, 0, 0, 0))]
    assert device.next_due() == pytest.approx(100 / DEFAULT_SPEED)
    clock.advance(0.05)
    assert _approx(device.position(), (50.0, 25.0, 0.0))
    clock.advance(0.05)
    assert _approx(device.position(), (100.0, 50.0, 0.0))
    assert device.next_due() is None


def test_speeds_are_per_axis_and_the_slowest_sets_the_duration() -> None:
    device, _ = _device()
    device.receive(frame(LINEAR, 100, 100, 10, speeds=(100, 50, 10)))
    # X needs 1 s, Y 2 s, Z 1 s: the move lasts 2 s, all axes in a straight line.
    assert device.next_due() == pytest.approx(2.0)
    assert _approx(device.position(1.0), (50.0, 50.0, 5.0))
    assert _approx(device.position(2.0), (100.0, 100.0, 10.0))


def test_an_axis_that_does_not_move_does_not_count() -> None:
    device, _ = _device()
    device.receive(frame(LINEAR, 200, 0, 0, speeds=(400, 1, 1)))
    assert device.next_due() == pytest.approx(0.5)


def test_negative_coordinates_are_twos_complement() -> None:
    device, clock = _device()
    raw = bytes.fromhex("7B7D01 FF9C FFCE 8000 0000 0000 0000 0000 0000 0000 0000 00 2A")
    assert raw == frame(LINEAR, -100, -50, -32768)
    device.receive(raw)
    clock.advance(60)
    assert _approx(device.position(), (-100.0, -50.0, -32768.0))


def _at_100_0(device: PiFrameDevice, clock: ManualClock) -> None:
    device.receive(frame(LINEAR, 100, 0, 0))
    clock.advance(0.1)
    assert _approx(device.position(), (100.0, 0.0, 0.0))


def test_ccw_arc_follows_the_circle() -> None:
    device, clock = _device()
    _at_100_0(device, clock)
    device.receive(
        frame(CIRCULAR, 0, 0, 0, radius=100, angular=9000, start=0, end=9000, direction=CCW)
    )
    t0 = clock.now
    assert device.next_due() == pytest.approx(t0 + 1.0)  # 90° at 90°/s
    half = 100 * math.sqrt(0.5)
    assert _approx(device.position(t0 + 0.5), (half, half, 0.0))
    clock.advance(1.0)
    assert _approx(device.position(), (0.0, 100.0, 0.0))


def test_cw_arc_goes_the_other_way() -> None:
    device, clock = _device()
    _at_100_0(device, clock)
    device.receive(frame(CIRCULAR, 0, 0, 0, radius=100, start=0, end=27000, direction=CW))
    t0 = clock.now
    half = 100 * math.sqrt(0.5)
    assert device.next_due() == pytest.approx(t0 + 1.0)  # 0° down to 270°: 90° clockwise
    assert _approx(device.position(t0 + 0.5), (half, -half, 0.0))
    assert _approx(device.position(t0 + 1.0), (0.0, -100.0, 0.0))


def test_equal_start_and_end_is_a_full_circle_with_z_going_linearly() -> None:
    device, clock = _device()
    _at_100_0(device, clock)
    device.receive(frame(CIRCULAR, 0, 0, 40, radius=100, angular=36000, direction=CCW))
    t0 = clock.now
    assert device.next_due() == pytest.approx(t0 + 1.0)
    assert _approx(device.position(t0 + 0.5), (-100.0, 0.0, 20.0))
    assert _approx(device.position(t0 + 0.75), (0.0, -100.0, 30.0))
    assert _approx(device.position(t0 + 1.0), (100.0, 0.0, 40.0))


def test_arc_away_from_its_start_first_moves_there_straight() -> None:
    device, _ = _device()
    device.receive(frame(CIRCULAR, 0, 0, 0, radius=100, start=9000, end=18000, direction=CCW))
    # From (0, 0) to (0, 100) at the default speed: 0.1 s, then 90° at 90°/s.
    assert _approx(device.position(0.05), (0.0, 50.0, 0.0))
    assert _approx(device.position(0.1), (0.0, 100.0, 0.0))
    assert _approx(device.position(1.1), (-100.0, 0.0, 0.0))
    assert device.next_due() == pytest.approx(0.1 + 1.0)


def test_dwell_delays_the_next_frame() -> None:
    device, clock = _device()
    device.receive(dwell(40000) + frame(LINEAR, 100, 0, 0))  # 40000 ms: X read unsigned
    assert device.queue_length() == 1
    assert device.next_due() == pytest.approx(40.0)
    clock.advance(40.0)
    assert device.queue_length() == 0
    assert _approx(device.position(), (0.0, 0.0, 0.0))
    assert [action for action, _ in device.history] == [DWELL, LINEAR]
    clock.advance(0.1)
    assert _approx(device.position(), (100.0, 0.0, 0.0))


def test_set_home_makes_the_current_position_zero() -> None:
    device, clock = _device()
    device.receive(frame(LINEAR, 100, 50, 0) + frame(SET_HOME) + frame(LINEAR, 10, 0, 0))
    assert _approx(device.position(0.09), (90.0, 45.0, 0.0))
    # After SET_HOME the move to (10, 0) starts from the new (0, 0): 10 ticks, 0.01 s.
    assert _approx(device.position(0.105), (5.0, 0.0, 0.0))
    clock.advance(0.2)
    assert _approx(device.position(), (10.0, 0.0, 0.0))
    assert device.queue_length() == 0


def test_garbage_and_a_bad_end_byte_are_skipped() -> None:
    device, clock = _device()
    bad = frame(LINEAR, 500, 500, 0)[:-1] + b"\x2b"
    unknown = frame(7, 300, 0, 0)
    device.receive(b"\x00\x7b\x11hello" + bad + unknown + frame(LINEAR, 100, 0, 0))
    assert (device.frames_ok, device.frames_bad) == (1, 2)
    assert device.garbage_bytes > 7
    assert device.history == [(LINEAR, (100, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0))]
    clock.advance(1)
    assert _approx(device.position(), (100.0, 0.0, 0.0))


def test_a_truncated_frame_resyncs_at_the_next_header_inside_it() -> None:
    device, clock = _device()
    device.receive(frame(LINEAR, 900, 0, 0)[:10] + frame(LINEAR, 0, 100, 0))
    assert (device.frames_ok, device.frames_bad) == (1, 1)
    clock.advance(1)
    assert _approx(device.position(), (0.0, 100.0, 0.0))


def test_a_frame_split_over_writes_is_assembled() -> None:
    device, _ = _device()
    for byte in SEED_LINEAR:
        device.receive(bytes((byte,)))
    assert device.frames_ok == 1


def test_frames_queue_and_reception_never_blocks() -> None:
    device, clock = _device(baud=115200)
    frames = b"".join(frame(LINEAR, 100 * (i + 1), 0, 0) for i in range(10))
    device.receive(frames)  # 250 bytes: more than an Arduino buffer, none lost
    clock.advance(0.03)  # the last byte arrives after 250 × 10 bits / 115200 baud
    assert device.read_output() == b""
    assert device.frames_ok == 10
    assert device.dropped_rx == 0
    assert device.queue_length() == 9
    while (due := device.next_due()) is not None:
        clock.now = due
        device.read_output()
    assert _approx(device.position(), (1000.0, 0.0, 0.0))
    assert len(device.history) == 10
    assert device.read_output() == b""


def test_instant_moves_and_dwells_take_no_time() -> None:
    device, _ = _device(instant=True, mute=True)
    device.receive(frame(LINEAR, 1000, 0, 0) + dwell(5000) + frame(LINEAR, 0, 500, 0))
    assert device.next_due() is None
    assert device.queue_length() == 0
    assert _approx(device.position(), (0.0, 500.0, 0.0))


def test_registry_creates_it() -> None:
    device = create_device("pi-frame", ManualClock(), None, instant=True)
    assert isinstance(device, PiFrameDevice)
    assert device.default_baud == 115200


@pytest.mark.timeout(10)
def test_sim_url_moves_the_stage() -> None:
    port = serial.serial_for_url("sim://pi-frame", 115200, timeout=0.2)
    try:
        port.write(SEED_LINEAR)
        deadline = time.monotonic() + 5
        while port.device.position() != (100.0, 50.0, 0.0) and time.monotonic() < deadline:
            time.sleep(0.01)
        assert port.device.position() == (100.0, 50.0, 0.0)
        assert port.read(1) == b""  # write-only
    finally:
        port.close()
