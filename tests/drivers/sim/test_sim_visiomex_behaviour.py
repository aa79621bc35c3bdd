"""Quirks of the Visiomex firmware that the simulator reproduces, on a manual clock."""

from __future__ import annotations

import time

import pytest
import serial

import drivers.link.transport  # noqa: F401  (registers the sim:// handler)
from app.simcli import build_parser
from drivers.protocols.visiomex.timing import stepping_start
from drivers.sim.clock import ManualClock
from drivers.sim.registry import create_device
from drivers.sim.visiomex_device import POWER_ON, SILENCE, VisiomexDevice

STEP = 4000e-6 + 4000e-6  # one power-on X step: 15 high, 16 low (drivers/protocols/README.md §2b)


def _device(**options: object) -> tuple[VisiomexDevice, ManualClock]:
    clock = ManualClock()
    return VisiomexDevice(clock, **options), clock  # type: ignore[arg-type]


def _drain(device: VisiomexDevice, clock: ManualClock) -> bytes:
    """Run the device until it has nothing left to do; everything it sent."""
    out = bytearray()
    while (due := device.next_due()) is not None:
        clock.now = max(clock.now, due)
        out += device.read_output()
    return bytes(out)


def _ask(device: VisiomexDevice, clock: ManualClock, packet: bytes) -> bytes:
    device.receive(packet)
    return _drain(device, clock)


def _debug(out: bytes) -> dict[str, str]:
    """The `name: value` debug lines of a move reply."""
    lines = out.decode("latin-1").split("\r\n")
    return dict(line.split(": ", 1) for line in lines if ": " in line)


def _lead(out: bytes) -> float:
    """From the reply's first byte to the start of stepping: FP0001 enters the TX buffer."""
    return stepping_start(out.index(b"FP0001\r\n") + len(b"FP0001\r\n"))


def _move(device: VisiomexDevice, clock: ManualClock, packet: bytes) -> dict[str, str]:
    out = _ask(device, clock, packet)
    assert out.endswith(b"FP0001\r\nFA0001\r\n"), out
    return _debug(out)


# -- framing -----------------------------------------------------------------------------------
def test_reply_comes_one_second_after_the_last_byte() -> None:
    device, clock = _device()
    device.receive(b"S05000200NNNNNNNNN")
    clock.advance(SILENCE - 0.001)
    assert device.read_output() == b""
    clock.advance(0.001)
    assert device.read_output() == b"FS0005\r\n"


def test_two_packets_within_a_second_merge_and_only_the_first_counts() -> None:
    device, clock = _device()
    device.receive(b"S05000300NNNNNNNNN")
    clock.advance(0.5)
    device.receive(b"S06000300NNNNNNNNN")
    assert _drain(device, clock) == b"FS0005\r\n"
    assert clock.now == pytest.approx(1.5)
    assert device.parameters[5] == 300
    assert device.parameters[6] == POWER_ON[6]


def test_packets_more_than_a_second_apart_get_two_replies() -> None:
    device, clock = _device()
    device.receive(b"S05000300NNNNNNNNN")
    clock.advance(1.1)
    device.receive(b"S06000300NNNNNNNNN")
    assert _drain(device, clock) == b"FS0005\r\nFS0006\r\n"


def test_bytes_sent_during_a_move_are_answered_one_second_after_fa() -> None:
    device, clock = _device()
    device.receive(b"MLP0010000P0010000")
    clock.advance(1.0)
    out = device.read_output()
    assert out.endswith(b"FP0001\r\n")
    clock.advance(1.0)
    device.receive(b"S05000200NNNNNNNNN")
    fa_at = 1.0 + _lead(out) + 400 * STEP
    clock.now = fa_at
    assert device.read_output() == b"FA0001\r\n"
    clock.now = fa_at + SILENCE - 0.01
    assert device.read_output() == b""
    clock.now = fa_at + SILENCE
    assert device.read_output() == b"FS0005\r\n"


def test_receive_buffer_holds_63_bytes_while_stepping() -> None:
    device, clock = _device()
    device.receive(b"MLP0010000P0010000")
    clock.advance(1.5)
    device.receive(b"G" * 100)
    assert device.dropped_rx == 100 - 63


# -- set ---------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("packet", "reply"),
    [
        (b"S3X000100NNNNNNNNN", b"FS0003\r\n"),  # atol stops at X
        (b" 3000100NNNNNNNNN", b"EP0002\r\n"),
        (b"S 7000003", b"FS0007\r\n"),  # short, leading space skipped
        (b"S00000001NNNNNNNNN", b"EP0006\r\n"),
        (b"S29000001NNNNNNNNN", b"EP0006\r\n"),
        (b"S-1000001NNNNNNNNN", b"EP0006\r\n"),
        (b"S23000000NNNNNNNNN", b"FS0023\r\n"),  # a division by zero the STM32 survives
        (b"S24000000NNNNNNNNN", b"FS0024\r\n"),
        (b"S27000005NNNNNNNNN", b"FS0027\r\n"),  # EF0002 never comes
    ],
)
def test_set_replies(packet: bytes, reply: bytes) -> None:
    device, clock = _device()
    assert _ask(device, clock, packet) == reply


def test_pulley_diameter_is_stored_divided_by_four() -> None:
    device, clock = _device()
    assert _ask(device, clock, b"S03000382NNNNNNNNN") == b"FS0003\r\n"
    assert _ask(device, clock, b"S04000401NNNNNNNNN") == b"FS0004\r\n"
    assert device.parameters[3] == 95
    assert device.parameters[4] == 100


def test_every_set_forces_the_lead_screw() -> None:
    device, clock = _device()
    assert _ask(device, clock, b"S27000000NNNNNNNNN") == b"FS0027\r\n"
    assert device.parameters[27] == 1
    debug = _move(device, clock, b"MLP0001000P0000000")
    assert debug["Driving Mechanism"] == "1"
    assert debug["System cycle linear distance x"] == "10.00"


def test_fullcycle_and_microstep_change_the_steps() -> None:
    device, clock = _device()
    assert _move(device, clock, b"MLP0010000P0000000")["Step x"] == "400"
    _ask(device, clock, b"S05000800NNNNNNNNN")
    assert _move(device, clock, b"MLP0010000P0000000")["Step x"] == "800"
    _ask(device, clock, b"S07000004NNNNNNNNN")
    assert _move(device, clock, b"MLP0010000P0000000")["Step x"] == "3200"
    _ask(device, clock, b"S06000100NNNNNNNNN")
    assert _move(device, clock, b"MLP0000000P0010000")["Step y"] == "100"


def test_thread_distance_set_after_boot_changes_nothing() -> None:
    device, clock = _device()
    assert _ask(device, clock, b"S01000005NNNNNNNNN") == b"FS0001\r\n"
    debug = _move(device, clock, b"MLP0010000P0000000")
    assert debug["System cycle linear distance x"] == "10.00"
    assert debug["Step x"] == "400"


# -- move --------------------------------------------------------------------------------------
def test_move_timing_depends_on_x_alone_by_default() -> None:
    device, clock = _device()
    device.receive(b"MLP0001000N0050000")
    out = _drain(device, clock)
    assert clock.now == pytest.approx(1.0 + _lead(out) + 40 * STEP)
    assert device.position() == pytest.approx((1.0, 0.0))
    assert device.firmware_position == pytest.approx((1.0, -50.0))


def test_y_never_moves_at_power_on_and_a_set_of_20_changes_nothing() -> None:
    device, clock = _device()
    _ask(device, clock, b"S20000010NNNNNNNNN")  # recomputed at the move
    start = clock.now
    device.receive(b"MLP0000000N0050000")
    out = _drain(device, clock)
    assert _debug(out)["Step y"] == "2000"
    assert clock.now - start == pytest.approx(1.0 + _lead(out))
    assert device.position() == (0.0, 0.0)
    assert device.parameters[20] == 0


def test_y_loop_runs_the_ramp_count() -> None:
    device, clock = _device()
    _ask(device, clock, b"S22006000NNNNNNNNN")
    _ask(device, clock, b"S24000001NNNNNNNNN")  # ramp length A_y = 14
    start = clock.now
    device.receive(b"MLP0000000N0050000")
    out = _drain(device, clock)
    ramp = 2 * (4000 + 5000 + sum(5000 - k * 5000 // 14 for k in range(1, 13))) * 1e-6
    assert clock.now - start == pytest.approx(1.0 + _lead(out) + ramp)
    assert device.position() == pytest.approx((0.0, -14 * 10 / 400))
    assert (device.parameters[20], device.parameters[16]) == (14, 358)


def test_position_moves_x_then_y() -> None:
    device, clock = _device()
    _ask(device, clock, b"S22006000NNNNNNNNN")
    _ask(device, clock, b"S24000001NNNNNNNNN")  # Y makes 14 steps
    start = clock.now
    device.receive(b"MLN0010000P0010000")
    clock.advance(1.0)
    t0 = start + 1.0 + _lead(device.read_output())  # stepping starts
    assert device.position(t0 + 200 * STEP) == pytest.approx((-5.0, 0.0))
    assert device.position(t0 + 400 * STEP) == pytest.approx((-10.0, 0.0))
    _drain(device, clock)
    assert device.position() == pytest.approx((-10.0, 14 * 10 / 400))


def test_type_letter_is_not_inspected() -> None:
    device, clock = _device()
    debug = _move(device, clock, b"MRP0002500P0000000")
    assert (debug["Distance x (mm)"], debug["Step x"]) == ("2.50", "100")
    assert _move(device, clock, b"MSP0002500P0000000")["Step x"] == "100"


def test_bad_directions_print_ep0003_per_axis_and_run_positive() -> None:
    device, clock = _device()
    out = _ask(device, clock, b"MLX0001000Y0002000")
    assert out.startswith(b"EP0003\r\nEP0003\r\nDriving Mechanism: 1\r\n")
    assert out.count(b"\r\n") == 2 + 9 + 2
    assert device.position() == pytest.approx((1.0, 0.0))
    assert device.firmware_position == pytest.approx((1.0, 2.0))


def test_short_move_still_runs() -> None:
    device, clock = _device()
    out = _ask(device, clock, b"MLP1")
    assert out.startswith(b"EP0003\r\nDriving Mechanism: 1\r\n")
    assert _debug(out)["Distance x (mm)"] == "0.00"


def test_unknown_first_char_and_d_in_the_seed() -> None:
    device, clock = _device()
    assert _ask(device, clock, b"D") == b"EP0002\r\n"
    assert _ask(device, clock, b"m") == b"EP0002\r\n"


def test_instant_moves_keep_the_silence() -> None:
    device, clock = _device(instant=True)
    device.receive(b"MLP0010000P0010000")
    clock.advance(1.0)
    assert device.read_output().endswith(b"FP0001\r\nFA0001\r\n")
    assert device.next_due() is None


def test_mute_device_never_sends_anything() -> None:
    device, clock = _device(mute=True)
    device.boot()
    device.receive(b"S05000200NNNNNNNNN")
    clock.advance(2.0)
    device.receive(b"MLP0010000P0010000")
    clock.advance(10.0)
    assert device.read_output() == b""


# -- variants ----------------------------------------------------------------------------------
def test_unknown_variant_names_the_known_ones() -> None:
    with pytest.raises(ValueError, match="seed, prefixed, board12"):
        VisiomexDevice(ManualClock(), variant="nope")


@pytest.mark.parametrize(
    ("variant", "baud"), [("seed", 9600), ("prefixed", 9600), ("board12", 115200)]
)
def test_default_baud_depends_on_the_variant(variant: str, baud: int) -> None:
    assert create_device("visiomex", variant=variant).default_baud == baud


def test_prefixed_variant_marks_feedback_only() -> None:
    device, clock = _device(variant="prefixed")
    device.boot()
    assert device.read_output() == b"Checkpoint 2\r\n"
    assert _ask(device, clock, b"S03000382NNNNNNNNN") == b">FS0003\r\n"
    assert _ask(device, clock, b"S99000382NNNNNNNNN") == b">EP0006\r\n"
    assert _ask(device, clock, b"X") == b">EP0002\r\n"
    out = _ask(device, clock, b"MLP0001000X0001000")
    assert out.startswith(b">EP0003\r\nDriving Mechanism: 1\r\n")
    assert out.endswith(b"Step y: 40\r\n>FP0001\r\n>FA0001\r\n")


def test_board12_set_move_and_go_home() -> None:
    device, clock = _device(variant="board12")
    assert _ask(device, clock, b"S05000800NNN") == b"FS0005\r\n"
    debug = _move(device, clock, b"MLP0010N0005")
    assert (debug["Distance x (mm)"], debug["Step x"]) == ("10.00", "800")
    assert (debug["Distance y (mm)"], debug["Step y"]) == ("5.00", "200")
    assert device.firmware_position == pytest.approx((10.0, -5.0))
    debug = _move(device, clock, b"D")
    assert (debug["Distance x (mm)"], debug["Distance y (mm)"]) == ("10.00", "5.00")
    assert len(debug) == 9
    assert device.firmware_position == pytest.approx((0.0, 0.0))
    assert device.position() == pytest.approx((0.0, 0.0))
    _move(device, clock, b"MLN0003P0000")
    assert _move(device, clock, b"DNNNNNNNNNNN")["Distance x (mm)"] == "3.00"
    assert device.firmware_position == pytest.approx((0.0, 0.0))


# -- the documented firmware (bugs=False) ------------------------------------------------------
@pytest.mark.parametrize(
    ("packet", "reply"),
    [
        (b"S05000200", b"EP0001\r\n"),
        (b"MLP0010000P0010000N", b"EP0001\r\n"),
        (b"MLX0010000P0010000", b"EP0004\r\n"),
        (b"MLP0010000X0010000", b"EP0005\r\n"),
        (b"MQP0010000P0010000", b"EP0003\r\n"),
        (b"S27000002NNNNNNNNN", b"EF0002\r\n"),
        (b"S27000000NNNNNNNNN", b"FS0027\r\n"),
        (b"S29000002NNNNNNNNN", b"EP0006\r\n"),
        (b"X", b"EP0002\r\n"),
        (b"G", b""),
    ],
)
def test_documented_firmware_errors(packet: bytes, reply: bytes) -> None:
    device, clock = _device(bugs=False)
    assert _ask(device, clock, packet) == reply


def test_documented_firmware_stores_what_it_is_sent() -> None:
    device, clock = _device(bugs=False)
    _ask(device, clock, b"S27000000NNNNNNNNN")
    _ask(device, clock, b"S03000382NNNNNNNNN")
    assert device.parameters[3] == 382
    assert device.parameters[27] == 0


def test_documented_firmware_rotational_and_step_moves() -> None:
    device, clock = _device(bugs=False)
    debug = _move(device, clock, b"MRP0000090N0000036")
    assert (debug["Distance x (mm)"], debug["Degree x"], debug["Step x"]) == (
        "2.50",
        "90.00",
        "100",
    )
    assert (debug["Distance y (mm)"], debug["Step y"]) == ("1.00", "40")
    assert device.position() == pytest.approx((2.5, -1.0))
    start = clock.now
    device.receive(b"MSP0000100P0000040")
    out = _drain(device, clock)
    debug = _debug(out)
    assert (debug["Step x"], debug["Step y"], debug["Degree y"]) == ("100", "40", "36.00")
    # The Y loop runs Step y here: 140 steps in all.
    assert clock.now - start == pytest.approx(1.0 + _lead(out) + 140 * STEP)


def test_documented_firmware_board12_lone_d_goes_home() -> None:
    device, clock = _device(variant="board12", bugs=False)
    _move(device, clock, b"MLP0002P0001")
    assert _move(device, clock, b"D")["Distance x (mm)"] == "2.00"
    assert device.position() == pytest.approx((0.0, 0.0))


# -- the ways in: sim:// URL and motionsim -----------------------------------------------------
@pytest.mark.timeout(10)
def test_sim_url_with_variant_and_bugs_answers_a_set() -> None:
    port = serial.serial_for_url(
        "sim://visiomex?variant=prefixed&bugs=0&line_timing=0", 9600, timeout=2.0
    )
    try:
        assert port.read_until(b"\n") == b"Checkpoint 2\r\n"
        start = time.monotonic()
        port.write(b"S05000200NNNNNNNNN")
        assert port.read_until(b"\n") == b">FS0005\r\n"
        assert 0.9 <= time.monotonic() - start <= 1.3
        port.write(b"S05000200")  # bugs=0: the length is checked
        assert port.read_until(b"\n") == b">EP0001\r\n"
    finally:
        port.close()


def test_sim_url_rejects_an_unknown_variant() -> None:
    with pytest.raises(serial.SerialException, match="board12"):
        serial.serial_for_url("sim://visiomex?variant=nope", 9600)


def test_motionsim_accepts_the_visiomex_options() -> None:
    options = build_parser().parse_args(
        ["visiomex", "--variant", "board12", "--no-bugs", "--instant", "--mute"]
    )
    assert (options.variant, options.no_bugs, options.instant, options.mute) == (
        "board12",
        True,
        True,
        True,
    )
    assert build_parser().parse_args(["visiomex"]).variant is None
    assert build_parser().parse_args(["visiomex", "--pace", "uart"]).pace == "uart"
    with pytest.raises(SystemExit):
        build_parser().parse_args(["visiomex", "--pace", "fast"])
    with pytest.raises(SystemExit):
        build_parser().parse_args(["visiomex", "--variant", "nope"])


def test_the_sim_url_takes_the_pace() -> None:
    with serial.serial_for_url("sim://visiomex?pace=uart", 9600) as port:
        assert port.device.pacing == 1.0  # type: ignore[attr-defined]
    with pytest.raises(serial.SerialException, match="recorded"):
        serial.serial_for_url("sim://visiomex?pace=fast", 9600)
