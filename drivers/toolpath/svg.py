"""SVG drawings as toolpaths (read with svgelements): stroked paths and shapes, in mm.

Every stroked shape (path, rect, circle, ellipse, line, polyline, polygon) is run in the file's
order, each subpath a piece (a travel move between pieces that do not join), with the transforms
of its groups and its own and the viewBox applied. Circular arcs, and circles, stay arcs where the
transform keeps them circular (a circle one full arc from its first point); elliptic arcs, cubic
and quadratic Béziers are straight lines within the chord tolerance: the pieces are chosen from a
bound on the curve's second derivative, so no point of the curve is farther than the tolerance
from them. Fill-only shapes (no stroke), hidden ones, text and images are skipped with one notice.

Size: a root `width`/`height` in mm, cm, in, pt, pc or px (1/96 in; unitless is px) gives the
page's size in mm, and the drawing is converted to mm from it. Without one, 1 user unit is
`scale` mm (1 by default; a notice says so); `scale` given always sets mm per user unit.
Axes: SVG's Y points down, the device's up; the drawing is flipped so that it looks the same as
on screen: x_mm = x, y_mm = page height - y, so the page's bottom-left corner is (0, 0) (the
drawing's lowest point when the file has neither a height nor a viewBox). Z is 0, speeds None.
The text is read through drivers/files.py; malformed XML is refused naming its line.
"""

from __future__ import annotations

import io
import math
import re
from collections import Counter
from pathlib import Path
from xml.etree.ElementTree import ParseError

import numpy as np
import svgelements as se  # type: ignore[import-untyped]

from drivers.files import PROGRAM_MAX_BYTES, read_text
from drivers.messages import Message
from drivers.toolpath.drawing import MAX_STEPS, PathBuilder, bezier_chords
from drivers.toolpath.model import CHORD_TOLERANCE, Point, Source, Toolpath, ToolpathError

PPI = 96.0  # CSS pixels per inch
MM_PER_PX = 25.4 / PPI
_ABSOLUTE = re.compile(
    r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(mm|cm|in|pt|pc|px|q)?\s*", re.I
)
MM_PER = {
    "mm": 1.0,
    "cm": 10.0,
    "in": 25.4,
    "pt": 25.4 / 72,
    "pc": 25.4 / 6,
    "px": MM_PER_PX,
    "q": 0.25,
}
_SIMILAR = 1e-9  # relative: how close to circular an arc, and to a similarity a transform, must be
# what svgelements raises for values it cannot make sense of
_MALFORMED = (ValueError, TypeError, LookupError, AttributeError, ArithmeticError, RecursionError)

_PLURAL = {
    "fill-only shape": "fill-only shapes",
    "unpainted shape": "unpainted shapes",
    "hidden shape": "hidden shapes",
    "text": "texts",
    "image": "images",
}

Affine = tuple[float, float, float, float, float, float]
"""(a, b, c, d, e, f): x' = a x + c y + e, y' = b x + d y + f, as SVG's matrix()."""


def read_svg(
    path: str | Path, scale: float | None = None, tolerance: float = CHORD_TOLERANCE
) -> Toolpath:
    """An SVG drawing's toolpath, in mm (`scale`: mm per user unit, for a file without a
    physical size or to override it); refused whole if anything is wrong."""
    file = Path(path)
    name = file.name
    if not (math.isfinite(tolerance) and tolerance > 0):
        raise ToolpathError(
            Message("chord tolerance {tolerance:g} mm must be above 0", tolerance=tolerance)
        )
    if scale is not None and not (math.isfinite(scale) and scale > 0):
        raise ToolpathError(Message("SVG scale {scale:g} mm per unit must be above 0", scale=scale))
    text = read_text(file, PROGRAM_MAX_BYTES, Message("SVG drawing"), ToolpathError, "utf-8-sig")
    svg = _parse(text, name)
    notices: list[Message] = []
    page = _page(svg, scale, name, notices)
    builder = PathBuilder(name)
    skipped: Counter[str] = Counter()
    number = 0
    for element in svg.elements():
        if not isinstance(element, (se.Shape, se.Text, se.Image)):
            continue
        number += 1
        tag = str(element.values.get("tag") or type(element).__name__.lower())
        if isinstance(element, se.Text):
            skipped["text"] += 1
            continue
        if isinstance(element, se.Image):
            skipped["image"] += 1
            continue
        if str(element.values.get("visibility", "")).strip() in ("hidden", "collapse"):
            skipped["hidden shape"] += 1
            continue
        if not _painted(element.stroke):
            skipped["fill-only shape" if _painted(element.fill) else "unpainted shape"] += 1
            continue
        ident = element.id
        builder.begin(Source("element", number, f"{tag}#{ident}" if ident else tag))
        try:
            _shape(builder, element, _then(_affine(element.transform), page), tolerance)
        except ToolpathError:
            raise
        except _MALFORMED as exc:
            raise ToolpathError(
                Message(
                    "{where}: not a shape the panel reads: {why}", where=builder.where(), why=exc
                )
            ) from None
    if not builder.steps:
        raise ToolpathError(Message("{name}: no stroked paths or shapes to run", name=name))
    if skipped:
        what = ", ".join(
            f"{count} {kind if count == 1 else _PLURAL[kind]}"
            for kind, count in sorted(skipped.items())
        )
        notices.append(Message("{name}: skipped {what}", name=name, what=what))
    return builder.toolpath(notices)


def _parse(text: str, name: str) -> se.SVG:
    """The document, its transforms kept on each element (not applied: see `_shape`)."""
    try:
        svg = se.SVG.parse(io.StringIO(text), reify=False, ppi=PPI)
    except ParseError as exc:
        line = exc.position[0] if exc.position else 0
        raise ToolpathError(
            Message("{name} line {line}: not SVG: {why}", name=name, line=line, why=exc.msg)
        ) from None
    except _MALFORMED as exc:
        raise ToolpathError(
            Message("{name}: not an SVG drawing the panel reads: {why}", name=name, why=exc)
        ) from None
    if not isinstance(svg, se.SVG):
        raise ToolpathError(Message("{name}: not an SVG drawing (no svg element)", name=name))
    return svg


def _page(svg: se.SVG, scale: float | None, name: str, notices: list[Message]) -> Affine:
    """From svgelements' page pixels to mm, Y flipped about the page's lower edge."""
    width, height = svg.values.get("width"), svg.values.get("height")
    physical = all(isinstance(v, str) and _ABSOLUTE.fullmatch(v) for v in (width, height))
    if scale is None and physical and svg.width:
        # svgelements turns mm into px with a rounded 0.0393701 in/mm: the page's own width,
        # read here exactly, undoes that
        mm = _length_mm(str(width)) / float(svg.width)
    else:
        if scale is None:
            scale = 1.0
            notices.append(
                Message(
                    "{name}: no width and height in mm, cm, in, pt, pc or px; "
                    "1 unit taken as {scale:g} mm",
                    name=name,
                    scale=scale,
                )
            )
        per_unit = 1.0  # page pixels per user unit
        if svg.viewbox is not None and svg.viewbox_transform:
            a, b, c, d, _, _ = _affine(se.Matrix(svg.viewbox_transform))
            per_unit = math.sqrt(abs(a * d - b * c)) or 1.0
        mm = scale / per_unit
    if height is not None or svg.viewbox is not None:
        bottom = float(svg.height)
    else:
        box = svg.bbox()
        bottom = float(box[3]) if box is not None else 0.0
    return (mm, 0.0, 0.0, -mm, 0.0, bottom * mm)


def _length_mm(text: str) -> float:
    """A length with an absolute unit (or none: px), in mm."""
    match = _ABSOLUTE.fullmatch(text)
    if match is None:
        raise ValueError(text)
    return float(match[1]) * MM_PER[(match[2] or "px").lower()]


def _painted(paint: object) -> bool:
    return paint is not None and getattr(paint, "value", None) is not None


def _affine(matrix: se.Matrix) -> Affine:
    return (
        float(matrix.a),
        float(matrix.b),
        float(matrix.c),
        float(matrix.d),
        float(matrix.e),
        float(matrix.f),
    )


def _then(first: Affine, second: Affine) -> Affine:
    """`first`, then `second`."""
    a1, b1, c1, d1, e1, f1 = first
    a2, b2, c2, d2, e2, f2 = second
    return (
        a2 * a1 + c2 * b1,
        b2 * a1 + d2 * b1,
        a2 * c1 + c2 * d1,
        b2 * c1 + d2 * d1,
        a2 * e1 + c2 * f1 + e2,
        b2 * e1 + d2 * f1 + f2,
    )


def _apply(m: Affine, x: float, y: float) -> Point:
    return (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5], 0.0)


def _similarity(m: Affine) -> bool:
    """Whether `m` keeps circles circles (rotation, uniform scale, mirror, translation)."""
    a, b, c, d, _, _ = m
    size = a * a + b * b + c * c + d * d
    return abs(a * c + b * d) <= _SIMILAR * size and abs(a * a + b * b - c * c - d * d) <= (
        _SIMILAR * size
    )


def _stretch(m: Affine) -> float:
    """The most `m` lengthens a vector (its largest singular value)."""
    a, b, c, d, _, _ = m
    half = (a * a + b * b + c * c + d * d) / 2
    return math.sqrt(half + math.sqrt(max(half * half - (a * d - b * c) ** 2, 0.0)))


def _shape(builder: PathBuilder, element: se.Shape, m: Affine, tolerance: float) -> None:
    """One shape's pieces, its local geometry mapped by `m` to mm."""
    segments = list(se.Path(element).segments(transformed=False))
    arcs = [s for s in segments if isinstance(s, se.Arc)]
    if isinstance(element, (se.Circle, se.Ellipse)) and arcs and _similarity(m):
        first = arcs[0]
        if all(_circular(arc) and arc.center == first.center for arc in arcs):
            builder.move_to(_apply(m, first.start.x, first.start.y))
            centre = _apply(m, first.center.x, first.center.y)
            builder.arc_to(builder.position, centre[:2], _ccw(first, m), full=True)
            return
    drawing = False
    for segment in segments:
        if isinstance(segment, se.Move):
            builder.move_to(_apply(m, segment.end.x, segment.end.y))
            drawing = True
            continue
        if not drawing:
            builder.move_to(_apply(m, segment.start.x, segment.start.y))
            drawing = True
        end = _apply(m, segment.end.x, segment.end.y)
        if isinstance(segment, (se.Line, se.Close)):
            builder.line_to(end)
        elif isinstance(segment, se.Arc):
            _arc(builder, segment, m, end, tolerance)
        elif isinstance(segment, (se.CubicBezier, se.QuadraticBezier)):
            _bezier(builder, segment, m, tolerance)
        else:  # a segment kind svgelements may add: its end, straight
            builder.line_to(end)


def _circular(arc: se.Arc) -> bool:
    rx, ry = float(arc.rx), float(arc.ry)
    return abs(rx - ry) <= _SIMILAR * max(rx, ry)


def _ccw(arc: se.Arc, m: Affine) -> bool:
    """Whether the arc turns counter-clockwise once mapped by `m` (Y up): svgelements' sweep
    is positive toward increasing angles in the local frame; a mirroring `m` turns it round."""
    a, b, c, d, _, _ = m
    return bool(arc.sweep > 0) != (a * d - b * c < 0)


def _arc(builder: PathBuilder, arc: se.Arc, m: Affine, end: Point, tolerance: float) -> None:
    if not arc.sweep or not arc.rx or not arc.ry:  # SVG: a radius 0 makes a straight line
        builder.line_to(end)
        return
    if _circular(arc) and _similarity(m):
        centre = _apply(m, arc.center.x, arc.center.y)
        builder.arc_to(end, centre[:2], _ccw(arc, m))
        return
    # the local arc is c + rx cos t u + ry sin t v: |d²P/dp²| <= sweep² max(rx, ry) for p in [0, 1]
    local = tolerance / _stretch(m)
    count = math.ceil(abs(arc.sweep) * math.sqrt(max(arc.rx, arc.ry) / (8 * local)))
    builder.reserve(count)
    points = np.asarray(arc.npoint(np.linspace(0.0, 1.0, count + 1)), dtype=float)
    for x, y in points[1:-1]:
        builder.line_to(_apply(m, float(x), float(y)))
    builder.line_to(end)


def _bezier(
    builder: PathBuilder, curve: se.CubicBezier | se.QuadraticBezier, m: Affine, tolerance: float
) -> None:
    """A Bézier as chords within the tolerance (an affine map keeps a Bézier a Bézier)."""
    if isinstance(curve, se.CubicBezier):
        local = [curve.start, curve.control1, curve.control2, curve.end]
    else:
        local = [curve.start, curve.control, curve.end]
    controls = [_apply(m, p.x, p.y) for p in local]
    chords = bezier_chords(controls, tolerance, MAX_STEPS - len(builder.steps))
    for x, y, z in chords:
        builder.line_to((float(x), float(y), float(z)))
