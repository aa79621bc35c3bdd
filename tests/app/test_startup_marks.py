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


def _env(tmp_path: Path, **extra: str) -> dict[str, str]:
    """The panel's environment: offscreen, its settings and logs in `tmp_path`."""
    return {
        **os.environ,
        "QT_QPA_PLATFORM": "offscreen",
        "MOTIONPANEL_SETTINGS": str(tmp_path / "settings.ini"),
        "MOTIONPANEL_LOG_DIR": str(tmp_path / "logs"),
        **extra,
    }


@pytest.mark.timeout(60)
def test_the_panel_notes_its_first_paint_its_views_and_the_device_connected(tmp_path: Path) -> None:
    marks = tmp_path / "marks.json"
    env = _env(tmp_path, MOTIONPANEL_STARTUP_MARKS=str(marks))
    command = [sys.executable, "-m", "app.main", "--port", "sim://coxiris", "--protocol", "coxiris"]
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, timeout=50)
    assert done.returncode == 0, done.stderr.decode()
    times = json.loads(marks.read_text(encoding="utf-8"))
    assert times["painted"] < times["connected"] and times["painted"] < times["ready"]
    logs = list((tmp_path / "logs").glob("*.log"))  # the session log saw the connection
    assert any("connected to sim://coxiris" in log.read_text(encoding="utf-8") for log in logs)


ENTRY_CODE = """
import json, sys
from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QApplication
app = QApplication([])
seen = {}


class Painted(QObject):
    def eventFilter(self, watched, event):
        if (
            event.type() == QEvent.Type.Paint
            and watched.objectName() == "mainWindow"
            and "painted" not in seen
        ):
            seen["painted"] = sorted(
                m for m in ("numpy", "drivers.protocols.visiomex.protocol") if m in sys.modules
            )
        return False


watcher = Painted()
app.installEventFilter(watcher)
from app.main import main
code = main(sys.argv[1:])
print(json.dumps(seen))
sys.exit(code)
"""


@pytest.mark.timeout(60)
def test_the_entry_point_imports_the_protocol_after_the_first_paint(tmp_path: Path) -> None:
    """The Visiomex module imports numpy (its timing model): the window paints before it."""
    marks = tmp_path / "marks.json"
    env = _env(tmp_path, MOTIONPANEL_STARTUP_MARKS=str(marks))
    port = ["--port", "sim://visiomex?instant=1", "--protocol", "visiomex"]
    done = subprocess.run(
        [sys.executable, "-c", ENTRY_CODE, *port],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=50,
    )
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout.strip().splitlines()[-1]) == {"painted": []}
    assert "connected" in json.loads(marks.read_text(encoding="utf-8"))


@pytest.mark.timeout(60)
def test_a_wrong_variant_is_refused_on_the_command_line(tmp_path: Path) -> None:
    env = _env(tmp_path)
    command = [sys.executable, "-m", "app.main", "--protocol", "visiomex", "--variant", "bogus"]
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True, timeout=50)
    assert done.returncode == 2
    assert "visiomex has no variant 'bogus' (variants: seed, prefixed, board12)" in done.stderr
