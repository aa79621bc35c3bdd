"""Quirks of the COXIRIS firmware that the simulator reproduces, on a manual clock."""

from __future__ import annotations

import pytest

from drivers.sim.arduino import print_float
from drivers.sim.clock import ManualClock
from drivers.sim.coxiris_device import CoxirisDevice

pytestmark = pytest.mark.timeout(60)


def _device(**options: object) -> tuple[CoxirisDevice, ManualClock]:
    clock = ManualClock()
    return CoxirisDevice(clock, **options), clock  # type: ignore[arg-type]


def _ask(device: CoxirisDevice, clock: ManualClock, text: bytes, wait: float = 0.001) -> bytes:
    device.receive(text)
    clock.advance(wait)
    return device.read_output()


def test_blocking_move_answers_done_when_the_move_ends() -> None:
    device, clock = _device(speed=10)
    assert _ask(device, clock, b"ABSOLUTE_MOVE 10 0 0\n") == b"ACK ABSOLUTE_MOVE\r\n"
    # Mid-move the sketch is inside its callback: GET_POSITION waits in the receive buffer.
    assert _ask(device, clock, b"GET_POSITION\n", 0.5) == b""
    clock.advance(0.6)
    assert device.read_output() == (
        b"DONE ABSOLUTE_MOVE\r\nACK GET_POSITION\r\nDONE GET_POSITION: 10.00 0.00 0.00\r\n"
    )


def test_next_due_points_at_the_end_of_a_blocking_move() -> None:
    device, clock = _device(speed=10)
    _ask(device, clock, b"ABSOLUTE_MOVE 0 20 0\n")
    assert device.next_due() == pytest.approx(2.0)


def test_non_blocking_move_reports_positions_along_the_way() -> None:
    device, clock = _device(speed=10, blocking=False)
    assert _ask(device, clock, b"ABSOLUTE_MOVE 10 0 0\n", 0.0) == (
        b"ACK ABSOLUTE_MOVE\r\nDONE ABSOLUTE_MOVE\r\n"
    )
    clock.advance(0.5)
    assert _ask(device, clock, b"GET_POSITION\n", 0.0).endswith(b": 5.00 0.00 0.00\r\n")
    clock.advance(1.0)
    assert _ask(device, clock, b"GET_POSITION\n", 0.0).endswith(b": 10.00 0.00 0.00\r\n")


def test_receive_buffer_overflows_while_the_firmware_is_busy() -> None:
    device, clock = _device(speed=1)
    _ask(device, clock, b"ABSOLUTE_MOVE 1 0 0\n")
    device.receive(b"GET_ID\n" * 20)  # 140 bytes; the 63-byte buffer keeps 9 commands
    clock.advance(2.0)
    assert device.read_output().count(b"DONE GET_ID") == 9
    assert device.dropped_rx == 140 - 63


def test_too_long_on_a_fast_line_discards_the_rest() -> None:
    device, clock = _device()
    assert _ask(device, clock, b"X" * 70 + b"\n") == b"ERROR: Command too long\r\n"


def test_too_long_on_a_slow_line_parses_the_rest_as_a_new_command() -> None:
    device, clock = _device()
    out = _ask(device, clock, b"X" * 64)
    assert out == b"ERROR: Command too long\r\n"
    out = _ask(device, clock, b"YZ\n")
    assert out.startswith(b"ERROR: Unknown command - \r\nYZ\r\nAvailable commands:\r\n")


def test_63_characters_fit() -> None:
    device, clock = _device()
    line = b"GET_ID" + b" " * 57
    assert len(line) == 63
    assert _ask(device, clock, line + b"\n").startswith(b"ACK GET_ID")


def test_tab_makes_the_command_unknown_and_blank_lines_say_nothing() -> None:
    device, clock = _device()
    assert _ask(device, clock, b"GET_ID\t\n") == b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"
    assert _ask(device, clock, b"GET\tID\n").startswith(b"ERROR: Unknown command - \r\nGET\tID")
    assert _ask(device, clock, b"   \r\n\n\r") == b""


def test_leading_spaces_lower_case_and_extra_parameters() -> None:
    device, clock = _device(instant=True)
    out = _ask(device, clock, b"  absolute_move  1  2  3  4\r\n")
    assert out == b"ACK ABSOLUTE_MOVE\r\nDONE ABSOLUTE_MOVE\r\n"
    assert _ask(device, clock, b"get_position\n").endswith(b": 1.00 2.00 3.00\r\n")


@pytest.mark.parametrize("number", [b"1e3", b".", b"nan", b"0x10", b"1,5", b"--1", b"1.2.3"])
def test_numbers_the_firmware_rejects(number: bytes) -> None:
    device, clock = _device(instant=True)
    out = _ask(device, clock, b"DELTA_MOVE " + number + b" 0 0\n")
    assert b"ERROR: Invalid number format" in out


@pytest.mark.parametrize(
    ("value", "digits", "text"),
    [
        (12.5, 0, "13"),
        (1.5, 2, "1.50"),
        (-2, 2, "-2.00"),
        (-0.001, 2, "-0.00"),
        (4294967040.0, 2, "4294967040.00"),
        (4294967300.0, 2, "ovf"),
        (-5e9, 2, "ovf"),
        (float("nan"), 2, "nan"),
        (1e39, 2, "inf"),
        (0.125, 2, "0.12"),
    ],
)
def test_arduino_float_printing(value: float, digits: int, text: str) -> None:
    assert print_float(value, digits) == text


def test_huge_position_prints_ovf() -> None:
    device, clock = _device(instant=True)
    _ask(device, clock, b"ABSOLUTE_MOVE 5000000000 0 0\n")
    assert _ask(device, clock, b"GET_POSITION\n").endswith(b": ovf 0.00 0.00\r\n")


def test_line_timing_paces_output_at_the_baud_rate() -> None:
    device, clock = _device(baud=9600)
    device.receive(b"GET_ID\n")
    reply = b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"
    clock.advance(len(reply) * 10 / 9600 / 2)
    assert 0 < len(device.read_output()) < len(reply)


def test_mute_device_never_answers() -> None:
    device, clock = _device(mute=True)
    assert _ask(device, clock, b"GET_ID\n", 5.0) == b""


# -- issue 11: differences from the real firmware ------------------------------------------
GET_ID_REPLY = b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"
SETTLE = 0.1  # long enough for every reply below at 115200


@pytest.mark.parametrize("baud", [None, 115200])
def test_a_nul_cuts_the_command_but_does_not_end_the_line(baud: int | None) -> None:
    device, clock = _device(baud=baud)
    assert _ask(device, clock, b"GET_ID\0\n", SETTLE) == GET_ID_REPLY
    assert _ask(device, clock, b"get_id\0", SETTLE) == b""  # no line end yet
    assert _ask(device, clock, b"ABSOLUTE_MOVE 9 9 9\n", SETTLE) == GET_ID_REPLY
    out = _ask(device, clock, b"GET\0ID\n", SETTLE)
    assert out.startswith(b"ERROR: Unknown command - \r\nGET\r\nAvailable commands:\r\n")
    assert out.count(b"ERROR: Unknown command - \r\n") == 1
    assert _ask(device, clock, b"\0GET_ID\n", SETTLE) == b""  # an empty command


def test_too_long_on_a_fast_line_keeps_the_next_command_of_the_same_write() -> None:
    device, clock = _device()
    out = _ask(device, clock, b"X" * 70 + b"\nGET_ID\n")
    assert out == b"ERROR: Command too long\r\n" + GET_ID_REPLY


def test_too_long_on_a_fast_line_stops_discarding_at_cr() -> None:
    device, clock = _device()
    out = _ask(device, clock, b"X" * 70 + b"\r\nGET_ID\rGET_ID\r\n")
    assert out == b"ERROR: Command too long\r\n" + GET_ID_REPLY * 2


def test_too_long_on_a_timed_line_keeps_the_next_command_of_the_same_write() -> None:
    device, clock = _device(baud=115200)
    out = _ask(device, clock, b"X" * 64 + b"\nGET_ID\n", SETTLE)
    assert out == b"ERROR: Command too long\r\n" + GET_ID_REPLY


def test_too_long_on_a_timed_line_parses_the_rest_then_the_next_command() -> None:
    device, clock = _device(baud=115200)
    out = _ask(device, clock, b"X" * 70 + b"\nGET_ID\n", SETTLE)
    assert out.startswith(b"ERROR: Command too long\r\nERROR: Unknown command - \r\nXXXXXX\r\n")
    assert out.endswith(
        b"CHECK_ERRORS - Performs system diagnostics and reports any errors\r\n" + GET_ID_REPLY
    )


FLT_MAX_PLUS = b"340282350000000000000000000000000000000"  # rounds to FLT_MAX, not to inf


@pytest.mark.parametrize("baud", [None, 115200])
def test_just_above_float32_max_prints_ovf(baud: int | None) -> None:
    device, clock = _device(baud=baud, instant=True)
    _ask(device, clock, b"ABSOLUTE_MOVE " + FLT_MAX_PLUS + b" 0 0\n", SETTLE)
    _ask(device, clock, b"DELTA_MOVE 0 -" + FLT_MAX_PLUS + b" 0\n", SETTLE)
    assert _ask(device, clock, b"GET_POSITION\n", SETTLE).endswith(b": ovf ovf 0.00\r\n")


def test_float32_sum_just_above_max_stays_finite() -> None:
    device, clock = _device(instant=True)
    _ask(device, clock, b"ABSOLUTE_MOVE " + FLT_MAX_PLUS + b" 0 0\n")
    _ask(device, clock, b"DELTA_MOVE 1000 0 0\n")  # FLT_MAX + 1000 is FLT_MAX in float32
    assert _ask(device, clock, b"GET_POSITION\n").endswith(b": ovf 0.00 0.00\r\n")


def test_beyond_float32_range_prints_inf_and_nan() -> None:
    device, clock = _device(instant=True)
    big = b"340282370000000000000000000000000000000"  # rounds to infinity
    _ask(device, clock, b"ABSOLUTE_MOVE " + big + b" 0 0\n")
    _ask(device, clock, b"DELTA_MOVE -" + big + b" 0 0\n")  # inf + -inf
    _ask(device, clock, b"DELTA_MOVE 0 -" + big + b" 0\n")  # -inf prints without a sign
    assert _ask(device, clock, b"GET_POSITION\n").endswith(b": nan inf 0.00\r\n")


def test_chatter_prints_debug_lines_between_replies() -> None:
    device, clock = _device(chatter=10)
    device.boot()
    assert device.wake_at() == pytest.approx(0.1)
    clock.advance(0.25)
    assert device.read_output() == b"dbg 1 loop ok\r\ndbg 2 loop ok\r\n"
    out = _ask(device, clock, b"GET_ID\n", 0.1)
    assert out == GET_ID_REPLY + b"dbg 3 loop ok\r\n"
