"""Shared fixtures: clients on in-process simulated devices."""

from __future__ import annotations

import gc
import itertools
import os
from collections.abc import Iterator

from tests.support.worker_display import own_display_per_worker

# two test files at a time: a display each (tests/support/worker_display.py)
own_display_per_worker()

# Qt tests run headless unless a display is there (Xvfb in CI, for the OpenGL tests).
_PLATFORM = os.environ.get("QT_QPA_PLATFORM")  # as the run was started
if "DISPLAY" not in os.environ and "WAYLAND_DISPLAY" not in os.environ:
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from widgets.position_view_3d import share_opengl_contexts

share_opengl_contexts()  # as the application does, before any QApplication exists

import re
from pathlib import Path

import pytest
from PySide6.QtCore import QCoreApplication, QTranslator

from app.window.main_window import MainWindow
from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.link.records import Traffic
from drivers.link.transport import Link, open_link
from drivers.protocols.coxiris import CoxirisProtocol
from tests.support.simproc import SimProcess


class Recorder:
    """Collects every traffic record of a link."""

    def __init__(self) -> None:
        self.records: list[Traffic] = []

    def __call__(self, record: Traffic) -> None:
        self.records.append(record)

    def sent(self) -> bytes:
        """Everything written to the device."""
        return b"".join(r.data for r in self.records if r.direction == "tx")

    def received(self) -> bytes:
        """Everything read from the device."""
        return b"".join(r.data for r in self.records if r.direction == "rx")


@pytest.fixture
def sim_link(request: pytest.FixtureRequest) -> Iterator[tuple[Link, Recorder]]:
    """A link to `sim://coxiris` with the options of `@pytest.mark.sim_url(...)`."""
    marker = request.node.get_closest_marker("sim_url")
    url = marker.args[0] if marker else "sim://coxiris?speed=100"
    link = open_link(url, 115200)
    recorder = Recorder()
    link.listeners.append(recorder)
    yield link, recorder
    link.close()


FULL_COLLECTION_EVERY = 25  # tests; a full collection scans every object of the session
_tests_ended = itertools.count(1)


@pytest.fixture(autouse=True)
def _garbage_collected_outside_qt() -> Iterator[None]:
    """As the application does (app/window/gc_main_thread.py): no automatic collection, which could
    run inside a Qt call holding a lock and deadlock on it; collected here after each test: what
    the test made (the young generations) every time, all of it every FULL_COLLECTION_EVERY tests
    (a full collection took about 0.2 s a test, a fifth of the suite's time)."""
    gc.disable()
    yield
    gc.collect(2 if next(_tests_ended) % FULL_COLLECTION_EVERY == 0 else 1)


@pytest.fixture(autouse=True)
def _settings_in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every test's panel and motionctl (a child process inherits it) keep their settings in
    the test's own folder: nothing read from or left in the user's (a laser frame numbering
    kept per port by one test once broke another that got the same pty number)."""
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(tmp_path / "settings.ini"))


@pytest.fixture(autouse=True)
def _session_logs_in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Session logs of the panels a test opens go to the test's own folder."""
    folder = tmp_path / "session-logs"
    monkeypatch.setenv("MOTIONPANEL_LOG_DIR", str(folder))
    return folder


@pytest.fixture
def settings_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The panel's (and motionctl's) settings in a file of the test's own."""
    path = tmp_path / "settings.ini"
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(path))
    return path


@pytest.fixture
def window(qtbot, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[MainWindow]:
    """A shown, active main window with its settings in a temporary file; closed afterwards."""
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(tmp_path / "settings.ini"))
    win = MainWindow()
    qtbot.addWidget(win)
    win.show()
    win.activateWindow()
    qtbot.waitActive(win)
    qtbot.waitUntil(win.views.is_ready, timeout=10_000)  # the views are built after the paint
    yield win
    win.close()
    assert not win.worker_thread.thread.isRunning()


@pytest.fixture
def motion(sim_link: tuple[Link, Recorder]) -> Motion:
    """A Motion on the simulated COXIRIS device."""
    link, _ = sim_link
    return Motion(Client(link, CoxirisProtocol(), timeout=1.0))


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """On CI the OpenGL tests must run, not skip: fail early when there is no display."""
    has_gl_tests = any(item.get_closest_marker("gl") for item in items)
    if os.environ.get("CI") and has_gl_tests and "DISPLAY" not in os.environ:
        raise pytest.UsageError(
            "CI must run the tests under Xvfb (no DISPLAY): see resources/setup.sh"
        )
    platform = os.environ.get("QT_QPA_PLATFORM")
    if "DISPLAY" in os.environ and platform == "offscreen" and platform != _PLATFORM:
        # conftest leaves a display alone: a test module set offscreen when it was imported,
        # and every test of the session would run without the display (no OpenGL, no focus)
        raise pytest.UsageError(
            "QT_QPA_PLATFORM=offscreen was set while collecting, with a display there: a test "
            "module must not set it (tests/conftest.py chooses the platform)"
        )


class UpperTranslator(QTranslator):
    """Translates every message template (drivers/messages.py) into upper case, its fields kept."""

    def translate(self, context, source, disambiguation=None, n=-1):
        from drivers.messages import CONTEXT

        if context != CONTEXT:
            return None
        parts = re.split(r"(\{[^{}]*\})", source)
        return "".join(p if p.startswith("{") else p.upper() for p in parts)


@pytest.fixture
def upper(qapp) -> Iterator[None]:
    """Messages shown upper-cased, as a translation would change them, while the test runs."""
    translator = UpperTranslator()
    QCoreApplication.installTranslator(translator)
    yield
    QCoreApplication.removeTranslator(translator)


@pytest.fixture
def record(tmp_path: Path) -> Path:
    """Where a motionsim process keeps its `--record` of what it received and sent."""
    return tmp_path / "device.log"


@pytest.fixture
def sim(request: pytest.FixtureRequest, record: Path) -> Iterator[SimProcess]:
    """`motionsim coxiris --record` in another process, with `@pytest.mark.sim_args(...)`."""
    marker = request.node.get_closest_marker("sim_args")
    process = SimProcess("coxiris", "--record", str(record), *(marker.args if marker else ()))
    yield process
    if process.proc.poll() is None:
        assert process.stop() == 0
