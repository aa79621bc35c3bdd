"""The operator's actions in the model-based truth tests as one state machine: a step at a
time, the rule after each (tests/support/model_truth.py), on one rig. Its subclasses say how an
action reaches the device: the scripting session (tests/drivers/session/test_model_truth.py), the
window's
worker on its thread (tests/app/window/device/test_model_truth_worker.py); `run_model` runs one,
seeded and
bounded, and says how many steps ran clean."""

from __future__ import annotations

import logging
import threading
from collections import Counter

import pytest
from hypothesis import seed
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule, run_state_machine_as_test

from drivers.protocols import commands as cmd
from drivers.protocols.base import Protocol
from drivers.protocols.events import PositionReport
from drivers.session.device_session import ProgressListener
from drivers.toolpath.loader import from_points
from drivers.toolpath.model import Toolpath
from drivers.toolpath.point_program import ProgramPoint
from drivers.toolpath.streaming import StreamProgress
from tests.support.model_truth import (
    BOX_MM,
    PROFILES,
    QUARTERS,
    TARGETS,
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

log = logging.getLogger(__name__)


class RigMachine(RuleBasedStateMachine):
    """A model on one rig: the truth is the simulator's `where` from the operator's home
    (`origin`); the steps it ran are counted by action (`ran`, given by `run_model`)."""

    profile: Profile
    ran: Counter[str]
    checked: Counter[str]
    """The reports checked, by kind (measured, confirmed, counted, not claimed)."""

    def __init__(self) -> None:
        super().__init__()
        self.rig = Rig(self.profile)
        self.origin: Point = (0.0, 0.0, 0.0)  # the operator's home in `where` mm (power-on)
        self.history: list[str] = []

    def _truth(self) -> Point:
        raw = self.rig.where()
        return (raw[0] - self.origin[0], raw[1] - self.origin[1], raw[2] - self.origin[2])

    def _step(self, what: str) -> None:
        self.history.append(what)
        self.ran[what.split()[0].split("(")[0]] += 1


class OperatorMachine(RigMachine):
    """The operator's actions on one device and the rule after each; how an action reaches
    the device (a session's call, a worker's job) is the subclass's. An action's hook returns
    the report to hold to the rule at once, or None (the invariant does, after the step)."""

    said = "the session reports"  # what a failure calls the report

    def __init__(self) -> None:
        super().__init__()
        # Whether the machine's own count starts from the operator's home (no loss since).
        self.counting = True

    # -- how the actions reach the device ------------------------------------------------------
    def _report(self) -> PositionReport:
        """The position last reported."""
        raise NotImplementedError

    def _protocol(self) -> Protocol:
        """The device's protocol (capabilities, encoding)."""
        raise NotImplementedError

    def _speed(self) -> float:
        """The speed the device moves at now (0: not known)."""
        raise NotImplementedError

    def _look(self) -> PositionReport | None:
        """Read the position (and the speed) again."""
        raise NotImplementedError

    def _move_by(self, delta: Point) -> PositionReport | None:
        raise NotImplementedError

    def _move_to(self, target: Point) -> PositionReport | None:
        raise NotImplementedError

    def _home(self) -> PositionReport | None:
        raise NotImplementedError

    def _set_home(self) -> None:
        raise NotImplementedError

    def _set_speed(self, value: float) -> None:
        """Set the speed; what the device will move at is checked."""
        raise NotImplementedError

    def _run_program(self, program: Toolpath, progress: ProgressListener) -> PositionReport | None:
        raise NotImplementedError

    def _pause_program(self, paused: bool) -> None:
        """Pause or resume the program (from the streaming thread or a timer's)."""
        raise NotImplementedError

    def _stop_program(self) -> None:
        """Stop the program (from the streaming thread)."""
        raise NotImplementedError

    def _send_raw(self, data: bytes) -> PositionReport | None:
        raise NotImplementedError

    def _reopen(self) -> None:
        """Disconnect and connect again."""
        raise NotImplementedError

    def _begin_move_to(self, target: Point) -> None:
        """Start a go-to; return once the move has begun."""
        raise NotImplementedError

    def _after_kill(self, target: Point, before: Point, at_kill: Point, moved: bool) -> None:
        """The go-to begun lost its device (at `at_kill`, from `before`): what was said of it
        is held to the rule, and the machine connects again."""
        raise NotImplementedError

    def _counted(self, report: PositionReport) -> bool:
        """Whether `report`, claiming nothing, is a count from the operator's home."""
        return self.counting

    # -- the rule ------------------------------------------------------------------------------
    def _here(self) -> Point:
        report = self._report()
        return (report.x, report.y, report.z)

    def _check(self, report: PositionReport, what: str) -> None:
        """The rule: a claim is the truth within a step; a count of the machine's own from the
        operator's home too, once its move had the time to end."""
        tolerance = self.profile.step * 1.01 + 1e-6
        truth = self._truth()
        if claims(report):
            kind = "measured" if report.measured else "confirmed"
        elif self._counted(report):
            kind = "counted"
            truth = settled(self.rig, self.origin, report, tolerance)
        else:
            self.checked["not claimed"] += 1  # not measured nor confirmed, or from no home
            return
        self.checked[kind] += 1
        assert off_by(report, truth) <= tolerance, (
            f"{self.profile.protocol}: after {what}: {self.said} {report} ({kind}); the device "
            f"is at {truth} mm; steps: {self.history}"
        )

    def _moved(self, report: PositionReport | None, what: str) -> None:
        """After a move: a device sent absolute targets (pi-frame, laser) is where it was
        sent, whatever was known before; then the rule on `report` (if any)."""
        if not self._protocol().capabilities.relative_moves:
            self.counting = True
        if report is not None:
            self._check(report, what)

    # -- operator actions ----------------------------------------------------------------------
    @rule()
    def check_readout(self) -> None:
        """The operator only looks (the panel's idle poll). Hypothesis's first example is its
        first rule (by arguments, then name) every step: this one, which costs little."""
        self._step("check_readout")
        report = self._look()
        if report is not None:
            self._check(report, "an idle poll")

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def jog(self, x: int, y: int, z: int) -> None:
        """Jog by a small step, turned back where it would leave the box."""
        delta = inside(self._here(), axes_mm(self.profile, x, y, z))
        self._step(f"jog{delta}")
        self._moved(self._move_by(delta), f"jog by {delta}")

    @rule(x=TARGETS, y=TARGETS, z=TARGETS)
    def go_to(self, x: int, y: int, z: int) -> None:
        """Go to a point in the box."""
        target = axes_mm(self.profile, x, y, z)
        self._step(f"go_to{target}")
        self._moved(self._move_to(target), f"go to {target}")

    @rule()
    def home(self) -> None:
        """Home: (0, 0, 0) by the device's homing or by the count."""
        self._step("home")
        self._moved(self._home(), "home")

    @rule()
    def set_home(self) -> None:
        """Set Home where the stage stands."""
        self._step("set_home")
        self._set_home()
        if not self.profile.origin_on_device:
            self.origin = self.rig.where()
        self.counting = True

    @rule(index=st.integers(0, 2))
    def speed(self, index: int) -> None:
        """Set one of the device's speeds."""
        value = self.profile.speeds[index % len(self.profile.speeds)]
        self._step(f"speed({value:g})")
        self._set_speed(value)

    @rule(
        points=st.lists(st.tuples(TARGETS, TARGETS, TARGETS), min_size=1, max_size=3),
        how=st.sampled_from(("run", "pause", "stop")),
    )
    def program(self, points: list[tuple[int, int, int]], how: str) -> None:
        """Run a short program to its end, paused once on the way, or stopped after the first
        point is sent (the Program dock's Pause and Stop, any thread)."""
        speed = self._speed() or self.profile.speeds[0]
        path = [ProgramPoint(*axes_mm(self.profile, *p), speed) for p in points]
        self._step(f"program {how} {[(p.x, p.y, p.z) for p in path]}")
        timers: list[threading.Timer] = []

        def progress(state: StreamProgress) -> None:  # in the streaming thread
            if state.sent >= 1 and how == "stop":
                self._stop_program()
            elif state.sent >= 1 and how == "pause" and not timers:
                self._pause_program(True)
                timers.append(threading.Timer(0.2, self._pause_program, (False,)))
                timers[0].start()

        try:
            report = self._run_program(from_points(path), progress)
        finally:
            for timer in timers:
                timer.join(5)
        self._moved(report, f"program ({how})")

    @rule(x=QUARTERS, y=QUARTERS, z=QUARTERS)
    def raw_move(self, x: int, y: int, z: int) -> None:
        """A move typed as the protocol's own bytes (the console's send line)."""
        here = self._here()
        delta = inside(here, axes_mm(self.profile, x, y, z))
        protocol = self._protocol()
        caps = protocol.capabilities
        speed = (self._speed() or None) if caps.speed_in_moves else None
        if caps.relative_moves:
            command: cmd.Command = cmd.MoveBy(*delta, speed=speed)
        else:
            target = tuple(h + d for h, d in zip(here, delta, strict=True))
            command = cmd.MoveTo(*target, speed=speed)
        self._step(f"raw {command}")
        self._moved(self._send_raw(protocol.encode(command)), f"raw {command}")

    @rule()
    def reopen(self) -> None:
        """Disconnect and connect again (the device goes on where it is)."""
        self._step("reopen")
        self._reopen()
        if not self._protocol().capabilities.position_feedback:
            self.counting = False  # a new session's count starts from nowhere it knows

    @rule(x=st.sampled_from((-1, 1)))
    def kill_mid_move(self, x: int) -> None:
        """The device vanishes during a go-to (along X) and is served again on the same path;
        what was said of the move is held to the rule, and the machine connects again."""
        here = self._here()
        target = (x * BOX_MM if abs(here[0] - x * BOX_MM) >= 2 else -x * BOX_MM, here[1], here[2])
        self._step(f"kill_mid_move to {target}")
        before = self._truth()
        self._begin_move_to(target)
        moved = moving(self.rig, self.rig.where())
        at_kill = self._truth()
        self.rig.kill_and_serve_again()
        self._after_kill(target, before, at_kill, moved)
        self.origin = (0.0, 0.0, 0.0)  # the device served again is at its power-on place
        self.counting = True  # ... which is where a new session's count starts

    @invariant()
    def position_is_true(self) -> None:
        """After every step, the position last reported."""
        self._check(self._report(), "the step")


def run_model(
    base: type[RigMachine],
    protocol: str,
    plan: tuple[int, int, int],
    request: pytest.FixtureRequest,
    name: str = "",
    **members: object,
) -> None:
    """Run `base` on `protocol`'s device for `plan` (examples, steps at most, seed); keep the
    steps run as the test's `model_steps` and log them ("model truth: NAME PROTOCOL: 48 steps
    ran clean (...)", shown by `pytest -rA`)."""
    examples, steps, seeded = plan
    ran: Counter[str] = Counter()
    checked: Counter[str] = Counter()
    members = {"profile": PROFILES[protocol], "ran": ran, "checked": checked, **members}
    machine = type(f"{base.__name__}_{protocol}", (base,), members)
    request.getfixturevalue("caplog").set_level(logging.INFO, logger=__name__)
    run_state_machine_as_test(seed(seeded)(machine), settings=machine_settings(examples, steps))
    request.node.user_properties.append(("model_steps", ran.total()))
    note = steps_note(ran) + (f"; reports: {steps_note(checked)}" if checked else "")
    who = f"{name} {protocol}".strip()
    log.info("model truth: %s: %d steps ran clean (%s)", who, ran.total(), note)
    assert ran.total() >= examples, "the model ran no steps"
