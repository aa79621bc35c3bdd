"""Thread safety as a class of bug (issue 11).

Every signal that crosses from the serial worker reaches the GUI thread through a queued
connection to a receiver that lives there: a bare lambda (or functools.partial, or free
function) connected to a worker signal is called directly, in the worker's thread. Under a flood
of 50,000 device lines with jogs going on, this test asserts that no method of a GUI-side class
ran in another thread, and that Qt printed no warning (a timer started or a widget touched from
the wrong thread is one).
"""

from __future__ import annotations

import functools
import importlib
import inspect
import pkgutil
import threading
from collections import Counter
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

import pytest
from PySide6.QtCore import QObject, QThread, QtMsgType, qInstallMessageHandler
from PySide6.QtWidgets import QApplication

import app
import widgets
from app.window.console.traffic_console import RawConsole
from app.window.device import jobs
from app.window.device.worker import SerialWorker
from app.window.main_window import MainWindow
from tests.support.relay import GuiRelay
from widgets.position_buffer import PositionBuffer
from widgets.traffic_timeline import TrafficTimeline

pytestmark = pytest.mark.timeout(120)

# 15,000 debug lines a second from the simulated device: 50,000 lines in a few seconds. (At
# 20,000-25,000 a second the panel used to fall behind for good: the line framer copied the rest
# of its buffer for every line, so late reads grew and took longer still; its split is linear
# now, and 25,000 passes too, in 11-15 s.)
FLOOD_URL = "sim://coxiris?chatter=15000&line_timing=0&speed=100"
FLOOD_LINES = 50_000
JOGS = 3

# Qt messages that are not about threads and that a headless platform prints whatever the
# panel does: the offscreen platform says this one on every window shown (Xvfb does not; see
# qt_log_ignore in pyproject.toml). Matched by exact text, nothing else is let through.
HARMLESS_QT_MESSAGES = frozenset({"This plugin does not support propagateSizeHints()"})

# Methods of GUI-side classes that are, by design, the body of another thread; none of them
# touches Qt (they hand their result to the GUI thread through a queued signal, or a queue
# drained by a GUI timer).
OTHER_THREAD_BY_DESIGN = frozenset(
    {
        "BridgeSession._tap",  # the bridge's thread: session log, then a deque
        "BridgeSession._serve",  # the bridge's thread's target; emits the queued `_done`
        "LogViewer._read",  # the log reader thread's target; emits the queued `_loaded`
    }
)


def gui_classes() -> list[type]:
    """Every class of ours whose methods must run in the GUI thread only: each QObject subclass
    (QWidgets included) defined in `app` and `widgets`, but the serial worker (it lives in its
    own thread), and the position buffer the views draw from."""
    found: dict[str, type] = {}
    for package in (app, widgets):
        for module_info in pkgutil.walk_packages(package.__path__, f"{package.__name__}."):
            if module_info.name.endswith(".__main__"):
                continue  # a program's entry point (app/cli/__main__.py runs motionctl)
            module = importlib.import_module(module_info.name)
            for _, cls in inspect.getmembers(module, inspect.isclass):
                if cls.__module__ == module.__name__ and issubclass(cls, QObject):
                    found[f"{cls.__module__}.{cls.__qualname__}"] = cls
    classes = [cls for cls in found.values() if cls is not SerialWorker]
    for required in (MainWindow, RawConsole, TrafficTimeline):
        assert required in classes, required
    return [*classes, PositionBuffer]


# Every spy made, kept for the whole session: PySide caches a Python override it has looked up
# without owning it, so a spy freed once its test has undone it could still be called by an
# object of the next test (a segmentation fault inside rowsAboutToBeInserted, seen when no
# collection ran between the two tests).
_SPIES: list[Callable[..., Any]] = []


class _Default:
    """Shows as the expression that reads a parameter's default in a generated function."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return f"_defaults[{self.name!r}]"


def same_signature(func: Callable[..., Any], before: Callable[[], None]) -> Callable[..., Any]:
    """A function with `func`'s very parameters that calls `before()`, then `func`.

    The same parameters, not `*args, **kwargs`: PySide passes a slot as many of the signal's
    arguments as the slot's code takes, so a catch-all wrapper would be given too many.
    """
    signature = inspect.signature(func)
    parameters, call = [], []
    for p in signature.parameters.values():
        default = p.empty if p.default is p.empty else _Default(p.name)
        parameters.append(p.replace(annotation=p.empty, default=default))
        prefix = {p.VAR_POSITIONAL: "*", p.VAR_KEYWORD: "**"}.get(p.kind, "")
        call.append(f"{p.name}={p.name}" if p.kind is p.KEYWORD_ONLY else prefix + p.name)
    shown = signature.replace(parameters=parameters, return_annotation=signature.empty)
    source = f"def spied{shown}:\n    _before()\n    return _func({', '.join(call)})\n"
    defaults = {p.name: p.default for p in signature.parameters.values()}
    namespace: dict[str, Any] = {"_defaults": defaults, "_before": before, "_func": func}
    exec(source, namespace)  # the source is made from func's own parameter names only
    return namespace["spied"]


@dataclass
class ForeignCall:
    """A method of a GUI-side class called outside the GUI thread."""

    method: str
    ident: int
    thread: str  # the Python thread's name, and the QThread's object name when it has one


@dataclass
class ThreadGuard:
    """Spies on GUI-side methods and Qt's messages for the length of a test."""

    gui_ident: int
    foreign: list[ForeignCall] = field(default_factory=list)
    calls: Counter[str] = field(default_factory=Counter)  # GUI-thread calls, per method
    qt_messages: list[tuple[str, str]] = field(default_factory=list)  # (kind, text)

    def spy(self, owner: type, func: Callable[..., Any]) -> Callable[..., Any]:
        """`func`, recording the thread of every call."""
        name = f"{owner.__name__}.{func.__name__}"
        gui, calls, foreign = self.gui_ident, self.calls, self.foreign

        def check() -> None:
            ident = threading.get_ident()
            if ident == gui:
                calls[name] += 1
            elif name not in OTHER_THREAD_BY_DESIGN:
                qthread = QThread.currentThread().objectName()
                where = threading.current_thread().name + (f" / {qthread}" if qthread else "")
                foreign.append(ForeignCall(name, ident, where))

        spied = functools.wraps(func)(same_signature(func, check))
        _SPIES.append(spied)
        return spied

    def check(self) -> None:
        """No GUI-side method has run in another thread, and Qt has not warned."""
        assert not self.foreign, self.foreign[:10]
        assert not self.qt_messages, self.qt_messages

    def wait(self, qtbot: Any, condition: Callable[[], bool], timeout: int = 10_000) -> None:
        """Wait for `condition`, but fail as soon as a method runs in the wrong thread."""
        qtbot.waitUntil(
            lambda: bool(self.foreign or self.qt_messages) or condition(), timeout=timeout
        )
        self.check()

    def on_qt_message(self, mode: QtMsgType, text: str) -> None:
        """Keep warnings and worse, but the known harmless ones."""
        if mode in (QtMsgType.QtDebugMsg, QtMsgType.QtInfoMsg):
            return
        if text.strip() not in HARMLESS_QT_MESSAGES:
            self.qt_messages.append((mode.name, text))


@pytest.fixture
def guard(monkeypatch: pytest.MonkeyPatch) -> Iterator[ThreadGuard]:
    """Every function defined on a GUI-side class wrapped by a thread spy, and a Qt message
    handler; the window is built after this (see `window` below), so that its signal
    connections are made to the spied methods."""
    qapp = QApplication.instance()
    assert qapp is not None and QThread.currentThread() is qapp.thread()
    result = ThreadGuard(threading.get_ident())
    for cls in gui_classes():
        for name, value in list(vars(cls).items()):
            if inspect.isfunction(value):
                monkeypatch.setattr(cls, name, result.spy(cls, value))
            elif isinstance(value, (staticmethod, classmethod)):
                wrapped = type(value)(result.spy(cls, value.__func__))
                monkeypatch.setattr(cls, name, wrapped)

    def handler(mode: QtMsgType, context: Any, text: str) -> None:
        result.on_qt_message(mode, text)
        if previous is not None:
            previous(mode, context, text)  # pytest-qt's capture still sees it

    previous = qInstallMessageHandler(handler)
    try:
        yield result
        # The window has been closed by now (its fixture ends first): shutting the worker
        # down must not call into the GUI from its thread, nor make Qt warn, either.
        result.check()
    finally:
        qInstallMessageHandler(previous)


@pytest.fixture
def window(guard: ThreadGuard, window: MainWindow) -> MainWindow:
    """conftest's window, built with the thread spies already in place."""
    assert guard.calls["MainWindow.__init__"] == 1  # the spies saw it built
    return window


def test_a_flood_of_device_lines_touches_the_gui_from_its_own_thread_only(
    qtbot, window: MainWindow, guard: ThreadGuard
) -> None:
    finished: list[list[object]] = []  # job_finished's (job, result), received in the GUI thread
    relay = GuiRelay(window.worker.job_finished)
    relay.fired.connect(finished.append)
    with qtbot.waitSignal(window.settled, timeout=15_000):
        window.connect_device(FLOOD_URL, "coxiris", 115200)
    guard.check()
    window.jog_panel.set_step(1)

    def jog(step: int) -> None:
        done = len(finished)
        window.jog_panel.jog_requested.emit("x", 1.0)
        guard.wait(  # (a jog's time through a flood, not its speed: room for a busy CPU)
            qtbot,
            lambda: len(finished) > done and window.readout.position() == (step, 0.0, 0.0),
            timeout=30_000,
        )
        assert isinstance(finished[done][0], jobs.MoveByJob), finished[done:]

    def flooded() -> bool:
        window.console.flush()
        return len(window.console.index) >= FLOOD_LINES

    for step in range(1, JOGS + 1):  # jogs while the device floods the console
        jog(step)
    guard.wait(qtbot, flooded, timeout=30_000)

    # The worker's signals reached the GUI thread (the spies saw them there), and nothing else.
    for slot in (
        "Connection._on_traffic",
        "MachineState._on_position",
        "JobDesk._on_job_finished",
        "Connection._on_state",
    ):
        assert guard.calls[slot] > 0, slot
    # The timeline got the flood's bytes (a call a second and direction, not one a line).
    assert guard.calls["TrafficTimeline.add_bytes"] > 0
    assert window.timeline.bytes_per_second("rx").sum() >= FLOOD_LINES * len(b"dbg 1 loop ok\r\n")
    guard.check()

    # The worker is alive and the window responds: a GET typed in the console, then a jog.
    assert window.worker_thread.thread.isRunning()
    assert window.connected and window.connection_bar.state() == "connected"
    done = len(finished)
    window.console.send_requested.emit(b"GET_POSITION\n")
    guard.wait(qtbot, lambda: len(finished) > done, timeout=30_000)
    job, result = finished[done]
    assert isinstance(job, jobs.RawJob), finished[done:]
    assert result is not None
    jog(JOGS + 1)
    guard.wait(qtbot, lambda: window.status_line.state() == "idle")
    relay.deleteLater()
