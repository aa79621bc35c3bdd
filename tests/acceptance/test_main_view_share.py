"""Issue 28 item 20: in Operate, the main position view takes at least a third of the window at
every laptop size, and no plot is clipped.

The real panel on a screen of each size, its window fitted to the screen (as an operator would),
in Operate; Qt's own account of the layout comes from the layout report
(MOTIONPANEL_LAYOUT_REPORT, app/window/layout_report.py): the largest position view's share of
the window's area, and each plot's place against the window and its neighbours.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from app.window.layout_report import ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, wait_for

pytestmark = pytest.mark.timeout(120)

SIZES = ((1024, 640), (1280, 720), (1366, 768), (1600, 1000))
VIEWS = ("positionView3d", "positionXYPlot", "positionTimePlot")
MAIN_SHARE = 1 / 3


def _report(path: Path, window: tuple[int, int]) -> dict | None:
    try:
        report = json.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return None
    if report["layout"] != "operate" or report["window"] != list(window):
        return None
    if not report["views_ready"] or not report["connected"]:
        return None
    return report


@pytest.mark.parametrize("size", SIZES, ids=[f"{w}x{h}" for w, h in SIZES])
def test_the_main_view_takes_a_third_of_the_window(
    size: tuple[int, int],
    x_server_of: Callable[[tuple[int, int]], XServer],
    rig: Rig,
    tmp_path: Path,
    shots: Path,
) -> None:
    x = x_server_of(size)
    path = tmp_path / "layout-report.json"
    panel = rig.panel(x, "--port", "sim://coxiris", env={ENVIRONMENT: str(path)})
    panel.wait_ready(b"DONE GET_SPEED")
    window = tuple(panel.geometry()[2:])
    report = wait_for(lambda: _report(path, window), 20.0, "a layout report of Operate", 0.1)
    panel.screenshot(shots / f"operate-{size[0]}x{size[1]}.png")
    area = window[0] * window[1]
    plots = {p["name"]: p for p in report["plots"] if p["visible"]}
    shares = {
        name: plots[name]["rect"][2] * plots[name]["rect"][3] / area
        for name in VIEWS
        if name in plots
    }
    main = max(shares, key=shares.__getitem__)
    print(
        f"{size[0]}x{size[1]} (window {window[0]}x{window[1]}): "
        + ", ".join(f"{name} {share:.1%}" for name, share in shares.items())
    )
    problems = [
        f"the plot {p['name']} {p['rect']} is clipped in the {window} window"
        for p in plots.values()
        if not (p["inside_window"] and p["whole"])
    ]
    assert not problems, "\n".join(problems)
    assert shares[main] >= MAIN_SHARE, (
        f"the largest view, {main}, takes {shares[main]:.1%} of the window"
    )
