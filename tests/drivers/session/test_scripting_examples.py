"""The README's Scripting examples, run as they are written (each in a Python of its own)."""

from __future__ import annotations

import itertools
import os
import re
import subprocess
import sys

import pytest

from tests.support.simproc import ROOT

pytestmark = pytest.mark.timeout(60)

README = ROOT / "README.md"


def _examples() -> list[str]:
    """The ```python blocks of the README's Scripting section, in order."""
    text = README.read_text(encoding="utf-8")
    start = text.index("\n## Scripting\n")
    end = text.index("\n## ", start + 1)
    return re.findall(r"```python\n(.*?)```", text[start:end], flags=re.DOTALL)


def _example(marker: str) -> str:
    found = [code for code in _examples() if marker in code]
    assert len(found) == 1, f"one Scripting example opens {marker}, found {len(found)}"
    return found[0]


def _run(code: str) -> list[str]:
    """Run an example; the lines it logged (it logs to stderr)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    done = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        timeout=50,
        cwd=ROOT,
        env=env,
    )
    assert done.returncode == 0, done.stderr
    return done.stderr.splitlines()


def test_the_section_has_the_four_examples() -> None:
    assert len(_examples()) == 4


def test_the_grid_example_logs_25_positions_on_the_grid() -> None:
    lines = _run(_example('open_device("sim://coxiris"'))
    grid = [re.fullmatch(r"(\d),(\d): (\S+) (\S+) (\S+)", line) for line in lines]
    points = [m for m in grid if m is not None]
    assert len(points) == 25
    for m in points:
        row, column = int(m[1]), int(m[2])
        assert (float(m[3]), float(m[4]), float(m[5])) == (column * 2.0, row * 2.0, 0.0)
    assert {(int(m[1]), int(m[2])) for m in points} == {(r, c) for r in range(5) for c in range(5)}
    assert lines[0].startswith("device ")


def test_the_profile_example_has_each_value_confirmed() -> None:
    lines = _run(_example('"sim://visiomex"'))
    assert "1/2 thread_distance_x = 10 confirmed" in lines
    assert "2/2 pulley_diameter_x = 38.2 confirmed" in lines
    kept = [line for line in lines if line.startswith("on the device: ")]
    assert len(kept) == 1
    assert "'thread_distance_x': 10" in kept[0] and "'pulley_diameter_x': 38.2" in kept[0]


def test_the_laser_example_reports_progress_until_all_are_executed() -> None:
    lines = _run(_example('open_device("sim://laser-frame"'))
    progress = [re.fullmatch(r"(\d+)/49 acknowledged, (\d+) executed", line) for line in lines]
    steps = [(int(m[1]), int(m[2])) for m in progress if m is not None]
    assert len(steps) >= 3  # told after each frame of 7, and while the queue drains
    for (sent, done), (later_sent, later_done) in itertools.pairwise(steps):
        assert sent <= later_sent and done <= later_done  # never goes back
    assert steps[-1] == (49, 49)
    assert lines[-1] == "done: 49 of 49 executed in 7 frames"


def test_the_grid_example_prints_only_its_own_lines() -> None:
    """The example configures logging at INFO for itself: the library adds no line of its own
    (how the device replies to a move is the library's business, logged at DEBUG)."""
    lines = _run(_example('open_device("sim://coxiris"'))
    own = re.compile(r"device \S+|\d,\d: \S+ \S+ \S+")
    assert [line for line in lines if not own.fullmatch(line)] == []


def test_the_bench_example_logs_where_each_device_went() -> None:
    lines = _run(_example("open_bench"))
    assert lines == ["stage: 10.00 5.00 2.00", "head: -3.00 4.00 0.00"]
