"""SVG drawings written by hand, with transforms and viewBoxes, read into toolpaths in mm."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from drivers.toolpath.model import ArcTo, Line, Point, Toolpath, ToolpathError, arc_sweep
from drivers.toolpath.svg import read_svg

PX = 25.4 / 96  # mm


def _svg(
    tmp_path: Path, body: str, root: str = 'viewBox="0 0 100 100"', name: str = "d.svg"
) -> Path:
    path = tmp_path / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" {root}>\n{body}\n</svg>\n')
    return path


def _starts(toolpath: Toolpath) -> list[Point]:
    starts, here = [], toolpath.start
    for step in toolpath.steps:
        starts.append(here)
        assert isinstance(step, (Line, ArcTo))
        here = step.end
    return starts


def _vertices(toolpath: Toolpath) -> np.ndarray:
    """The drawn polyline: the first drawing step's start, then every end (no travel moves)."""
    starts = _starts(toolpath)
    drawn = [i for i, step in enumerate(toolpath.steps) if not step.rapid]  # type: ignore[union-attr]
    assert all(isinstance(toolpath.steps[i], Line) for i in drawn)
    return np.array([starts[drawn[0]][:2]] + [toolpath.steps[i].end[:2] for i in drawn])  # type: ignore[union-attr]


def _distance_to_polyline(points: np.ndarray, polyline: np.ndarray) -> np.ndarray:
    a, b = polyline[:-1], polyline[1:]
    ab = b - a
    lengths = np.maximum((ab**2).sum(axis=1), 1e-300)
    ap = points[:, None, :] - a[None, :, :]
    t = np.clip((ap * ab[None]).sum(axis=2) / lengths[None], 0.0, 1.0)
    nearest = a[None] + t[..., None] * ab[None]
    return np.sqrt(((points[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1)


def test_a_viewbox_with_a_size_in_mm_and_a_translated_group(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<g transform="translate(20,10)"><path id="cut" d="M 0 0 L 40 0" stroke="black"/></g>',
        root='width="100mm" height="50mm" viewBox="0 0 200 100"',  # 0.5 mm per unit
    )
    toolpath = read_svg(path)
    # (20, 10) and (60, 10) in units; Y flipped about the page's 50 mm height
    assert toolpath.steps == [
        Line((10.0, 45.0, 0.0), None, 0, rapid=True),
        Line((30.0, 45.0, 0.0), None, 0),
    ]
    assert [(s.kind, s.number, s.text) for s in toolpath.sources] == [("element", 1, "path#cut")]
    assert toolpath.notices == []
    assert toolpath.name == "d.svg"


def test_rotate_and_scale_on_an_element_in_a_page_of_pixels(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<path d="M 10 0 L 20 0" stroke="black" transform="rotate(90) scale(2)"/>',
        root='width="96" height="96"',  # unitless: px, an inch square
    )
    travel, line = read_svg(path).steps
    # (10, 0) -> scale -> (20, 0) -> rotate 90° -> (0, 20); (20, 0) -> (0, 40)
    assert travel.end == pytest.approx((0.0, (96 - 20) * PX, 0.0), abs=1e-12)  # type: ignore[union-attr]
    assert line.end == pytest.approx((0.0, (96 - 40) * PX, 0.0), abs=1e-12)  # type: ignore[union-attr]


def test_a_circle_is_one_full_arc_and_keeps_its_direction(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<g transform="translate(30,40)"><circle cx="10" cy="0" r="5" stroke="red" '
        'fill="none" transform="rotate(30, 10, 0)"/></g>',
        root='width="100mm" height="100mm" viewBox="0 0 100 100"',
    )
    travel, circle = read_svg(path).steps
    assert isinstance(circle, ArcTo)
    assert circle.centre == pytest.approx((40.0, 60.0))
    assert circle.end == travel.end  # type: ignore[union-attr]
    assert math.dist(circle.end[:2], circle.centre) == pytest.approx(5.0)
    # SVG draws a circle clockwise on screen: with Y up it is clockwise too
    assert not circle.ccw
    assert arc_sweep(travel.end, circle) == pytest.approx(-math.tau)  # type: ignore[union-attr]


def test_a_circular_arc_its_direction_and_the_scale_of_a_file_without_size(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<path d="M 0 0 A 5 5 0 0 1 10 0 A 5 5 0 0 0 20 0" stroke="black" fill="none"/>',
    )
    toolpath = read_svg(path)
    travel, over, under = toolpath.steps
    assert travel == Line((0.0, 100.0, 0.0), None, 0, rapid=True)
    # sweep-flag 1 goes clockwise on screen, over the top: clockwise with Y up
    assert isinstance(over, ArcTo) and not over.ccw
    assert over.centre == pytest.approx((5.0, 100.0)) and over.end == pytest.approx((10, 100, 0))
    assert arc_sweep(travel.end, over) == pytest.approx(-math.pi)
    assert isinstance(under, ArcTo) and under.ccw
    assert under.centre == pytest.approx((15.0, 100.0))
    assert toolpath.notices == [
        "d.svg: no width and height in mm, cm, in, pt, pc or px; 1 unit taken as 1 mm"
    ]

    doubled = read_svg(path, scale=2.0)
    assert doubled.notices == []
    assert doubled.steps[0] == Line((0.0, 200.0, 0.0), None, 0, rapid=True)
    assert doubled.steps[1].centre == pytest.approx((10.0, 200.0))  # type: ignore[union-attr]


def test_an_explicit_scale_overrides_the_physical_size(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<path d="M 10 10 L 20 10" stroke="black"/>',
        root='width="50mm" height="50mm" viewBox="0 0 100 100"',
    )
    assert read_svg(path).steps[1] == Line((10.0, 45.0, 0.0), None, 0)
    assert read_svg(path, scale=1.0).steps[1] == Line((20.0, 90.0, 0.0), None, 0)


def test_an_elliptic_arc_is_flattened_within_the_tolerance(tmp_path) -> None:
    path = _svg(tmp_path, '<path d="M 0 50 A 20 10 0 0 1 40 50" stroke="black"/>')
    toolpath = read_svg(path, tolerance=0.01)
    ours = _vertices(toolpath)
    # the upper half (on screen) of the ellipse round (20, 50): y = 50 + 10 sin t with Y up
    t = np.linspace(math.pi, 0.0, 5001)
    truth = np.column_stack([20 + 20 * np.cos(t), 50 + 10 * np.sin(t)])
    on_curve = ((ours[:, 0] - 20) / 20) ** 2 + ((ours[:, 1] - 50) / 10) ** 2
    assert on_curve == pytest.approx(np.ones(len(ours)), abs=1e-9)
    assert ours[0] == pytest.approx((0.0, 50.0)) and ours[-1] == pytest.approx((40.0, 50.0))
    assert _distance_to_polyline(truth, ours).max() <= 0.01


def test_a_skewed_circle_is_an_ellipse_flattened_where_the_skew_puts_it(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<circle cx="50" cy="50" r="10" stroke="black" transform="skewX(30)"/>',
    )
    toolpath = read_svg(path, tolerance=0.01)
    ours = _vertices(toolpath)
    # back through the skew and the flip, every vertex is on the circle
    x_screen, y_screen = ours[:, 0], 100 - ours[:, 1]
    x_local = x_screen - math.tan(math.radians(30)) * y_screen
    assert np.hypot(x_local - 50, y_screen - 50) == pytest.approx(np.full(len(ours), 10.0))
    assert ours[0] == pytest.approx(ours[-1])


def test_cubic_and_quadratic_beziers_are_flattened_within_the_tolerance(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<path d="M 10 10 C 20 40 60 -20 70 30 Q 80 60 90 30" stroke="black" '
        'transform="scale(0.5)"/>',
    )
    tolerance = 0.002
    ours = _vertices(read_svg(path, tolerance=tolerance))
    t = np.linspace(0, 1, 4001)[:, None]
    cubic = np.array([[10, 10], [20, 40], [60, -20], [70, 30]], dtype=float)
    quad = np.array([[70, 30], [80, 60], [90, 30]], dtype=float)
    truth = np.vstack(
        [
            (1 - t) ** 3 * cubic[0]
            + 3 * (1 - t) ** 2 * t * cubic[1]
            + 3 * (1 - t) * t**2 * cubic[2]
            + t**3 * cubic[3],
            (1 - t) ** 2 * quad[0] + 2 * (1 - t) * t * quad[1] + t**2 * quad[2],
        ]
    )
    truth = np.column_stack([truth[:, 0] * 0.5, 100 - truth[:, 1] * 0.5])
    assert ours[0] == pytest.approx(truth[0]) and ours[-1] == pytest.approx(truth[-1])
    assert _distance_to_polyline(truth, ours).max() <= tolerance
    assert _distance_to_polyline(ours, truth).max() < 1e-3  # the vertices are on the curve


def test_a_rounded_rect_polyline_polygon_and_line(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<rect x="10" y="10" width="20" height="10" rx="2" stroke="black" fill="none"/>'
        '<polyline points="0,0 5,0 5,5" stroke="black" fill="none"/>'
        '<polygon points="50,50 60,50 60,60" stroke="black"/>'
        '<line x1="70" y1="70" x2="80" y2="70" stroke="black"/>',
    )
    toolpath = read_svg(path)
    rect = [s for s in toolpath.steps if toolpath.sources[s.source].text == "rect"]
    assert [type(s).__name__ for s in rect] == ["Line"] + ["Line", "ArcTo"] * 4
    arcs = [s for s in rect if isinstance(s, ArcTo)]
    assert all(not arc.ccw for arc in arcs)
    assert np.array([arc.centre for arc in arcs]) == pytest.approx(
        np.array([(28.0, 88.0), (28.0, 82.0), (12.0, 82.0), (12.0, 88.0)])
    )
    assert rect[-1].end == rect[0].end  # type: ignore[union-attr]  # closed
    polygon = [s.end for s in toolpath.steps if toolpath.sources[s.source].text == "polygon"]  # type: ignore[union-attr]
    assert polygon == [(50.0, 50.0, 0.0), (60.0, 50.0, 0.0), (60.0, 40.0, 0.0), (50.0, 50.0, 0.0)]
    assert [s.text for s in toolpath.sources] == ["rect", "polyline", "polygon", "line"]
    assert toolpath.steps[-1] == Line((80.0, 30.0, 0.0), None, 3)


def test_fill_only_hidden_text_and_images_are_skipped_with_one_notice(tmp_path) -> None:
    path = _svg(
        tmp_path,
        '<rect x="1" y="1" width="2" height="2"/>'  # filled black by default, no stroke
        '<rect x="1" y="1" width="2" height="2" fill="blue" stroke="none"/>'
        '<rect x="1" y="1" width="2" height="2" stroke="black" visibility="hidden"/>'
        '<g style="display:none"><path d="M 0 0 L 9 9" stroke="black"/></g>'
        '<text x="5" y="5">label</text>'
        '<path id="keep" d="M 0 0 L 9 0" stroke="black"/>',
    )
    toolpath = read_svg(path)
    assert [s.text for s in toolpath.sources] == ["path#keep"]
    assert toolpath.steps[-1] == Line((9.0, 100.0, 0.0), None, 0)
    assert toolpath.notices[-1] == "d.svg: skipped 2 fill-only shapes, 1 hidden shape, 1 text"


def test_malformed_xml_is_refused_naming_its_line(tmp_path) -> None:
    path = tmp_path / "bad.svg"
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg">\n<path d="M 0 0 L 1 1"\n</svg>\n')
    with pytest.raises(ToolpathError, match=r"^bad\.svg line 3: not SVG: "):
        read_svg(path)


def test_a_drawing_with_nothing_stroked_is_refused(tmp_path) -> None:
    path = _svg(tmp_path, '<rect x="1" y="1" width="2" height="2" fill="red"/>')
    with pytest.raises(ToolpathError) as refused:
        read_svg(path)
    assert str(refused.value) == "d.svg: no stroked paths or shapes to run"
    with pytest.raises(ToolpathError, match="not a regular file"):
        read_svg(tmp_path)
