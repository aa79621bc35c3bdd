"""The model-based truth test (issue 28) through the window's worker: on each of the five
protocols, random sequences of operator actions (jog, go to, home, set home, speed, a program
run, paused or stopped, a raw move, disconnect and connect again, the device killed mid-move and
served again on the same path) as the window submits them to its SerialWorker on its QThread,
against `motionsim --control` in another process. Observed only through the worker's signals,
received in the GUI thread (tests/support/relay.py): after every step the last position_changed
report,
if it claims to be the device's (measured, or commanded and confirmed, from a known place), is
the simulator's own `where` within one motor step; a count the worker's session keeps from its
own home is held to the same rule once its move had the time to end.

Seeded, no example database, no shrinking, bounded in steps and time; the steps that ran clean
are logged per protocol ("model truth: worker coxiris: 14 steps ran clean (...)") and kept as
the test's `model_steps` property.
"""

from __future__ import annotations

from typing import Any

import pytest
from PySide6.QtCore import QObject

from app.window.device import jobs
from app.window.device.connect_options import ConnectOptions
from app.window.device.worker_thread import WorkerThread
from drivers.device.travel import parse_travel
from drivers.protocols.base import Protocol
from drivers.protocols.events import PositionReport
from drivers.session.device_session import ProgressListener
from drivers.session.setup import make_protocol
from drivers.toolpath.model import Toolpath
from tests.support.model_truth import KILL_MARGIN, TRAVEL, Point, claims
from tests.support.model_truth_machine import OperatorMachine, run_model
from tests.support.relay import GuiRelay, wait_in_gui

pytestmark = [pytest.mark.e2e]

# Per protocol: examples, steps each, and the seed (picked for a mix of every action; the
# rules chosen depend on the seed alone, and Hypothesis's first example is the first rule,
# check_readout, at every step). About 60 s for all five on a 2-core machine: a Visiomex move
# is a packet and 1 s of silence.
PLAN = {
    "coxiris": (3, 8, 114),
    "laser-frame": (3, 8, 120),
    "pi-frame": (3, 8, 138),
    "firmata": (4, 6, 39),
    "visiomex": (3, 6, 105),
}
JOB_MS = 30_000  # the longest a job may take (a program, a move whose device vanished)
READY_MS = 15_000  # a lost port's path back: the worker connects again (PORT_RETRY_S and more)


class Seen(QObject):
    """What the worker said, received in the GUI thread in the order it was said."""

    def __init__(self, thread: WorkerThread) -> None:
        super().__init__()
        worker = thread.worker
        self.reports: list[PositionReport] = []
        self.outcomes: list[tuple[jobs.Job, str, object]] = []
        self.starts = 0
        self.ready = 0
        self.connecting_at = 0  # reports said before the last connection began
        self.started_at = 0  # ... before the last move began
        self.speed = 0.0
        self._relays = [
            self._relay(worker.position_changed, lambda a: self.reports.append(a[0])),
            self._relay(worker.job_finished, lambda a: self._ended(a, "finished")),
            self._relay(worker.job_failed, lambda a: self._ended(a, "failed")),
            self._relay(worker.job_stopped, lambda a: self._ended(a, "stopped")),
            self._relay(worker.move_started, lambda a: self._started()),
            self._relay(worker.device_ready, lambda a: self._count("ready")),
            self._relay(worker.state_changed, self._state),
            self._relay(worker.speed_changed, lambda a: setattr(self, "speed", a[0])),
        ]

    @staticmethod
    def _relay(signal: Any, slot: Any) -> GuiRelay:
        relay = GuiRelay(signal)
        relay.fired.connect(slot)
        return relay

    def _ended(self, args: list[Any], how: str) -> None:
        self.outcomes.append((args[0], how, args[1]))

    def _started(self) -> None:
        self.starts, self.started_at = self.starts + 1, len(self.reports)

    def _state(self, args: list[Any]) -> None:
        if args[0] == "connecting":
            self.connecting_at = len(self.reports)

    def _count(self, name: str) -> None:
        setattr(self, name, getattr(self, name) + 1)

    def outcome(self, job: jobs.Job) -> tuple[str, object] | None:
        """How `job` ended (finished, failed, stopped; its result or message), or None yet."""
        return next(((how, what) for j, how, what in self.outcomes if j is job), None)


class WorkerTruthMachine(OperatorMachine):
    """One device, one worker on its thread; the truth is the simulator's `where`. Only the
    worker's signals are read: a step's report is held to the rule by the invariant."""

    qtbot: Any
    said = "the worker's last position_changed is"

    def __init__(self) -> None:
        super().__init__()
        self.thread = WorkerThread()
        self.seen = Seen(self.thread)
        self.thread.set_travel(parse_travel(TRAVEL))
        self.protocol = make_protocol(
            self.profile.protocol, None, self.profile.open_options.get("settings"), None
        )
        try:
            self._open()
        except BaseException:
            self.teardown()  # Hypothesis tears down only a machine it made
            raise

    # -- the worker, as the window drives it -------------------------------------------------
    def _open(self) -> None:
        options = ConnectOptions(settings=dict(self.profile.open_options.get("settings", {})))
        with wait_in_gui(self.qtbot, self.thread.worker.device_ready, timeout=10_000):
            self.thread.open(self.rig.path, self.profile.protocol, 115200, options)
        self.qtbot.waitUntil(lambda: self.seen.ready > 0 and bool(self.seen.reports), timeout=5000)

    def _do(self, job: jobs.Job, expect: tuple[str, ...] = ("finished",)) -> tuple[str, object]:
        """Submit `job` and wait (in the GUI thread) for how it ended."""
        self.thread.worker.submit(job)
        self.qtbot.waitUntil(lambda: self.seen.outcome(job) is not None, timeout=JOB_MS)
        how, what = self.seen.outcome(job) or ("", None)
        assert how in expect, f"{job.describe()}: {how}: {what}; steps: {self.history}"
        return how, what

    def _report(self) -> PositionReport:
        return self.seen.reports[-1]

    def _protocol(self) -> Protocol:
        return self.protocol

    def _speed(self) -> float:
        return self.seen.speed

    def _counted(self, report: PositionReport) -> bool:
        return self.counting and report.known

    def _look(self) -> None:
        """Position and speed read again (RefreshJob)."""
        self._do(jobs.RefreshJob())

    def _move_by(self, delta: Point) -> None:
        self._do(jobs.MoveByJob(*delta))

    def _move_to(self, target: Point) -> None:
        self._do(jobs.MoveToJob(*target))

    def _home(self) -> None:
        self._do(jobs.HomeJob())

    def _set_home(self) -> None:
        self._do(jobs.SetHomeJob())

    def _set_speed(self, value: float) -> None:
        """What the device will move at is said (speed_changed)."""
        _, result = self._do(jobs.SetSpeedJob(value))
        assert isinstance(result, float) and result > 0, (result, self.history)
        self.qtbot.waitUntil(lambda: self.seen.speed == result, timeout=5000)

    def _run_program(self, program: Toolpath, progress: ProgressListener) -> None:
        worker = self.thread.worker
        worker.stream_progress.connect(progress)  # direct: the pause lands where the sim is
        try:
            self._do(jobs.StreamJob(program), ("finished", "failed", "stopped"))
        finally:
            worker.stream_progress.disconnect(progress)

    def _pause_program(self, paused: bool) -> None:
        self.thread.stream_pause(paused)

    def _stop_program(self) -> None:
        self.thread.stream_stop()

    def _send_raw(self, data: bytes) -> None:
        self._do(jobs.RawJob(data))

    def _reopen(self) -> None:
        self.thread.close()
        self._open()

    def _begin_move_to(self, target: Point) -> None:
        self.starts, self.ready = self.seen.starts, self.seen.ready
        self.job = jobs.MoveToJob(*target)
        self.thread.worker.submit(self.job)
        self.qtbot.waitUntil(lambda: self.seen.starts > self.starts, timeout=5000)

    def _after_kill(self, target: Point, before: Point, at_kill: Point, moved: bool) -> None:
        """The worker says the move failed and connects again by itself (the lost port's path
        is back). What it said meanwhile, a claim, is a place the stage passed: between where
        the move began and where the device vanished."""
        self.qtbot.waitUntil(lambda: self.seen.outcome(self.job) is not None, timeout=JOB_MS)
        self.qtbot.waitUntil(lambda: self.seen.ready > self.ready, timeout=READY_MS)
        margin = self.profile.step * 1.01 + KILL_MARGIN
        ends = zip(before, at_kill, strict=True)
        passed = [(min(a, b) - margin, max(a, b) + margin) for a, b in ends]
        for report in self.seen.reports[self.seen.started_at : self.seen.connecting_at]:
            where = (report.x, report.y, report.z)
            assert not claims(report) or all(
                low <= v <= high for v, (low, high) in zip(where, passed, strict=True)
            ), (
                f"worker {self.profile.protocol}: during a go to {target} from {before} mm, the "
                f"device vanished at {at_kill} mm; the worker said {report}; steps: "
                f"{self.history}"
            )

    def teardown(self) -> None:
        """Stop the worker's thread and the simulator."""
        try:
            assert self.thread.stop()
        finally:
            self.rig.close()


@pytest.mark.parametrize(
    "protocol",
    [pytest.param(p, marks=pytest.mark.timeout(60 if p == "visiomex" else 40)) for p in PLAN],
)
def test_positions_the_worker_reports_are_the_devices(
    qtbot: Any, protocol: str, request: pytest.FixtureRequest
) -> None:
    run_model(WorkerTruthMachine, protocol, PLAN[protocol], request, name="worker", qtbot=qtbot)
