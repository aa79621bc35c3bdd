"""Issue 28 item 20: in Operate, the main position view takes at least a third of the window at
every laptop size, and no plot is clipped.

The real panel on a screen of each size, its window fitted to the screen (as an operator would),
in Operate; Qt's own account of the layout comes from the layout report
(MOTIONPANEL_LAYOUT_REPORT, app/window/layout/layout_report.py): the largest position view's share
of
the window's area, and each plot's place against the window and its neighbours.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.layout_reading import by_screen, label, launch
from tests.acceptance.xsession import XServer

pytestmark = pytest.mark.timeout(120)

SIZES = ((1024, 640), (1280, 720), (1366, 768), (1600, 1000))
VIEWS = ("positionView3d", "positionXYPlot", "positionTimePlot")
MAIN_SHARE = 1 / 3


@by_screen(SIZES)
def test_the_main_view_takes_a_third_of_the_window(
    any_screen: XServer, rig: Rig, shots: Path
) -> None:
    reading = launch(rig, any_screen, "--port", "sim://coxiris")
    reading.panel.wait_ready(b"DONE GET_SPEED")
    window = reading.panel.geometry()[2:]
    report = reading.settled_in("operate", lambda r: bool(r["connected"]))
    reading.keep(shots / f"operate-{label(any_screen.size)}.png", report)
    area = window[0] * window[1]
    plots = {p["name"]: p for p in report["plots"] if p["visible"]}
    shares = {
        name: plots[name]["rect"][2] * plots[name]["rect"][3] / area
        for name in VIEWS
        if name in plots
    }
    main = max(shares, key=shares.__getitem__)
    print(
        f"{label(any_screen.size)} (window {window[0]}x{window[1]}): "
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
