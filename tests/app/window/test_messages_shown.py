"""A message the driver layer or the worker composes reaches the window in the interface's
language: the macro editor, the status line, and what the worker's signals carry."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from app.common import macros
from app.window.device import jobs
from app.window.device.worker_thread import WorkerThread
from app.window.main_window import MainWindow
from tests.support.relay import wait_in_gui

pytestmark = pytest.mark.timeout(60)

URL = "sim://coxiris?speed=100"


@pytest.fixture
def worker_thread(qtbot) -> Iterator[WorkerThread]:
    thread = WorkerThread()
    yield thread
    assert thread.stop()


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device(URL, "coxiris", 115200)


def test_a_refused_step_is_shown_translated_in_the_macro_editor(
    qtbot, window: MainWindow, upper: None
) -> None:
    dock = window.tools.macros
    dock.set_protocol("coxiris")
    editor = dock.new()
    assert editor is not None
    editor.name_edit.setText("probe")
    editor.steps_edit.setPlainText("home\nfly away")
    shown = editor.problem.text()
    assert "MACRO probe, STEP 2 ('fly away'): UNKNOWN COMMAND 'fly'; A STEP IS ONE OF:" in shown
    editor.steps_edit.setPlainText("wait 5000")
    assert "WAIT 5000 S REFUSED: FROM 0 TO 3600 S" in editor.problem.text()
    editor.close()


def test_a_refused_macro_is_shown_translated_on_the_status_line(
    qtbot, window: MainWindow, upper: None
) -> None:
    macros.save(window.settings, "coxiris", [macros.Macro("bad", "coxiris", ("home", "wait"))])
    dock = window.tools.macros
    dock.set_protocol("visiomex")
    dock.set_protocol("coxiris")  # read again from the settings
    assert not dock.run("bad")
    assert "MACRO bad, STEP 2 ('wait'): USAGE: WAIT SECONDS" in window.status_line.message()


def test_a_failed_job_reaches_the_main_window_translated(
    qtbot, window: MainWindow, upper: None
) -> None:
    _connect(qtbot, window)
    job = jobs.MacroJob(macros.Macro("m", "coxiris", ("wait",)))  # not checked: fails running
    with wait_in_gui(qtbot, window.worker.job_failed) as failed:
        window.worker.submit(job)
    assert failed.args[1] == "USAGE: WAIT SECONDS"
    qtbot.waitUntil(lambda: "USAGE: WAIT SECONDS" in window.status_line.message())
    assert "MACRO m (1 STEP)" in window.status_line.message()


def test_the_workers_notices_and_states_come_translated(
    qtbot, worker_thread: WorkerThread, upper: None
) -> None:
    worker = worker_thread.worker
    with wait_in_gui(qtbot, worker.notice) as notice:
        worker_thread.set_control_line("rts", True)
    assert notice.args[0] == "RTS NOT CHANGED: NOT CONNECTED"
    states: list[tuple[str, str]] = []
    worker.state_changed.connect(lambda state, detail: states.append((state, detail)))
    with wait_in_gui(qtbot, worker.device_ready):
        worker_thread.open(URL, "coxiris", 115200)
    qtbot.waitUntil(lambda: any(state == "connected" for state, _ in states))
    assert ("connecting", f"{URL} (coxiris, 115200 BAUD)") in states
    assert ("connected", f"CX25F7TK9P ON {URL}") in states
    with wait_in_gui(qtbot, worker.job_failed) as failed:
        worker.submit(jobs.MacroJob(macros.Macro("m", "coxiris", ("wait 9999",))))
    assert failed.args[1] == "WAIT 9999 S REFUSED: FROM 0 TO 3600 S"


def test_a_refused_connection_reaches_the_worker_state_translated(
    qtbot, worker_thread: WorkerThread, upper: None
) -> None:
    states: list[tuple[str, str]] = []
    worker_thread.worker.state_changed.connect(lambda state, detail: states.append((state, detail)))
    worker_thread.open("sim://coxiris?bogus=1", "coxiris", 115200)
    qtbot.waitUntil(lambda: any(state == "error" for state, _ in states))
    errors = [detail for state, detail in states if state == "error"]
    assert "UNKNOWN SIM:// OPTION 'bogus'" in errors[0]


def test_the_console_shows_decoded_meanings_translated(qtbot, upper) -> None:
    from app.window.console.traffic_console import RawConsole
    from drivers.protocols.registry import create_protocol

    console = RawConsole()
    qtbot.addWidget(console)
    console.set_protocol(create_protocol("visiomex"))  # a new connection keeps the language
    console.append_traffic("rx", b"FP0001\r\nChecking 2\r\n", 1.0)
    console.flush()
    text = console.text()
    assert "FEEDBACK FP0001 (MOVE PACKAGE CONFIRMED)" in text
    assert "feedback" not in text
