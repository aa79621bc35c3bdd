"""DXF drawings as toolpaths (read with ezdxf): lines, arcs, circles, polylines, splines, ellipses.

The modelspace's entities are run in the file's order, each a path (a travel move between paths
that do not join): LINE; ARC and CIRCLE as arcs (a CIRCLE a full circle, counter-clockwise, from
its point at 0°); LWPOLYLINE and 2D/3D POLYLINE with their bulges as arcs and their closed flag;
SPLINE and ELLIPSE, and arcs not drawn in the XY plane (an extrusion other than +Z), as straight
lines within the chord tolerance; INSERT (block references) exploded into
what the block holds. Anything else (TEXT, HATCH, DIMENSION, POINT, meshes, ...) is skipped with
one notice. Coordinates are the drawing's WCS, Z included, scaled to mm from `$INSUNITS` (0,
unitless, is taken as mm with a notice). Speeds are None: the panel's speed.

`Toolpath.layers` lists every layer that has something to run; `layers` chooses those that are
run. DXF is read strictly, not with ezdxf's recover module (which would run half of a truncated
file): text DXF in the encoding its header gives, a malformed file refused with the line ezdxf
names; binary DXF with ezdxf's loader for untrusted binary data, once it is seen to end with its
EOF marker. Splines and ellipses become chords within the tolerance by a bound on their second
derivative (a rational spline by ezdxf's adaptive flattening). The file is checked and bounded
by drivers/files.py (`read_bytes`: DXF has its own encodings and a binary form).
"""

from __future__ import annotations

import io
import math
import struct
from collections import Counter
from collections.abc import Callable, Collection, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

import ezdxf
import ezdxf.path
import ezdxf.units
import numpy as np
from ezdxf.document import Drawing
from ezdxf.entities.dxfgfx import DXFGraphic
from ezdxf.enums import InsertUnits
from ezdxf.filemanagement import dxf_stream_info
from ezdxf.filemanagement import read as read_stream
from ezdxf.lldxf.const import VTX_SPLINE_FRAME_CONTROL_POINT, DXFError, DXFStructureError
from ezdxf.lldxf.tagger import binary_tags_loader
from ezdxf.math import Vec3, bulge_center

from drivers.files import PROGRAM_MAX_BYTES, read_bytes
from drivers.messages import Message
from drivers.toolpath.drawing import MAX_STEPS, PathBuilder, bezier_chords
from drivers.toolpath.model import CHORD_TOLERANCE, Point, Source, Toolpath, ToolpathError

DRAWN = frozenset({"LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE", "SPLINE", "ELLIPSE"})
MAX_BLOCK_DEPTH = 16  # blocks inside blocks; deeper is refused (a block may not hold itself)
BINARY_SIGNATURE = b"AutoCAD Binary DXF\r\n\x1a\x00"
# mm per unit of $INSUNITS; exact where the unit is defined exactly (ezdxf's own factors are
# rounded, 25.400000000101603 for the inch): the rest come from ezdxf.units.conversion_factor
MM_PER_UNIT = {
    1: 25.4,  # inch
    2: 304.8,  # foot
    4: 1.0,  # millimetre
    5: 10.0,  # centimetre
    6: 1000.0,  # metre
    8: 25.4e-6,  # microinch
    9: 0.0254,  # mil
    10: 914.4,  # yard
    13: 0.001,  # micron
    14: 100.0,  # decimetre
    21: 1200 / 3937 * 1000,  # US survey foot
    22: 1 / 39.37 * 1000,  # US survey inch
}
# what ezdxf (or the data it is given) raises for a malformed drawing
_MALFORMED = (
    DXFError,
    ValueError,
    TypeError,
    LookupError,
    AttributeError,
    ArithmeticError,
    RecursionError,
    EOFError,
    struct.error,
)
_UP = Vec3(0, 0, 1)
_ToMm = Callable[[Iterable[float]], Point]


@dataclass(frozen=True)
class _Item:
    """A modelspace entity, or one of what an INSERT of it explodes into."""

    number: int  # the modelspace entity's, counted from 1
    entity: DXFGraphic
    layer: str
    block: str | None  # the block it comes from, for an exploded INSERT


def read_dxf(
    path: str | Path,
    layers: Collection[str] | None = None,
    tolerance: float = CHORD_TOLERANCE,
) -> Toolpath:
    """A DXF drawing's toolpath, in mm (`layers`: those to run, None: all); refused whole if
    anything is wrong."""
    file = Path(path)
    name = file.name
    if not (math.isfinite(tolerance) and tolerance > 0):
        raise ToolpathError(
            Message("chord tolerance {tolerance:g} mm must be above 0", tolerance=tolerance)
        )
    data = read_bytes(file, PROGRAM_MAX_BYTES, Message("DXF drawing"), ToolpathError)
    document = _load(data, name)
    notices: list[Message] = []
    scale = _mm_per_unit(document, name, notices)
    items, skipped = _items(document, name)
    found = tuple(sorted({item.layer for item in items if item.entity.dxftype() in DRAWN}))
    chosen = _chosen(layers, found, name)
    builder = PathBuilder(name)
    for item in items:
        if item.layer not in chosen:
            continue
        kind = item.entity.dxftype()
        if kind not in DRAWN:
            skipped[kind] += 1
            continue
        where = f"{kind} in block {item.block}" if item.block is not None else kind
        builder.begin(Source("entity", item.number, f"{where} on layer {item.layer}"))
        try:
            _entity(builder, item.entity, scale, tolerance)
        except ToolpathError:
            raise
        except _MALFORMED as exc:
            raise ToolpathError(
                Message(
                    "{where}: not a drawing the panel reads: {why}", where=builder.where(), why=exc
                )
            ) from None
    if not builder.steps:
        raise ToolpathError(
            Message("{name}: no lines, arcs or curves on the chosen layers", name=name)
        )
    if skipped:
        what = ", ".join(f"{count} {kind}" for kind, count in sorted(skipped.items()))
        notices.append(Message("{name}: skipped what is not a path: {what}", name=name, what=what))
    return builder.toolpath(notices, found)


def _load(data: bytes, name: str) -> Drawing:
    """The drawing in `data`, read strictly; refused whole, naming why, if it is malformed."""
    if data.startswith(BINARY_SIGNATURE) and not data.rstrip(b"\x00").endswith(b"EOF"):
        raise ToolpathError(Message("{name}: binary DXF cut short (no EOF at its end)", name=name))
    if data.startswith(b"AC10"):
        raise ToolpathError(Message("{name}: a DWG drawing, not DXF (save it as DXF)", name=name))
    try:
        if data.startswith(BINARY_SIGNATURE):
            return Drawing.load(binary_tags_loader(data, errors="replace"))
        # the header, which names the encoding of the rest, is ASCII
        info = dxf_stream_info(io.StringIO(data.decode("utf-8", errors="ignore")))
        text = data.decode(info.encoding, errors="replace")
        return read_stream(io.StringIO(text))
    except _MALFORMED as exc:
        raise ToolpathError(
            Message("{name}: not a DXF drawing the panel reads: {why}", name=name, why=exc)
        ) from None


def _mm_per_unit(document: Drawing, name: str, notices: list[Message]) -> float:
    """The drawing's unit in mm, from `$INSUNITS`."""
    raw = document.header.get("$INSUNITS", 0)
    try:
        code = int(raw)
    except (TypeError, ValueError):
        raise ToolpathError(
            Message("{name}: $INSUNITS {value!r} is not a unit code", name=name, value=raw)
        ) from None
    if code == 0:
        notices.append(Message("{name}: no units given ($INSUNITS 0), taken as mm", name=name))
        return 1.0
    if code in MM_PER_UNIT:
        return MM_PER_UNIT[code]
    try:
        return float(ezdxf.units.conversion_factor(InsertUnits(code), InsertUnits.Millimeters))
    except (TypeError, ValueError, LookupError, ArithmeticError):
        raise ToolpathError(
            Message(
                "{name}: units $INSUNITS {code} the panel cannot convert to mm",
                name=name,
                code=code,
            )
        ) from None


def _items(document: Drawing, name: str) -> tuple[list[_Item], Counter[str]]:
    """The modelspace's entities in order, INSERTs exploded; the kinds left out, counted."""
    items: list[_Item] = []
    skipped: Counter[str] = Counter()
    for number, entity in enumerate(document.modelspace(), start=1):
        layer = str(entity.dxf.get("layer", "0"))
        try:
            items.extend(_exploded(number, entity, layer, None, 0, skipped))
        except ToolpathError:
            raise
        except _MALFORMED as exc:
            raise ToolpathError(
                Message(
                    "{name} entity {number} ({kind} on layer {layer}): not a drawing the panel "
                    "reads: {why}",
                    name=name,
                    number=number,
                    kind=entity.dxftype(),
                    layer=layer,
                    why=exc,
                )
            ) from None
    return items, skipped


def _exploded(
    number: int,
    entity: DXFGraphic,
    layer: str,
    block: str | None,
    depth: int,
    skipped: Counter[str],
) -> Iterator[_Item]:
    kind = entity.dxftype()
    if kind == "POLYLINE" and not (entity.is_2d_polyline or entity.is_3d_polyline):  # type: ignore[attr-defined]
        skipped["POLYLINE (mesh)"] += 1
        return
    if kind != "INSERT":
        yield _Item(number, entity, layer, block)
        return
    if depth >= MAX_BLOCK_DEPTH:
        raise DXFStructureError(f"blocks nested more than {MAX_BLOCK_DEPTH} deep")
    name = str(entity.dxf.get("name", "?"))
    for part in entity.virtual_entities():  # type: ignore[attr-defined]
        own = str(part.dxf.get("layer", "0"))
        # by DXF's convention what a block draws on layer 0 takes the INSERT's layer
        yield from _exploded(number, part, layer if own == "0" else own, name, depth + 1, skipped)


def _chosen(layers: Collection[str] | None, found: tuple[str, ...], name: str) -> frozenset[str]:
    if layers is None:
        return frozenset(found)
    unknown = sorted(set(layers) - set(found))
    if unknown:
        raise ToolpathError(
            Message(
                "{name}: no layer {layer} with lines, arcs or curves; the drawing's layers: "
                "{layers}",
                name=name,
                layer=", ".join(unknown),
                layers=", ".join(found) or "none",
            )
        )
    return frozenset(layers)


def _entity(builder: PathBuilder, entity: DXFGraphic, scale: float, tolerance: float) -> None:
    """One entity's path (coordinates times `scale` for mm)."""
    kind = entity.dxftype()
    in_units = tolerance / scale  # ezdxf flattens in the drawing's units

    def mm(point: Iterable[float]) -> Point:
        x, y, z = Vec3(point)
        return (x * scale, y * scale, z * scale)

    flat_xy = Vec3(entity.dxf.get("extrusion", _UP)).isclose(_UP)
    if kind == "LINE":
        builder.move_to(mm(entity.dxf.start))
        builder.line_to(mm(entity.dxf.end))
    elif kind in ("ARC", "CIRCLE") and flat_xy:
        centre = mm(entity.dxf.center)
        if kind == "CIRCLE":
            start = (centre[0] + entity.dxf.radius * scale, centre[1], centre[2])
            full = True
        else:
            start = mm(entity.start_point)  # type: ignore[attr-defined]
            sweep = (entity.dxf.end_angle - entity.dxf.start_angle) % 360.0
            full = math.isclose(sweep, 0.0, abs_tol=1e-9) or math.isclose(sweep, 360.0)
        builder.move_to(start)
        end = start if full else mm(entity.end_point)  # type: ignore[attr-defined]
        builder.arc_to(end, centre[:2], ccw=True, full=full)
    elif kind == "LWPOLYLINE" and flat_xy:
        z = float(entity.dxf.get("elevation", 0.0))
        vertices = [(x, y, z, b) for x, y, b in entity.get_points("xyb")]  # type: ignore[attr-defined]
        _polyline(builder, vertices, bool(entity.closed), mm)  # type: ignore[attr-defined]
    elif kind == "POLYLINE" and entity.is_2d_polyline and flat_xy:  # type: ignore[attr-defined]
        z = Vec3(entity.dxf.get("elevation", (0, 0, 0))).z
        vertices = [
            (v.dxf.location.x, v.dxf.location.y, z, float(v.dxf.get("bulge", 0.0)))
            for v in entity.vertices  # type: ignore[attr-defined]
            if not v.dxf.get("flags", 0) & VTX_SPLINE_FRAME_CONTROL_POINT
        ]
        _polyline(builder, vertices, bool(entity.is_closed), mm)  # type: ignore[attr-defined]
    elif kind == "POLYLINE" and entity.is_3d_polyline:  # type: ignore[attr-defined]
        points = [
            (*Vec3(v.dxf.location).xyz, 0.0)
            for v in entity.vertices  # type: ignore[attr-defined]
            if not v.dxf.get("flags", 0) & VTX_SPLINE_FRAME_CONTROL_POINT
        ]
        _polyline(builder, points, bool(entity.is_closed), mm)  # type: ignore[attr-defined]
    elif kind == "SPLINE":
        _spline(builder, entity, in_units, mm)
    elif kind == "ELLIPSE":
        _ellipse(builder, entity, in_units, mm)
    elif kind in ("ARC", "CIRCLE"):  # not in the XY plane
        _points(builder, entity.flattening(in_units), mm)  # type: ignore[attr-defined]
    else:  # LWPOLYLINE or 2D POLYLINE not in the XY plane: ezdxf's path is in WCS
        _points(builder, ezdxf.path.make_path(entity).flattening(in_units), mm)


def _polyline(
    builder: PathBuilder,
    vertices: list[tuple[float, float, float, float]],
    closed: bool,
    mm: _ToMm,
) -> None:
    """A polyline in the XY plane: (x, y, z, bulge) vertices; a bulge makes the segment from its
    vertex an arc (tan(sweep / 4), counter-clockwise when positive)."""
    if not vertices:
        return
    ends = [*vertices[1:], vertices[0]] if closed else vertices[1:]
    builder.move_to(mm(vertices[0][:3]))
    for (x0, y0, _, bulge), (x1, y1, z1, _) in zip(vertices, ends, strict=False):
        end = mm((x1, y1, z1))
        if bulge == 0.0 or math.hypot(x1 - x0, y1 - y0) == 0.0:
            builder.line_to(end)
            continue
        cx, cy = bulge_center((x0, y0), (x1, y1), bulge)
        centre = mm((cx, cy, 0.0))
        builder.arc_to(end, centre[:2], ccw=bulge > 0)


def _spline(builder: PathBuilder, entity: DXFGraphic, tolerance: float, mm: _ToMm) -> None:
    """A spline as chords: a non-rational one as its Bézier pieces, flattened with a bound
    (`bezier_chords`); a rational one (weights) by ezdxf's adaptive flattening, which checks
    the middle of each chord only, asked for a quarter of the tolerance."""
    curve = entity.construction_tool()  # type: ignore[attr-defined]
    if curve.is_rational:
        _points(builder, entity.flattening(tolerance / 4, segments=8), mm)  # type: ignore[attr-defined]
        return
    first = True
    for controls in curve.bezier_decomposition():
        points = np.array([tuple(point) for point in controls], dtype=float)
        if first:
            builder.move_to(mm(points[0]))
            first = False
        for point in bezier_chords(points, tolerance, MAX_STEPS - len(builder.steps)):
            builder.line_to(mm(point))


def _ellipse(builder: PathBuilder, entity: DXFGraphic, tolerance: float, mm: _ToMm) -> None:
    """An ellipse (or elliptic arc) as chords: c + a cos t + b sin t has |P''| <= |a|, so n
    equal steps of t over the span s stray at most |a| s² / (8 n²) from it."""
    ellipse = entity.construction_tool()  # type: ignore[attr-defined]
    span = ellipse.param_span
    count = max(1, math.ceil(span * math.sqrt(ellipse.major_axis.magnitude / (8 * tolerance))))
    builder.reserve(count + 1)
    params = ellipse.start_param + span * np.linspace(0.0, 1.0, count + 1)
    _points(builder, ellipse.vertices(params), mm)


def _points(builder: PathBuilder, points: Iterable[Vec3], mm: _ToMm) -> None:
    """A flattened curve: straight lines through `points`."""
    first = True
    for point in points:
        if first:
            builder.move_to(mm(point))
            first = False
        else:
            builder.line_to(mm(point))
