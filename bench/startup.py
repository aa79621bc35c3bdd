"""Start-up time: the panel's first painted window against a bare QApplication's empty window.

Each is a fresh process (the interpreter's start included, as a user sees it), timed from the
launch until the window has painted once; the ratio of their medians is `startup_ratio`.
Run: .venv/bin/python bench/startup.py [--runs N] [--display]   (offscreen unless --display)
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

_CHILD = """
import sys
sys.path.insert(0, {root!r})
from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QApplication, QWidget

app = QApplication([])
if {panel}:
    from app.main_window import MainWindow
    window = MainWindow()
else:
    window = QWidget()
    window.resize(1400, 900)


class Painted(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint:
            QTimer.singleShot(0, app.quit)
        return False


watcher = Painted()
window.installEventFilter(watcher)
window.show()
QTimer.singleShot(30_000, app.quit)
app.exec()
"""


def _launch(panel: bool, env: dict[str, str]) -> float:
    """Seconds from launching a process to its window's first paint (and its exit)."""
    code = _CHILD.format(root=str(ROOT), panel=panel)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], env=env, check=True, capture_output=True)
    return time.perf_counter() - start


def measure(runs: int = 5, display: bool = False) -> dict[str, float]:
    """Median start-up of the bare window and of the panel, and their ratio."""
    env = dict(os.environ)
    if not display:
        env.pop("DISPLAY", None)
        env["QT_QPA_PLATFORM"] = "offscreen"
    folder = tempfile.mkdtemp()
    env["MOTIONPANEL_SETTINGS"] = os.path.join(folder, "startup.ini")
    env["MOTIONPANEL_LOG_DIR"] = folder
    bare = [_launch(False, env) for _ in range(runs)]
    panel = [_launch(True, env) for _ in range(runs)]
    return {
        "runs": runs,
        "bare_s": statistics.median(bare),
        "panel_s": statistics.median(panel),
        "startup_ratio": statistics.median(panel) / statistics.median(bare),
    }


def main() -> int:
    """Print one JSON object."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--display", action="store_true", help="use $DISPLAY instead of offscreen")
    options = parser.parse_args()
    print(json.dumps(measure(options.runs, options.display)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
