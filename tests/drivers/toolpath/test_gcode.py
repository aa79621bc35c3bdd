"""G-code read into the program model: every form understood, and every refusal naming its line."""

from __future__ import annotations

import math
import time
from pathlib import Path

import pytest

from drivers.toolpath import gcode
from drivers.toolpath.gcode import parse_gcode, read_gcode
from drivers.toolpath.model import ArcTo, Dwell, Line, Source, Toolpath, ToolpathError, arc_sweep

pytestmark = pytest.mark.timeout(60)


def _starts(toolpath: Toolpath) -> list[tuple[float, float, float]]:
    """Where each step starts."""
    starts = []
    here = toolpath.start
    for step in toolpath.steps:
        starts.append(here)
        if not isinstance(step, Dwell):
            here = step.end
    return starts


def _only_arc(text: str) -> tuple[tuple[float, float, float], ArcTo]:
    """The one arc of a program, with where it starts."""
    toolpath = parse_gcode(text)
    arcs = [
        (s, a)
        for s, a in zip(_starts(toolpath), toolpath.steps, strict=True)
        if isinstance(a, ArcTo)
    ]
    assert len(arcs) == 1
    return arcs[0]


def _refusal(text: str, name: str = "job.nc") -> str:
    with pytest.raises(ToolpathError) as refused:
        parse_gcode(text, name)
    return str(refused.value)


def test_every_line_is_a_source_and_each_step_names_its_line() -> None:
    text = "%\n(a square)\nG21 G90\n\nG0 X0 Y0 ; start\nG1 X10 F600\nY10\r\nG4 P0.5\n%"
    toolpath = parse_gcode(text, "square.nc")
    assert toolpath.name == "square.nc"
    assert toolpath.start == (0.0, 0.0, 0.0)
    assert toolpath.sources == [
        Source("line", number, line)
        for number, line in enumerate(
            [
                "%",
                "(a square)",
                "G21 G90",
                "",
                "G0 X0 Y0 ; start",
                "G1 X10 F600",
                "Y10",
                "G4 P0.5",
                "%",
            ],
            start=1,
        )
    ]
    assert toolpath.steps == [
        Line((0.0, 0.0, 0.0), None, 4, rapid=True),
        Line((10.0, 0.0, 0.0), 10.0, 5),
        Line((10.0, 10.0, 0.0), 10.0, 6),
        Dwell(0.5, 7),
    ]
    assert toolpath.where(toolpath.steps[2].source) == "square.nc line 7"
    assert toolpath.notices == []


def test_rapids_have_no_speed_and_the_feed_rate_is_modal_in_mm_per_second() -> None:
    toolpath = parse_gcode("G1 X1 F300\nG0 X2 Y3 Z4\nG1 X5\nG1 X6 F1200\nX7")
    assert toolpath.steps == [
        Line((1.0, 0.0, 0.0), 5.0, 0),
        Line((2.0, 3.0, 4.0), None, 1, rapid=True),
        Line((5.0, 3.0, 4.0), 5.0, 2),
        Line((6.0, 3.0, 4.0), 20.0, 3),
        Line((7.0, 3.0, 4.0), 20.0, 4),
    ]


def test_a_line_of_axis_words_repeats_the_last_motion_code() -> None:
    toolpath = parse_gcode("G0 X1\nY2\nG1 X3 F60\nZ-1\nG2 X5 Y2 I1 J0\nX7 I1")
    kinds = [(type(s).__name__, getattr(s, "rapid", None)) for s in toolpath.steps]
    assert kinds == [
        ("Line", True),
        ("Line", True),
        ("Line", False),
        ("Line", False),
        ("ArcTo", None),
        ("ArcTo", None),
    ]
    assert toolpath.steps[-1] == ArcTo((7.0, 2.0, -1.0), (6.0, 2.0), False, 1.0, 5)


def test_g80_cancels_the_motion_mode() -> None:
    assert _refusal("G1 X1 F60\nG80\nX2") == (
        "job.nc line 3: X2 with no motion mode (G0, G1, G2 or G3) set"
    )


def test_clockwise_and_counter_clockwise_arcs_with_i_and_j() -> None:
    start, arc = _only_arc("G0 X0 Y0\nG2 X5 Y5 I5 J0 F600")
    assert arc == ArcTo((5.0, 5.0, 0.0), (5.0, 0.0), False, 10.0, 1)
    assert arc_sweep(start, arc) == pytest.approx(-math.pi / 2)
    start, arc = _only_arc("G0 X0 Y0\nG3 X5 Y5 I5 J0 F600")
    assert arc == ArcTo((5.0, 5.0, 0.0), (5.0, 0.0), True, 10.0, 1)
    assert arc_sweep(start, arc) == pytest.approx(3 * math.pi / 2)
    # only J: I is 0
    start, arc = _only_arc("G0 X1 Y1\nG3 X1 Y5 J2 F600")
    assert arc.centre == (1.0, 3.0)
    assert arc_sweep(start, arc) == pytest.approx(math.pi)


@pytest.mark.parametrize(
    ("code", "radius", "centre", "sweep"),
    [
        ("G2", "10", (10.0, 0.0), -math.pi / 2),
        ("G2", "-10", (0.0, 10.0), -3 * math.pi / 2),
        ("G3", "10", (0.0, 10.0), math.pi / 2),
        ("G3", "-10", (10.0, 0.0), 3 * math.pi / 2),
    ],
)
def test_r_arcs_positive_the_short_one_negative_the_long_one(
    code: str, radius: str, centre: tuple[float, float], sweep: float
) -> None:
    start, arc = _only_arc(f"G1 X0 Y0 F60\n{code} X10 Y10 R{radius}")
    assert arc.centre == pytest.approx(centre)
    assert arc.ccw == (code == "G3")
    assert arc_sweep(start, arc) == pytest.approx(sweep)
    assert math.dist(start[:2], arc.centre) == pytest.approx(10.0)


def test_an_r_a_hair_short_of_half_the_chord_is_a_half_circle() -> None:
    start, arc = _only_arc("G1 X0 Y0 F60\nG2 X10.004 Y0 R5")
    assert arc.centre == pytest.approx((5.002, 0.0))
    assert arc_sweep(start, arc) == pytest.approx(-math.pi)


def test_a_full_circle_with_i_and_j() -> None:
    start, arc = _only_arc("G0 X10 Y0\nG2 X10 Y0 I-10 J0 F600")
    assert arc == ArcTo((10.0, 0.0, 0.0), (0.0, 0.0), False, 10.0, 1)
    assert arc_sweep(start, arc) == pytest.approx(-math.tau)
    start, arc = _only_arc("G0 X10 Y0\nG3 I-10 F600")  # no axis words: it ends where it starts
    assert arc.end == (10.0, 0.0, 0.0)
    assert arc_sweep(start, arc) == pytest.approx(math.tau)


def test_incremental_arcs_and_absolute_centres() -> None:
    start, arc = _only_arc("G0 X10 Y10\nG91\nG2 X10 Y0 I5 J0 F600")  # G91: the end incremental
    assert start == (10.0, 10.0, 0.0)
    assert arc.end == (20.0, 10.0, 0.0) and arc.centre == (15.0, 10.0)
    assert arc_sweep(start, arc) == pytest.approx(-math.pi)
    start, arc = _only_arc("G0 X10 Y10\nG90.1\nG3 X20 Y10 I15 J10 F600")  # G90.1: I/J absolute
    assert arc.centre == (15.0, 10.0)
    assert arc_sweep(start, arc) == pytest.approx(math.pi)
    _, arc = _only_arc("G0 X10 Y10\nG90.1\nG91.1\nG3 X20 Y10 I5 J0 F600")  # back to incremental
    assert arc.centre == (15.0, 10.0)


def test_z_on_an_arc_makes_a_helix_and_k_is_ignored_in_g17() -> None:
    start, arc = _only_arc("G17 G0 X5 Y0 Z0\nG3 X5 Y0 Z-2 I-5 J0 K1 F600")
    assert arc.end == (5.0, 0.0, -2.0)
    assert arc_sweep(start, arc) == pytest.approx(math.tau)


def test_inches_scale_axis_words_centres_radii_and_feed_rates() -> None:
    toolpath = parse_gcode(
        "G20\nG1 X1 Y2 F10\nG2 X2 Y2 I0.5 J0\nG3 X3 Y2 R0.5\nG21\nG1 X100 F600\nG20\nX5"
    )
    first, arc, arc_r, mm, inches = toolpath.steps
    assert first == Line((25.4, 50.8, 0.0), pytest.approx(10 * 25.4 / 60), 1)
    assert isinstance(arc, ArcTo) and isinstance(arc_r, ArcTo)
    assert arc.end == pytest.approx((50.8, 50.8, 0.0))
    assert arc.centre == pytest.approx((38.1, 50.8))
    assert arc.speed == pytest.approx(10 * 25.4 / 60)
    assert arc_r.centre == pytest.approx((63.5, 50.8))
    assert mm == Line((100.0, 50.8, 0.0), 10.0, 5)
    # the feed rate is a number of the units in force when moving, as in LinuxCNC
    assert inches == Line(pytest.approx((127.0, 50.8, 0.0)), pytest.approx(600 * 25.4 / 60), 7)


def test_absolute_and_incremental_distances() -> None:
    toolpath = parse_gcode("G90 G1 X1 Y1 Z1 F60\nG91\nX1 Y-2\nZ0.5\nG90\nX0")
    assert [step.end for step in toolpath.steps if isinstance(step, Line)] == [
        (1.0, 1.0, 1.0),
        (2.0, -1.0, 1.0),
        (2.0, -1.0, 1.5),
        (0.0, -1.0, 1.5),
    ]


def test_g4_dwells_p_seconds() -> None:
    toolpath = parse_gcode("G4 P1.5\nG1 X1 F60\nG4 P0")
    assert toolpath.steps == [Dwell(1.5, 0), Line((1.0, 0.0, 0.0), 1.0, 1), Dwell(0.0, 2)]


def test_comments_percent_lines_line_numbers_checksums_and_the_ways_to_write_words() -> None:
    text = (
        "%\n"
        "(header (an opening inside a comment is fine)\n"
        "N10 G21 (mm) G90 ; absolute\n"
        "n20 g1x10y-5.5f300*71\n"
        "N30 G01 X 10. Y .5 Z+3 (spaces between letter and number)\n"
        "N40 G1 X-0.5 ; (a parenthesis in a ; comment\n"
        "\t G00   Z5\n"
        "%\n"
    )
    toolpath = parse_gcode(text)
    assert toolpath.steps == [
        Line((10.0, -5.5, 0.0), 5.0, 3),
        Line((10.0, 0.5, 3.0), 5.0, 4),
        Line((-0.5, 0.5, 3.0), 5.0, 5),
        Line((-0.5, 0.5, 5.0), None, 6, rapid=True),
    ]
    assert len(toolpath.sources) == 8


def test_cam_preamble_codes_change_nothing() -> None:
    toolpath = parse_gcode("G17 G21 G40 G49 G80 G90 G94\nG54\nG61\nG64 P0.01 Q0.01\nG0 X1")
    assert toolpath.steps == [Line((1.0, 0.0, 0.0), None, 4, rapid=True)]


def test_m_t_and_s_words_are_skipped_with_one_notice() -> None:
    toolpath = parse_gcode("T1 M6\nS12000 M3\nG0 X1\nG1 X2 F60 S12000\nM5\nM30")
    assert [step.source for step in toolpath.steps] == [2, 3]
    assert toolpath.notices == [
        "program: skipped what the panel does not do: T1, M6, S12000, M3, M5, M30 (on 5 of 6 lines)"
    ]
    assert toolpath.notices[0].template.startswith("{name}: skipped")


def test_the_skipped_notice_names_ten_words_at_most() -> None:
    text = "G0 X0\n" + "\n".join(f"M{n}" for n in range(100, 200)) + "\nM03\nM3"
    (notice,) = parse_gcode(text).notices
    assert notice == (
        "program: skipped what the panel does not do: "
        + ", ".join(f"M{n}" for n in range(100, 110))
        + ", … (on 102 of 103 lines)"
    )
    (notice,) = parse_gcode("G0 X0\nM03\nM3\nm3.0").notices
    assert notice == "program: skipped what the panel does not do: M3 (on 3 of 4 lines)"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("G0 X0\nG1 X1", "job.nc line 2: no feed rate (F) set before this G1"),
        ("G0 X0\nG2 X2 I1", "job.nc line 2: no feed rate (F) set before this G2"),
        ("X1", "job.nc line 1: X1 with no motion mode (G0, G1, G2 or G3) set"),
        ("G28 G91 Z0", "job.nc line 1: G28 is not understood"),
        ("G0 X0\nG41 D1", "job.nc line 2: G41 is not understood"),
        ("G43 H1", "job.nc line 1: G43 is not understood"),
        ("G55", "job.nc line 1: G55 is not understood"),
        ("G93", "job.nc line 1: G93 is not understood"),
        ("G38.2 Z-10 F100", "job.nc line 1: G38.2 is not understood"),
        ("G81 X1 Y1 Z-1 R1", "job.nc line 1: G81 is not understood"),
        ("G0 X0 A5", "job.nc line 1: A5 is not understood"),
        ("G0 X0\nL2", "job.nc line 2: L2 is not understood"),
        ("G1 X1 E0.5 F60", "job.nc line 1: E0.5 is not understood"),
        ("G0 X1 G1 Y1", "job.nc line 1: G0 and G1 cannot be on one line"),
        ("G90 G91", "job.nc line 1: G90 and G91 cannot be on one line"),
        ("G0 X1 X2", "job.nc line 1: X1 and X2 cannot be on one line"),
        ("G2 X1 Y1 R1 I1 F60", "job.nc line 1: R1 and I1 cannot be on one line"),
        ("G0 X", "job.nc line 1: 'X' is not a G-code word (a letter and a number)"),
        ("G0 X1.2.3", "job.nc line 1: 'X1.2.3' is not a G-code word (a letter and a number)"),
        ("G0 X1_0", "job.nc line 1: 'X1_0' is not a G-code word (a letter and a number)"),
        ("G0 X#1", "job.nc line 1: 'X#1' is not a G-code word (a letter and a number)"),
        ("5 G0 X1", "job.nc line 1: '5' is not a G-code word (a letter and a number)"),
        ("G0 X1)", "job.nc line 1: 'X1)' is not a G-code word (a letter and a number)"),
        ("G0 X\u0661", "job.nc line 1: 'X\u0661' is not a G-code word (a letter and a number)"),
        ("G0 X1*7a", "job.nc line 1: 'X1*7' is not a G-code word (a letter and a number)"),
        ("G0 X1 (no end", "job.nc line 1: a comment opened with ( is not closed"),
        (
            "G0 X" + "9" * 40,
            "job.nc line 1: X '" + "9" * 40 + "' is not a finite float32 number",
        ),
        ("G0 X" + "9" * 400, "job.nc line 1: X '" + "9" * 400 + "' is not a finite float32 number"),
        ("G1 X1 F0", "job.nc line 1: F0: the feed rate must be above 0"),
        ("G1 X1 F-100", "job.nc line 1: F-100: the feed rate must be above 0"),
        ("G4", "job.nc line 1: G4 needs P, the seconds to dwell"),
        ("G4 P-1", "job.nc line 1: P-1: a dwell cannot be negative"),
        ("G0 X1 P2", "job.nc line 1: P2 is not used by anything on the line"),
        ("G1 X1 F60 I2", "job.nc line 1: I2 is not used by anything on the line"),
        ("G0 X1 R2", "job.nc line 1: R2 is not used by anything on the line"),
        ("G4 P1 Q2", "job.nc line 1: Q2 is not used by anything on the line"),
        ("G2 X1 Y1 F60", "job.nc line 1: G2 needs I and J, or R"),
        ("G1 F60\nG2 X0 Y0 R5", "job.nc line 2: G2 with R: a full circle needs I/J"),
        (
            "G1 F60\nG3 X10 Y0 R4",
            "job.nc line 2: G3: R 4 mm is less than half the way to the end point (5 mm)",
        ),
        (
            "G1 F60\nG2 X10 Y0 I4 J0",
            "job.nc line 2: G2: the centre is 4 mm from the start point and 6 mm from the end "
            "point, not on one circle",
        ),
        ("G1 F60\nG2 X0 Y0 I0 J0", "job.nc line 2: G2: an arc of radius 0"),
        (
            "G18\nG1 X1 F60\nG2 X2 Z1 I1",
            "job.nc line 3: G2: arcs in the XZ plane (G18) are not supported: only G17 (XY)",
        ),
        (
            "G19 G1 Y1 F60\nG3 Y2 Z1 J1",
            "job.nc line 2: G3: arcs in the YZ plane (G19) are not supported: only G17 (XY)",
        ),
        ("(nothing)\n%\nM3", "job.nc: no moves and no dwells"),
    ],
)
def test_refusals_name_the_line_and_the_word(text: str, message: str) -> None:
    assert _refusal(text) == message


def test_a_refusal_is_a_message_with_its_template_and_the_line() -> None:
    with pytest.raises(ToolpathError) as refused:
        parse_gcode("G0 X0\nG0 X1\nG28", "job.nc")
    said = refused.value.args[0]
    assert said.template == "{where}: {word} is not understood"
    assert said.values["where"].template == "{name} line {number}"
    assert dict(said.values["where"].values) == {"name": "job.nc", "number": 3}


def test_arcs_within_linuxcnc_s_tolerance_are_taken() -> None:
    # the centre 0.1 % farther from the end (0.01 mm of a 10 mm radius: over 0.005 mm)
    assert "not on one circle" in _refusal("G1 X0 Y0 F60\nG2 X20.011 Y0 I10")
    _, arc = _only_arc("G1 X0 Y0 F60\nG2 X20.0049 Y0 I10")
    assert arc.centre == (10.0, 0.0)
    # 0.09 mm is over 0.005 mm but under 0.1 % of a 100 mm radius: taken
    _, arc = _only_arc("G1 X0 Y0 F60\nG2 X200.09 Y0 I100")
    assert arc.centre == (100.0, 0.0)
    # but never more than 0.5 mm, though under 0.1 % of a 1000 mm radius
    assert "not on one circle" in _refusal("G1 X0 Y0 F60\nG2 X2000.6 Y0 I1000")


def test_read_gcode_names_the_program_after_its_file(tmp_path: Path) -> None:
    file = tmp_path / "part.ngc"
    file.write_bytes(b"\xef\xbb\xbfG21\r\nG0 X1 Y2\r\nG1 X3 F60\r\n")
    toolpath = read_gcode(file)
    assert toolpath.name == "part.ngc"
    assert toolpath.sources[0] == Source("line", 1, "G21")
    assert toolpath.steps == [
        Line((1.0, 2.0, 0.0), None, 1, rapid=True),
        Line((3.0, 2.0, 0.0), 1.0, 2),
    ]
    file.write_text("G0 X0\nG28\n", encoding="utf-8")
    with pytest.raises(ToolpathError, match=r"^part\.ngc line 2: G28 is not understood$"):
        read_gcode(file)


def test_read_gcode_refuses_a_binary_or_too_large_file_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    binary = tmp_path / "binary.nc"
    binary.write_bytes(b"G0 X1\nG1 X2\x00 F60\n")
    with pytest.raises(ToolpathError, match=r"binary\.nc: a NUL byte \(line 2\), not a program"):
        read_gcode(binary)
    latin = tmp_path / "latin.nc"
    latin.write_bytes(b"(caf\xe9)\nG0 X1\n")
    with pytest.raises(ToolpathError, match=r"latin\.nc: not UTF-8 text \(line 1\)"):
        read_gcode(latin)
    large = tmp_path / "large.nc"
    large.write_text("G0 X1\n" * 200, encoding="utf-8")
    monkeypatch.setattr(gcode, "PROGRAM_MAX_BYTES", 1024)
    with pytest.raises(
        ToolpathError, match=r"large\.nc: larger than 1 KiB .* too large for a program"
    ):
        read_gcode(large)
    with pytest.raises(ToolpathError, match=r"cannot read the program .*missing\.nc"):
        read_gcode(tmp_path / "missing.nc")


def test_too_many_lines_are_refused_before_parsing(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(gcode, "MAX_LINES", 3)
    refused = "job.nc: more than 3 lines, too many for a program"
    assert _refusal("G0 X1\nG0 X2\nG0 X3\nG0 X4") == refused
    assert _refusal("G0 X1\r\n\r\n\r\nG0 X4") == refused  # counted after the cut
    assert _refusal("\n" * 7) == refused  # counted before it
    assert len(parse_gcode("G0 X1\r\nG0 X2\r\nG0 X3\r\n").steps) == 3


def test_a_hundred_thousand_lines_parse_within_the_time_budget() -> None:
    lines = ["G21 G90 G17", "G0 X0 Y0 Z1", "G1 Z0 F1200"]
    for n in range(49_999):
        lines.append(f"G2 X{2 * n + 2:.4f} Y0 I1.0000 J0")
        lines.append(f"G1 X{2 * n + 2:.4f} Y0 Z{-(n % 5) * 0.1:.4f}")
    text = "\n".join(lines)
    assert len(lines) == 100_001
    # The parser's own CPU time: a wall-clock budget failed beside other test workers.
    began = time.process_time()
    toolpath = parse_gcode(text)
    took = time.process_time() - began
    print(f"100,001 lines of G-code parsed in {took:.3f} s of CPU")
    assert len(toolpath.steps) == 100_000 and len(toolpath.sources) == 100_001
    last = toolpath.steps[-1]
    assert isinstance(last, Line) and last.end == pytest.approx((99_998.0, 0.0, -0.3))
    assert took < 1.5
