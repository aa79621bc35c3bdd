"""DXF drawings written by ezdxf itself, read into toolpaths: geometry, layers, units, refusals."""

from __future__ import annotations

import math
from pathlib import Path

import ezdxf
import numpy as np
import pytest
from ezdxf.document import Drawing

from drivers.toolpath.dxf import read_dxf
from drivers.toolpath.model import ArcTo, Line, Point, Toolpath, ToolpathError, arc_sweep


def _drawing(units: int = 4) -> Drawing:
    doc = ezdxf.new()
    doc.header["$INSUNITS"] = units
    return doc


def _save(doc: Drawing, tmp_path: Path, name: str = "d.dxf") -> Path:
    path = tmp_path / name
    doc.saveas(path)
    return path


def _starts(toolpath: Toolpath) -> list[Point]:
    """Where each step starts."""
    starts, here = [], toolpath.start
    for step in toolpath.steps:
        starts.append(here)
        assert isinstance(step, (Line, ArcTo))
        here = step.end
    return starts


def _close(a: Point, b: Point, tol: float = 1e-9) -> bool:
    return math.dist(a, b) <= tol


def _distance_to_polyline(points: np.ndarray, polyline: np.ndarray) -> np.ndarray:
    """Each point's distance to the nearest segment of `polyline` (both N x 2)."""
    a, b = polyline[:-1], polyline[1:]
    ab = b - a
    lengths = np.maximum((ab**2).sum(axis=1), 1e-300)
    ap = points[:, None, :] - a[None, :, :]
    t = np.clip((ap * ab[None]).sum(axis=2) / lengths[None], 0.0, 1.0)
    nearest = a[None] + t[..., None] * ab[None]
    return np.sqrt(((points[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1)


def test_lines_arcs_and_circles_with_a_travel_move_between_disjoint_paths(tmp_path) -> None:
    doc = _drawing()
    msp = doc.modelspace()
    msp.add_line((0, 0), (10, 0), dxfattribs={"layer": "CUT"})
    msp.add_arc((10, 5), 5, -90, 90, dxfattribs={"layer": "CUT"})  # joins the line's end
    msp.add_circle((50, 50, 2), 5, dxfattribs={"layer": "CUT"})
    toolpath = read_dxf(_save(doc, tmp_path))

    assert toolpath.name == "d.dxf"
    assert toolpath.start == (0.0, 0.0, 0.0)
    line, arc, travel, circle = toolpath.steps
    assert line == Line((10.0, 0.0, 0.0), None, 0)
    assert isinstance(arc, ArcTo) and arc.ccw and arc.speed is None and arc.source == 1
    assert _close(arc.end, (10.0, 10.0, 0.0)) and _close((*arc.centre, 0.0), (10.0, 5.0, 0.0))
    assert arc_sweep(line.end, arc) == pytest.approx(math.pi)
    assert travel == Line((55.0, 50.0, 2.0), None, 2, rapid=True)  # its source: the circle
    assert circle == ArcTo((55.0, 50.0, 2.0), (50.0, 50.0), True, None, 2)
    assert arc_sweep(travel.end, circle) == pytest.approx(math.tau)
    assert [(s.kind, s.number, s.text) for s in toolpath.sources] == [
        ("entity", 1, "LINE on layer CUT"),
        ("entity", 2, "ARC on layer CUT"),
        ("entity", 3, "CIRCLE on layer CUT"),
    ]
    assert toolpath.notices == []
    assert toolpath.layers == ("CUT",)


def test_an_inch_drawing_is_scaled_to_mm_z_included(tmp_path) -> None:
    doc = _drawing(units=1)
    msp = doc.modelspace()
    msp.add_line((1, 2, 0.5), (3, 4, 0.5))
    msp.add_arc((0, 0), 1, 0, 90)
    toolpath = read_dxf(_save(doc, tmp_path))

    travel, line, travel_2, arc = toolpath.steps
    assert travel == Line((25.4, 50.8, 12.7), None, 0, rapid=True)
    assert line.end == pytest.approx((76.2, 101.6, 12.7))
    assert travel_2.end == pytest.approx((25.4, 0.0, 0.0))
    assert isinstance(arc, ArcTo) and arc.centre == pytest.approx((0.0, 0.0))
    assert arc.end == pytest.approx((0.0, 25.4, 0.0), abs=1e-12)
    assert toolpath.notices == []


def test_a_drawing_in_metres_and_one_without_units(tmp_path) -> None:
    doc = _drawing(units=6)
    doc.modelspace().add_line((0, 0), (0.25, 0))
    assert read_dxf(_save(doc, tmp_path)).steps[-1].end == pytest.approx((250.0, 0.0, 0.0))  # type: ignore[union-attr]

    doc = _drawing(units=0)
    doc.modelspace().add_line((0, 0), (7, 0))
    toolpath = read_dxf(_save(doc, tmp_path, "plain.dxf"))
    assert toolpath.steps == [Line((7.0, 0.0, 0.0), None, 0)]
    assert toolpath.notices == ["plain.dxf: no units given ($INSUNITS 0), taken as mm"]


def test_polyline_bulges_become_arcs_and_the_closed_flag_closes_it(tmp_path) -> None:
    doc = _drawing()
    quarter_cw = -math.tan(math.radians(90) / 4)
    doc.modelspace().add_lwpolyline(
        [(0, 0, 0), (10, 0, 1), (10, 10, 0), (0, 10, quarter_cw)], format="xyb", close=True
    )
    toolpath = read_dxf(_save(doc, tmp_path))

    first, semicircle, third, quarter = toolpath.steps
    starts = _starts(toolpath)
    assert first == Line((10.0, 0.0, 0.0), None, 0)
    # bulge 1 from (10, 0) to (10, 10): a half circle counter-clockwise round (10, 5)
    assert isinstance(semicircle, ArcTo) and semicircle.ccw
    assert semicircle.centre == pytest.approx((10.0, 5.0))
    assert semicircle.end == (10.0, 10.0, 0.0)
    assert arc_sweep(starts[1], semicircle) == pytest.approx(math.pi)
    assert third == Line((0.0, 10.0, 0.0), None, 0)
    # bulge -tan(22.5°) from (0, 10) back to the start: a quarter circle clockwise round (-5, 5)
    assert isinstance(quarter, ArcTo) and not quarter.ccw
    assert quarter.centre == pytest.approx((-5.0, 5.0))
    assert quarter.end == (0.0, 0.0, 0.0)
    assert arc_sweep(starts[3], quarter) == pytest.approx(-math.pi / 2)
    assert toolpath.sources[0].text == "LWPOLYLINE on layer 0"


def test_a_2d_polyline_with_a_bulge_and_an_open_one(tmp_path) -> None:
    doc = _drawing()
    msp = doc.modelspace()
    polyline = msp.add_polyline2d([(0, 0), (4, 0)])
    polyline.vertices[0].dxf.bulge = -1.0  # a half circle clockwise: below the chord
    toolpath = read_dxf(_save(doc, tmp_path))

    (arc,) = toolpath.steps
    assert isinstance(arc, ArcTo) and not arc.ccw
    assert arc.centre == pytest.approx((2.0, 0.0)) and arc.end == (4.0, 0.0, 0.0)
    assert arc_sweep((0.0, 0.0, 0.0), arc) == pytest.approx(-math.pi)


def test_spline_and_ellipse_are_flattened_within_the_tolerance(tmp_path) -> None:
    doc = _drawing()
    msp = doc.modelspace()
    spline = msp.add_spline_control_frame([(0, 0), (10, 20), (30, -10), (50, 15), (60, 0)])
    ellipse = msp.add_ellipse((100, 0), major_axis=(20, 10), ratio=0.4, start_param=0.3)
    path = _save(doc, tmp_path)
    tolerance = 0.05
    toolpath = read_dxf(path, tolerance=tolerance)

    assert all(isinstance(step, Line) for step in toolpath.steps)
    # the spline starts where the toolpath does; a travel move to the ellipse
    assert [step.rapid for step in toolpath.steps].count(True) == 1  # type: ignore[union-attr]
    starts = _starts(toolpath)
    for number, entity in ((1, spline), (2, ellipse)):
        mine = [
            index
            for index, step in enumerate(toolpath.steps)
            if toolpath.sources[step.source].number == number and not step.rapid  # type: ignore[union-attr]
        ]
        ours = np.array([starts[mine[0]][:2]] + [toolpath.steps[i].end[:2] for i in mine])  # type: ignore[union-attr]
        reference = np.array([(v.x, v.y) for v in entity.flattening(0.0005)])
        assert ours[0] == pytest.approx(reference[0]) and ours[-1] == pytest.approx(reference[-1])
        # every vertex on the curve, every point of the curve within the tolerance of the chords
        assert _distance_to_polyline(ours, reference).max() < 0.001
        assert _distance_to_polyline(reference, ours).max() <= tolerance + 0.001
        assert len(ours) < len(reference)
    assert toolpath.sources[0].text == "SPLINE on layer 0"
    assert toolpath.sources[1].text == "ELLIPSE on layer 0"


def test_an_arc_not_in_the_xy_plane_is_flattened_in_world_coordinates(tmp_path) -> None:
    doc = _drawing()
    arc = doc.modelspace().add_arc((10, 0), 5, 0, 90, dxfattribs={"extrusion": (0, 0, -1)})
    toolpath = read_dxf(_save(doc, tmp_path), tolerance=0.01)

    assert all(isinstance(step, Line) for step in toolpath.steps)
    travel, *chords = toolpath.steps
    # seen from below: the OCS centre (10, 0) is (-10, 0) in WCS, 0° points to -X
    assert tuple(arc.start_point) == pytest.approx((-15.0, 0.0, 0.0))
    assert tuple(arc.end_point) == pytest.approx((-10.0, 5.0, 0.0))
    assert travel.end == pytest.approx((-15.0, 0.0, 0.0))  # type: ignore[union-attr]
    assert chords[-1].end == pytest.approx((-10.0, 5.0, 0.0))  # type: ignore[union-attr]
    assert len(chords) > 4
    for step in chords:
        assert math.dist(step.end[:2], (-10.0, 0.0)) == pytest.approx(5.0)  # type: ignore[union-attr]


def test_layers_are_listed_and_chosen(tmp_path) -> None:
    doc = _drawing()
    msp = doc.modelspace()
    msp.add_line((0, 0), (1, 0), dxfattribs={"layer": "MARK"})
    msp.add_line((5, 5), (6, 5), dxfattribs={"layer": "CUT"})
    msp.add_text("note", dxfattribs={"layer": "NOTES"})
    path = _save(doc, tmp_path)

    everything = read_dxf(path)
    assert everything.layers == ("CUT", "MARK")  # NOTES has nothing to run
    assert [s.number for s in everything.sources] == [1, 2]

    cut = read_dxf(path, layers=["CUT"])
    assert cut.layers == ("CUT", "MARK")
    assert [s.text for s in cut.sources] == ["LINE on layer CUT"]
    assert cut.steps == [
        Line((5.0, 5.0, 0.0), None, 0, rapid=True),
        Line((6.0, 5.0, 0.0), None, 0),
    ]
    assert cut.notices == []  # the text is on a layer not chosen


def test_an_unknown_layer_is_refused_naming_the_drawings_layers(tmp_path) -> None:
    doc = _drawing()
    doc.modelspace().add_line((0, 0), (1, 0), dxfattribs={"layer": "CUT"})
    doc.modelspace().add_circle((0, 0), 1, dxfattribs={"layer": "ENGRAVE"})
    with pytest.raises(ToolpathError) as refused:
        read_dxf(_save(doc, tmp_path), layers=["CUT", "LASER"])
    assert str(refused.value) == (
        "d.dxf: no layer LASER with lines, arcs or curves; the drawing's layers: CUT, ENGRAVE"
    )


def test_what_is_not_a_path_is_skipped_with_one_notice(tmp_path) -> None:
    doc = _drawing()
    msp = doc.modelspace()
    msp.add_text("a")
    msp.add_line((0, 0), (1, 0))
    msp.add_text("b")
    msp.add_mtext("c")
    msp.add_point((3, 3))
    toolpath = read_dxf(_save(doc, tmp_path))

    assert toolpath.steps == [Line((1.0, 0.0, 0.0), None, 0)]
    assert toolpath.sources[0].number == 2
    assert toolpath.notices == ["d.dxf: skipped what is not a path: 1 MTEXT, 1 POINT, 2 TEXT"]


def test_a_block_reference_is_exploded_onto_the_inserts_layer(tmp_path) -> None:
    doc = _drawing()
    block = doc.blocks.new("PART")
    block.add_line((0, 0), (1, 0))  # layer 0: takes the INSERT's layer
    block.add_circle((0, 0), 1, dxfattribs={"layer": "HOLES"})
    doc.modelspace().add_blockref("PART", (100, 0), dxfattribs={"layer": "PARTS", "xscale": 2})
    toolpath = read_dxf(_save(doc, tmp_path))

    assert toolpath.layers == ("HOLES", "PARTS")
    assert [s.text for s in toolpath.sources] == [
        "LINE in block PART on layer PARTS",
        "ELLIPSE in block PART on layer HOLES",  # a circle scaled 2 in X only
    ]
    assert {s.number for s in toolpath.sources} == {1}
    assert toolpath.steps[:2] == [
        Line((100.0, 0.0, 0.0), None, 0, rapid=True),
        Line((102.0, 0.0, 0.0), None, 0),
    ]
    # the ellipse flattened
    assert all(isinstance(step, Line) for step in toolpath.steps)
    assert max(step.end[0] for step in toolpath.steps) == pytest.approx(102.0)  # type: ignore[union-attr]


def test_binary_dxf_is_read_as_text_dxf_is(tmp_path) -> None:
    doc = _drawing(units=5)
    doc.modelspace().add_line((1, 1), (2, 1))
    path = tmp_path / "b.dxf"
    doc.saveas(path, fmt="bin")
    assert path.read_bytes().startswith(b"AutoCAD Binary DXF")
    assert read_dxf(path).steps == [
        Line((10.0, 10.0, 0.0), None, 0, rapid=True),
        Line((20.0, 10.0, 0.0), None, 0),
    ]
    path.write_bytes(path.read_bytes()[:-40])
    with pytest.raises(ToolpathError, match=r"^b\.dxf: binary DXF cut short"):
        read_dxf(path)


def test_corrupt_or_truncated_dxf_is_refused_whole_naming_the_file(tmp_path) -> None:
    doc = _drawing()
    for n in range(20):
        doc.modelspace().add_line((n, 0), (n, 1))
    whole = _save(doc, tmp_path).read_bytes()

    cut = tmp_path / "cut.dxf"
    cut.write_bytes(whole[: len(whole) * 3 // 4])  # the entities half read: refused, not run
    with pytest.raises(ToolpathError, match=r"^cut\.dxf: not a DXF drawing the panel reads: "):
        read_dxf(cut)

    junk = tmp_path / "junk.dxf"
    junk.write_text("this is no drawing\nat all\n")
    with pytest.raises(ToolpathError, match=r"(?s)^junk\.dxf: not a DXF drawing .*line 1"):
        read_dxf(junk)

    with pytest.raises(ToolpathError, match="not a regular file"):
        read_dxf(tmp_path)


def test_a_drawing_with_nothing_to_run_is_refused(tmp_path) -> None:
    doc = _drawing()
    doc.modelspace().add_text("only words")
    with pytest.raises(ToolpathError) as refused:
        read_dxf(_save(doc, tmp_path))
    assert str(refused.value) == "d.dxf: no lines, arcs or curves on the chosen layers"
