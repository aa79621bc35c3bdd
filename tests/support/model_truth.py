"""What the model-based truth tests (tests/drivers/session/test_model_truth.py,
tests/app/window/device/test_model_truth_worker.py)
stand on: each protocol's simulator in another process on a fixed path, read through its own
`where`, and the rule that a position claimed (measured, or commanded and confirmed) is the
device's. The operator's actions as a state machine are in tests/support/model_truth_machine.py."""

from __future__ import annotations

import json
import math
import signal
import tempfile
import time
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, Phase, settings
from hypothesis import strategies as st

import drivers
from drivers.protocols.events import PositionReport
from drivers.session.device_session import DeviceSession
from tests.support.e2e import Run, motionctl
from tests.support.simproc import SimProcess

Point = tuple[float, float, float]
BOX_MM = 3.0  # every X and Y target the model picks lies within ±BOX_MM
BOX = (BOX_MM, BOX_MM, 1.0)  # ... and Z within ±1 mm
TRAVEL = "-4:4,-4:4,-1:1"  # the session's travel box, a little wider than the model's
SETTLE_S = 3.0  # a commanded (unconfirmed) count may take this long to be reached
MOVE_START_S = 4.0  # a Visiomex move starts after 1 s of silence and its debug lines
KILL_MARGIN = 0.1  # mm the stage may move between the last `where` and a kill
QUARTERS = st.integers(-8, 8)  # a jog's axis: -2..2 mm in quarters of a mm (whole steps)
TARGETS = st.integers(-12, 12)  # a target's axis: -3..3 mm in quarters of a mm, in the box
FIRMATA = {"steps_per_mm": 80.0, "steps_per_rev": 200.0, "pin1": 8.0, "pin2": 9.0}


@dataclass(frozen=True)
class Profile:
    """One protocol as the model drives it."""

    protocol: str
    sim_args: tuple[str, ...] = ()
    open_options: dict[str, Any] = field(default_factory=dict)
    per_mm: float = 1.0
    """`where` units a mm (pi-frame: ticks, Firmata: steps)."""
    step: float = 0.01
    """One motor step (or the finest position the device reports), mm: the tolerance."""
    axes: int = 3
    """Axes the model moves (Visiomex X, Y; Firmata X)."""
    origin_on_device: bool = True
    """Set Home makes the device's own axes (0, 0, 0); False: `where` counts from power-on
    (Visiomex, Firmata) and the model keeps the origin."""
    speeds: tuple[float, ...] = (5.0, 10.0, 20.0)
    cli_options: tuple[str, ...] = ()
    """What motionctl is given on every run (Firmata: its steps per mm)."""


PROFILES: dict[str, Profile] = {
    "coxiris": Profile("coxiris"),
    "laser-frame": Profile("laser-frame", step=0.001),
    "pi-frame": Profile("pi-frame", per_mm=100.0),  # ticks per mm: the protocol's default
    # At power-on parameters: cycle 10 mm, 400 steps a turn: 0.025 mm a step (visiomex_model).
    "visiomex": Profile("visiomex", step=0.025, axes=2, origin_on_device=False, speeds=(10, 20)),
    "firmata": Profile(
        "firmata",
        ("--reset-delay", "0.2"),
        {"settings": FIRMATA},
        per_mm=80.0,
        step=1 / 80,
        axes=1,
        origin_on_device=False,
        cli_options=("--steps-per-mm", "80"),
    ),
}


class Rig:
    """A motionsim process serving `profile`'s device under one fixed path (`--link`), which
    survives the device being killed and served again."""

    def __init__(self, profile: Profile) -> None:
        self.profile = profile
        self._dir = tempfile.TemporaryDirectory(prefix="model-truth-")
        self.path = str(Path(self._dir.name) / "device")
        self.sim = self._serve()
        self.restarts = 0

    def _serve(self) -> SimProcess:
        return SimProcess(self.profile.protocol, "--link", self.path, *self.profile.sim_args,
                          control=True)  # fmt: skip

    def open(self) -> DeviceSession:
        """A session on the device, through the public API."""
        return drivers.open_device(
            self.path, self.profile.protocol, travel=TRAVEL, **self.profile.open_options
        )

    def where(self) -> Point:
        """Where the simulator's axes are, in mm (axes it has not: 0)."""
        values = [float(v) / self.profile.per_mm for v in self.sim.fault("where").split()[2:]]
        values += [0.0] * (3 - len(values))
        return (values[0], values[1], values[2])

    def kill_and_serve_again(self) -> None:
        """The device vanishes at once (SIGKILL), and a fresh one is served on the same path."""
        self.sim.kill()
        self.sim = self._serve()
        self.restarts += 1

    def close(self) -> None:
        """Stop the simulator and remove its folder."""
        try:
            if self.sim.proc.poll() is None:
                self.sim.stop(signal.SIGTERM)
        finally:
            self._dir.cleanup()


def motionctl_run(rig: Rig, *args: str) -> Run:
    """One motionctl run on the rig's device (--json, the model's travel box)."""
    profile = rig.profile
    options = ("--json", "--travel", TRAVEL, *profile.cli_options)
    return motionctl(profile.protocol, rig.path, *args, options=options, timeout=30)


def run_report(run: Run) -> PositionReport | None:
    """The position a motionctl run printed (None: none, or unknown): measured unless it says
    otherwise; a count (Visiomex, Firmata) or a kept commanded position (pi-frame) counts as
    confirmed, for motionctl gives it as the device's."""
    out = json.loads(run.stdout) if run.stdout.strip() else {}
    if out.get("position") is None:  # none, or null: "position unknown" (position_note)
        return None
    x, y, z = [*out["position"], 0.0, 0.0][:3]
    measured = bool(out.get("measured", True))
    counted = bool(out.get("counted") or out.get("commanded"))
    return PositionReport(x, y, z, measured=measured, confirmed=counted)


def axes_mm(profile: Profile, x: int, y: int, z: int) -> Point:
    """Quarters of a mm (Z: eighths, to a quarter) as mm, on the axes the device moves."""
    keep_y = profile.axes >= 2
    return (x / 4, y / 4 if keep_y else 0.0, round(z / 8) / 4 if profile.axes >= 3 else 0.0)


def claims(report: PositionReport) -> bool:
    """Whether a report says it is the device's position (measured, or confirmed arrived,
    from a known place)."""
    return report.known and (report.measured or report.confirmed)


def off_by(report: PositionReport, truth: Sequence[float]) -> float:
    """The largest axis difference between a report and the truth, mm."""
    return max(abs(a - b) for a, b in zip((report.x, report.y, report.z), truth, strict=True))


def settled(rig: Rig, origin: Point, report: PositionReport, tolerance: float) -> Point:
    """The truth once it stops changing or reaches `report` (a commanded count whose move the
    session stopped waiting for by estimate), within SETTLE_S; the last truth read."""
    deadline = time.monotonic() + SETTLE_S
    previous: Point | None = None
    while True:
        raw = rig.where()
        truth = (raw[0] - origin[0], raw[1] - origin[1], raw[2] - origin[2])
        if off_by(report, truth) <= tolerance or time.monotonic() > deadline:
            return truth
        if previous is not None and math.dist(previous, truth) == 0.0:
            return truth  # the device stands still elsewhere
        previous = truth
        time.sleep(0.05)  # a poll interval (bounded by SETTLE_S), not a synchronisation


def inside(here: Point, delta: Point) -> Point:
    """A jog turned back on each axis where it would leave the model's box."""
    x, y, z = (-d if abs(h + d) > box else d for h, d, box in zip(here, delta, BOX, strict=True))
    return (x, y, z)


def moving(rig: Rig, start: Point) -> bool:
    """Whether the stage has begun to move from `start` (within MOVE_START_S)."""
    deadline = time.monotonic() + MOVE_START_S
    while time.monotonic() < deadline:
        if rig.where() != start:
            return True
        time.sleep(0.02)  # a poll interval bounded by MOVE_START_S
    return False


def still(rig: Rig) -> Point:
    """Where the stage stands once it has stopped moving (within SETTLE_S), in `where` mm."""
    deadline = time.monotonic() + SETTLE_S
    previous = rig.where()
    while time.monotonic() < deadline:
        time.sleep(0.05)  # a poll interval (bounded by SETTLE_S), not a synchronisation
        now = rig.where()
        if now == previous:
            return now
        previous = now
    return previous


def machine_settings(examples: int, steps: int) -> settings:
    """Hypothesis settings for a model: so many examples of at most so many steps, no
    database, no shrinking (the time stays bounded)."""
    return settings(
        max_examples=examples,
        stateful_step_count=steps,
        deadline=None,
        database=None,
        phases=(Phase.explicit, Phase.generate),
        suppress_health_check=list(HealthCheck),
    )


def steps_note(ran: Counter[str]) -> str:
    """`go_to 3, jog 5, ...`: the actions a model ran, by name."""
    return ", ".join(f"{name} {count}" for name, count in sorted(ran.items()))
