"""Issue 28 item 26: the parts seen cut are shown whole, at 1024×640, 1280×720 and 1600×1000.

The real panel under Xvfb + openbox: on a pi-frame device the Arc tab is clicked (with the mouse,
where the layout report says its tab is) and CW, CCW, Preview and Run arc must be whole, with
Go to's Home, Set Home and Stop when it is in front; on a Visiomex device the red "position
unknown" line and the Home / Set Home / Drop queued row; in Set up, the parameter table's Last
written column as wide as its text and the Description not squeezed. What Qt shows comes from
the layout report (MOTIONPANEL_LAYOUT_REPORT); a screenshot of each is kept.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from app.window.layout_report import ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.test_layouts_fit import Report, _read, _switch
from tests.acceptance.xsession import Panel, XServer, wait_for

pytestmark = pytest.mark.timeout(120)

SIZES = ((1024, 640), (1280, 720), (1600, 1000))
GO_TO = ("homeButton", "setHomeButton", "stopButton", "goButton")
ARC = ("arcCw", "arcCcw", "arcPreview", "runArcButton")
DESCRIPTION_LEAST = 200  # px: "Le…" was 42


def _cut(report: Report, names: tuple[str, ...], where: str) -> list[str]:
    details: dict = report["details"]  # type: ignore[assignment]
    found = []
    for name in names:
        part = details.get(name)
        if part is None or not part["visible"]:
            found.append(f"{where}: {name} is not shown")
        elif not part["whole"] or part["squeezed"]:
            found.append(f"{where}: {name} is cut: {part}")
    return found


def _later(panel: Panel, path: Path, also: Callable[[Report], bool]) -> Report:
    before = int(_read(path)["sequence"])  # type: ignore[index, call-overload]

    def settled() -> Report | None:
        panel.alive()
        report = _read(path)
        ok = report is not None and int(report["sequence"]) > before  # type: ignore[call-overload]
        return report if ok and also(report) else None  # type: ignore[arg-type]

    return wait_for(settled, 20.0, "a new layout report", 0.1)


def _tab(report: Report, text: str) -> list[int]:
    for bar in report["tab_bars"]:  # type: ignore[attr-defined]
        for tab in bar["tabs"]:
            if tab["text"].replace("&", "") == text:
                return tab["rect"]
    raise AssertionError(f"no tab {text!r} in {report['tab_bars']}")


@pytest.mark.parametrize("size", SIZES, ids=[f"{w}x{h}" for w, h in SIZES])
def test_the_arc_tab_shows_its_direction_and_run_arc_whole(
    size: tuple[int, int],
    x_server_of: Callable[[tuple[int, int]], XServer],
    rig: Rig,
    tmp_path: Path,
    shots: Path,
) -> None:
    x = x_server_of(size)
    path = tmp_path / "layout-report.json"
    sim = rig.sim("pi-frame")
    panel = rig.panel(x, "--port", sim.path, "--protocol", "pi-frame", env={ENVIRONMENT: str(path)})
    panel.wait_state("idle", 30.0)
    label = f"{size[0]}x{size[1]}"
    report = _switch(panel, path, "operate", lambda r: bool(r["connected"]) and "Arc" in str(r))
    found = _cut(report, GO_TO, f"Go to at {label}")
    left, top, _, _ = panel.geometry()
    tx, ty, tw, th = _tab(report, "Arc")
    x.xdotool("mousemove", str(left + tx + tw // 2), str(top + ty + th // 2), "click", "1")
    report = _later(panel, path, lambda r: bool(r["details"]["arcCw"]["visible"]))
    panel.screenshot(shots / f"arc-tab-{label}.png")
    (shots / f"arc-tab-{label}.json").write_text(json.dumps(report, indent=1), encoding="utf-8")
    found += _cut(report, ARC, f"Arc at {label}")
    assert not found, "\n".join(found)


@pytest.mark.parametrize("size", SIZES, ids=[f"{w}x{h}" for w, h in SIZES])
def test_visiomex_shows_position_unknown_go_to_and_the_parameter_columns_whole(
    size: tuple[int, int],
    x_server_of: Callable[[tuple[int, int]], XServer],
    rig: Rig,
    tmp_path: Path,
    shots: Path,
) -> None:
    x = x_server_of(size)
    path = tmp_path / "layout-report.json"
    sim = rig.sim("visiomex")
    panel = rig.panel(x, "--port", sim.path, "--protocol", "visiomex", env={ENVIRONMENT: str(path)})
    panel.wait_state("idle", 30.0)
    label = f"{size[0]}x{size[1]}"
    report = _switch(
        panel, path, "operate", lambda r: bool(r["details"]["positionStatus"]["visible"])
    )
    panel.screenshot(shots / f"visiomex-operate-{label}.png")
    found = _cut(report, ("positionStatus", *GO_TO), f"Operate at {label}")
    report = _switch(panel, path, "setup", lambda r: "parameterTable" in r["columns"])
    panel.screenshot(shots / f"visiomex-setup-{label}.png")
    (shots / f"visiomex-setup-{label}.json").write_text(json.dumps(report, indent=1), "utf-8")
    columns = {c["title"]: c for c in report["columns"]["parameterTable"]["columns"]}  # type: ignore[index]
    written, description = columns["Last written"], columns["Description"]
    if written["width"] < written["needed"]:
        found.append(f"Set up at {label}: Last written cut: {written}")
    if description["width"] < DESCRIPTION_LEAST:
        found.append(f"Set up at {label}: Description squeezed: {description}")
    assert not found, "\n".join(found)
