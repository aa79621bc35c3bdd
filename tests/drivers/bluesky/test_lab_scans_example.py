"""The README's Lab scans example, run as it is written (in a Python of its own)."""

from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest

from tests.support.simproc import ROOT

pytest.importorskip("ophyd_async")  # the `lab` extra; the test set-up installs it
pytestmark = pytest.mark.timeout(90)


def _example() -> str:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    start = text.index("\n## Lab scans (Bluesky)\n")
    end = text.index("\n## ", start + 1)
    found = re.findall(r"```python\n(.*?)```", text[start:end], flags=re.DOTALL)
    assert len(found) == 1
    return found[0]


def test_the_lab_scan_example_logs_its_nine_points() -> None:
    done = subprocess.run(
        [sys.executable, "-c", _example()],
        capture_output=True,
        text=True,
        timeout=80,
        cwd=ROOT,
        env=dict(os.environ, PYTHONPATH=str(ROOT)),
    )
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    assert lines == [
        f"{n}: x {x:.1f} y {y:.1f} live"
        for n, (x, y) in enumerate(((x, y) for x in (-4, 0, 4) for y in (-2, 0, 2)), start=1)
    ]
