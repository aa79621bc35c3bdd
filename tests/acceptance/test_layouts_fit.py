"""Issue 22: each layout (Operate, Set up, Traffic) fits a laptop screen, in English and Spanish.

The real panel on a screen of each size, its window fitted to the screen, switched by Ctrl+1/2/3
from the keyboard; a screenshot of each layout is kept. Qt's own account of what it shows comes
from the panel's layout report (MOTIONPANEL_LAYOUT_REPORT, app/window/layout/layout_report.py): no
control of the layout's list may be hidden, clipped, covered or overlapping another, and the
plots lie wholly inside the window.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from itertools import combinations
from pathlib import Path

import pytest

from app.window.layout.layout_report import CONTROLS, ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, XServer, wait_for

pytestmark = pytest.mark.timeout(120)

SIZES = ((1024, 640), (1280, 720), (1366, 768), (1600, 1000))
LANGUAGES = ("en", "es")
KEYS = {"operate": "ctrl+1", "setup": "ctrl+2", "traffic": "ctrl+3"}
# Set up shows the panels the device calls for (one in front, the others as its tabs).
SETUP_PANELS = frozenset(
    {"parameterEditorPanel", "firmataPanel", "piFramePanel", "travelLimits", "macroPanel"}
)
REPORT_TIMEOUT = 20.0

Report = dict[str, object]


def _read(path: Path) -> Report | None:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return None


def _sequence(path: Path) -> int:
    report = _read(path)
    return int(report["sequence"]) if report else 0  # type: ignore[call-overload]


def _controls(report: Report) -> dict[str, dict]:
    return {c["name"]: c for c in report["controls"]}  # type: ignore[attr-defined]


def _switch(
    panel: Panel,
    path: Path,
    layout: str,
    also: Callable[[Report], bool] = lambda report: True,
) -> Report:
    """Press the layout's shortcut; the report written once the window has settled in it (at
    the size the window has on the screen then)."""
    before = _sequence(path)
    panel.key(KEYS[layout])
    return _settled(panel, path, before, layout, also)


def _settled(
    panel: Panel, path: Path, before: int, layout: str, also: Callable[[Report], bool]
) -> Report:
    """The first report after report number `before` of `layout` settled: at the window's size
    on the screen, its views made, and that `also` accepts."""

    def settled() -> Report | None:
        panel.alive()
        report = _read(path)
        if (
            report is None
            or int(report["sequence"]) <= before  # type: ignore[call-overload]
            or report["layout"] != layout
            or report["window"] != list(panel.geometry()[2:])
            or not report["views_ready"]
            or not also(report)
        ):
            return None
        return report

    return wait_for(settled, REPORT_TIMEOUT, f"a layout report of {layout}", 0.1)


def _overlap(a: list[int], b: list[int]) -> bool:
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    return ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah


def problems(report: Report, where: str, required: Iterable[str]) -> list[str]:
    """What is wrong with the layout `report` describes (`where`: layout, size, language)."""
    found: list[str] = []
    controls = _controls(report)
    required = set(required)
    shown: list[dict] = []
    for name, control in controls.items():
        if not control["found"]:
            if name in required:
                found.append(f"{where}: {name} is not in the window")
            continue
        if control["behind_tab"]:
            if name in required:
                found.append(f"{where}: {name} is behind the tab {control['behind_tab']!r}")
            continue
        if not control["visible"]:
            if name in required or control["dock_shown"]:
                found.append(f"{where}: {name} is not shown")
            continue
        shown.append(control)
        x, y, w, h = control["rect"]
        if not control["whole"]:
            found.append(
                f"{where}: {name} is clipped: Qt shows {control['shown_area']} px² of its "
                f"{w}×{h} at ({x}, {y})"
            )
        if control["covered_by"]:
            found.append(f"{where}: {name} at ({x}, {y}, {w}×{h}) is under {control['covered_by']}")
    for a, b in combinations(shown, 2):
        nested = a["name"] in b["inside"] or b["name"] in a["inside"]
        if not nested and _overlap(a["rect"], b["rect"]):
            found.append(f"{where}: {a['name']} {a['rect']} overlaps {b['name']} {b['rect']}")
    window = report["window"]
    for plot in report["plots"]:  # type: ignore[attr-defined]
        if plot["visible"] and not (plot["inside_window"] and plot["whole"]):
            found.append(
                f"{where}: the plot {plot['name']} {plot['rect']} is not wholly inside the "
                f"{window} window"
            )
    return found


def _required(layout: str, report: Report, device: str) -> list[str]:
    """The controls `layout` must show whole: all of its list; in Set up, the device's setup
    panel in front (Visiomex: its parameters), the others possibly as its tabs."""
    if layout != "setup":
        return list(CONTROLS[layout])
    fixed = [name for name in CONTROLS[layout] if name not in SETUP_PANELS]
    front = "parameterEditorPanel" if device == "visiomex" else "macroPanel"
    return [*fixed, front]


@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("size", SIZES, ids=[f"{w}x{h}" for w, h in SIZES])
def test_each_layout_fits_the_screen(
    size: tuple[int, int],
    lang: str,
    x_server_of: Callable[[tuple[int, int]], XServer],
    rig: Rig,
    tmp_path: Path,
    shots: Path,
) -> None:
    """Ctrl+3, Ctrl+2, Ctrl+1 on a COXIRIS device, then Ctrl+2 and Ctrl+1 on a Visiomex one
    (typed in Port after the first went away; its Operate has lines of its own: a speed note,
    "position unknown"): every control of each layout whole, the plots inside."""
    x = x_server_of(size)
    path = tmp_path / "layout-report.json"
    sim = rig.sim("coxiris", "--speed", "100")
    panel = rig.panel(
        x, "--port", sim.path, "--protocol", "coxiris", "--lang", lang, env={ENVIRONMENT: str(path)}
    )
    panel.wait_ready(b"DONE GET_SPEED")
    label = f"{size[0]}x{size[1]}-{lang}"
    found: list[str] = []
    rows: int | None = None

    def check(layout: str, device: str, also: Callable[[Report], bool] = lambda r: True) -> Report:
        report = _switch(panel, path, layout, also)
        where = f"{layout} ({device}) at {label} (window {report['window']})"
        name = f"{layout}-{device}-{label}"
        panel.screenshot(shots / f"{name}.png")
        (shots / f"{name}.json").write_text(json.dumps(report, indent=1), encoding="utf-8")
        left, top, width, height = panel.geometry()
        if left < 0 or top < 0 or left + width > size[0] or top + height > size[1]:
            found.append(f"{where}: the window ({width}×{height} at {left}, {top}) is off screen")
        found.extend(problems(report, where, _required(layout, report, device)))
        return report

    for layout in ("traffic", "setup", "operate"):
        check(layout, "coxiris")

    sim.kill()  # the device goes; a Visiomex one is typed in Port
    panel.wait_state("error", 15.0)
    panel.type_port("sim://visiomex")
    panel.wait_state("idle", 20.0)
    report = check(
        "setup",
        "visiomex",
        lambda r: bool(_controls(r)["parameterEditorPanel"].get("visible")),
    )
    rows = report["parameter_rows"]  # type: ignore[assignment]
    check("operate", "visiomex")
    print(f"{label}: {rows} parameter rows whole in Set up; screenshots in {shots}")
    assert not found, "\n".join(found)


@pytest.mark.parametrize("lang", LANGUAGES)
def test_operate_fits_on_a_piframe_device(
    lang: str,
    x_server_of: Callable[[tuple[int, int]], XServer],
    rig: Rig,
    tmp_path: Path,
    shots: Path,
) -> None:
    """Operate on a pi-frame device, whose position panel has a line more ("position unknown"):
    one panel on the largest screen, its window made the size of each screen in turn (smallest
    first, as a window fitted to it): every control of Operate whole, the plots inside."""
    x = x_server_of(SIZES[-1])
    path = tmp_path / "layout-report.json"
    panel = rig.panel(x, "--port", "sim://pi-frame", "--lang", lang, env={ENVIRONMENT: str(path)})
    panel.wait_state("idle", 30.0)
    left, top = panel.geometry()[:2]  # below and beside the window manager's frame
    found: list[str] = []
    for width, height in SIZES:
        before = _sequence(path)
        x.xdotool("windowsize", panel.window, str(width - left), str(height - top))
        report = _settled(panel, path, before, "operate", lambda r: bool(r["connected"]))
        label = f"{width}x{height}-{lang}"
        where = f"operate (pi-frame) at {label} (window {report['window']})"
        panel.screenshot(shots / f"operate-pi-frame-{label}.png")
        text = json.dumps(report, indent=1)
        (shots / f"operate-pi-frame-{label}.json").write_text(text, encoding="utf-8")
        found.extend(problems(report, where, CONTROLS["operate"]))
    print(f"pi-frame, {lang}: screenshots in {shots}")
    assert not found, "\n".join(found)
