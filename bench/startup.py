"""Start-up time: the panel's first painted window against a bare QApplication's empty window.

Each is a fresh process (the interpreter's start included, as a user sees it), timed from the
launch until the window has painted once (the child notes the time of its first paint on the
system's monotonic clock, the one the launcher reads); the ratio of their medians is
`startup_ratio`. The panel's 3D and 2D views, traffic console and device and parameter docks
are built just after its first paint: the time until they are (`panel_views_ready_s`) and
until each process has exited (`*_exit_s`) are given too.
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
import json
import sys
import time
sys.path.insert(0, {root!r})
from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QApplication, QWidget

app = QApplication([])
views = None
if {panel}:
    from app.window.main_window import MainWindow
    window = MainWindow()
    views = getattr(window, "views", None)  # built after the first paint
else:
    window = QWidget()
    window.resize(1400, 900)
marks = {{}}


def done():
    print(json.dumps(marks))
    app.quit()


def ready():
    marks["ready"] = time.monotonic()
    QTimer.singleShot(0, done)


class Painted(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint and "painted" not in marks:
            marks["painted"] = time.monotonic()
            if views is None:
                QTimer.singleShot(0, done)
        return False


watcher = Painted()
window.installEventFilter(watcher)
if views is not None:
    views.ready.connect(ready)
window.show()
QTimer.singleShot(30_000, app.quit)
app.exec()
"""


def _launch(panel: bool, env: dict[str, str]) -> dict[str, float]:
    """Seconds from launching a process to its window's first paint, to its views being built
    (the panel), and to its exit."""
    code = _CHILD.format(root=str(ROOT), panel=panel)
    start = time.monotonic()
    out = subprocess.run([sys.executable, "-c", code], env=env, check=True, capture_output=True)
    exited = time.monotonic() - start
    marks = json.loads(out.stdout.decode().strip().splitlines()[-1])
    figures = {"painted": marks["painted"] - start, "exit": exited}
    if "ready" in marks:
        figures["ready"] = marks["ready"] - start
    return figures


def measure(runs: int = 5, display: bool = False) -> dict[str, float]:
    """Median start-up of the bare window and of the panel, and their ratio."""
    env = dict(os.environ)
    if not display:
        env.pop("DISPLAY", None)
        env["QT_QPA_PLATFORM"] = "offscreen"
    folder = tempfile.mkdtemp()
    env["MOTIONPANEL_SETTINGS"] = os.path.join(folder, "startup.ini")
    env["MOTIONPANEL_LOG_DIR"] = folder
    # Compiled modules cached, as an installed application has them (pip compiles at install;
    # this environment sets PYTHONDONTWRITEBYTECODE, which would recompile every module of the
    # panel, and none of the bare window's, at each launch): one launch of each fills the cache.
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPYCACHEPREFIX"] = os.path.join(folder, "pycache")
    _launch(False, env)
    _launch(True, env)
    bare, panel = [], []
    for _ in range(runs):  # interleaved: a busy moment of the machine falls on both
        bare.append(_launch(False, env))
        panel.append(_launch(True, env))

    def median(figures: list[dict[str, float]], key: str) -> float:
        return statistics.median(f[key] for f in figures if key in f)

    result = {
        "runs": runs,
        "bare_s": median(bare, "painted"),
        "panel_s": median(panel, "painted"),
        "startup_ratio": median(panel, "painted") / median(bare, "painted"),
        "bare_exit_s": median(bare, "exit"),
        "panel_exit_s": median(panel, "exit"),
    }
    if any("ready" in f for f in panel):
        result["panel_views_ready_s"] = median(panel, "ready")
    return result


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
