"""The Visiomex driver: packets, codes, parameters, variants and pacing (no device needed)."""

from __future__ import annotations

import math

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.device.param_profile import ProfileError, format_profile, parse_profile
from drivers.errors import BadInput, DeviceError, DeviceRestarted, DeviceTimeout
from drivers.link.records import TX
from drivers.link.transport import Link, open_link
from drivers.protocols import commands as cmd
from drivers.protocols.events import ErrorReport, Feedback, TextLine
from drivers.protocols.registry import create_protocol
from drivers.protocols.visiomex.model import POWER_ON
from drivers.protocols.visiomex.params import DEFAULTS, PARAMETERS
from drivers.protocols.visiomex.protocol import VisiomexProtocol
from tests.support.fakes import ScriptedPort

# (id, name, unit, a value, its wire digits): every parameter's scaling, as decided
SCALING = [
    (1, "thread_distance_x", "mm", 8, "000008"),
    (2, "thread_distance_y", "mm", 12, "000012"),
    (3, "pulley_diameter_x", "mm", 38.2, "000382"),
    (4, "pulley_diameter_y", "mm", 99999.9, "999999"),
    (5, "motor_fullcycle_step_x", "steps", 200, "000200"),
    (6, "motor_fullcycle_step_y", "steps", 400, "000400"),
    (7, "microstep_coeff_x", "×", 16, "000016"),
    (8, "microstep_coeff_y", "×", 1, "000001"),
    (9, "max_speed_x", "mm/s", 50, "000050"),
    (10, "max_speed_y", "mm/s", 0, "000000"),
    (11, "step_delay_speed_steady_x", "µs", 4000, "004000"),
    (12, "step_delay_speed_steady_y", "µs", 999999, "999999"),
    (13, "step_delay_speed_min_x", "µs", 8000, "008000"),
    (14, "step_delay_speed_min_y", "µs", 8000, "008000"),
    (15, "step_delay_instantaneous_x", "µs", 4000, "004000"),
    (16, "step_delay_instantaneous_y", "µs", 2500, "002500"),
    (17, "step_delay_acceleration_avg_x", "µs", 6000, "006000"),
    (18, "step_delay_acceleration_avg_y", "µs", 6000, "006000"),
    (19, "step_count_acceleration_x", "steps", 30, "000030"),
    (20, "step_count_acceleration_y", "steps", 0, "000000"),
    (21, "input_speed_steady_x", "mm/s", 10, "000010"),
    (22, "input_speed_steady_y", "mm/s", 25, "000025"),
    (23, "input_acceleration_x", "mm/s²", 100, "000100"),
    (24, "input_acceleration_y", "mm/s²", 0, "000000"),
    (25, "delta_t_x", "s", 3, "000003"),
    (26, "delta_t_y", "s", 0, "000000"),
    (27, "driving_mechanism", "", 0, "000000"),
]
OUTPUTS = {11, 12, 17, 18, 19, 20, 25, 26}  # 15/16 steer every move (§2b): inputs


def test_the_table_covers_every_parameter_once() -> None:
    assert [row[0] for row in SCALING] == [p.id for p in PARAMETERS] == list(range(1, 28))


@pytest.mark.parametrize(("pid", "name", "unit", "value", "digits"), SCALING)
def test_set_packet_for_every_parameter(
    pid: int, name: str, unit: str, value: float, digits: str
) -> None:
    protocol = VisiomexProtocol()
    parameter = protocol.parameter(name)
    assert (parameter.id, parameter.unit, parameter.output) == (pid, unit, pid in OUTPUTS)
    packet = protocol.encode(cmd.SetParameter(pid, value))
    assert packet == f"S{pid:02d}{digits}NNNNNNNNN".encode()
    assert len(packet) == 18


@pytest.mark.parametrize(
    ("name", "value", "why"),
    [
        ("pulley_diameter_x", 38.25, "in steps of 0.1 mm"),
        ("pulley_diameter_x", 100000, "0.0 mm to 99999.9 mm"),
        ("thread_distance_x", -1, "0 mm to 999999 mm"),
        ("thread_distance_x", 1.5, "whole numbers"),
        ("max_speed_x", math.inf, "max_speed_x: inf refused"),
        ("max_speed_x", math.nan, "max_speed_x: nan refused"),
        ("max_speed_x", "ten", "is not a number"),
        ("driving_mechanism", 2, "0 to 1"),
        ("step_delay_speed_min_x", 1_000_000, "999999 µs"),
    ],
)
def test_bad_values_refused_naming_parameter_unit_and_range(
    name: str, value: object, why: str
) -> None:
    protocol = VisiomexProtocol()
    with pytest.raises(BadInput, match=name) as caught:
        protocol.parameter(name).to_wire(value)
    assert why in str(caught.value)


def test_unknown_parameters_refused() -> None:
    protocol = VisiomexProtocol()
    for key in ("nope", "28", "0", ""):
        with pytest.raises(BadInput, match="unknown parameter"):
            protocol.parameter(key)
    assert protocol.parameter("03").name == "pulley_diameter_x"


@pytest.mark.parametrize(
    ("command", "packet"),
    [
        (cmd.MoveBy(10, -2.5), "MLP0010000N0002500"),
        (cmd.MoveBy(0, 0), "MLP0000000P0000000"),
        (cmd.MoveBy(-9999.999, 0.001), "MLN9999999P0000001"),
        (cmd.MoveBy(90, -360, kind="rotational"), "MRP0000090N0000360"),
        (cmd.MoveBy(400, 3, kind="steps"), "MSP0000400P0000003"),
    ],
)
def test_move_packets(command: cmd.MoveBy, packet: str) -> None:
    assert VisiomexProtocol().encode(command) == packet.encode()


@pytest.mark.parametrize(
    ("command", "why"),
    [
        (cmd.MoveBy(1, 2, 3), "X and Y only"),
        (cmd.MoveBy(10000, 0), "at most 9999.999 mm"),
        (cmd.MoveBy(0.0005, 0), "1 µm"),
        (cmd.MoveBy(0.5, 0, kind="rotational"), "whole °"),
        (cmd.MoveBy(1, 0, kind="diagonal"), "move kind"),
        (cmd.MoveTo(1, 2, 0), "relative"),
        (cmd.GetPosition(), "no packet"),
    ],
)
def test_moves_refused_before_sending(command: cmd.Command, why: str) -> None:
    with pytest.raises(BadInput, match=why):
        VisiomexProtocol().encode(command)


def test_board12_variant_packets_and_capabilities() -> None:
    protocol = create_protocol("visiomex", "board12")
    assert protocol.encode(cmd.MoveBy(3, -2)) == b"MLP0003N0002"
    assert protocol.encode(cmd.SetParameter(3, 38.2)) == b"S03000382NNN"
    assert protocol.encode(cmd.Home()) == b"DNNNNNNNNNNN"
    assert protocol.capabilities.default_baud == 115200
    assert protocol.capabilities.homing and protocol.capabilities.resolution == 1.0
    with pytest.raises(BadInput, match="at most 9999 mm"):
        protocol.encode(cmd.MoveBy(10000, 0))
    with pytest.raises(BadInput, match="whole mm"):
        protocol.encode(cmd.MoveBy(0.5, 0))
    with pytest.raises(BadInput, match="no variant"):
        create_protocol("visiomex", "board13")
    with pytest.raises(BadInput, match="no wire variants"):
        create_protocol("coxiris", "seed")


def test_every_code_decoded_and_other_lines_are_device_text() -> None:
    protocol = VisiomexProtocol()
    assert protocol.decode(b"FS0003\r\n") == [Feedback("FS0003", meaning="pulley_diameter_x set")]
    assert protocol.decode(b"FS0028\r\n")[0].meaning == "driving_mechanism_y set"  # type: ignore[attr-defined]
    assert protocol.decode(b"FP0001\r\n")[0] == Feedback("FP0001", meaning="move package confirmed")
    assert protocol.decode(b"FA0001\r\n")[0] == Feedback("FA0001", meaning="action accomplished")
    for number in range(1, 7):
        event = protocol.decode(f"EP000{number}\r\n".encode())[0]
        assert isinstance(event, ErrorReport) and event.code == f"EP000{number}"
        assert "documentation does not list" not in event.message
    for number in (1, 2):
        event = protocol.decode(f"EF000{number}\r\n".encode())[0]
        assert isinstance(event, ErrorReport) and event.message
    assert protocol.decode(b"Step x: 400\r\n") == [TextLine("Step x: 400")]
    assert protocol.decode(b"Checkpoint 2\r\n") == [TextLine("Checkpoint 2")]
    prefixed = create_protocol("visiomex", "prefixed")
    assert prefixed.decode(b">FS0003\r\n")[0] == Feedback("FS0003", meaning="pulley_diameter_x set")
    assert prefixed.decode(b"FS0003\r\n") == [TextLine("FS0003")]  # not a packet there


def test_the_firmware_forces_the_driving_mechanism() -> None:
    protocol = VisiomexProtocol()
    protocol.known[27] = 0
    written = protocol.parameter_written(cmd.SetParameter(3, 38.2))
    assert written.device_values == {"driving_mechanism": 1.0}
    assert any("forces driving_mechanism to 1" in note for note in written.notes)
    assert protocol.known[27] == 1 and protocol.known[3] == 38.2


def test_defaults_are_the_firmware_power_on_values() -> None:
    assert DEFAULTS == POWER_ON
    assert (DEFAULTS[5], DEFAULTS[7]) == (400, 1)  # 400 full steps × 1, not 200 × 2


def test_written_outputs_are_reported_as_the_firmware_recomputes_them() -> None:
    protocol = VisiomexProtocol()
    written = protocol.parameter_written(cmd.SetParameter(17, 6000))
    assert written.device_values["step_delay_acceleration_avg_x"] == 2500
    assert any("recomputes step_delay_acceleration_avg_x" in note for note in written.notes)
    assert protocol.known[17] == 2500
    written = protocol.parameter_written(cmd.SetParameter(1, 5))
    assert any("only at boot" in note for note in written.notes)
    assert protocol.firmware.steps("x", 10_000) == 400  # the boot's cycle, 10 mm


def test_a_set_reports_the_outputs_it_recomputed_in_other_parameters() -> None:
    protocol = VisiomexProtocol()
    written = protocol.parameter_written(cmd.SetParameter(21, 6000))
    assert written.device_values == {"driving_mechanism": 1.0, "delta_t_x": 600.0}  # 21 ÷ 23
    assert protocol.known[25] == 600
    written = protocol.parameter_written(cmd.SetParameter(23, 0))  # integer ÷ 0 = 0
    assert written.device_values == {"driving_mechanism": 1.0, "delta_t_x": 0.0}
    written = protocol.parameter_written(cmd.SetParameter(3, 38.2))  # nothing else changes
    assert written.device_values == {"driving_mechanism": 1.0}


def test_move_timing_follows_the_firmware_state_and_moves_sent() -> None:
    protocol = VisiomexProtocol()
    move = cmd.MoveBy(10.0, 10.0, 0.0)
    delay, duration = protocol.move_timing(move, (0, 0, 0), (10, 10, 0))
    transmit = 18 * 10 / 9600
    # visiomex-moves.json: FA0001 4.382 s after MLP0010000P0010000 at power-on (Y never moves)
    assert delay + duration - transmit == pytest.approx(4.382, rel=0.02)
    assert duration == pytest.approx(400 * 0.008)
    protocol.parameter_written(cmd.SetParameter(15, 8000))
    slower = sum(protocol.move_timing(move, (0, 0, 0), (10, 10, 0)))
    assert slower - (delay + duration) == pytest.approx(400 * 0.004)
    assert protocol.firmware.values[19] == 50  # power-on: replaced at the first move
    protocol.on_sent(move)
    assert (protocol.firmware.values[19], protocol.firmware.values[20]) == (0, 0)


def test_profile_round_trip_and_bad_profiles() -> None:
    values = {p.name: p.default for p in PARAMETERS}
    text = format_profile(values, PARAMETERS, "visiomex")
    inputs = {p.name: p.default for p in PARAMETERS if not p.output}  # outputs are never written
    assert parse_profile(text, PARAMETERS, "visiomex") == inputs
    bad = text.replace("pulley_diameter_x = 38.2", "pulley_diameter_x = 38.25")
    with pytest.raises(ProfileError, match=r"line \d+: pulley_diameter_x: 38.25 mm refused"):
        parse_profile(bad, PARAMETERS, "visiomex")
    with pytest.raises(ProfileError, match="unknown parameter 'nope'"):
        parse_profile("[parameters]\nnope = 1\n", PARAMETERS, "visiomex")
    with pytest.raises(ProfileError, match="not a number"):
        parse_profile('[parameters]\nmax_speed_x = "fast"\n', PARAMETERS, "visiomex")
    with pytest.raises(ProfileError, match="for 'coxiris'"):
        parse_profile(
            'protocol = "coxiris"\n[parameters]\nmax_speed_x = 1\n', PARAMETERS, "visiomex"
        )
    with pytest.raises(ProfileError, match="not a parameter profile"):
        parse_profile("import os\n", PARAMETERS, "visiomex")


@pytest.mark.timeout(20)
def test_two_sets_in_a_row_wait_for_each_reply_and_never_merge() -> None:
    link = open_link("sim://visiomex?instant=1", 9600)
    sent: list[float] = []
    link.listeners.append(
        lambda record: sent.append(record.time) if record.direction == TX else None
    )
    try:
        motion = Motion(Client(link, VisiomexProtocol()))
        first = motion.set_parameter("pulley_diameter_x", 38.2)
        second = motion.set_parameter(22, 25)
        assert first.parameter.id == 3 and second.parameter.id == 22
        assert sent[1] - sent[0] >= 1.0  # the second waited for the first's reply
        # Parameters 21 and 22 are written; X steps at 4000 + 4000 µs a 0.025 mm step whatever
        # they say (issue 28), and Y makes no step at power-on.
        assert motion.set_speed(20) == 3.125
        report = motion.move_to(1, -0.5)
        assert (report.x, report.y, report.measured, report.confirmed) == (1, 0, False, True)
        with pytest.raises(DeviceError, match="EP0002"):
            motion.client.send_raw(b"X")
    finally:
        link.close()


@pytest.mark.timeout(10)
def test_a_silent_device_times_out_naming_the_parameter() -> None:
    link = open_link("sim://visiomex?mute=1", 9600)
    try:
        motion = Motion(Client(link, VisiomexProtocol()))
        with pytest.raises(DeviceTimeout, match=r"S03000382NNNNNNNNN \(set pulley_diameter_x\)"):
            motion.set_parameter("pulley_diameter_x", 38.2)
    finally:
        link.close()


@pytest.mark.timeout(10)
def test_a_restart_that_cut_the_reply_line_is_still_named() -> None:
    # The board restarted between FP0001 and its CR LF: the banner ends the cut line. Seen in
    # CI as a 27 s timeout instead of "restarted during".
    port = ScriptedPort(b"Step x: 2000\r\nStep y: 0\r\nFP0001Checkpoint 2\r\n")
    client = Client(Link(port, "scripted"), VisiomexProtocol())  # type: ignore[arg-type]
    with pytest.raises(DeviceRestarted, match="restarted during MLP0001000P0000000"):
        client.execute(cmd.MoveBy(1, 0), timeout=3)
    assert not VisiomexProtocol().is_restart(TextLine("Step x: 2"))
