"""Event-loop stalls of the main window while jogging the simulated stage.

A 5 ms timer in the GUI thread records the gap between its ticks from the first keyboard jog on
(a second after the window has connected and settled), while the worker moves the stage and the
views redraw. Prints one JSON object:
max and 99th-percentile gap (ms), jogs completed, and the console's record count.
Run: .venv/bin/python bench/gui_latency.py [--jogs N] [--display]   (offscreen unless --display)
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))


def measure(jogs: int) -> dict[str, float]:
    """Jog `jogs` times by keyboard and return the event-loop gap figures."""
    from PySide6.QtCore import QElapsedTimer, QObject, Qt, QTimer
    from PySide6.QtTest import QTest
    from PySide6.QtWidgets import QApplication, QDockWidget

    from app.window.gc_main_thread import collect_for
    from app.window.main_window import MainWindow

    app = QApplication.instance() or QApplication([])
    window = MainWindow()
    collect_for(app, window.views.ready)  # garbage collected as the application does
    window.show()
    # Operate hides the console; these figures are for the console on screen beside the views.
    window.findChild(QDockWidget, "rawConsoleDock").show()
    window.activateWindow()
    QTest.qWaitForWindowActive(window, 5000)  # the jog keys act only in the active window
    window.jog_panel.set_step(1)
    window.connect_device("sim://coxiris?speed=50", "coxiris", 115200)

    gaps: list[float] = []
    clock = QElapsedTimer()
    clock.start()
    last = [clock.nsecsElapsed()]

    def tick() -> None:
        now = clock.nsecsElapsed()
        if sent[0] > 0:  # from the first jog on: "while jogging"
            gaps.append((now - last[0]) / 1e6)
        last[0] = now

    sent = [0]
    timer = QTimer()
    timer.setTimerType(Qt.TimerType.PreciseTimer)
    timer.setInterval(5)
    timer.timeout.connect(tick)
    timer.start()

    class Counter(QObject):
        """Counts finished jobs in the GUI thread, as the window sees them (a bare lambda would
        run in the worker's thread, ahead of the window)."""

        def __init__(self) -> None:
            super().__init__()
            self.count = 0

        def add(self, *_args: object) -> None:
            self.count += 1

    finished = Counter()
    window.worker.job_finished.connect(finished.add)
    keys = [Qt.Key.Key_Right, Qt.Key.Key_Up, Qt.Key.Key_Left, Qt.Key.Key_Down]
    give_up = time.monotonic() + 120
    settle_until = [float("inf")]
    window.settled.connect(lambda: settle_until.__setitem__(0, time.monotonic() + 1.0))

    def drive() -> None:
        """Press the next jog key once the previous jogs are nearly done, like a user would."""
        if finished.count >= jogs or time.monotonic() > give_up:
            app.quit()
            return
        settled = window.connected and time.monotonic() > settle_until[0]
        if settled and sent[0] < jogs and sent[0] - finished.count < 2:
            window.view2d.setFocus()
            QTest.keyClick(window.view2d, keys[sent[0] % len(keys)])
            sent[0] += 1

    driver = QTimer()
    driver.setInterval(10)
    driver.timeout.connect(drive)
    driver.start()
    app.exec()
    driver.stop()
    timer.stop()
    window.console.flush()
    records = len(window.console.records())
    window.close()
    over = sum(1 for g in gaps if g > 50.0)
    worst_at = gaps.index(max(gaps)) if gaps else 0
    gaps.sort()
    return {
        "gaps_over_50ms": over,
        "worst_gap_index": worst_at,
        "jogs": finished.count,
        "ticks": len(gaps),
        "max_gap_ms": gaps[-1] if gaps else 0.0,
        "p99_gap_ms": gaps[int(0.99 * (len(gaps) - 1))] if gaps else 0.0,
        "median_gap_ms": gaps[len(gaps) // 2] if gaps else 0.0,
        "console_records": records,
    }


def main() -> int:
    """Run the measurement and print one JSON object."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--jogs", type=int, default=40)
    parser.add_argument("--display", action="store_true", help="use $DISPLAY instead of offscreen")
    options = parser.parse_args()
    if not options.display:
        os.environ["QT_QPA_PLATFORM"] = "offscreen"
    os.environ.setdefault("MOTIONPANEL_SETTINGS", os.path.join(tempfile.mkdtemp(), "bench.ini"))
    os.environ.setdefault("MOTIONPANEL_LOG_DIR", tempfile.mkdtemp())  # the session log
    print(json.dumps(measure(options.jogs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
