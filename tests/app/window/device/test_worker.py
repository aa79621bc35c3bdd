"""The serial worker on its QThread against the in-process simulated device."""

from __future__ import annotations

import pytest

from app.window.device import jobs
from app.window.device.connect_options import DeviceInfo
from app.window.device.worker_thread import WorkerThread
from drivers.protocols.events import PositionReport
from tests.support.relay import wait_in_gui

pytestmark = pytest.mark.timeout(30)


@pytest.fixture
def worker_thread(qtbot):
    thread = WorkerThread()
    yield thread
    assert thread.stop()


def _connect(qtbot, thread: WorkerThread, url: str = "sim://coxiris?speed=100") -> DeviceInfo:
    with wait_in_gui(qtbot, thread.worker.device_ready) as ready:
        thread.open(url, "coxiris", 115200)
    return ready.args[0]


def test_connects_and_reports_the_device(qtbot, worker_thread: WorkerThread) -> None:
    info = _connect(qtbot, worker_thread)
    assert info.identity == "CX25F7TK9P"
    assert info.capabilities.axes == ("x", "y", "z")


def test_move_job_reports_positions_and_traffic(qtbot, worker_thread: WorkerThread) -> None:
    _connect(qtbot, worker_thread)
    traffic: list = []
    worker_thread.worker.traffic.connect(traffic.extend)
    with wait_in_gui(qtbot, worker_thread.worker.job_finished) as done:
        worker_thread.worker.submit(jobs.MoveToJob(10, -5, 2.5))
    assert done.args[1] == PositionReport(10.0, -5.0, 2.5)
    qtbot.waitUntil(lambda: b"DONE ABSOLUTE_MOVE" in b"".join(r.data for r in traffic))
    sent = b"".join(r.data for r in traffic if r.direction == "tx")
    assert b"ABSOLUTE_MOVE 10 -5 2.5\n" in sent


def test_bad_job_fails_with_a_reason_and_nothing_sent(qtbot, worker_thread: WorkerThread) -> None:
    _connect(qtbot, worker_thread)
    traffic: list = []
    worker_thread.worker.traffic.connect(traffic.extend)
    with wait_in_gui(qtbot, worker_thread.worker.job_failed) as failed:
        worker_thread.worker.submit(jobs.SetSpeedJob(500))
    assert "1 to 100" in failed.args[1]
    assert b"SET_SPEED" not in b"".join(r.data for r in traffic)


def test_cancel_pending_returns_what_was_not_sent(qtbot, worker_thread: WorkerThread) -> None:
    worker = worker_thread.worker
    for i in range(3):
        worker.submit(jobs.MoveByJob(i, 0, 0))
    dropped = worker.cancel_pending()
    assert [job.dx for job in dropped] == [0, 1, 2]


def test_device_vanishing_mid_move_is_an_error_not_a_hang(
    qtbot, worker_thread: WorkerThread
) -> None:
    _connect(qtbot, worker_thread, "sim://coxiris?speed=1")
    worker = worker_thread.worker
    states: list[tuple[str, str]] = []
    worker.state_changed.connect(lambda s, d: states.append((s, d)))
    with wait_in_gui(qtbot, worker.busy_changed):
        worker.submit(jobs.MoveToJob(100, 0, 0))
    worker.submit(jobs.HomeJob())
    worker.session.link.port.close()  # the device goes away under the worker
    qtbot.waitUntil(lambda: any(s == "error" for s, _ in states), timeout=5000)
    detail = next(d for s, d in states if s == "error")
    assert "not sent: go home" in detail


def test_stop_while_a_move_waits_ends_the_thread_quickly(
    qtbot, worker_thread: WorkerThread
) -> None:
    _connect(qtbot, worker_thread, "sim://coxiris?speed=1")
    with wait_in_gui(qtbot, worker_thread.worker.busy_changed):
        worker_thread.worker.submit(jobs.MoveToJob(100, 0, 0))
    assert worker_thread.stop(3000)
    assert not worker_thread.thread.isRunning()


def test_open_failure_is_reported(qtbot, worker_thread: WorkerThread) -> None:
    states: list[tuple[str, str]] = []
    worker_thread.worker.state_changed.connect(lambda s, d: states.append((s, d)))
    worker_thread.open("/dev/does-not-exist", "coxiris", 115200)
    qtbot.waitUntil(lambda: any(s == "error" for s, _ in states), timeout=5000)
    assert "cannot open /dev/does-not-exist" in states[-1][1]


def test_disconnect_mid_move_is_a_disconnection_not_an_error(
    qtbot, worker_thread: WorkerThread
) -> None:
    _connect(qtbot, worker_thread, "sim://coxiris?speed=1")
    worker = worker_thread.worker
    states: list[str] = []
    worker.state_changed.connect(lambda s, d: states.append(s))
    with wait_in_gui(qtbot, worker.busy_changed):
        worker.submit(jobs.MoveToJob(100, 0, 0))
    with wait_in_gui(qtbot, worker.job_failed) as failed:
        worker_thread.close()
    assert "abandoned" in failed.args[1]
    qtbot.waitUntil(lambda: "disconnected" in states, timeout=5000)
    assert "error" not in states


def test_a_move_queued_before_a_stop_is_not_sent(qtbot, worker_thread: WorkerThread) -> None:
    """A held jog let go while its next step is queued behind the step under way: the stop
    halts the move under way and the queued step never goes (laser-frame has a stop)."""
    worker = worker_thread.worker
    with wait_in_gui(qtbot, worker.device_ready):
        worker_thread.open("sim://laser-frame", "laser-frame", 115200)
    traffic: list = []
    worker.traffic.connect(traffic.extend)
    stopped: list = []  # an operator's stop, said as a stop (job_stopped), not a failure
    worker.job_stopped.connect(lambda job, why: stopped.append((job, why)))
    with wait_in_gui(qtbot, worker.busy_changed):
        worker.submit(jobs.MoveByJob(30, 0, 0))  # 3 s at the default 10 mm/s
    queued = jobs.MoveByJob(0, 30, 0)
    worker.submit(queued)
    worker.stop_now()
    qtbot.waitUntil(lambda: any(job is queued for job, _ in stopped), timeout=10000)
    assert dict((id(j), w) for j, w in stopped)[id(queued)] == "stopped before it was sent"
    with wait_in_gui(qtbot, worker.job_finished):
        worker.submit(jobs.RefreshJob())  # the worker went on to the next job
    protocol = worker.session.protocol
    moves = [r.data for r in traffic if r.direction == "tx" and protocol.sent_commands(r.data)[0]]
    assert len(moves) == 1, moves  # the first move only
