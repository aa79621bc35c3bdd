"""The panel's layout report (MOTIONPANEL_LAYOUT_REPORT, app/window/layout/layout_report.py) as the
acceptance tier reads it: the panel launched to write it, a layout switched to from the
keyboard, and the report taken once the window has settled (a newer one than before, of that
layout, at the size the window has on the screen, its views made)."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from app.window.layout.layout_report import ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, XServer, wait_for

Report = dict[str, object]
KEYS = {"operate": "ctrl+1", "setup": "ctrl+2", "traffic": "ctrl+3"}
REPORT_TIMEOUT = 20.0


def label(size: tuple[int, int]) -> str:
    """A screen size as tests and screenshots name it: 1280x720."""
    return f"{size[0]}x{size[1]}"


def by_screen(sizes: tuple[tuple[int, int], ...]) -> pytest.MarkDecorator:
    """Run a test once per screen size, its `any_screen` fixture (conftest.py) the X server of
    each (ids: 1280x720)."""
    return pytest.mark.parametrize(
        "any_screen", sizes, ids=[label(size) for size in sizes], indirect=True
    )


def read(path: Path) -> Report | None:
    """The report at `path`, None before the first one."""
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return None


def _always(report: Report) -> bool:
    return True


class LayoutReading:
    """A panel that writes its layout report to `path`, and what it reports."""

    def __init__(self, panel: Panel, path: Path) -> None:
        self.panel = panel
        self.path = path

    def sequence(self) -> int:
        """The number of the last report written (0: none yet)."""
        report = read(self.path)
        return int(report["sequence"]) if report else 0  # type: ignore[call-overload]

    def after(
        self,
        before: int,
        accept: Callable[[Report], bool],
        what: str,
        timeout: float = REPORT_TIMEOUT,
    ) -> Report:
        """The first report numbered above `before` that `accept`s, within `timeout` s."""

        def settled() -> Report | None:
            self.panel.alive()
            report = read(self.path)
            newer = report is not None and int(report["sequence"]) > before  # type: ignore[call-overload]
            return report if newer and accept(report) else None  # type: ignore[arg-type]

        return wait_for(settled, timeout, what, 0.1)

    def shows(self, report: Report, layout: str) -> bool:
        """Whether `report` is of `layout` settled: the window's size now, its views made."""
        return (
            report["layout"] == layout
            and report["window"] == list(self.panel.geometry()[2:])
            and bool(report["views_ready"])
        )

    def _of(self, layout: str, also: Callable[[Report], bool]) -> Callable[[Report], bool]:
        return lambda report: self.shows(report, layout) and also(report)

    def settled_in(self, layout: str, also: Callable[[Report], bool] = _always) -> Report:
        """A report (of any time) of `layout` settled, that `also` accepts."""
        return self.after(0, self._of(layout, also), f"a layout report of {layout}")

    def switch(self, layout: str, also: Callable[[Report], bool] = _always) -> Report:
        """Press the layout's shortcut; the report written once the window has settled in it
        (that `also` accepts)."""
        before = self.sequence()
        self.panel.key(KEYS[layout])
        return self.after(before, self._of(layout, also), f"a layout report of {layout}")

    def later(self, also: Callable[[Report], bool]) -> Report:
        """The next report that `also` accepts (after a click, say)."""
        return self.after(self.sequence(), also, "a new layout report")

    def keep(self, shot: Path, report: Report) -> None:
        """Keep the screen as `shot` (a .png) and the report beside it (.json)."""
        self.panel.screenshot(shot)
        text = json.dumps(report, indent=1)
        shot.with_suffix(".json").write_text(text, encoding="utf-8")


def launch(rig: Rig, x: XServer, *args: str) -> LayoutReading:
    """The panel on `x` with `args`, writing its layout report in the test's folder."""
    path = rig.tmp / "layout-report.json"
    return LayoutReading(rig.panel(x, *args, env={ENVIRONMENT: str(path)}), path)
