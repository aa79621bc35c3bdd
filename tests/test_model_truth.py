"""A model-based test of the truth of positions (issue 28): on each of the five protocols,
random sequences of operator actions (jog, go to, home, set home, speed, a program run, paused
or stopped, a raw move, disconnect and reopen, the device killed mid-move and served again on the
same path) through the scripting session, against `motionsim --control` in another process over
a pty. After every step the position the session reports equals the simulator's own axes
(`where`) within one motor step, or is marked as not measured and not confirmed: a measured
report or a "commanded, confirmed" one is a claim of truth, never a confident wrong value. A
commanded count the session keeps from its own Set Home (Visiomex, Firmata, pi-frame) is held to
the same rule once its move had the time to end. A second, smaller machine drives the same
actions through motionctl, one process a run, on the protocols whose position motionctl keeps
between runs (pi-frame, Firmata, Visiomex): what a run prints as the position is the device's,
and a run refused for want of a position ("position unknown") moved nothing.

Seeded (a seed per protocol, no example database, no shrinking), bounded in steps and time;
the steps that ran clean are logged per protocol (`pytest -rA` shows them: "model truth:
coxiris: 48 steps ran clean (...)") and kept as the test's `model_steps` property. The
defects it found are fixed; each is kept as its smallest example at the end of this file.
"""

from __future__ import annotations

import logging
import threading
from collections import Counter
from collections.abc import Iterator

import pytest
from hypothesis import HealthCheck, Phase, seed, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule, run_state_machine_as_test

from drivers import commands as cmd
from drivers.events import PositionReport
from drivers.program import ProgramPoint
from drivers.streaming import StreamProgress
from drivers.toolpath.loader import from_points
from tests.model_truth_support import (
    BOX_MM,
    PROFILES,
    Point,
    Profile,
    Rig,
    axes_mm,
    claims,
    inside,
    motionctl_run,
    moving,
    off_by,
    run_report,
    settled,
    still,
)

pytestmark = [pytest.mark.e2e]
log = logging.getLogger(__name__)

# Examples and steps per protocol: about 90 s for all five on a 2-core machine. A Visiomex
# move is a packet and 1 s of silence, so it gets fewer steps.
BUDGET = {
    "coxiris": (4, 12),
    "laser-frame": (4, 12),
    "pi-frame": (4, 12),
    "firmata": (3, 10),
    "visiomex": (3, 6),
}
# Each protocol's seed, picked for a mix of every action (Hypothesis turns some rules off in
# each example, and its first example is the first rule, check_readout, at every step).
SEEDS = {"coxiris": 58, "laser-frame": 4, "pi-frame": 46, "firmata": 48, "visiomex": 109}
STEPS: dict[str, Counter[str]] = {}
"""Steps that ran and were checked, per protocol and action (reported after each test)."""
QUARTERS = st.integers(-8, 8)  # a jog: -2..2 mm in quarters of a mm (whole steps everywhere)
TARGETS = st.integers(-12, 12)  # a target: -3..3 mm, inside the box
KILL_MARGIN = 0.1  # mm the stage may move between the last `where` and the kill


class TruthMachine(RuleBasedStateMachine):
    """One device, one session; the truth is the simulator's `where`."""

    profile: Profile

    def __init__(self) -> None:
        super().__init__()
        self.rig = Rig(self.profile)
        self.session = self.rig.open()
        self.origin: Point = (0.0, 0.0, 0.0)  # the operator's home in `where` mm (power-on)
        # Whether the session's own count starts from the operator's home (no loss since).
        self.counting = True
        self.speed_now = self.session.speed()
        self.history: list[str] = []

    # -- what the model keeps ------------------------------------------------------------------
    def _axes(self, x: int, y: int, z: int) -> Point:
        return axes_mm(self.profile, x, y, z)

    def _here(self) -> Point:
        report = self.session.position()
        return (report.x, report.y, report.z)

    def _truth(self) -> Point:
        raw = self.rig.where()
        return (raw[0] - self.origin[0], raw[1] - self.origin[1], raw[2] - self.origin[2])

    def _step(self, what: str) -> None:
        self.history.append(what)
        STEPS.setdefault(self.profile.protocol, Counter())[what.split()[0].split("(")[0]] += 1

    def _check(self, report: PositionReport, what: str) -> None:
        """The rule: a claim is the truth within a step; a count of the session's own too."""
        tolerance = self.profile.step * 1.01 + 1e-6
        truth = self._truth()
        if claims(report):
            kind = "measured" if report.measured else "commanded, confirmed"
        elif self.counting:
            kind = "commanded, counted from the session's own home"
            truth = settled(self.rig, self.origin, report, tolerance)
        else:
            return  # marked as not measured, not confirmed, and counted from no known home
        assert off_by(report, truth) <= tolerance, (
            f"{self.profile.protocol}: after {what}: the session reports {report} ({kind}); "
            f"the device is at {truth} mm; steps: {self.history}"
        )

    def _moved(self, report: PositionReport, what: str) -> None:
        """After a move: a device sent absolute targets (pi-frame, laser) is where the session
        sent it, whatever it knew before; then the rule."""
        if not self.session.capabilities.relative_moves:
            self.counting = True
        self._check(report, what)

    # -- operator actions ----------------------------------------------------------------------
    @rule()
    def check_readout(self) -> None:
        """The operator only looks (the panel's idle poll). Hypothesis's first example is its
        first rule (by arguments, then name) every step: this one, which costs nothing."""
        self._step("check_readout")
        self._check(self.session.position(), "an idle poll")

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def jog(self, x: int, y: int, z: int) -> None:
        """Jog by a small step, turned back where it would leave the box."""
        here = self._here()
        delta = inside(here, self._axes(x, y, z))
        self._step(f"jog{delta}")
        self._moved(self.session.move_by(*delta), f"jog by {delta}")

    @rule(x=TARGETS, y=TARGETS, z=TARGETS)
    def go_to(self, x: int, y: int, z: int) -> None:
        """Go to a point in the box."""
        target = self._axes(x, y, z)
        self._step(f"go_to{target}")
        self._moved(self.session.move_to(*target), f"go to {target}")

    @rule()
    def home(self) -> None:
        """Home: (0, 0, 0) by the device's homing or by the count."""
        self._step("home")
        self._moved(self.session.home(), "home")

    @rule()
    def set_home(self) -> None:
        """Set Home where the stage stands."""
        self._step("set_home")
        self.session.set_home()
        if not self.profile.origin_on_device:
            self.origin = self.rig.where()
        self.counting = True

    @rule(index=st.integers(0, 2))
    def speed(self, index: int) -> None:
        """Set one of the device's speeds; the device reports it."""
        value = self.profile.speeds[index % len(self.profile.speeds)]
        self._step(f"speed({value:g})")
        # What the device reports, or the speed it will really move at (Visiomex times its
        # steps from its step delays: not the speed asked for, issue 28 item 3).
        self.speed_now = self.session.speed(value)
        assert self.session.speed() == self.speed_now > 0, self.history

    @rule(
        points=st.lists(st.tuples(TARGETS, TARGETS, TARGETS), min_size=1, max_size=3),
        how=st.sampled_from(("run", "pause", "stop")),
    )
    def program(self, points: list[tuple[int, int, int]], how: str) -> None:
        """Run a short program to its end, paused once on the way, or stopped after the first
        point is sent."""
        path = [ProgramPoint(*self._axes(*p), self.speed_now) for p in points]
        self._step(f"program {how} {[(p.x, p.y, p.z) for p in path]}")
        timers: list[threading.Timer] = []

        def progress(state: StreamProgress) -> None:
            if state.sent >= 1 and how == "stop":
                self.session.stop_program()
            elif state.sent >= 1 and how == "pause" and not timers:
                self.session.pause_program(True)
                timers.append(threading.Timer(0.2, self.session.pause_program, (False,)))
                timers[0].start()

        self.session.run_program(from_points(path), progress)
        for timer in timers:
            timer.join(5)
        self._moved(self.session.position(), f"program ({how})")

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def raw_move(self, x: int, y: int, z: int) -> None:
        """A move typed as the protocol's own bytes (the console's send line)."""
        here = self._here()
        delta = inside(here, self._axes(x, y, z))
        caps = self.session.capabilities
        speed = self.speed_now if caps.speed_in_moves else None
        if caps.relative_moves:
            command: cmd.Command = cmd.MoveBy(*delta, speed=speed)
        else:
            target = tuple(h + d for h, d in zip(here, delta, strict=True))
            command = cmd.MoveTo(*target, speed=speed)
        data = self.session.protocol.encode(command)
        self._step(f"raw {command}")
        result = self.session.motion.send_raw(data)
        assert isinstance(result, PositionReport), (result, self.history)
        self._moved(result, f"raw {command}")

    @rule()
    def reopen(self) -> None:
        """Disconnect and connect again (the device goes on where it is)."""
        self._step("reopen")
        self.session.close()
        self.session = self.rig.open()
        self.speed_now = self.session.speed()
        if not self.session.capabilities.position_feedback:
            self.counting = False  # a new session's count starts from nowhere it knows

    @rule(x=st.sampled_from((-1, 1)))
    def kill_mid_move(self, x: int) -> None:
        """The device vanishes during a go-to; it is served again on the same path and the
        session opened again."""
        here = self._here()
        target = (x * BOX_MM if abs(here[0] - x * BOX_MM) >= 2 else -x * BOX_MM, here[1], here[2])
        self._step(f"kill_mid_move to {target}")
        started = threading.Event()
        self.session.motion.move_listeners.append(lambda move: started.set())
        outcome: list[PositionReport | BaseException] = []

        def move() -> None:
            try:
                outcome.append(self.session.move_to(*target))
            except Exception as exc:  # whatever the lost device makes of the move
                outcome.append(exc)

        mover = threading.Thread(target=move, daemon=True)
        mover.start()
        assert started.wait(5), self.history
        start = self.rig.where()
        moved = moving(self.rig, start)
        truth_at_kill = self._truth()
        self.rig.kill_and_serve_again()
        mover.join(30)
        assert not mover.is_alive(), (
            f"the move did not end when its device vanished: {self.history}"
        )
        report = outcome[0]
        if isinstance(report, PositionReport) and claims(report) and moved:
            assert off_by(report, truth_at_kill) <= self.profile.step + KILL_MARGIN, (
                f"{self.profile.protocol}: the device vanished at {truth_at_kill} mm during a "
                f"go to {target}; the session reported {report}; steps: {self.history}"
            )
        self.session.close()
        self.session = self.rig.open()
        self.speed_now = self.session.speed()
        self.origin = (0.0, 0.0, 0.0)  # the device served again is at its power-on place
        self.counting = True  # ... which is where a new session's count starts

    @invariant()
    def position_is_true(self) -> None:
        """After every step, the position the session reports."""
        self._check(self.session.position(), "the step")

    def teardown(self) -> None:
        """Close the session and stop the simulator."""
        try:
            self.session.close()
        finally:
            self.rig.close()


def _settings(examples: int, steps: int) -> settings:
    """Bounded: so many examples of at most so many steps, no database, no shrinking."""
    return settings(
        max_examples=examples,
        stateful_step_count=steps,
        deadline=None,
        database=None,
        phases=(Phase.explicit, Phase.generate),  # no shrinking: the time stays bounded
        suppress_health_check=list(HealthCheck),
    )


def _machine(protocol: str) -> type[TruthMachine]:
    """The machine for one protocol, seeded: the same steps on every run."""
    machine = type(f"TruthMachine_{protocol}", (TruthMachine,), {"profile": PROFILES[protocol]})
    return seed(SEEDS[protocol])(machine)


@pytest.fixture
def steps_report(request: pytest.FixtureRequest, caplog: pytest.LogCaptureFixture) -> Iterator[str]:
    """Logs, and keeps as the test's property, how many steps ran clean."""
    protocol = request.node.callspec.params["protocol"]
    caplog.set_level(logging.INFO, logger=__name__)
    STEPS[protocol] = Counter()
    yield protocol
    ran = STEPS[protocol]
    request.node.user_properties.append(("model_steps", ran.total()))
    actions = ", ".join(f"{name} {count}" for name, count in sorted(ran.items()))
    log.info("model truth: %s: %d steps ran clean (%s)", protocol, ran.total(), actions)


@pytest.mark.parametrize(
    "protocol",
    # About 35 s for Visiomex, 15 s for the others on a quiet machine: twice or more that.
    [pytest.param(p, marks=pytest.mark.timeout(90 if p == "visiomex" else 45)) for p in BUDGET],
)
def test_positions_reported_are_the_devices(protocol: str, steps_report: str) -> None:
    examples, steps = BUDGET[protocol]
    run_state_machine_as_test(
        _machine(protocol),
        settings=_settings(examples, steps),
    )
    assert STEPS[protocol].total() >= examples, "the model ran no steps"


# -- the same actions through motionctl, one process a run ---------------------------------
CTL_BUDGET = {"pi-frame": (2, 6), "firmata": (2, 6), "visiomex": (2, 5)}
"""Examples and steps: the protocols whose position motionctl keeps between runs."""
CTL_SEEDS = {"pi-frame": 78, "firmata": 54, "visiomex": 49}
UNKNOWN = "position unknown"  # how motionctl refuses a move it has no position for


class MotionctlMachine(RuleBasedStateMachine):
    """One device; every action a motionctl run of its own, the count kept in the test's
    settings file (tests/conftest.py: a temporary MOTIONPANEL_SETTINGS) between runs."""

    profile: Profile

    def __init__(self) -> None:
        super().__init__()
        self.rig = Rig(self.profile)  # a new path each example: no count kept for it yet
        self.origin: Point = (0.0, 0.0, 0.0)
        self.known = self.profile.protocol not in ("visiomex", "firmata", "pi-frame")
        self.history: list[str] = []
        if self.profile.protocol == "firmata":  # its stepper, kept for the port
            configured = motionctl_run(self.rig, "config", "--steps-per-rev", "200", "--pins",
                                       "8", "9")  # fmt: skip
            assert configured.returncode == 0, configured.stderr

    def _truth(self) -> Point:
        raw = self.rig.where()
        return (raw[0] - self.origin[0], raw[1] - self.origin[1], raw[2] - self.origin[2])

    def _run(self, *args: str) -> PositionReport | None:
        """A run; the rule on what it printed (or on its refusal: nothing moved)."""
        what = " ".join(args)
        self.history.append(what)
        STEPS.setdefault("motionctl " + self.profile.protocol, Counter())[args[0]] += 1
        before = self.rig.where()
        run = motionctl_run(self.rig, *args)
        if run.returncode != 0:
            refused = not self.known and run.returncode == 2 and UNKNOWN in run.stderr
            assert refused, f"motionctl {what}: exit {run.returncode}: {run.stderr}; {self.history}"
            assert self.rig.where() == before, f"refused, yet moved: {self.history}"
            return None
        report = run_report(run)
        if report is not None:
            tolerance = self.profile.step * 1.01 + 1e-6
            truth = (
                self._truth()
                if report.measured
                else settled(self.rig, self.origin, report, tolerance)
            )
            assert not claims(report) or off_by(report, truth) <= tolerance, (
                f"{self.profile.protocol}: motionctl {what} printed {run.stdout.strip()}; the "
                f"device is at {truth} mm; runs: {self.history}"
            )
        return report

    @rule()
    def check_position(self) -> None:
        """`motionctl position` (Hypothesis's first example: this, every step)."""
        self._run("position")

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def jog(self, x: int, y: int, z: int) -> None:
        """`motionctl jog`, turned back where it would leave the box."""
        here = self._truth() if self.known else (0.0, 0.0, 0.0)
        delta = inside(here, axes_mm(self.profile, x, y, z))
        self._run("jog", *(f"{d:g}" for d in delta[: self.profile.axes]))

    @rule(x=TARGETS, y=TARGETS, z=TARGETS)
    def move(self, x: int, y: int, z: int) -> None:
        """`motionctl move` to a point in the box."""
        target = axes_mm(self.profile, x, y, z)
        if self._run("move", *(f"{v:g}" for v in target[: self.profile.axes])) is not None:
            self.known = True  # an absolute target (pi-frame) is known once reached

    @rule()
    def home(self) -> None:
        """`motionctl home`."""
        self._run("home")

    @rule()
    def set_home(self) -> None:
        """`motionctl set-home`: the count starts here (where the stage stands still)."""
        if not self.profile.origin_on_device:
            self.origin = self.rig.where()
        self.known = True
        self._run("set-home")

    @rule(index=st.integers(0, 2))
    def speed(self, index: int) -> None:
        """`motionctl speed`."""
        self._run("speed", f"{self.profile.speeds[index % len(self.profile.speeds)]:g}")

    def teardown(self) -> None:
        """Stop the simulator."""
        self.rig.close()


@pytest.mark.parametrize(
    "protocol", [pytest.param(p, marks=pytest.mark.timeout(60)) for p in CTL_BUDGET]
)
def test_motionctl_positions_across_runs_are_the_devices(
    protocol: str, request: pytest.FixtureRequest, caplog: pytest.LogCaptureFixture
) -> None:
    caplog.set_level(logging.INFO, logger=__name__)
    STEPS["motionctl " + protocol] = Counter()
    examples, steps = CTL_BUDGET[protocol]
    machine = type(f"MotionctlMachine_{protocol}", (MotionctlMachine,),
                   {"profile": PROFILES[protocol]})  # fmt: skip
    run_state_machine_as_test(seed(CTL_SEEDS[protocol])(machine), settings=_settings(examples,
                              steps))  # fmt: skip
    ran = STEPS["motionctl " + protocol]
    request.node.user_properties.append(("model_steps", ran.total()))
    actions = ", ".join(f"{name} {count}" for name, count in sorted(ran.items()))
    log.info("model truth: motionctl %s: %d runs ran clean (%s)", protocol, ran.total(), actions)
    assert ran.total() >= examples, "the model ran no steps"


# -- the defects the model found, each as its smallest example ------------------------------


@pytest.mark.timeout(30)
def test_visiomex_count_after_reopen() -> None:
    """Jog X 0.25, disconnect, reopen, jog X 0.25: the device is at 0.5 mm from where it was
    switched on (and from the first session's origin); the second session counts 0.25 from
    where it opened, which it must say is no known place (it said "commanded, confirmed")."""
    rig = Rig(PROFILES["visiomex"])
    try:
        with rig.open() as first:
            first.move_by(0.25, 0)
        with rig.open() as second:
            report = second.move_by(0.25, 0)
        assert rig.where() == pytest.approx((0.5, 0.0, 0.0), abs=0.026)
        assert not report.known and "position unknown" in str(report), report
        assert not claims(report) or off_by(report, rig.where()) <= 0.026, report
    finally:
        rig.close()


@pytest.mark.timeout(30)
def test_laser_move_end_is_not_reported_early() -> None:
    """At 0.1 mm/s, jog X 0.01 mm (0.1 s of motion): the first poll found the stage within
    0.011 mm of the target and the jog returned at once, "measured" at about 0, while the stage
    stood at 0.01 when it stopped. The move ends where the stage stops (within float32)."""
    rig = Rig(PROFILES["laser-frame"])
    try:
        with rig.open() as laser:
            laser.speed(0.1)
            report = laser.move_by(0.01, 0)
            stands = still(rig)
        assert stands == pytest.approx((0.01, 0.0, 0.0), abs=1e-6)
        assert not claims(report) or off_by(report, stands) <= 0.001, report
    finally:
        rig.close()
