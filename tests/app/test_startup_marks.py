"""The real `motionpanel` start-up, as bench/startup.py measures it: the marks written where
MOTIONPANEL_STARTUP_MARKS says, and the panel gone after."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.timeout(60)
def test_the_panel_notes_its_first_paint_its_views_and_the_device_connected(tmp_path: Path) -> None:
    marks = tmp_path / "marks.json"
    env = {
        **os.environ,
        "QT_QPA_PLATFORM": "offscreen",
        "MOTIONPANEL_SETTINGS": str(tmp_path / "settings.ini"),
        "MOTIONPANEL_LOG_DIR": str(tmp_path / "logs"),
        "MOTIONPANEL_STARTUP_MARKS": str(marks),
    }
    command = [sys.executable, "-m", "app.main", "--port", "sim://coxiris", "--protocol", "coxiris"]
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, timeout=50)
    assert done.returncode == 0, done.stderr.decode()
    times = json.loads(marks.read_text(encoding="utf-8"))
    assert times["painted"] < times["connected"] and times["painted"] < times["ready"]
    logs = list((tmp_path / "logs").glob("*.log"))  # the session log saw the connection
    assert any("connected to sim://coxiris" in log.read_text(encoding="utf-8") for log in logs)
