"""The simulated FirmataPlus board (drivers/protocols/README.md §5), on a manual clock."""

from __future__ import annotations

import time

import pytest
import serial

import drivers.link.transport  # noqa: F401  (registers the sim:// handler)
from app.simcli import build_parser
from drivers.sim.clock import ManualClock
from drivers.sim.firmata_device import (
    CONFIG_ERROR,
    NOT_CONFIGURED_ERROR,
    SPEED_ERROR,
    FirmataDevice,
)
from drivers.sim.registry import create_device
from drivers.sim.urlhandler.protocol_sim import parse_sim_url

VERSION = bytes.fromhex("F9 02 05")
NAME = (
    bytes.fromhex("F0 79 02 05")
    + b"".join(bytes((ord(c), 0)) for c in "FirmataPlus.ino")
    + bytes.fromhex("F7")
)
CONFIG_200 = bytes.fromhex("F0 72 00 48 01 08 09 F7")
CONFIG_4096 = bytes.fromhex("F0 72 00 00 20 08 09 0A 0B F7")
STEP_500_AT_300 = bytes.fromhex("F0 72 01 2C 02 00 74 03 01 F7")


def _device(**options: object) -> tuple[FirmataDevice, ManualClock]:
    """A booted board with no reset delay unless one is given."""
    clock = ManualClock()
    options.setdefault("reset_delay", 0.0)
    device = FirmataDevice(clock, **options)  # type: ignore[arg-type]
    device.boot()
    return device, clock


def _drain(device: FirmataDevice, clock: ManualClock) -> bytes:
    """Run the device until it has nothing left to do; everything it sent."""
    out = bytearray()
    while (due := device.next_due()) is not None:
        clock.now = max(clock.now, due)
        out += device.read_output()
    return bytes(out)


def _ready(**options: object) -> tuple[FirmataDevice, ManualClock]:
    device, clock = _device(**options)
    assert _drain(device, clock) == VERSION + NAME
    return device, clock


def _ask(device: FirmataDevice, clock: ManualClock, request: bytes) -> bytes:
    device.receive(request)
    return _drain(device, clock)


def _string_data(message: bytes) -> str:
    """The text of a STRING_DATA SysEx."""
    assert message[:2] == b"\xf0\x71" and message[-1:] == b"\xf7", message
    body = message[2:-1]
    return "".join(chr(body[i] | body[i + 1] << 7) for i in range(0, len(body), 2))


# -- reset and handshake -----------------------------------------------------------------------
def test_nothing_during_the_reset_then_version_and_name() -> None:
    device, clock = _device(reset_delay=2.0)
    device.receive(b"\xf9")  # eaten by the bootloader
    clock.advance(1.999)
    device.receive(b"\xf0\x79\xf7")
    assert device.read_output() == b""
    clock.advance(0.001)
    assert device.read_output() == VERSION + NAME
    assert _drain(device, clock) == b""


def test_without_line_timing_the_name_is_the_documented_bytes() -> None:
    assert NAME.hex(" ") == (
        "f0 79 02 05 46 00 69 00 72 00 6d 00 61 00 74 00 61 00 50 00 6c 00 75 00 73 00 2e 00 "
        "69 00 6e 00 6f 00 f7"
    )


def test_version_and_firmware_queries() -> None:
    device, clock = _ready()
    assert _ask(device, clock, b"\xf9") == VERSION
    assert _ask(device, clock, b"\xf0\x79\xf7") == NAME


def test_capability_query() -> None:
    device, clock = _ready()
    pwm = {3, 5, 6, 9, 10, 11}
    expected = bytearray(b"\xf0\x6c")
    for pin in range(20):
        expected += b"\x00\x01\x01\x01"
        if pin in pwm:
            expected += b"\x03\x08"
        if pin >= 14:
            expected += b"\x02\x0a"
        expected += b"\x7f"
    expected += b"\xf7"
    assert _ask(device, clock, b"\xf0\x6b\xf7") == bytes(expected)


def test_analog_mapping_query() -> None:
    device, clock = _ready()
    expected = b"\xf0\x6a" + b"\x7f" * 14 + bytes(range(6)) + b"\xf7"
    assert _ask(device, clock, b"\xf0\x69\xf7") == expected


def test_stepper_library_version() -> None:
    device, clock = _ready()
    assert _ask(device, clock, b"\xf0\x72\x02\xf7") == bytes.fromhex("F0 72 05 00 F7")


# -- stepper -----------------------------------------------------------------------------------
def test_reference_configs() -> None:
    device, clock = _ready()
    assert _ask(device, clock, CONFIG_200) == b""
    assert (device.steps_per_revolution, device.pins) == (200, (8, 9))
    assert _ask(device, clock, CONFIG_4096) == b""
    assert (device.steps_per_revolution, device.pins) == (4096, (8, 9, 10, 11))
    assert device.configured


def test_three_pins_is_a_config_error() -> None:
    device, clock = _ready()
    out = _ask(device, clock, bytes.fromhex("F0 72 00 48 01 08 09 0A F7"))
    assert _string_data(out) == CONFIG_ERROR == "STEPPER CONFIG Error: Wrong Number of arguments"
    assert not device.configured


def test_step_before_config_is_an_error() -> None:
    device, clock = _ready()
    out = _ask(device, clock, STEP_500_AT_300)
    assert _string_data(out) == NOT_CONFIGURED_ERROR
    assert device.steps() == 0


def test_speed_zero_is_an_error() -> None:
    device, clock = _ready()
    device.receive(CONFIG_200)
    out = _ask(device, clock, bytes.fromhex("F0 72 01 00 00 00 0A 00 01 F7"))
    assert _string_data(out) == SPEED_ERROR
    assert device.steps() == 0


def test_reference_step_takes_half_a_second_and_reports_nothing() -> None:
    device, clock = _ready()
    device.receive(CONFIG_200 + STEP_500_AT_300)
    t0 = clock.now
    assert device.busy_until == pytest.approx(t0 + 0.5)  # 500 × 60 / (300 × 200)
    assert device.steps(t0 + 0.25) == pytest.approx(250)
    assert _drain(device, clock) == b""
    assert device.steps() == 500


def test_reverse_direction() -> None:
    device, clock = _ready()
    device.receive(CONFIG_200 + STEP_500_AT_300)
    device.receive(bytes.fromhex("F0 72 01 2C 02 00 64 00 00 F7"))  # 100 steps back
    _drain(device, clock)
    assert device.steps() == 400
    assert clock.now == pytest.approx(0.5 + 0.1)


def test_a_step_blocks_the_board() -> None:
    device, clock = _ready()
    device.receive(CONFIG_200 + STEP_500_AT_300)
    clock.advance(0.1)
    device.receive(b"\xf9")
    clock.advance(0.399)
    assert device.read_output() == b""
    clock.advance(0.001)
    assert device.read_output() == VERSION


def test_bytes_beyond_the_receive_buffer_are_lost_while_stepping() -> None:
    device, clock = _ready()
    device.receive(CONFIG_200 + STEP_500_AT_300)
    device.receive(b"\xf9" * 70)
    assert device.dropped_rx == 70 - 63
    assert _drain(device, clock) == VERSION * 63


def test_instant_steps_take_no_time() -> None:
    device, clock = _ready(instant=True)
    device.receive(CONFIG_200 + STEP_500_AT_300)
    assert device.busy_until <= clock.now
    assert device.steps() == 500


def test_mute_sends_nothing() -> None:
    device, clock = _device(mute=True)
    device.receive(b"\xf9\xf0\x79\xf7\xf0\x72\x02\xf7")
    assert _drain(device, clock) == b""


def test_garbage_is_ignored() -> None:
    device, clock = _ready()
    noise = bytes.fromhex("00 01 7F F7 F0 F7 F0 55 66 F7 90 01 02 E0 F9 F0 72 07 F7 F0 72 01 05 F7")
    device.receive(noise + b"\xff")
    out = _drain(device, clock)
    assert out == VERSION  # only the F9 (after the digital message's data bytes)
    assert _ask(device, clock, b"\x10\x20\xf9") == VERSION
    assert device.steps() == 0


def test_every_byte_value_is_survived() -> None:
    device, clock = _ready()
    device.receive(bytes(range(256)) * 3 + b"\xf7")
    _drain(device, clock)
    assert _ask(device, clock, b"\xf9") == VERSION


# -- the ways in -------------------------------------------------------------------------------
def test_registry_creates_it_with_the_firmata_defaults() -> None:
    device = create_device("firmata", ManualClock(), None, reset_delay=0.5)
    assert isinstance(device, FirmataDevice)
    assert device.default_baud == 57600
    assert device.reset_delay == 0.5
    assert FirmataDevice(ManualClock()).reset_delay == 2.0


def test_sim_url_reset_delay_option() -> None:
    assert parse_sim_url("sim://firmata?reset_delay=0.25") == (
        "firmata",
        {"reset_delay": 0.25},
        True,
    )
    with pytest.raises(serial.SerialException):
        serial.serial_for_url("sim://firmata?reset_delay=soon", 57600)


@pytest.mark.timeout(10)
def test_sim_url_board_announces_itself_after_the_reset() -> None:
    start = time.monotonic()
    port = serial.serial_for_url("sim://firmata?reset_delay=0.1", 57600, timeout=2.0)
    try:
        assert port.read(len(VERSION + NAME)) == VERSION + NAME
        assert time.monotonic() - start >= 0.1
        port.write(b"\xf0\x72\x02\xf7")
        assert port.read(5) == bytes.fromhex("F0 72 05 00 F7")
    finally:
        port.close()


def test_motionsim_accepts_a_reset_delay() -> None:
    options = build_parser().parse_args(["firmata", "--reset-delay", "0.5"])
    assert options.reset_delay == 0.5
    assert build_parser().parse_args(["firmata"]).reset_delay is None
