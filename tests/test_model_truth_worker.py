"""The model-based truth test (issue 28) through the window's worker: on each of the five
protocols, random sequences of operator actions (jog, go to, home, set home, speed, a program
run, paused or stopped, a raw move, disconnect and connect again, the device killed mid-move and
served again on the same path) as the window submits them to its SerialWorker on its QThread,
against `motionsim --control` in another process. Observed only through the worker's signals,
received in the GUI thread (tests/relay.py): after every step the last position_changed report,
if it claims to be the device's (measured, or commanded and confirmed, from a known place), is
the simulator's own `where` within one motor step; a count the worker's session keeps from its
own home is held to the same rule once its move had the time to end.

Seeded, no example database, no shrinking, bounded in steps and time; the steps that ran clean
are logged per protocol ("model truth: worker coxiris: 14 steps ran clean (...)") and kept as
the test's `model_steps` property.
"""

from __future__ import annotations

import logging
import threading
from collections import Counter
from typing import Any

import pytest
from hypothesis import seed
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule, run_state_machine_as_test
from PySide6.QtCore import QObject

from app.window import jobs
from app.window.worker import ConnectOptions
from app.window.worker_thread import WorkerThread
from drivers import commands as cmd
from drivers.events import PositionReport
from drivers.program import ProgramPoint
from drivers.session_setup import make_protocol
from drivers.streaming import StreamProgress
from drivers.toolpath.loader import from_points
from drivers.travel import parse_travel
from tests.model_truth_support import (
    BOX_MM,
    KILL_MARGIN,
    PROFILES,
    QUARTERS,
    TARGETS,
    TRAVEL,
    Point,
    Profile,
    Rig,
    axes_mm,
    claims,
    inside,
    machine_settings,
    moving,
    off_by,
    settled,
    steps_note,
)
from tests.relay import GuiRelay, wait_in_gui

pytestmark = [pytest.mark.e2e]
log = logging.getLogger(__name__)

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
STEPS: dict[str, Counter[str]] = {}
CHECKS: dict[str, Counter[str]] = {}
"""The reports checked after the steps, per protocol and kind (a claim, a count, neither)."""
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


class WorkerTruthMachine(RuleBasedStateMachine):
    """One device, one worker on its thread; the truth is the simulator's `where`."""

    profile: Profile
    qtbot: Any

    def __init__(self) -> None:
        super().__init__()
        self.rig = Rig(self.profile)
        self.thread = WorkerThread()
        self.seen = Seen(self.thread)
        self.thread.set_travel(parse_travel(TRAVEL))
        self.protocol = make_protocol(
            self.profile.protocol, None, self.profile.open_options.get("settings"), None
        )
        self.origin: Point = (0.0, 0.0, 0.0)  # the operator's home in `where` mm
        self.counting = True  # the worker's count starts from the operator's home
        self.history: list[str] = []
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

    def _here(self) -> Point:
        report = self.seen.reports[-1]
        return (report.x, report.y, report.z)

    def _truth(self) -> Point:
        raw = self.rig.where()
        return (raw[0] - self.origin[0], raw[1] - self.origin[1], raw[2] - self.origin[2])

    def _step(self, what: str) -> None:
        self.history.append(what)
        STEPS.setdefault(self.profile.protocol, Counter())[what.split()[0].split("(")[0]] += 1

    def _check(self, what: str) -> None:
        """The rule on the last report the worker gave: a claim is the truth within a step; a
        count of the worker's own from the operator's home too, once its move could end."""
        report = self.seen.reports[-1]
        tolerance = self.profile.step * 1.01 + 1e-6
        truth = self._truth()
        checked = CHECKS.setdefault(self.profile.protocol, Counter())
        if claims(report):
            kind = "measured" if report.measured else "confirmed"
        elif self.counting and report.known:
            kind = "counted"  # commanded, counted from the worker's own home
            truth = settled(self.rig, self.origin, report, tolerance)
        else:
            checked["not claimed"] += 1  # not measured nor confirmed, or from no known home
            return
        checked[kind] += 1
        assert off_by(report, truth) <= tolerance, (
            f"worker {self.profile.protocol}: after {what}: the last position_changed is "
            f"{report} ({kind}); the device is at {truth} mm; steps: {self.history}"
        )

    def _moved(self) -> None:
        """A device sent absolute targets (pi-frame, laser) is where it was sent."""
        if not self.protocol.capabilities.relative_moves:
            self.counting = True

    # -- operator actions ----------------------------------------------------------------------
    @rule()
    def check_readout(self) -> None:
        """The operator only looks: position and speed read again (RefreshJob). Hypothesis's
        first example is its first rule (by arguments, then name) every step: this one, which
        costs little."""
        self._step("check_readout")
        self._do(jobs.RefreshJob())

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def jog(self, x: int, y: int, z: int) -> None:
        """Jog by a small step, turned back where it would leave the box."""
        delta = inside(self._here(), axes_mm(self.profile, x, y, z))
        self._step(f"jog{delta}")
        self._do(jobs.MoveByJob(*delta))
        self._moved()

    @rule(x=TARGETS, y=TARGETS, z=TARGETS)
    def go_to(self, x: int, y: int, z: int) -> None:
        """Go to a point in the box."""
        target = axes_mm(self.profile, x, y, z)
        self._step(f"go_to{target}")
        self._do(jobs.MoveToJob(*target))
        self._moved()

    @rule()
    def home(self) -> None:
        """Home: (0, 0, 0) by the device's homing or by the count."""
        self._step("home")
        self._do(jobs.HomeJob())
        self._moved()

    @rule()
    def set_home(self) -> None:
        """Set Home where the stage stands."""
        self._step("set_home")
        self._do(jobs.SetHomeJob())
        if not self.profile.origin_on_device:
            self.origin = self.rig.where()
        self.counting = True

    @rule(index=st.integers(0, 2))
    def speed(self, index: int) -> None:
        """Set one of the device's speeds; what it will move at is said (speed_changed)."""
        value = self.profile.speeds[index % len(self.profile.speeds)]
        self._step(f"speed({value:g})")
        _, result = self._do(jobs.SetSpeedJob(value))
        assert isinstance(result, float) and result > 0, (result, self.history)
        self.qtbot.waitUntil(lambda: self.seen.speed == result, timeout=5000)

    @rule(
        points=st.lists(st.tuples(TARGETS, TARGETS, TARGETS), min_size=1, max_size=3),
        how=st.sampled_from(("run", "pause", "stop")),
    )
    def program(self, points: list[tuple[int, int, int]], how: str) -> None:
        """Run a short program to its end, paused once on the way, or stopped after the first
        point is sent (the Program dock's Pause and Stop, any thread)."""
        speed = self.seen.speed or self.profile.speeds[0]
        path = [ProgramPoint(*axes_mm(self.profile, *p), speed) for p in points]
        self._step(f"program {how} {[(p.x, p.y, p.z) for p in path]}")
        timers: list[threading.Timer] = []

        def progress(state: StreamProgress) -> None:  # in the worker's thread, as it streams
            if state.sent >= 1 and how == "stop":
                self.thread.stream_stop()
            elif state.sent >= 1 and how == "pause" and not timers:
                self.thread.stream_pause(True)
                timers.append(threading.Timer(0.2, self.thread.stream_pause, (False,)))
                timers[0].start()

        worker = self.thread.worker
        worker.stream_progress.connect(progress)  # direct: the pause lands where the sim is
        try:
            self._do(jobs.StreamJob(from_points(path)), ("finished", "failed", "stopped"))
        finally:
            worker.stream_progress.disconnect(progress)
            for timer in timers:
                timer.join(5)
        self._moved()

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def raw_move(self, x: int, y: int, z: int) -> None:
        """A move typed as the protocol's own bytes (the console's send line)."""
        here = self._here()
        delta = inside(here, axes_mm(self.profile, x, y, z))
        caps = self.protocol.capabilities
        speed = (self.seen.speed or None) if caps.speed_in_moves else None
        if caps.relative_moves:
            command: cmd.Command = cmd.MoveBy(*delta, speed=speed)
        else:
            target = tuple(h + d for h, d in zip(here, delta, strict=True))
            command = cmd.MoveTo(*target, speed=speed)
        self._step(f"raw {command}")
        self._do(jobs.RawJob(self.protocol.encode(command)))
        self._moved()

    @rule()
    def reopen(self) -> None:
        """Disconnect and connect again through the worker (the device goes on where it is)."""
        self._step("reopen")
        self.thread.close()
        self._open()
        if not self.protocol.capabilities.position_feedback:
            self.counting = False  # a new session's count starts from nowhere it knows

    @rule(x=st.sampled_from((-1, 1)))
    def kill_mid_move(self, x: int) -> None:
        """The device vanishes during a go-to (along X) and is served again on the same path:
        the worker says the move failed and connects again by itself (the lost port's path is
        back). What it said meanwhile, a claim, is a place the stage passed: between where the
        move began and where the device vanished."""
        here = self._here()
        target = (x * BOX_MM if abs(here[0] - x * BOX_MM) >= 2 else -x * BOX_MM, here[1], here[2])
        self._step(f"kill_mid_move to {target}")
        starts, ready = self.seen.starts, self.seen.ready
        before = self._truth()
        job = jobs.MoveToJob(*target)
        self.thread.worker.submit(job)
        self.qtbot.waitUntil(lambda: self.seen.starts > starts, timeout=5000)
        moving(self.rig, self.rig.where())
        truth_at_kill = self._truth()
        self.rig.kill_and_serve_again()
        self.qtbot.waitUntil(lambda: self.seen.outcome(job) is not None, timeout=JOB_MS)
        self.qtbot.waitUntil(lambda: self.seen.ready > ready, timeout=READY_MS)
        margin = self.profile.step * 1.01 + KILL_MARGIN
        ends = zip(before, truth_at_kill, strict=True)
        passed = [(min(a, b) - margin, max(a, b) + margin) for a, b in ends]
        for report in self.seen.reports[self.seen.started_at : self.seen.connecting_at]:
            where = (report.x, report.y, report.z)
            assert not claims(report) or all(
                low <= v <= high for v, (low, high) in zip(where, passed, strict=True)
            ), (
                f"worker {self.profile.protocol}: during a go to {target} from {before} mm, the "
                f"device vanished at {truth_at_kill} mm; the worker said {report}; steps: "
                f"{self.history}"
            )
        self.origin = (0.0, 0.0, 0.0)  # the device served again is at its power-on place
        self.counting = True  # ... which is where the new session's count starts

    @invariant()
    def position_is_true(self) -> None:
        """After every step, the last position the worker reported."""
        self._check("the step")

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
    qtbot: Any, protocol: str, request: pytest.FixtureRequest, caplog: pytest.LogCaptureFixture
) -> None:
    caplog.set_level(logging.INFO, logger=__name__)
    STEPS[protocol], CHECKS[protocol] = Counter(), Counter()
    examples, steps, seeded = PLAN[protocol]
    members = {"profile": PROFILES[protocol], "qtbot": qtbot}
    machine = type(f"WorkerTruthMachine_{protocol}", (WorkerTruthMachine,), members)
    settings = machine_settings(examples, steps)
    run_state_machine_as_test(seed(seeded)(machine), settings=settings)
    ran = STEPS[protocol]
    request.node.user_properties.append(("model_steps", ran.total()))
    note = f"{steps_note(ran)}; reports: {steps_note(CHECKS[protocol])}"
    log.info("model truth: worker %s: %d steps ran clean (%s)", protocol, ran.total(), note)
    assert ran.total() >= examples, "the model ran no steps"
