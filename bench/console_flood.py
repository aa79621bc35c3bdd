"""The traffic console under load: ingest rate, memory for a million lines, GUI stalls in a flood.

Modes (each prints one JSON object; run each in its own process so memory figures are its own):
- `ingest --lines N`: lines/s a console (COXIRIS decoding, every line kept and viewable)
  takes in, fed as the worker feeds it (batches, a flush per 20 ms batch); also per second of
  the process's CPU time (`lines_per_cpu_s`), which a busy machine disturbs less.
- `memory --lines N`: resident memory the process gained for N lines, and the spool's size.
- `flood --seconds S`: the main window on `sim://coxiris?chatter=5000` (5,000 debug lines/s,
  a USB device with no baud limit), jogging so the 3D/2D views update; a 5 ms timer records
  the longest event-loop gap from one second after connecting on, and the GUI thread's CPU
  time in each gap (`max_busy_ms`, `p99_busy_ms`: the gaps without what other programs on a
  busy machine, or the worker thread holding the interpreter lock, add to them).

Run: .venv/bin/python bench/console_flood.py MODE [...] [--display]  (offscreen unless --display)
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

BATCH = 100  # records a worker batch carries at 5,000 lines/s (one batch per 20 ms)
EXCHANGE = [
    ("tx", b"GET_POSITION\n"),
    ("rx", b"ACK GET_POSITION\r\nDONE GET_POSITION: 12.50 -3.25 0.00\r\n"),
    ("tx", b"DELTA_MOVE 1 0 0\n"),
    ("rx", b"ACK DELTA_MOVE\r\n"),
    ("rx", b"dbg 1234 loop ok\r\n"),
    ("rx", b"DONE DELTA_MOVE\r\n"),
]  # 7 lines (a round: `lines // 8` rounds make 875,000 lines of 1,000,000)


def _rss_mb() -> float:
    with open("/proc/self/statm", encoding="ascii") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 1e6


def _console() -> object:
    """A shown console decoding COXIRIS, as the window has it."""
    from PySide6.QtWidgets import QApplication

    from app.traffic_console import RawConsole
    from drivers.registry import create_protocol

    QApplication.instance() or QApplication([])
    console = RawConsole()
    console.resize(1000, 400)
    console.show()
    console.set_protocol(create_protocol("coxiris"))
    return console


def _feed(lines: int, console: object | None = None) -> tuple[object, float, float]:
    """A console fed `lines` lines in worker-sized batches; (console, seconds, CPU seconds)."""
    console = console or _console()
    rounds = lines // 8
    cpu = time.process_time()
    start = time.perf_counter()
    t = 0.0
    for i in range(rounds):
        for direction, data in EXCHANGE:
            t += 0.0002
            console.append_traffic(direction, data, t, 1.7e9 + t)  # type: ignore[attr-defined]
        if i % (BATCH // 8) == 0:
            console.flush()  # type: ignore[attr-defined]
    console.flush()  # type: ignore[attr-defined]
    return console, time.perf_counter() - start, time.process_time() - cpu


def ingest(lines: int) -> dict[str, float]:
    """Lines per second into the console (and per second of this process's CPU time, which
    other programs on a busy machine disturb less)."""
    console, seconds, cpu = _feed(lines)
    count = len(console.index)  # type: ignore[attr-defined]
    return {
        "lines": count,
        "seconds": seconds,
        "console_lines_per_s": count / seconds,
        "cpu_seconds": cpu,
        "lines_per_cpu_s": count / cpu,
    }


def memory(lines: int) -> dict[str, float]:
    """Resident memory gained for `lines` lines, and what went to disk (the console is made
    first: what its modules and widgets take is not counted as the lines')."""
    console = _console()
    before = _rss_mb()
    console, seconds, _ = _feed(lines, console)
    after = _rss_mb()
    index = console.index  # type: ignore[attr-defined]
    spool = os.fstat(index._fd).st_size
    timings = {}
    for name, action in (
        ("show_poll_ms", lambda: console.show_poll(True)),  # type: ignore[attr-defined]
        ("filter_regex_ms", lambda: console.set_filter(pattern="DELTA_MOVE")),  # type: ignore[attr-defined]
        ("search_ms", lambda: console.search("dbg 1234")),  # type: ignore[attr-defined]
        ("jump_middle_ms", lambda: console.jump_to_line(len(index) // 2)),  # type: ignore[attr-defined]
    ):
        start = time.perf_counter()
        action()
        timings[name] = (time.perf_counter() - start) * 1000
    return {
        **timings,
        "lines": len(index),
        "seconds": seconds,
        "rss_gain_mb": after - before,
        "bytes_per_line_in_memory": (after - before) * 1e6 / len(index),
        "spool_mb": spool / 1e6,
    }


def flood(seconds: float) -> dict[str, float]:
    """The window's longest event-loop gap while the device floods 5,000 lines/s."""
    from PySide6.QtCore import QElapsedTimer, Qt, QTimer
    from PySide6.QtTest import QTest
    from PySide6.QtWidgets import QApplication

    from app.gc_main_thread import collect_for
    from app.main_window import MainWindow

    app = QApplication.instance() or QApplication([])
    window = MainWindow()
    collect_for(app, window.views.ready)  # garbage collected as the application does
    window.resize(1600, 1000)
    window.show()
    window.activateWindow()
    QTest.qWaitForWindowActive(window, 5000)  # the jog keys act only in the active window
    window.jog_panel.set_step(1)
    window.connect_device("sim://coxiris?chatter=5000&line_timing=0&speed=50", "coxiris", 115200)
    clock = QElapsedTimer()
    clock.start()
    gaps: list[float] = []
    busy: list[float] = []  # the GUI thread's CPU time in each gap: what a busy machine adds
    last = [clock.nsecsElapsed()]  # to the gaps (waiting for a core or the GIL) is not in it
    last_cpu = [time.thread_time()]
    started = [float("inf")]
    window.settled.connect(lambda: started.__setitem__(0, min(started[0], time.monotonic() + 1)))
    keys = [Qt.Key.Key_Right, Qt.Key.Key_Up, Qt.Key.Key_Left, Qt.Key.Key_Down]
    jogs = [0]

    def tick() -> None:
        now, cpu = clock.nsecsElapsed(), time.thread_time()
        if time.monotonic() >= started[0]:
            gaps.append((now - last[0]) / 1e6)
            busy.append((cpu - last_cpu[0]) * 1e3)
            if time.monotonic() >= started[0] + seconds:
                app.quit()
        last[0], last_cpu[0] = now, cpu

    def jog() -> None:
        if time.monotonic() >= started[0] and window.jog_panel.isEnabled():
            window.view2d.setFocus()
            QTest.keyClick(window.view2d, keys[jogs[0] % len(keys)])
            jogs[0] += 1

    timer = QTimer()
    timer.setTimerType(Qt.TimerType.PreciseTimer)
    timer.setInterval(5)
    timer.timeout.connect(tick)
    timer.start()
    jogger = QTimer()
    jogger.setInterval(500)
    jogger.timeout.connect(jog)
    jogger.start()
    QTimer.singleShot(int((seconds + 60) * 1000), app.quit)  # never hang
    app.exec()
    timer.stop()
    jogger.stop()
    backlog = window.console.backlog()  # traffic received but not yet decoded and shown
    window.console.flush()
    lines = len(window.console.index)
    debug = window.console.index.counts["debug"]
    window.close()
    gaps.sort()
    busy.sort()
    return {
        "seconds": seconds,
        "lines": lines,
        "debug_lines_per_s": debug / (seconds + 1.0),
        "jogs": jogs[0],
        "backlog_lines": backlog,
        "gui_max_stall_ms": gaps[-1] if gaps else float("nan"),
        "p99_gap_ms": gaps[int(0.99 * (len(gaps) - 1))] if gaps else float("nan"),
        "median_gap_ms": gaps[len(gaps) // 2] if gaps else float("nan"),
        "max_busy_ms": busy[-1] if busy else float("nan"),
        "p99_busy_ms": busy[int(0.99 * (len(busy) - 1))] if busy else float("nan"),
    }


def main() -> int:
    """Run one mode and print one JSON object."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mode", choices=["ingest", "memory", "flood"])
    parser.add_argument("--lines", type=int, default=200_000)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--display", action="store_true", help="use $DISPLAY instead of offscreen")
    options = parser.parse_args()
    if not options.display:
        os.environ["QT_QPA_PLATFORM"] = "offscreen"
    os.environ.setdefault("MOTIONPANEL_SETTINGS", os.path.join(tempfile.mkdtemp(), "bench.ini"))
    os.environ.setdefault("MOTIONPANEL_LOG_DIR", tempfile.mkdtemp())
    if options.mode == "ingest":
        result = ingest(options.lines)
    elif options.mode == "memory":
        result = memory(options.lines)
    else:
        result = flood(options.seconds)
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
