"""Faults on the line, for every protocol, seen by `motionctl`: one clear line and exit 3 within
seconds when the device hangs, restarts or vanishes; the right answer despite noise, a slow
device or a stray reply. The simulator runs in its own process on a real pty (`--control`)."""

from __future__ import annotations

import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.support.e2e import ROOT, motionctl
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(90)]


@dataclass(frozen=True)
class Case:
    """A command run while a fault is applied: before it starts, or once `after` was sent."""

    protocol: str
    command: tuple[str, ...]
    fault: str
    exit: int
    says: str  # a regular expression the one line (stderr on failure, stdout on success) matches
    sim: tuple[str, ...] = ("--instant",)
    after: str = ""  # text in the host's log (16 bytes a line); "": the fault comes first
    within: float = 15.0  # seconds the command may take in all

    def __str__(self) -> str:
        return f"{self.protocol}-{self.fault.split()[0]}-{'during' if self.after else 'before'}"


CASES = [
    Case("coxiris", ("position",), "hang", 3, r"did not answer to GET_POSITION within 2 s"),
    Case("coxiris", ("position",), "garbage 300", 0, r"^0\.00 0\.00 0\.00$"),
    Case("coxiris", ("position",), "slow 0.5", 0, r"^0\.00 0\.00 0\.00$"),
    # Its DONE comes as a second ACK: a mix-up the client names.
    Case("coxiris", ("position",), "wrong", 3, r"expected DONE GET_POSITION, got ACK"),
    Case(
        "coxiris",
        ("move", "6", "0", "0"),
        "reboot",
        3,
        r"did not (answer|finish its reply) to ABSOLUTE_MOVE",
        sim=("--speed", "2"),
        after="ABSOLUTE_MOVE",
    ),
    Case(
        "coxiris",
        ("move", "6", "0", "0"),
        "vanish",
        3,
        r"reading from .* failed|disconnected",
        sim=("--speed", "2"),
        after="ABSOLUTE_MOVE",
    ),
    Case("laser-frame", ("position",), "hang", 3, r"GET_POSITION failed after 3 tries"),
    Case("laser-frame", ("position",), "garbage 300", 0, r"^0\.00 0\.00 0\.00$"),
    Case("laser-frame", ("position",), "wrong", 0, r"^0\.00 0\.00 0\.00$"),
    Case("visiomex", ("jog", "1", "0"), "hang", 3, r"did not answer to MLP0001000P0000000"),
    Case(
        "visiomex",
        ("jog", "50", "0"),
        "reboot",
        3,
        r"restarted during MLP0050000P0000000",
        sim=(),
        after="FP0001",  # the move has started
    ),
    Case(
        "visiomex",
        ("jog", "50", "0"),
        "vanish",
        3,
        r"reading from .* failed|disconnected",
        sim=(),
        after="MLP0050000P00000",  # a hexdump line holds 16 bytes
    ),
    Case("firmata", ("version",), "hang", 3, r"did not answer to STEPPER_LIBRARY_VERSION"),
    # A write-only device cannot tell: the position is reported as commanded, never measured.
    Case("pi-frame", ("move", "1", "0", "0"), "hang", 0, r"\(commanded, not measured\)$"),
]


def _log_text(log: Path, direction: str) -> str:
    if not log.exists():
        return ""
    lines = log.read_text(errors="replace").splitlines()
    return "\n".join(line for line in lines if f" {direction} " in line or not direction)


@pytest.mark.parametrize("case", CASES, ids=str)
def test_a_fault_gives_one_clear_line_and_the_right_exit(case: Case, tmp_path: Path) -> None:
    sim = SimProcess(case.protocol, *case.sim, control=True)
    log = tmp_path / "host.log"
    try:
        if not case.after:
            sim.fault(case.fault)
            run = motionctl(case.protocol, sim.path, *case.command, log=log, timeout=60)
            returncode, stdout, stderr, seconds = (
                run.returncode,
                run.stdout,
                run.stderr,
                run.seconds,
            )
        else:
            start = time.monotonic()
            proc = subprocess.Popen(
                [sys.executable, "-m", "app.cli", "--port", sim.path, "--protocol",
                 case.protocol, "--log", str(log), *case.command],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT,
            )  # fmt: skip
            deadline = time.monotonic() + 20
            while case.after not in _log_text(log, ""):
                assert time.monotonic() < deadline, f"{case.after} was never sent"
                assert proc.poll() is None, proc.communicate()
                time.sleep(0.02)  # polling a file for a condition, with a deadline
            sim.fault(case.fault)
            stdout, stderr = proc.communicate(timeout=60)
            returncode, seconds = proc.returncode, time.monotonic() - start
    finally:
        if sim.proc.poll() is None:
            sim.stop()
    said = (stdout if case.exit == 0 else stderr).strip()
    assert returncode == case.exit, (stdout, stderr)
    assert len(said.splitlines()) == 1, said
    assert re.search(case.says, said), said
    assert seconds < case.within
    assert log.exists() and _log_text(log, "TX")  # the traffic is kept, to the last byte


def test_motionsim_control_refuses_a_fault_it_does_not_know() -> None:
    sim = SimProcess("coxiris", "--instant", control=True)
    try:
        with pytest.raises(RuntimeError, match="unknown fault 'melt'"):
            sim.fault("melt")
        with pytest.raises(RuntimeError, match="out of range"):
            sim.fault("slow 100")
        assert sim.fault("slow 0") == "ok slow 0"  # it still takes the next one
    finally:
        sim.stop()
