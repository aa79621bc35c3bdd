"""The serial worker's control lines: reported after connecting, toggled and broken by queued
signals as the window sends them, polled inputs, notes in the session log and the console."""

from __future__ import annotations

import io
import os
from collections.abc import Callable, Iterator
from typing import Any

import pytest
from PySide6.QtCore import QObject, Signal

from app.window.device.connect_options import ConnectOptions
from app.window.device.worker_thread import WorkerThread
from drivers.link.control_lines import ControlLines
from tests.support.relay import GuiRelay, wait_in_gui

pytestmark = pytest.mark.timeout(30)

POWERED = ControlLines(dtr=True, rts=True, cts=True, dsr=True, cd=False, ri=False)


class Window(QObject):
    """Stands for the main window: its signals reach the worker's slots queued."""

    toggle = Signal(str, bool)
    brk = Signal()


@pytest.fixture
def worker_thread(qtbot) -> Iterator[WorkerThread]:
    thread = WorkerThread()
    yield thread
    assert thread.stop()


@pytest.fixture
def window(worker_thread: WorkerThread) -> Window:
    sender = Window()
    sender.toggle.connect(worker_thread.worker.set_control_line)
    sender.brk.connect(worker_thread.worker.send_break)
    return sender


@pytest.fixture
def record() -> Iterator[Callable[[Any], list[object]]]:
    """`got = record(worker.signal)`: each emission's first argument, received in the GUI thread
    (through a relay living there, as the window receives them)."""
    relays: list[GuiRelay] = []

    def _record(signal: Any) -> list[object]:
        got: list[object] = []
        relay = GuiRelay(signal)
        relay.fired.connect(lambda args: got.append(args[0]))
        relays.append(relay)
        return got

    yield _record
    for relay in relays:
        relay.deleteLater()


def _connect(
    qtbot: Any,
    record: Callable[[Any], list[object]],
    thread: WorkerThread,
    url: str = "sim://coxiris?speed=100",
    protocol: str = "coxiris",
    options: ConnectOptions | None = None,
) -> ControlLines:
    """Connect; the lines reported first (right after the port opened), once it is ready."""
    lines = record(thread.worker.control_lines_changed)
    with wait_in_gui(qtbot, thread.worker.device_ready):
        thread.open(url, protocol, 115200, options)
    qtbot.waitUntil(lambda: len(lines) >= 2)  # after the open, and once connected
    assert lines[0] == lines[-1]
    return lines[0]  # type: ignore[return-value]


def test_lines_are_reported_after_connecting(qtbot, record, worker_thread: WorkerThread) -> None:
    assert _connect(qtbot, record, worker_thread) == POWERED


def test_a_toggle_reaches_the_device_and_is_noted(
    qtbot, record, worker_thread: WorkerThread, window: Window
) -> None:
    log = io.StringIO()
    log.close = lambda: None  # type: ignore[method-assign]  (kept readable after the worker)
    worker_thread.set_session_log(log)
    _connect(qtbot, record, worker_thread)
    worker = worker_thread.worker
    notes = record(worker.control_note)
    with wait_in_gui(qtbot, worker.control_lines_changed) as changed:
        window.toggle.emit("dtr", False)
    assert changed.args[0] == ControlLines(False, True, True, True, False, False)
    qtbot.waitUntil(lambda: notes == ["DTR off"])
    assert worker.session is not None and worker.session.link.port.device.dtr is False
    text = log.getvalue()
    assert "# control lines: DTR on, RTS on, CTS on, DSR on, CD off, RI off" in text
    assert "# DTR off" in text


def test_a_polled_input_change_is_reported_and_noted(
    qtbot, record, worker_thread: WorkerThread
) -> None:
    _connect(qtbot, record, worker_thread)
    worker = worker_thread.worker
    notes = record(worker.control_note)
    device = worker.session.link.port.device  # type: ignore[union-attr]
    dropped = ControlLines(True, True, False, True, False, False)
    with wait_in_gui(qtbot, worker.control_lines_changed, timeout=3000) as changed:
        device.modem_inputs = lambda: dropped  # the device drops CTS
    assert changed.args[0] == dropped
    qtbot.waitUntil(lambda: notes == ["CTS off"])


def test_a_break(qtbot, record, worker_thread: WorkerThread, window: Window) -> None:
    _connect(qtbot, record, worker_thread)
    worker = worker_thread.worker
    notes = record(worker.control_note)
    with wait_in_gui(qtbot, worker.control_lines_changed):
        window.brk.emit()
    qtbot.waitUntil(lambda: notes == ["break 250 ms"])
    assert worker.session.link.port.device.breaks == 1  # type: ignore[union-attr]


def test_connect_options_choose_dtr_and_rts(qtbot, record, worker_thread: WorkerThread) -> None:
    options = ConnectOptions(dtr=False, rts=False)
    lines = _connect(qtbot, record, worker_thread, "sim://pi-frame?instant=1", "pi-frame", options)
    assert lines.dtr is False and lines.rts is False  # pi-frame's default is DTR on


def test_a_pty_reports_unknown_lines_and_refuses_a_toggle(
    qtbot, record, worker_thread: WorkerThread, window: Window
) -> None:
    master, slave = os.openpty()
    try:
        # pi-frame is write-only: it connects to a pty with nobody behind it
        lines = _connect(qtbot, record, worker_thread, os.ttyname(slave), "pi-frame")
        assert lines == ControlLines()
        worker = worker_thread.worker
        with wait_in_gui(qtbot, worker.notice) as notice:
            window.toggle.emit("dtr", False)
        assert "has no modem control lines (a pseudo-terminal)" in str(notice.args[0])
        with wait_in_gui(qtbot, worker.notice) as notice:
            window.brk.emit()
        assert "no break can be sent" in str(notice.args[0])
    finally:
        worker_thread.close()
        os.close(master)
        os.close(slave)


def test_a_toggle_while_disconnected_is_a_notice(
    qtbot, record, worker_thread: WorkerThread, window: Window
) -> None:
    with wait_in_gui(qtbot, worker_thread.worker.notice) as notice:
        window.toggle.emit("rts", True)
    assert notice.args[0] == "RTS not changed: not connected"
