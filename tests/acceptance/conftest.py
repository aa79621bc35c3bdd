"""The real-input acceptance tier: the real panel under Xvfb + openbox, driven by xdotool.

One X server per screen size for the whole run (started when first needed), a panel per test.
Skipped as a whole, with the reason, where Xvfb, openbox, xdotool, xprop or ImageMagick's
`import` are missing (`bash resources/setup.sh test` installs them as root).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from tests.acceptance.xsession import (
    SCREENS,
    Panel,
    Sim,
    XServer,
    busy_cpu,
    missing_tools,
)

_MISSING = missing_tools()


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Mark every test of this folder `acceptance`, and skip them without the X tools."""
    here = Path(__file__).parent
    for item in items:
        if here in Path(str(item.fspath)).parents:
            item.add_marker(pytest.mark.acceptance)
            if _MISSING:
                item.add_marker(
                    pytest.mark.skip(
                        reason="acceptance tier needs "
                        + ", ".join(_MISSING)
                        + " (Debian: xvfb openbox xdotool x11-utils imagemagick)"
                    )
                )


@pytest.fixture(scope="session")
def x_servers() -> Iterator[dict[tuple[int, int], XServer]]:
    """The X servers started so far, by screen size; all stopped at the end of the run."""
    servers: dict[tuple[int, int], XServer] = {}
    yield servers
    for server in servers.values():
        server.stop()


@pytest.fixture
def x_server_of(
    x_servers: dict[tuple[int, int], XServer],
) -> Callable[[tuple[int, int]], XServer]:
    """The X server (Xvfb + openbox) of a screen size, started the first time it is asked for."""

    def get(size: tuple[int, int]) -> XServer:
        if size not in x_servers:
            x_servers[size] = XServer(*size)
        return x_servers[size]

    return get


@pytest.fixture
def x_server(x_server_of: Callable[[tuple[int, int]], XServer]) -> XServer:
    """The 1280×720 X server."""
    return x_server_of(SCREENS[1])


@pytest.fixture(params=SCREENS, ids=[f"{w}x{h}" for w, h in SCREENS])
def any_screen(
    request: pytest.FixtureRequest, x_server_of: Callable[[tuple[int, int]], XServer]
) -> XServer:
    """Each of the three screen sizes in turn."""
    return x_server_of(request.param)


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo) -> Iterator[object]:
    """Keep each phase's report on the test, for the fixtures' teardown to see a failure."""
    report = yield
    setattr(item, f"report_{report.when}", report)  # type: ignore[attr-defined]
    return report


@pytest.fixture
def processes(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[list[Panel | Sim]]:
    """Panels and simulators a test starts, closed at its end (panels first); when the test
    failed, the screen and the panel's output are kept in its folder first."""
    started: list[Panel | Sim] = []
    yield started
    call = getattr(request.node, "report_call", None)
    for proc in sorted(started, key=lambda p: not isinstance(p, Panel)):
        if isinstance(proc, Panel):
            if call is not None and call.failed:
                with contextlib.suppress(Exception):
                    shot = proc.screenshot(tmp_path / "failure.png")
                    print(f"screen at the failure: {shot}; the panel said: {proc.stderr()}")
            with contextlib.suppress(Exception):  # the others must still be ended
                proc.close()
        else:
            with contextlib.suppress(Exception):
                proc.stop()


class Rig:
    """Starts a test's simulators and panels, each ended when the test ends."""

    def __init__(self, tmp: Path, started: list[Panel | Sim]) -> None:
        self.tmp = tmp
        self.started = started
        self._sims = 0

    def sim(
        self, protocol: str, *args: str, link: Path | None = None, control: bool = False
    ) -> Sim:
        """A motionsim process recording to its own file in the test's folder."""
        self._sims += 1
        record = self.tmp / f"device-{self._sims}.rec"
        sim = Sim(protocol, record, *args, link=link, control=control)
        self.started.append(sim)
        return sim

    def panel(
        self,
        x: XServer,
        *args: str,
        settings: Path | None = None,
        env: dict[str, str] | None = None,
    ) -> Panel:
        """The panel on `x` with `args` (e.g. --port PATH --protocol NAME), in English; `env`
        adds to its environment."""
        panel = Panel(x, self.tmp, "--lang", "en", *args, settings=settings, env_extra=env)
        self.started.append(panel)
        return panel


@pytest.fixture
def rig(tmp_path: Path, processes: list[Panel | Sim]) -> Rig:
    """Start simulators and panels for this test."""
    return Rig(tmp_path, processes)


@pytest.fixture
def cpu_busy() -> Iterator[None]:
    """Three `yes > /dev/null` processes while the test runs."""
    with busy_cpu(3):
        yield


@pytest.fixture
def shots(tmp_path: Path) -> Path:
    """Where a test keeps its screenshots."""
    folder = tmp_path / "screenshots"
    folder.mkdir()
    return folder
