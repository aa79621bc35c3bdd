"""Program files as the tools people draw with write them, for the tests of issue 23: a DXF
written by ezdxf (standing in for a CAD program), an SVG as an illustration program writes it
(nested transforms, a viewBox in mm, a fill-only shape) and G-code as a CAM program writes it
(preamble, tool change, spindle, line numbers); and the same three along X only, for Firmata's
one motor."""

from __future__ import annotations

from pathlib import Path

import ezdxf

CAM_GCODE = """%
(part.nc - as a CAM program writes it)
(T1 D=3 FLAT)
N10 G90 G94 G17 G21
N20 G54
N30 T1 M6
N40 S10000 M3
N50 G0 X5 Y5
N60 G1 X15 Y5 F600
N70 G1 X15 Y10
N80 G3 X10 Y15 I-5 J0
N90 G4 P0.1
N100 G0 X2 Y3
N110 M5
N120 M30
%
"""
ILLUSTRATION_SVG = """<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="30mm" viewBox="0 0 40 30">
  <g transform="translate(5 5)">
    <path d="M 0 0 L 10 0 A 5 5 0 0 1 15 5" stroke="#000" fill="none"/>
    <g transform="scale(0.5)"><circle cx="40" cy="20" r="6" stroke="#000" fill="none"/></g>
  </g>
  <rect x="1" y="1" width="4" height="4" fill="#f00" stroke="none"/>
  <line x1="20" y1="20" x2="30" y2="24" stroke="#000"/>
</svg>
"""
# Firmata turns one motor: the same three kinds of file, along X only.
CAM_GCODE_X = """(one axis)
G21 G90 G17
G1 X10 F300
G0 X2
G4 P0.1
G1 X6 F300
M30
"""
ILLUSTRATION_SVG_X = """<svg xmlns="http://www.w3.org/2000/svg"
     width="30mm" height="10mm" viewBox="0 0 30 10">
  <path d="M 2 10 H 12 M 15 10 H 8" stroke="black" fill="none"/>
</svg>
"""


def _cad_dxf(path: Path, one_axis: bool = False) -> Path:
    """A drawing as a CAD program saves it (ezdxf's own writer), in mm, on three layers."""
    doc = ezdxf.new("R2010", units=4)
    space = doc.modelspace()
    if one_axis:
        space.add_line((0, 0), (10, 0), dxfattribs={"layer": "CUT"})
        space.add_line((12, 0), (4, 0), dxfattribs={"layer": "CUT"})
    else:
        space.add_line((5, 5), (15, 5), dxfattribs={"layer": "CUT"})
        space.add_arc((15, 10), 5, -90, 90, dxfattribs={"layer": "CUT"})
        space.add_circle((25, 10), 3, dxfattribs={"layer": "CUT"})
        space.add_lwpolyline([(30, 2, 0.5), (34, 2)], format="xyb", dxfattribs={"layer": "CUT"})
        space.add_line((20, 2), (28, 4), dxfattribs={"layer": "CUT"})
    space.add_line((0, 20), (5, 20), dxfattribs={"layer": "ENGRAVE"})
    space.add_text("part 7", dxfattribs={"layer": "NOTES"})
    doc.saveas(path)
    return path


Drawings = dict[str, tuple[Path, tuple[float, float]]]


def write_drawings(tmp_path: Path) -> Drawings:
    """Write each file into `tmp_path`: each file's path and its last point (x, y) in mm."""
    files = {
        "part.nc": (CAM_GCODE, (2.0, 3.0)),
        "art.svg": (ILLUSTRATION_SVG, (30.0, 6.0)),
        "line.nc": (CAM_GCODE_X, (6.0, 0.0)),
        "line.svg": (ILLUSTRATION_SVG_X, (8.0, 0.0)),
    }
    made: Drawings = {}
    for name, (text, last) in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
        made[name] = (tmp_path / name, last)
    made["drawing.dxf"] = (_cad_dxf(tmp_path / "drawing.dxf"), (28.0, 4.0))
    made["line.dxf"] = (_cad_dxf(tmp_path / "line.dxf", one_axis=True), (4.0, 0.0))
    return made
