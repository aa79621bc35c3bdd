"""A 100,000-line G-code program: read, flattened, measured, checked and drawn (issue 23's
"parses and previews in under 2 s"), and what it costs the 3D view's frame beside a 1,000,000-
point trail.

Prints one JSON object as its last line: `parse_preview_s` (best of 3: parse + flatten +
summary + box check + both views' set_program), its parts, `done_ms` (the median cost of moving
the views' "done" row while it runs), and the 3D frame with the trail alone and with the
program too (`frame_ms_trail`, `frame_ms_with_program`, their ratio).
Needs a display with OpenGL (run under xvfb-run, or give --xvfb).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

XVFB_SERVER_ARGS = "-screen 0 1600x1000x24 +extension GLX"


def gcode(lines: int) -> str:
    """A CAM-like program of `lines` moves: rows of short G1 cuts with a G2 every tenth line."""
    out = ["G21 G90 G17", "G0 X0 Y0", "F600"]
    x = y = 0.0
    for i in range(lines):
        if i % 10 == 5:
            out.append(f"G2 X{x + 1:.3f} Y{y:.3f} I0.5 J0")
            x += 1
        else:
            x, y = (i % 500) * 0.1, (i // 500) * 0.2
            out.append(f"G1 X{x:.3f} Y{y:.3f}")
    return "\n".join(out)


def measure(lines: int, trail_points: int, frames: int) -> dict[str, object]:
    """Time the reading and the drawing, and the 3D frame with and without the program."""
    from widgets._gl_scene import share_opengl_contexts

    share_opengl_contexts()
    from PySide6.QtWidgets import QApplication

    QApplication.instance() or QApplication([])
    from trail_frame import SIZE, _buffer, _frames, raster_path

    from drivers.device.travel import TravelLimits
    from drivers.toolpath.gcode import parse_gcode
    from drivers.toolpath.geometry import check_travel, flatten, summarize
    from widgets.position_view_2d import PositionView2D
    from widgets.position_view_3d import PositionView3D, make_position_view_3d

    text = gcode(lines)
    rows = raster_path(trail_points)
    buffer = _buffer(rows)
    view2d = PositionView2D(buffer)
    view3d = make_position_view_3d(buffer)
    if not isinstance(view3d, PositionView3D):
        return {"skipped": f"no 3D view: {getattr(view3d, 'reason', '?')}"}
    box = TravelLimits(((-10.0, 300.0), (-10.0, 500.0), (-1.0, 1.0)))
    best: dict[str, float] | None = None
    for _ in range(3):
        marks = [time.perf_counter()]
        toolpath = parse_gcode(text, "big.nc")
        marks.append(time.perf_counter())
        flat = flatten(toolpath)
        summarize(toolpath, flat, 10.0)
        check_travel(toolpath, flat, box)
        marks.append(time.perf_counter())
        view2d.set_program(flat.points, flat.rapid)
        view3d.set_program(flat.points, flat.rapid)
        marks.append(time.perf_counter())
        parts = {
            "parse_s": marks[1] - marks[0],
            "flatten_check_s": marks[2] - marks[1],
            "draw_s": marks[3] - marks[2],
            "parse_preview_s": marks[3] - marks[0],
        }
        if best is None or parts["parse_preview_s"] < best["parse_preview_s"]:
            best = parts
    assert best is not None
    done = []
    for k in range(1, 101):
        start = time.perf_counter()
        row = k * len(flat) // 101
        view2d.set_program_done(row)
        view3d.set_program_done(row)
        done.append((time.perf_counter() - start) * 1000)
    view3d.set_program(None)
    trail_only = _frames(view3d, SIZE, buffer, rows, frames)[0]
    view3d = make_position_view_3d(buffer)
    view3d.set_program(flat.points, flat.rapid)
    with_program = _frames(view3d, SIZE, buffer, rows, frames)[0]
    result: dict[str, object] = {key: round(value, 3) for key, value in best.items()}
    result.update(
        lines=lines,
        segments=len(flat) - 1,
        done_ms=round(statistics.median(done), 3),
        trail_points=trail_points,
        frame_ms_trail=trail_only,
        frame_ms_with_program=with_program,
        frame_ratio=round(with_program / trail_only, 3),
    )
    return result


def main() -> int:
    """Print one JSON object (skipped without a display)."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--lines", type=int, default=100_000)
    parser.add_argument("--trail", type=int, default=1_000_000)
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--xvfb", action="store_true", help="without a display, use xvfb-run")
    options = parser.parse_args()
    if not os.environ.get("DISPLAY"):
        xvfb = shutil.which("xvfb-run")
        if options.xvfb and xvfb:
            argv = [a for a in sys.argv[1:] if a != "--xvfb"]
            command = [xvfb, "-a", "-s", XVFB_SERVER_ARGS, sys.executable, __file__, *argv]
            return subprocess.run(command, check=False).returncode
        print(json.dumps({"skipped": "no DISPLAY (run under xvfb-run)"}))
        return 0
    print(json.dumps(measure(options.lines, options.trail, options.frames)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
