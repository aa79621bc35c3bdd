"""One frame of the position views with a long trail: the 3D view (OpenGL) and the 2D plots.

Feeds N points of a raster path (zig-zag lines across a 200 x 100 mm field, climbing in Z, with a
little noise) into a trail buffer, shows the view, then times frames: before each one a new point
is appended (so the append path is exercised), then the view is refreshed from the buffer and
repainted at once (the 3D view renders its scene with OpenGL and reads the image back). Prints one
JSON object as its last line: `trail_frame_ms` (median 3D frame), `trail_frame_p95_ms`, the first
(cold) frame, and the same for the 2D view (`view2d_frame_ms`...).

Needs a display with OpenGL; without one (no DISPLAY) it prints {"skipped": ...} and exits 0,
unless `--xvfb` is given and xvfb-run is there: then it runs itself again under xvfb-run.
Run: xvfb-run -a -s "-screen 0 1600x1000x24 +extension GLX" \
         .venv/bin/python bench/trail_frame.py --points 1000000
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

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

LINE_POINTS = 2000  # points along one raster line
FIELD_MM = (200.0, 100.0)
SIZE = (800, 600)
XVFB_SERVER_ARGS = "-screen 0 1600x1000x24 +extension GLX"


def raster_path(points: int, seed: int = 1) -> np.ndarray:
    """(points, 4) rows (t, x, y, z): a zig-zag raster, 10 ms apart, with 5 µm of noise."""
    i = np.arange(points)
    line, along = np.divmod(i, LINE_POINTS)
    fraction = along / (LINE_POINTS - 1)
    x = np.where(line % 2 == 0, fraction, 1.0 - fraction) * FIELD_MM[0]
    lines_per_layer = 200
    y = (line % lines_per_layer) / lines_per_layer * FIELD_MM[1]
    z = (line // lines_per_layer) * 0.2
    noise = np.random.default_rng(seed).normal(0.0, 0.005, (points, 3))
    return np.column_stack([i * 0.01, x + noise[:, 0], y + noise[:, 1], z + noise[:, 2]])


def _buffer(rows: np.ndarray) -> object:
    """A trail buffer holding every row (an unbounded one where the buffer has that mode)."""
    from widgets.position_buffer import PositionBuffer

    if hasattr(PositionBuffer, "extend"):
        buffer = PositionBuffer(capacity=None)
        buffer.extend(rows)
    else:  # the fixed-capacity ring of before: as large as the trail
        buffer = PositionBuffer(capacity=len(rows))
        for row in rows:
            buffer.append(*row)
    return buffer


def _frames(view: object, size: tuple[int, int], buffer: object, rows: np.ndarray, frames: int):
    """Show `view` at `size`, time `frames` frames (after a cold first frame and 3 warm-up
    frames) and close it: (median, p95, max, first) in ms."""
    from PySide6.QtTest import QTest
    from PySide6.QtWidgets import QApplication

    app = QApplication.instance()
    view.resize(*size)
    view.show()
    QTest.qWaitForWindowExposed(view)
    app.processEvents()
    last = rows[-1]

    def frame(k: int) -> float:
        buffer.append(last[0] + 0.01 * (k + 1), last[1] + 0.01 * (k + 1), last[2], last[3])
        start = time.perf_counter()
        view.refresh()
        render = getattr(view, "render_scene", None)
        if render is not None:  # the 3D view renders in a turn of its own, then paints a copy
            render()
        view.repaint()
        elapsed = (time.perf_counter() - start) * 1000
        if getattr(view, "_stale", False):
            raise RuntimeError("the frame was not rendered (the view is not exposed?)")
        app.processEvents()  # what the event loop would do between frames
        return elapsed

    first = frame(0)
    for k in range(1, 4):
        frame(k)
    times = sorted(frame(k) for k in range(4, 4 + frames))
    view.hide()
    view.deleteLater()
    app.processEvents()
    p95 = times[min(len(times) - 1, round(0.95 * (len(times) - 1)))]
    return tuple(round(value, 2) for value in (statistics.median(times), p95, times[-1], first))


def measure(points: int, frames: int = 20, with_2d: bool = True) -> dict[str, object]:
    """Build the views on a trail of `points` points and time their frames."""
    from widgets._gl_scene import share_opengl_contexts

    share_opengl_contexts()
    from PySide6.QtWidgets import QApplication

    QApplication.instance() or QApplication([])
    from widgets.position_view_3d import PositionView3D, make_position_view_3d

    rows = raster_path(points)
    start = time.perf_counter()
    buffer = _buffer(rows)
    fill_s = time.perf_counter() - start
    result: dict[str, object] = {"points": points, "fill_s": round(fill_s, 3), "frames": frames}

    view = make_position_view_3d(buffer)
    if not isinstance(view, PositionView3D):
        result["skipped"] = f"no 3D view: {getattr(view, 'reason', '?')}"
        return result
    median, p95, most, first = _frames(view, SIZE, buffer, rows, frames)
    result.update(
        trail_frame_ms=median,
        trail_frame_p95_ms=p95,
        trail_frame_max_ms=most,
        trail_first_frame_ms=first,
        trail_drawn_vertices=len(buffer.lod.update()),  # of the whole trail's rows
        size=list(SIZE),
    )
    if with_2d:
        from widgets.position_view_2d import PositionView2D

        median, p95, _, first = _frames(
            PositionView2D(buffer), (2 * SIZE[0], SIZE[1]), buffer, rows, frames
        )
        result.update(view2d_frame_ms=median, view2d_frame_p95_ms=p95, view2d_first_frame_ms=first)
    return result


def main() -> int:
    """Print one JSON object (skipped without a display)."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--no-2d", action="store_true", help="time the 3D view only")
    parser.add_argument(
        "--xvfb", action="store_true", help="without a display, run again under xvfb-run"
    )
    options = parser.parse_args()
    if not os.environ.get("DISPLAY"):
        xvfb = shutil.which("xvfb-run")
        if options.xvfb and xvfb:
            argv = [a for a in sys.argv[1:] if a != "--xvfb"]
            command = [xvfb, "-a", "-s", XVFB_SERVER_ARGS, sys.executable, __file__, *argv]
            return subprocess.run(command, check=False).returncode
        print(json.dumps({"points": options.points, "skipped": "no DISPLAY (run under xvfb-run)"}))
        return 0
    print(json.dumps(measure(options.points, options.frames, not options.no_2d)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
