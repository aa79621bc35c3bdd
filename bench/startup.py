"""Start-up time: the panel's first painted window against a bare QApplication's empty window.

Each is a fresh process (the interpreter's start included, as a user sees it), timed from the
launch until the window has painted once, on the system's monotonic clock, the one the launcher
reads; the ratio of their medians is `startup_ratio`. The panel is the real `motionpanel` entry
point on `sim://coxiris`, which notes its marks where MOTIONPANEL_STARTUP_MARKS says
(app/startup_marks.py) and quits once it has shown the device connected: the time until its
views, console and docks are built (`panel_views_ready_s`, just after the first paint), until it
shows the device connected (`panel_connected_s`) and until each process has exited (`*_exit_s`)
are given too.
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
window = QWidget()
window.resize(1400, 900)
marks = {{}}


def done():
    print(json.dumps(marks))
    app.quit()


class Painted(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint and "painted" not in marks:
            marks["painted"] = time.monotonic()
            QTimer.singleShot(0, done)
        return False


watcher = Painted()
window.installEventFilter(watcher)
window.show()
QTimer.singleShot(30_000, app.quit)
app.exec()
"""


def _entry_point() -> list[str]:
    """The `motionpanel` command installed beside this interpreter (else its module)."""
    script = Path(sys.executable).with_name("motionpanel")
    return [str(script)] if script.exists() else [sys.executable, "-m", "app.main"]


def _launch(panel: bool, env: dict[str, str]) -> dict[str, float]:
    """Seconds from launching a process to its window's first paint, to its views being built
    and the device shown connected (the panel), and to its exit."""
    if panel:
        marks_file = os.path.join(env["MOTIONPANEL_LOG_DIR"], "marks.json")
        env = {**env, "MOTIONPANEL_STARTUP_MARKS": marks_file}
        command = [*_entry_point(), "--port", "sim://coxiris", "--protocol", "coxiris"]
    else:
        command = [sys.executable, "-c", _CHILD.format(root=str(ROOT))]
    start = time.monotonic()
    out = subprocess.run(command, env=env, check=True, capture_output=True, timeout=60)
    exited = time.monotonic() - start
    if panel:
        with open(marks_file, encoding="utf-8") as written:
            marks = json.load(written)
        os.remove(marks_file)
    else:
        marks = json.loads(out.stdout.decode().strip().splitlines()[-1])
    figures = {"painted": marks["painted"] - start, "exit": exited}
    for name in ("ready", "connected"):
        if name in marks:
            figures[name] = marks[name] - start
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
    if any("connected" in f for f in panel):
        result["panel_connected_s"] = median(panel, "connected")
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
