"""pi-frame and Firmata drivers: bytes against the documents' references, ranges, decoding."""

from __future__ import annotations

import struct

import pytest

from app.common.stepper_config import configure_stepper
from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.errors import BadInput, DeviceError, DeviceTimeout
from drivers.link.transport import open_link
from drivers.protocols import commands as cmd
from drivers.protocols.events import ErrorReport, Feedback, TextLine
from drivers.protocols.firmata import (
    FirmataProtocol,
    StepperConfig,
    StepperStep,
    StepperVersion,
    seven_bit_pairs,
    step_parts,
)
from drivers.protocols.piframe import PiFrameProtocol
from drivers.session.device_session import DeviceSession

FIRMATA_REFERENCE = [  # drivers/protocols/README.md §5: PyMata 2.20 / pymata4 1.15, byte for byte
    (StepperConfig(200, (8, 9)), "F0 72 00 48 01 08 09 F7"),
    (StepperConfig(4096, (8, 9, 10, 11)), "F0 72 00 00 20 08 09 0A 0B F7"),
    (StepperStep(300, 500), "F0 72 01 2C 02 00 74 03 01 F7"),
    (StepperStep(2097151, -16383), "F0 72 01 7F 7F 7F 7F 7F 00 F7"),
    (StepperVersion(), "F0 72 02 F7"),
]


@pytest.mark.parametrize(("command", "reference"), FIRMATA_REFERENCE)
def test_firmata_bytes_match_pymata(command: cmd.Command, reference: str) -> None:
    assert FirmataProtocol().encode(command) == bytes.fromhex(reference)


@pytest.mark.parametrize(
    ("command", "why"),
    [
        (StepperConfig(200, (8, 9, 10)), "2 or 4 pins"),
        (StepperConfig(20000, (8, 9)), "steps per revolution"),
        (StepperConfig(200, (8, 200)), "pin 200"),
        (StepperStep(0, 10), "speed"),
        (StepperStep(2**21, 10), "speed"),
        (StepperStep(300, 16384), "steps 16384"),
        (cmd.MoveBy(1, 2, 0, speed=10), "one axis"),
        (cmd.MoveBy(0.001, 0, 0, speed=10), "steps of 0.0125 mm"),
    ],
)
def test_firmata_refuses_what_does_not_fit(command: cmd.Command, why: str) -> None:
    with pytest.raises(BadInput, match=why):
        FirmataProtocol().encode(command)


def test_long_moves_are_split_never_masked() -> None:
    parts = step_parts(300, 20000)
    assert [p.steps for p in parts] == [16383, 3617]
    assert sum(p.steps for p in step_parts(300, -40000)) == -40000
    assert all(abs(p.steps) <= 16383 for p in step_parts(300, -40000))
    protocol = FirmataProtocol()
    move = cmd.MoveBy(250, 0, 0, speed=10)  # 250 mm × 80 steps/mm = 20000 steps
    assert [p.steps for p in protocol.expand(move)] == [16383, 3617]  # type: ignore[attr-defined]
    # 10 mm/s × 80 steps/mm = 800 steps/s = 240 rpm at 200 steps/rev: 25 s in all
    assert protocol.move_timing(move, (0, 0, 0), (250, 0, 0)) == pytest.approx((0.0, 25.0))


def test_firmata_messages_are_decoded_and_named() -> None:
    protocol = FirmataProtocol()
    name = bytes((0xF0, 0x79, 2, 5)) + seven_bit_pairs(b"FirmataPlus.ino") + b"\xf7"
    assert protocol.decode(name)[0] == Feedback("firmware", name, "FirmataPlus.ino 2.5")
    assert protocol.decode(b"\xf9\x02\x05")[0].meaning == "Firmata protocol 2.5"  # type: ignore[attr-defined]
    error = b"\xf0\x71" + seven_bit_pairs(b"STEPPER CONFIG Error: Wrong Number of arguments")
    assert protocol.decode(error + b"\xf7") == [
        ErrorReport("STEPPER CONFIG Error: Wrong Number of arguments", "STRING_DATA")
    ]
    hello = b"\xf0\x71" + seven_bit_pairs(b"hello") + b"\xf7"
    assert protocol.decode(hello) == [TextLine("hello")]
    assert protocol.decode(b"\xe3\x7f\x03")[0].meaning == "analog pin 3: 511"  # type: ignore[attr-defined]
    assert protocol.decode(b"\xf0\x72\x05\x00\xf7")[0].meaning == "5"  # type: ignore[attr-defined]
    assert "capability" in protocol.decode(b"\xf0\x6c\x7f\xf7")[0].meaning  # type: ignore[attr-defined]


PIFRAME = ">B3h7HB"


def _fields(frame: bytes) -> tuple[int, ...]:
    assert len(frame) == 25 and frame[:2] == b"\x7b\x7d" and frame[-1:] == b"\x2a"
    return struct.unpack(PIFRAME, frame[2:-1])


def test_piframe_linear_matches_the_seed_example() -> None:
    protocol = PiFrameProtocol()
    protocol.configure({"ticks_per_mm": 1})
    frame = protocol.encode(cmd.MoveTo(100, 50, 0, speed=10))
    assert frame[:9] == bytes.fromhex("7B 7D 01 00 64 00 32 00 00")
    fields = _fields(frame)
    assert fields[:4] == (1, 100, 50, 0)
    assert fields[4:7] == (9, 5, 0)  # 10 mm/s split along (100, 50): 8.94 and 4.47, rounded up


def test_piframe_every_action_and_field() -> None:
    protocol = PiFrameProtocol()  # 100 ticks/mm
    assert _fields(protocol.encode(cmd.Dwell(250)))[:2] == (0, 250)
    assert _fields(protocol.encode(cmd.SetHome())) == (3,) + (0,) * 11
    arc = cmd.Arc(1, -2, 10, 0, 90, True, z=0.5, speed=10)
    fields = _fields(protocol.encode(arc))
    assert fields[:4] == (2, 100, -200, 50)
    assert fields[7] == 1000  # radius in ticks
    assert fields[8] == 5730  # 10 mm/s on a 10 mm radius: 1 rad/s = 57.30°/s
    assert fields[9:] == (0, 9000, 1)
    assert _fields(protocol.encode(cmd.MoveTo(-1, 0, 0, speed=10)))[1] == -100  # two's complement


@pytest.mark.parametrize(
    ("command", "why"),
    [
        (cmd.MoveTo(40000, 0, 0, speed=10), "do not fit 16 bits"),
        (cmd.MoveTo(0.001, 0, 0, speed=10), "ticks of 0.01 mm"),
        (cmd.MoveTo(300, 0, 0, speed=1000), "speed X"),
        (cmd.Dwell(70000), "dwell 70000 ms"),
        (cmd.Arc(0, 0, 700, 0, 90, True, speed=10), "radius"),
        (cmd.GetPosition(), "no frame"),
    ],
)
def test_piframe_refuses_values_that_do_not_fit(command: cmd.Command, why: str) -> None:
    with pytest.raises(BadInput, match=why):
        PiFrameProtocol().encode(command)


def test_piframe_settings_set_the_resolution_and_box() -> None:
    protocol = PiFrameProtocol()
    protocol.configure({"ticks_per_mm": 10})
    assert protocol.capabilities.resolution == pytest.approx(0.1)
    assert protocol.capabilities.travel[0] == (-3276.8, 3276.7)  # type: ignore[index]
    with pytest.raises(BadInput, match="ticks_per_mm 0 refused"):
        protocol.configure({"ticks_per_mm": 0})


@pytest.mark.timeout(20)
def test_piframe_motion_on_the_simulator() -> None:
    link = open_link("sim://pi-frame?instant=1", 115200)
    try:
        protocol = PiFrameProtocol()
        motion = Motion(Client(link, protocol))
        motion.set_speed(100)
        assert motion.move_to(1, 2, 0).measured is False
        report = motion.arc(cmd.Arc(0, 0, 10, 0, 90, True))
        assert (round(report.x, 6), round(report.y, 6)) == (0.0, 10.0)
        assert protocol.commanded == (0, 1000, 0)
        with pytest.raises(BadInput, match="angular speed"):  # 100 mm/s on a 1 mm radius
            motion.arc(cmd.Arc(0, 0, 1, 0, 90, True))
        motion.dwell(10)
        assert link.port.device.history[-1][0] == 0  # type: ignore[attr-defined]
        device = link.port.device  # type: ignore[attr-defined]
        assert [a for a, _ in device.history] == [1, 1, 2, 0]  # to (1,2), to the arc's start
    finally:
        link.close()


@pytest.mark.timeout(20)
def test_firmata_handshake_config_and_split_move_on_the_simulator() -> None:
    link = open_link("sim://firmata?reset_delay=0.2&instant=1", 57600)
    try:
        protocol = FirmataProtocol()
        session = DeviceSession(link, protocol)
        motion = session.motion
        assert motion.identify() == "FirmataPlus.ino 2.5"
        assert configure_stepper(session, 200, (8, 9)) == 5
        protocol.configure({"steps_per_mm": 1})
        motion.set_speed(protocol.capabilities.speed_range[1])  # type: ignore[index]
        assert motion.move_by(20000, 0, 0).x == 20000
        assert link.port.device.steps() == 20000  # type: ignore[attr-defined]
    finally:
        link.close()


@pytest.mark.timeout(10)
def test_no_firmata_board_is_a_clear_timeout() -> None:
    link = open_link("sim://firmata?mute=1", 57600)
    try:
        motion = Motion(Client(link, FirmataProtocol()))
        with pytest.raises(DeviceTimeout, match="is a Firmata board on this port"):
            motion.identify()
    finally:
        link.close()


@pytest.mark.timeout(10)
def test_a_step_before_config_is_the_boards_error() -> None:
    link = open_link("sim://firmata?reset_delay=0.1", 57600)
    try:
        motion = Motion(Client(link, FirmataProtocol()))
        motion.identify()
        with pytest.raises(DeviceError, match="STEPPER Error: not configured"):
            motion.move_by(1, 0, 0)
    finally:
        link.close()
