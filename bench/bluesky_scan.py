"""A Bluesky 5x5 grid scan over the stage against the same grid through the scripting API.

Both on `sim://coxiris` at 50 mm/s (its replies at the real device's pace), the grid -4..4 mm
by -2..2 mm; `overhead` is the scan's time over the API's, less one (the scan moves Y at each
point and X at each row: 30 moves against the API's 25, so the figure counts those too).
Run: .venv/bin/python bench/bluesky_scan.py [--runs N]   (needs the `lab` extra)
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

PORT, BOX, SPEED = "sim://coxiris", "-10:10,-10:10,0:5", 50.0
XS, YS = (-4, -2, 0, 2, 4), (-2, -1, 0, 1, 2)


def _api_s() -> float:
    """The 25 points through `open_device`, each position read as the scan reads it."""
    import drivers

    with drivers.open_device(PORT, "coxiris", travel=BOX) as stage:
        stage.speed(SPEED)
        start = time.perf_counter()
        for x in XS:
            for y in YS:
                stage.move_to(x, y, 0)
                stage.position()
        return time.perf_counter() - start


def _scan_s() -> float:
    """The same grid as a RunEngine's `grid_scan` over `drivers.bluesky.Stage`."""
    from bluesky import RunEngine
    from bluesky.plans import grid_scan
    from ophyd_async.core import init_devices

    from drivers.bluesky import Stage

    engine = RunEngine({})
    with init_devices():
        stage = Stage(PORT, "coxiris", travel=BOX, speed=SPEED)
    try:
        start = time.perf_counter()
        engine(grid_scan([stage], stage.x, XS[0], XS[-1], 5, stage.y, YS[0], YS[-1], 5))
        return time.perf_counter() - start
    finally:
        stage.close()


def measure(runs: int = 3) -> dict[str, float]:
    """Medians of `runs` of each, and the scan's overhead over the API."""
    api = statistics.median(_api_s() for _ in range(runs))
    scan = statistics.median(_scan_s() for _ in range(runs))
    return {"runs": runs, "api_s": api, "scan_s": scan, "bluesky_grid_overhead": scan / api - 1}


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=3)
    print(json.dumps(measure(parser.parse_args().runs)))
