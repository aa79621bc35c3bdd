"""Reading a program file of any kind the panel takes, by its name's suffix."""

from __future__ import annotations

from collections.abc import Collection, Sequence
from pathlib import Path

from drivers.messages import Message
from drivers.toolpath.model import CHORD_TOLERANCE, Line, Source, Step, Toolpath, ToolpathError
from drivers.toolpath.point_program import ProgramPoint, read_program

GCODE_SUFFIXES = (".gcode", ".nc", ".ngc", ".tap")
POINT_SUFFIXES = (".csv", ".json")
SUFFIXES = (*GCODE_SUFFIXES, ".dxf", ".svg", *POINT_SUFFIXES)


def from_points(points: Sequence[ProgramPoint], name: str = "program") -> Toolpath:
    """The panel's CSV/JSON points as a toolpath: a straight move to each, at its speed."""
    steps: list[Step] = [Line((p.x, p.y, p.z), p.speed, index) for index, p in enumerate(points)]
    sources = [
        Source("point", index + 1, f"{p.x:g}, {p.y:g}, {p.z:g} @ {p.speed:g} mm/s")
        for index, p in enumerate(points)
    ]
    return Toolpath(name, steps, sources)


def load_toolpath(
    path: str | Path,
    *,
    layers: Collection[str] | None = None,
    svg_scale: float | None = None,
    tolerance: float = CHORD_TOLERANCE,
) -> Toolpath:
    """A program file as a toolpath: G-code (.gcode .nc .ngc .tap), DXF (`layers`: the ones to
    run, None: all), SVG (`svg_scale`: mm per user unit where the file has no size), or the
    panel's CSV/JSON points; `tolerance` mm for the curves flattened on reading."""
    file = Path(path)
    suffix = file.suffix.lower()
    if layers is not None and suffix != ".dxf":
        raise ToolpathError(Message("{file}: layers are chosen in DXF files only", file=file.name))
    if suffix in GCODE_SUFFIXES:
        from drivers.toolpath.gcode import read_gcode

        return read_gcode(file)
    if suffix == ".dxf":
        from drivers.toolpath.dxf import read_dxf

        return read_dxf(file, layers, tolerance=tolerance)
    if suffix == ".svg":
        from drivers.toolpath.svg import read_svg

        return read_svg(file, svg_scale, tolerance=tolerance)
    return from_points(read_program(file), file.name)
