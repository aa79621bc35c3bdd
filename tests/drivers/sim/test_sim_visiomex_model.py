"""The Visiomex firmware model (drivers/protocols/README.md §2b): power-on values, recalculation,
float32 step counts, C number parsing and printing, the stepping loops and their ramps."""

from __future__ import annotations

import pytest

from drivers.protocols.visiomex.model import (
    BOOT_ONLY,
    NEVER_READ,
    OVERWRITTEN_AFTER_SET,
    OVERWRITTEN_AT_MOVE,
    POWER_ON,
    FirmwareState,
    debug_lines,
    f32,
    format_float,
    format_steps,
    parse_atof,
    parse_atol,
)
from drivers.protocols.visiomex.timing import interpolate

pytestmark = pytest.mark.timeout(30)


def _state(**values: int) -> FirmwareState:
    """Power-on, then a set of each `pNN=value`, in order."""
    state = FirmwareState.boot()
    for key, value in values.items():
        state.set(int(key[1:]), value)
    return state


def test_power_on_values_after_the_boot_recalculation() -> None:
    assert sorted(POWER_ON) == list(range(1, 28))
    expected = {1: 10, 5: 400, 7: 1, 9: 3, 11: 0, 13: 5000, 15: 4000, 17: 2500, 19: 50}
    expected |= {21: 100, 23: 10, 25: 10, 27: 1}
    for i, value in expected.items():
        assert POWER_ON[i] == value and POWER_ON[i + (i < 27)] == value, i
    assert POWER_ON[3] == POWER_ON[4] == 38.2
    state = FirmwareState.boot()
    assert (state.cycle, state.ramp, state.delays) == ((10, 10), (0, 0), (4000, 4000))


def test_the_id_sets() -> None:
    assert {11, 12, 17, 18, 25, 26} == OVERWRITTEN_AFTER_SET
    assert {19, 20} == OVERWRITTEN_AT_MOVE
    assert ({1, 2}, {3, 4, 9, 10, 27}) == (BOOT_ONLY, NEVER_READ)


@pytest.mark.parametrize(
    ("micrometres", "steps"),
    [(225, 8), (575, 23), (275, 10), (900, 35), (37_500, 1500), (5000, 200), (9999, 399)],
)
def test_step_counts_in_float32_truncated(micrometres: float, steps: int) -> None:
    assert FirmwareState.boot().steps("x", micrometres) == steps
    assert FirmwareState.boot().steps("y", micrometres) == steps


def test_step_counts_follow_05_to_08() -> None:
    assert _state(p07=4).steps("x", 1000) == 160
    assert _state(p05=200).steps("x", 1000) == 20
    assert _state(p08=16).steps("y", 1000) == 640
    assert _state(p08=16).steps("x", 1000) == 40
    assert _state(p05=0).steps("x", 1000) == 0  # division through zero: no steps


def test_negative_counts_truncate_toward_zero_then_wrap() -> None:
    state = FirmwareState.boot()
    assert state.steps("x", -10) == 0  # -0.4 step
    assert state.steps("y", -1000) == 4294967256
    assert format_steps(-40) == "4294967256"


def test_thread_distance_after_boot_does_not_change_the_cycle() -> None:
    state = _state(p01=5)
    assert state.values[1] == 5 and state.cycle == (10, 10)
    assert state.steps("x", 10_000) == 400


def test_set_storage_rules() -> None:
    state = _state(p03=382, p13=-1, p07=3)
    assert state.values[3] == 95  # ÷ 4, a firmware bug
    assert state.values[13] == 4294967295  # unsigned 32-bit
    assert state.values[7] == 3.0
    state.set(27, 0)
    assert state.values[27] == 1  # forced after every set
    state.set(17, 100)
    assert state.values[17] == (4294967295 - 0) // 2  # overwritten by the recalculation


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("0001e03", 1000.0),
        ("00012.5", 12.5),
        ("12AB000", 12.0),
        ("-001000", -1000.0),
        ("  +7.5e", 7.5),
        ("", 0.0),
        ("ABC", 0.0),
        (".", 0.0),
        (".5", 0.5),
    ],
)
def test_atof(text: str, value: float) -> None:
    assert parse_atof(text) == value


@pytest.mark.parametrize(("text", "value"), [("3X", 3), ("-00001", -1), (" 7", 7), ("", 0)])
def test_atol(text: str, value: int) -> None:
    assert parse_atol(text) == value


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (0.225, "0.22"),
        (0.025, "0.03"),
        (0.275, "0.28"),
        (9.999, "10.00"),
        (359999.97, "359999.97"),
        (-0.01, "-0.01"),
        (5e9, "ovf"),
        (-5e9, "ovf"),
    ],
)
def test_float_printing_on_the_exact_double(value: float, text: str) -> None:
    assert format_float(f32(value)) == text


def test_debug_lines_of_a_move() -> None:
    lines = debug_lines(FirmwareState.boot(), 225, 0)
    assert lines[3:] == [
        "Distance x (mm): 0.22",
        "Distance y (mm): 0.00",
        "Degree x: 8.10",
        "Degree y: 0.00",
        "Step x: 8",
        "Step y: 0",
    ]


def test_y_never_moves_at_power_on() -> None:
    state = FirmwareState.boot()
    plan = state.move(10_000, 10_000)
    assert plan.steps == (400, 400)
    assert plan.loops == (400, 0)
    assert plan.seconds == pytest.approx(400 * 0.008)
    assert (state.values[19], state.values[20]) == (0, 0)  # 50 until the first move
    assert state.delays == (4000, 4000)


def test_an_x_step_is_15_high_and_16_low() -> None:
    plan = _state(p15=1000, p16=3000).move(5000, 0)
    assert plan.x_segments == ((200, 1000, 3000),)
    assert plan.seconds == pytest.approx(0.8)


def test_the_ramp_example_of_case_21_24() -> None:
    state = _state(p21=6000, p22=6000, p23=1, p24=1)
    assert state.ramp == (14, 14)
    assert state.values[25] == 6000
    plan = state.move(5000, 5000)
    highs = [high for n, high, _ in plan.x_segments for _ in range(n)]
    assert len(highs) == 200
    assert highs[:4] == [4000, 5000, 4643, 4286] and highs[13] == 715
    assert set(highs[14:188]) == {358}
    assert highs[188:191] == [357, 714, 1071] and highs[199] == 4285
    assert {low for _, _, low in plan.x_segments} == {4000}
    assert plan.x_seconds == pytest.approx(0.931, abs=0.001)
    assert plan.loops[1] == 14 and plan.y_seconds == pytest.approx(0.082, abs=0.001)
    assert plan.delays_after == state.delays == (4642, 358)
    assert (state.values[19], state.values[20]) == (14, 14)
    assert state.move(5000, 5000).seconds == pytest.approx(0.279, abs=0.001)


def test_a_ramp_longer_than_half_the_move_is_a_triangle() -> None:
    state = _state(p21=999999, p23=1)
    assert state.ramp == (2399, 0)
    plan = state.move(1000, 0)
    highs = [high for n, high, _ in plan.x_segments for _ in range(n)]
    assert plan.ramp_steps == (20, 0)
    assert highs[1] == 5000 and highs[20] == 4961 and highs[21] == 4961  # no steady part
    assert highs[22] == 4960 and highs[39] == 4995 and plan.delays_after[0] == 4997


def test_interpolation_is_arduino_map_truncating_toward_zero() -> None:
    assert interpolate(1, 0, 14, 5000, 0) == 4643
    assert interpolate(187, 186, 200, 0, 5000) == 357
    assert interpolate(3, 0, 0, 7, 9) == 7


def test_division_by_zero_never_stops_the_firmware() -> None:
    state = _state(p23=0)
    assert (state.values[25], state.ramp[0]) == (0, 0)
    assert state.move(1000, 0).seconds == pytest.approx(40 * 0.008)
    for key in ("p05", "p07", "p21"):
        assert _state(**{key: 0}).values[17] == 2500  # 11: x/0 = inf, converted to 0
    assert _state(p13=1).ramp[0] == 0  # 17 × 2 = 0: A = inf, 0 on the host
