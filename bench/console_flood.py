"""The traffic console under load: ingest rate, memory for a million lines, GUI stalls in a flood.

Modes (each prints one JSON object; run each in its own process so memory figures are its own):
- `ingest --lines N`: lines/s a console (COXIRIS decoding, every line kept and viewable)
  takes in, fed as the worker feeds it (batches, a flush per 20 ms batch); also per second of
  the process's CPU time (`lines_per_cpu_s`), which a busy machine disturbs less.
- `ingest --lines N --max-lines M`: the same with the console's line limit (a scrollback of M
  lines, its oldest dropped a block at a time).
- `trim --lines N`: what one trim of a console with a limit of N lines costs, in the steady
  state (N + 10% lines kept, the oldest 10% dropped): the index's part (arrays moved, the
  spool's hole punched), the table's part (rows removed) and the whole, with the view following
  the tail and with it scrolled up.
- `memory --lines N`: resident memory the process gained for N lines, and the spool's size.
- `backlog --lines N --rate R --seconds S`: the console alone (offscreen) with N lines waiting
  (a burst, or a moment when the GUI was busy) and R lines/s more coming in worker batches for
  S seconds: the event loop's gaps (99th percentile and worst), the lines/s it took meanwhile,
  and the seconds after the flood's end until every line is in the table.
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
import logging
import os
import sys
import tempfile
import threading
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
log = logging.getLogger("console_flood")

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

    from app.window.console.traffic_console import RawConsole
    from drivers.protocols.registry import create_protocol

    QApplication.instance() or QApplication([])
    console = RawConsole()
    console.resize(1000, 400)
    console.show()
    console.set_protocol(create_protocol("coxiris"))
    return console


def _feed(lines: int, console: object | None = None) -> tuple[object, float, float]:
    """A console fed `lines` lines as the window feeds it: the records made beforehand (the
    link makes them in the worker's thread), handed over a worker batch at a time, a flush per
    batch; (console, seconds, CPU seconds) of the console's part."""
    from drivers.link.records import Traffic

    console = console or _console()
    batches, batch, t = [], [], 0.0
    for _ in range(lines // 8):
        for direction, data in EXCHANGE:
            t += 0.0002
            batch.append(Traffic(direction, data, t, 1.7e9 + t))
        if len(batch) >= BATCH * 6 // 8:
            batches.append(batch)
            batch = []
    batches.append(batch)
    cpu = time.process_time()
    start = time.perf_counter()
    for records in batches:
        console.append_records(records)  # type: ignore[attr-defined]
        console.flush()  # type: ignore[attr-defined]
    return console, time.perf_counter() - start, time.process_time() - cpu


def ingest(lines: int, max_lines: int = 0) -> dict[str, float]:
    """Lines per second into the console (and per second of this process's CPU time, which
    other programs on a busy machine disturb less), with a line limit if `max_lines`."""
    console = _console()
    console.set_max_lines(max_lines)  # type: ignore[attr-defined]
    console, seconds, cpu = _feed(lines, console)
    count = len(console.index)  # type: ignore[attr-defined]
    return {
        "max_lines": max_lines,
        "kept": console.index.kept,  # type: ignore[attr-defined]
        "lines": count,
        "seconds": seconds,
        "console_lines_per_s": count / seconds,
        "cpu_seconds": cpu,
        "lines_per_cpu_s": count / cpu,
    }


def trim(lines: int) -> dict[str, float]:
    """One trim of a console limited to `lines` lines holding 10% more (ms), following the
    tail and scrolled up (the median of 3 each, fed without a limit to the limit and its margin
    before each)."""
    from app.window.console.traffic_console import TRIM_MARGIN

    console = _console()
    timings: dict[str, list[float]] = {}

    def timed(owner: object, name: str) -> None:
        original = getattr(owner, name)

        def wrapper(*args: object) -> object:
            start = time.perf_counter()
            try:
                return original(*args)
            finally:
                timings.setdefault(name, []).append((time.perf_counter() - start) * 1000)

        setattr(owner, name, wrapper)

    timed(console.index, "drop_oldest")  # type: ignore[attr-defined]
    timed(console._model, "drop_before")  # type: ignore[attr-defined]
    block = int(lines * TRIM_MARGIN) + 1  # the lines a trim drops
    index = console.index  # type: ignore[attr-defined]
    console.show_poll(True)  # type: ignore[attr-defined]
    results: dict[str, float] = {"lines": lines, "block": block}
    for following in (True, False):
        whole = []
        for _ in range(3):  # fed (without a limit) to the limit and its margin, then trimmed
            console.max_lines = 0  # type: ignore[attr-defined]
            _feed((lines + block - index.kept) * 8 // 7 + 16, console)
            if following:
                console.view.scrollToBottom()  # type: ignore[attr-defined]
                console.navigator.set_follow(True)  # type: ignore[attr-defined]
            else:
                console.jump_to_line(index.first + index.kept // 2)  # type: ignore[attr-defined]
            console.max_lines = lines  # type: ignore[attr-defined]
            assert console.is_following() is following  # type: ignore[attr-defined]
            start = time.perf_counter()
            console._trim()  # type: ignore[attr-defined]
            whole.append((time.perf_counter() - start) * 1000)
            assert index.kept == lines, index.kept
        tail = "following" if following else "scrolled_up"
        results[f"trim_ms_{tail}"] = sorted(whole)[1]
    results["index_drop_ms"] = sorted(timings["drop_oldest"])[len(timings["drop_oldest"]) // 2]
    results["table_drop_ms"] = sorted(timings["drop_before"])[len(timings["drop_before"]) // 2]
    results["kept"] = index.kept
    spool = os.fstat(index._spool.fd)
    results["spool_mb"] = spool.st_size / 1e6
    results["spool_on_disk_mb"] = spool.st_blocks * 512 / 1e6
    return results


def memory(lines: int) -> dict[str, float]:
    """Resident memory gained for `lines` lines, and what went to disk (the console is made
    first: what its modules and widgets take is not counted as the lines')."""
    console = _console()
    before = _rss_mb()
    console, seconds, _ = _feed(lines, console)
    after = _rss_mb()
    index = console.index  # type: ignore[attr-defined]
    spool = os.fstat(index._spool.fd).st_size
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


class GapSampler:
    """Diagnostics (`--profile-gaps MS`): the GUI thread's Python stack sampled every
    millisecond from another thread, and for each event-loop gap of at least MS what it was
    doing, logged to stderr (the samples cost the GUI thread some interpreter-lock waits)."""

    def __init__(self, threshold_ms: float, interval_s: float = 0.001) -> None:
        self.threshold_ms = threshold_ms
        self.interval_s = interval_s
        self.samples: list[tuple[int, tuple[str, ...]]] = []  # (perf_counter_ns, stack)
        self.gaps: list[tuple[int, int, float]] = []  # (start ns, end ns, busy ms)
        self._main = threading.main_thread().ident
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="gap-sampler", daemon=True)

    def start(self) -> None:
        """Start sampling."""
        self._thread.start()

    def stop(self) -> None:
        """Stop sampling."""
        self._stop.set()
        self._thread.join()

    def _run(self) -> None:
        main = self._main
        while not self._stop.wait(self.interval_s):
            frame = sys._current_frames().get(main)
            stack = []
            while frame is not None:
                code = frame.f_code
                name = code.co_filename
                short = name.rsplit("/site-packages/", 1)[-1].replace(str(ROOT) + "/", "")
                stack.append(f"{short}:{code.co_name}:{frame.f_lineno}")
                frame = frame.f_back
            self.samples.append((time.perf_counter_ns(), tuple(reversed(stack))))

    def gap(self, start_ns: int, end_ns: int, busy_ms: float) -> None:
        """Note a gap of the event loop (perf_counter_ns at its start and end)."""
        if (end_ns - start_ns) / 1e6 >= self.threshold_ms:
            self.gaps.append((start_ns, end_ns, busy_ms))

    def report(self) -> None:
        """Log each long gap's samples (the stacks below the event loop, innermost last) and
        a summary over all of them by the first frame under the event loop."""
        total: Counter[str] = Counter()
        leaves: Counter[str] = Counter()
        for start, end, busy in self.gaps:
            inside = [stack for when, stack in self.samples if start <= when <= end]
            counts: Counter[str] = Counter()
            for stack in inside:
                below = _below_loop(stack)
                counts[
                    " > ".join(below[:2] + (["..."] if len(below) > 4 else []) + below[-2:])
                    if len(below) > 4
                    else " > ".join(below)
                ] += 1
                total[below[0] if below else "(in Qt, no Python)"] += 1
                leaves[below[-1] if below else "(in Qt, no Python)"] += 1
            log.info(
                "gap %.1f ms (busy %.1f ms), %d samples:\n  %s",
                (end - start) / 1e6,
                busy,
                len(inside),
                "\n  ".join(f"{n:3d} {text}" for text, n in counts.most_common(8)),
            )
        log.info(
            "by entry point:\n  %s", "\n  ".join(f"{n:4d} {t}" for t, n in total.most_common(25))
        )
        log.info("by leaf:\n  %s", "\n  ".join(f"{n:4d} {t}" for t, n in leaves.most_common(25)))


class EventTracer:
    """Diagnostics (`--trace-gaps MS`): every event Qt hands to an object timed (an
    application whose `notify` is wrapped), and for each event-loop gap of at least MS the
    events that took 0.3 ms or more in it, nested ones (a widget's paint in a window's repaint)
    indented, logged to stderr with their wall and GUI-thread CPU times."""

    def __init__(self, threshold_ms: float) -> None:
        self.threshold_ms = threshold_ms
        self.events: list[tuple[int, int, float, int, str]] = []  # start, end ns, cpu ms, depth
        self.gaps: list[tuple[int, int, float]] = []
        self.calls: Counter[str] = Counter()  # calls of the TRACED functions
        self.depth = 0

    def application(self) -> object:
        """A QApplication whose events are timed."""
        from PySide6.QtCore import QEvent
        from PySide6.QtWidgets import QApplication

        tracer = self
        main = threading.main_thread().ident

        class TracedApplication(QApplication):
            def notify(self, receiver: object, event: object) -> bool:
                if threading.get_ident() != main:  # the worker's own events
                    return super().notify(receiver, event)
                tracer.depth += 1
                deleted = event.type() == QEvent.Type.DeferredDelete  # named while it lives
                what = _describe(receiver, event) if deleted else ""
                start, cpu = time.perf_counter_ns(), time.thread_time()
                try:
                    return super().notify(receiver, event)
                finally:
                    end = time.perf_counter_ns()
                    tracer.depth -= 1
                    if end - start >= 300_000:
                        tracer.events.append(
                            (
                                start,
                                end,
                                (time.thread_time() - cpu) * 1e3,
                                tracer.depth,
                                what or _describe(receiver, event),
                            )
                        )

        return TracedApplication([])

    def gap(self, start_ns: int, end_ns: int, busy_ms: float) -> None:
        """Note a gap of the event loop (perf_counter_ns at its start and end)."""
        if (end_ns - start_ns) / 1e6 >= self.threshold_ms:
            self.gaps.append((start_ns, end_ns, busy_ms))

    def report(self) -> None:
        """Log each long gap's events, and the events' totals over all long gaps."""
        totals: Counter[str] = Counter()
        counts: Counter[str] = Counter()
        for start, end, busy in self.gaps:
            inside = sorted(
                (e for e in self.events if e[0] < end and e[1] > start), key=lambda e: e[0]
            )
            lines = [
                f"{'  ' * depth}{(e_end - e_start) / 1e6:6.1f} ms (cpu {cpu:5.1f}) "
                f"@{(e_start - start) / 1e6:5.1f} {what}"
                for e_start, e_end, cpu, depth, what in inside
            ]
            for e_start, e_end, _, depth, what in inside:
                if depth == 0:
                    totals[what] += (e_end - e_start) // 1000
                    counts[what] += 1
            log.info(
                "gap %.1f ms (busy %.1f ms):\n  %s",
                (end - start) / 1e6,
                busy,
                "\n  ".join(lines),
            )
        origin = self.gaps[0][0] if self.gaps else 0
        log.info(
            "calls of the traced functions (the whole run):\n  %s",
            "\n  ".join(f"{n:6d} {t}" for t, n in self.calls.most_common()),
        )
        log.info(
            "events of 10 ms or more (from the first long gap on):\n  %s",
            "\n  ".join(
                f"{(e[1] - e[0]) / 1e6:6.1f} ms (cpu {e[2]:5.1f}) @{(e[0] - origin) / 1e9:6.2f} s "
                f"{'  ' * e[3]}{e[4]}"
                for e in self.events
                if e[1] - e[0] >= 10_000_000 and e[0] >= origin
            ),
        )
        log.info(
            "top-level events in long gaps (total ms, count):\n  %s",
            "\n  ".join(f"{n / 1000:7.1f} {counts[t]:4d} {t}" for t, n in totals.most_common(30)),
        )


def _describe(receiver: object, event: object) -> str:
    """An event and its receiver in words: type, class, objectName, and a timer's parent."""
    kind = getattr(event.type(), "name", str(event.type()))  # type: ignore[attr-defined]
    name = receiver.objectName() if hasattr(receiver, "objectName") else ""  # type: ignore[attr-defined]
    meta = receiver.metaObject().className() if hasattr(receiver, "metaObject") else "?"  # type: ignore[attr-defined]
    text = f"{kind} {type(receiver).__name__}/{meta}({name})"
    parent = receiver.parent() if hasattr(receiver, "parent") else None  # type: ignore[attr-defined]
    if (kind == "Timer" or not name) and parent is not None:
        text += f" of {type(parent).__name__}({parent.objectName()})"
    return text


TRACED = (  # Python functions the tracer times too: (module, class, method)
    ("widgets.position_view_2d", "PositionView2D", "refresh"),
    ("widgets.position_view_2d", "PositionView2D", "_follow_xy"),
    ("widgets.position_view_2d", "PositionView2D", "_follow_time"),
    ("widgets.position_view_3d", "PositionView3D", "refresh"),
    ("widgets.position_view_3d", "PositionView3D", "render_scene"),
    ("app.window.console.pacing", "FeedPacer", "take_pending"),
    ("app.window.console.traffic_console", "RawConsole", "_show_new"),
    ("widgets.traffic_timeline", "TrafficTimeline", "refresh"),
    ("pyqtgraph.graphicsItems.ViewBox.ViewBox", "ViewBox", "setRange"),
    ("pyqtgraph.graphicsItems.GridItem", "GridItem", "generatePicture"),
    ("pyqtgraph.graphicsItems.AxisItem", "AxisItem", "paint"),
    ("pyqtgraph.graphicsItems.AxisItem", "AxisItem", "generateDrawSpecs"),
    ("pyqtgraph.graphicsItems.PlotCurveItem", "PlotCurveItem", "paint"),
    ("pyqtgraph.graphicsItems.ScatterPlotItem", "ScatterPlotItem", "paint"),
    ("gc", None, "collect"),
)


def _trace_functions(tracer: EventTracer) -> None:
    """Wrap the TRACED functions so that their calls of 0.3 ms or more are events too."""
    import importlib
    from functools import wraps

    main = threading.main_thread().ident
    for module_name, class_name, name in TRACED:
        try:
            module = importlib.import_module(module_name)
        except ImportError:
            continue
        owner = getattr(module, class_name) if class_name else module
        original = getattr(owner, name)
        label = f"{class_name or module_name}.{name}()"

        def wrapper(*args: object, _f: object = original, _l: str = label, **kw: object) -> object:
            if threading.get_ident() != main:
                return _f(*args, **kw)  # type: ignore[operator]
            tracer.depth += 1
            tracer.calls[_l] += 1
            start, cpu = time.perf_counter_ns(), time.thread_time()
            try:
                return _f(*args, **kw)  # type: ignore[operator]
            finally:
                end = time.perf_counter_ns()
                tracer.depth -= 1
                if end - start >= 300_000:
                    tracer.events.append(
                        (start, end, (time.thread_time() - cpu) * 1e3, tracer.depth, _l)
                    )

        setattr(owner, name, wraps(original)(wrapper))  # type: ignore[arg-type]


def _below_loop(stack: tuple[str, ...]) -> list[str]:
    """The frames under the benchmark's `app.exec()` (Qt calling into Python)."""
    for i, frame in enumerate(stack):
        if ":flood:" in frame:
            return list(stack[i + 1 :])
    return list(stack)


def backlog(lines: int, rate: float, seconds: float) -> dict[str, float]:
    """A console with `lines` lines waiting and `rate` lines/s more for `seconds`: its gaps."""
    from PySide6.QtCore import QElapsedTimer, Qt, QTimer
    from PySide6.QtWidgets import QApplication

    from app.window.gc_main_thread import MainThreadCollector

    console = _console()
    app = QApplication.instance()
    collector = MainThreadCollector(app)  # garbage collected as the application does
    collector.settle()
    collector.behind = console.behind  # type: ignore[attr-defined]
    t = [0.0]
    fed = [0]

    def add(count: int) -> None:
        for _ in range(count):
            direction, data = EXCHANGE[fed[0] % len(EXCHANGE)]
            t[0] += 1e-5
            console.append_traffic(direction, data, t[0], 1.7e9 + t[0])  # type: ignore[attr-defined]
            fed[0] += 1

    add(lines)  # the burst, waiting (lines here are records: a record is one console line)
    per_batch = max(1, round(rate * 0.05))  # the worker hands over a batch every 50 ms
    clock = QElapsedTimer()
    clock.start()
    gaps: list[float] = []
    last = [clock.nsecsElapsed()]
    ended = [0.0, 0.0]  # perf_counter when the flood ended, when the table had every line
    start = time.perf_counter()
    taken_in_flood = [0]

    def tick() -> None:
        now = clock.nsecsElapsed()
        gaps.append((now - last[0]) / 1e6)
        last[0] = now
        waiting = console.backlog()  # type: ignore[attr-defined]
        in_table = console._shown_until == len(console.index)  # type: ignore[attr-defined]
        if ended[0] and not ended[1] and not waiting and in_table:
            ended[1] = time.perf_counter()
            app.quit()

    def batch() -> None:
        if time.perf_counter() - start >= seconds:
            if not ended[0]:
                ended[0] = time.perf_counter()
                taken_in_flood[0] = len(console.index)  # type: ignore[attr-defined]
                feeder.stop()
            return
        add(per_batch)

    timer = QTimer()
    timer.setTimerType(Qt.TimerType.PreciseTimer)
    timer.setInterval(5)
    timer.timeout.connect(tick)
    timer.start()
    feeder = QTimer()
    feeder.setTimerType(Qt.TimerType.PreciseTimer)
    feeder.setInterval(50)
    feeder.timeout.connect(batch)
    feeder.start()
    QTimer.singleShot(int((seconds + 60) * 1000), app.quit)  # never hang
    app.exec()
    timer.stop()
    gaps.sort()
    drained = ended[1] - ended[0] if ended[1] else float("nan")
    return {
        "backlog_lines": lines,
        "flood_lines_per_s": rate,
        "seconds": seconds,
        "p99_gap_ms": gaps[int(0.99 * (len(gaps) - 1))] if gaps else float("nan"),
        "max_gap_ms": gaps[-1] if gaps else float("nan"),
        "taken_lines_per_s": taken_in_flood[0] / seconds,
        "drained_s_after_flood": drained,
        "lines": len(console.index),  # type: ignore[attr-defined]
        "fed": fed[0],
    }


def flood(
    seconds: float, profile_gaps_ms: float | None = None, trace_gaps_ms: float | None = None
) -> dict[str, float]:
    """The window's longest event-loop gap while the device floods 5,000 lines/s."""
    from PySide6.QtCore import QElapsedTimer, Qt, QTimer
    from PySide6.QtTest import QTest
    from PySide6.QtWidgets import QApplication, QDockWidget

    from app.window.gc_main_thread import collect_for
    from app.window.main_window import MainWindow

    tracer = EventTracer(trace_gaps_ms) if trace_gaps_ms is not None else None
    app = QApplication.instance() or (tracer.application() if tracer else QApplication([]))
    if tracer is not None:
        _trace_functions(tracer)
    window = MainWindow()
    # garbage collected as the application does (app/main.py)
    collect_for(app, window.views.ready, lambda: window.console.behind())
    window.resize(1600, 1000)
    window.show()
    # Operate hides the console; these figures are for the console on screen beside the views.
    window.findChild(QDockWidget, "rawConsoleDock").show()
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

    sampler = GapSampler(profile_gaps_ms) if profile_gaps_ms is not None else None
    last_ns = [time.perf_counter_ns()]

    def tick() -> None:
        now, cpu = clock.nsecsElapsed(), time.thread_time()
        now_ns = time.perf_counter_ns()
        if time.monotonic() >= started[0]:
            gaps.append((now - last[0]) / 1e6)
            busy.append((cpu - last_cpu[0]) * 1e3)
            for diagnostics in (sampler, tracer):
                if diagnostics is not None:
                    diagnostics.gap(last_ns[0], now_ns, busy[-1])
            if time.monotonic() >= started[0] + seconds:
                app.quit()
        last[0], last_cpu[0], last_ns[0] = now, cpu, now_ns

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
    if sampler is not None:
        sampler.start()
    app.exec()
    if sampler is not None:
        sampler.stop()
        sampler.report()
    if tracer is not None:
        tracer.report()
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
    parser.add_argument("mode", choices=["ingest", "trim", "memory", "backlog", "flood"])
    parser.add_argument("--lines", type=int, default=200_000)
    parser.add_argument(
        "--max-lines", type=int, default=0, help="ingest: the console's line limit (0: none)"
    )
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--rate", type=float, default=20_000, help="backlog: lines/s coming")
    parser.add_argument("--display", action="store_true", help="use $DISPLAY instead of offscreen")
    parser.add_argument(
        "--profile-gaps",
        type=float,
        metavar="MS",
        help="flood: sample the GUI thread's stack and log what it did in each gap of MS or more",
    )
    parser.add_argument(
        "--trace-gaps",
        type=float,
        metavar="MS",
        help="flood: time every Qt event and log those in each gap of MS or more",
    )
    parser.add_argument(
        "--switch-interval",
        type=float,
        metavar="S",
        help="sys.setswitchinterval(S) first (an experiment: Python's default is 0.005)",
    )
    options = parser.parse_args()
    if options.switch_interval is not None:
        sys.setswitchinterval(options.switch_interval)
    if (
        options.profile_gaps is not None or options.trace_gaps is not None
    ):  # the report only: the app's own logging as it was
        log.addHandler(logging.StreamHandler())
        log.setLevel(logging.INFO)
    if not options.display:
        os.environ["QT_QPA_PLATFORM"] = "offscreen"
    os.environ.setdefault("MOTIONPANEL_SETTINGS", os.path.join(tempfile.mkdtemp(), "bench.ini"))
    os.environ.setdefault("MOTIONPANEL_LOG_DIR", tempfile.mkdtemp())
    if options.mode == "ingest":
        result = ingest(options.lines, options.max_lines)
    elif options.mode == "trim":
        result = trim(options.lines)
    elif options.mode == "memory":
        result = memory(options.lines)
    elif options.mode == "backlog":
        result = backlog(options.lines, options.rate, options.seconds)
    else:
        result = flood(options.seconds, options.profile_gaps, options.trace_gaps)
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
