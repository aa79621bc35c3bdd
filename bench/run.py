"""Benchmarks that print figures: framer throughput, command round trips, memory.

Usage: .venv/bin/python bench/run.py [--json] [--quick]
Figures are ratios where the machine is noisy (e.g. round trip over the pty versus in-process).
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import statistics
import subprocess
import sys
import time
import tracemalloc
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import bluesky_scan, bridge_latency, ser2net_latency, startup  # noqa: E402
from bench.laser_stream import bench_laser_stream  # noqa: E402
from bench.motionsim import motionsim  # noqa: E402
from bench.visiomex_write import bench_visiomex_write  # noqa: E402
from drivers import open_device  # noqa: E402
from drivers.framers.lines import LineFramer  # noqa: E402
from drivers.protocols.coxiris import CoxirisProtocol  # noqa: E402

log = logging.getLogger("bench")


def _best_of(repeats: int, run: Callable[[], float]) -> float:
    return min(run() for _ in range(repeats))


def bench_line_framer(lines: int) -> dict[str, float]:
    """Decode a stream of COXIRIS reply lines, fed in 64-byte chunks as a port delivers them."""
    stream = b"ACK GET_POSITION\r\nDONE GET_POSITION: 10.00 -5.00 2.50\r\n" * (lines // 2)
    chunks = [stream[i : i + 64] for i in range(0, len(stream), 64)]
    protocol = CoxirisProtocol()

    def run() -> float:
        framer = LineFramer()
        buffer = b""
        count = 0
        start = time.perf_counter()
        for chunk in chunks:
            frames, buffer = framer.split(buffer + chunk)
            for frame in frames:
                protocol.decode(frame)
                count += 1
        assert count == lines
        return time.perf_counter() - start

    seconds = _best_of(3, run)
    return {"lines": lines, "seconds": seconds, "lines_per_s": lines / seconds}


def _round_trips(url: str, count: int) -> list[float]:
    with open_device(url, "coxiris", baud=115200) as session:
        session.identify()
        times = []
        for _ in range(count):
            start = time.perf_counter()
            session.position()  # a device that reports its position is always asked
            times.append(time.perf_counter() - start)
        return times


def bench_round_trips(count: int) -> dict[str, float]:
    """GET_POSITION round trips: in-process sim:// and through motionsim on a real pty.

    motionsim hands the device's output to the host once a USB frame (1 ms), at the first frame
    start after it is due, so no round trip beats the wire time rounded up to whole frames
    (`frame_bound_ms`); one does only where the host answers within what is left of the frame.
    """
    import math

    from drivers.sim.pty_server import USB_FRAME

    in_process = _round_trips("sim://coxiris", count)
    with motionsim("coxiris") as path:
        over_pty = _round_trips(path, count)
    reply_bytes = len(b"ACK GET_POSITION\r\nDONE GET_POSITION: 0.00 0.00 0.00\r\n")
    wire = (len(b"GET_POSITION\n") + reply_bytes) * 10 / 115200
    frame_bound = math.ceil(wire / USB_FRAME) * USB_FRAME
    result = {
        "count": count,
        "sim_median_ms": statistics.median(in_process) * 1000,
        "pty_median_ms": statistics.median(over_pty) * 1000,
        "pty_p95_ms": sorted(over_pty)[int(0.95 * len(over_pty))] * 1000,
        "wire_time_ms": wire * 1000,
        "usb_frame_ms": USB_FRAME * 1000,
        "frame_bound_ms": frame_bound * 1000,
        "pty_share_at_bound": sum(t < frame_bound + USB_FRAME / 2 for t in over_pty) / count,
    }
    result["pty_over_wire_ratio"] = result["pty_median_ms"] / result["wire_time_ms"]
    return result


def bench_move_overhead(moves: int) -> dict[str, float]:
    """Commands a completed move costs (position before, move, speed, confirmation).

    A position is asked only where it is not known: once the device has shown that its reply to
    a move comes when the move has ended (`Motion.arrives_on_reply`), the target is where the
    stage is. Also measured on timed devices: blocking (DONE when the move ends) and not.
    """

    def jogs_on(url: str, first: list[float], jogs: int) -> tuple[float, float, float]:
        """Commands per move over `first` (absolute X), then per small jog; milliseconds a move."""
        written: list[bytes] = []
        with open_device(url, "coxiris", baud=115200) as session:
            session.on_traffic(lambda r: written.append(r.data) if r.direction == "tx" else None)
            start = time.perf_counter()
            for x in first:
                session.move_to(x, 0, 0)
            seconds = time.perf_counter() - start
            before = len(written)
            for i in range(jogs):
                session.move_by(0.1 if i % 2 else -0.1, 0, 0)  # small jogs, one after another
        return before / len(first), (len(written) - before) / jogs, seconds / len(first) * 1000

    per_move, per_jog, ms = jogs_on(
        "sim://coxiris?instant=1&line_timing=0", [i % 10 for i in range(moves)], moves
    )
    long_moves = [20.0, 0.0, 20.0]  # 0.2 s each at 100 mm/s: long enough to show the style
    timed = min(moves, 20)  # a non-blocking device's jog waits for a poll 0.1 s after its DONE
    _, blocking, _ = jogs_on("sim://coxiris?speed=100&line_timing=0", long_moves, timed)
    _, non_blocking, _ = jogs_on(
        "sim://coxiris?speed=100&blocking=0&line_timing=0", long_moves, timed
    )
    return {
        "moves": moves,
        "commands_per_move": per_move,
        "commands_per_jog": per_jog,
        "ms_per_move": ms,
        "commands_per_jog_timed_blocking": blocking,
        "commands_per_jog_timed_non_blocking": non_blocking,
    }


def bench_traffic_memory(records: int) -> dict[str, float]:
    """Memory held by a traffic tap's records (what a log keeps per byte)."""
    from drivers.link.records import Traffic

    tracemalloc.start()
    kept = [
        Traffic("rx", b"DONE GET_POSITION: 0.00 0.00 0.00\r\n", float(i)) for i in range(records)
    ]
    current, _ = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    payload = sum(len(r.data) for r in kept)
    return {
        "records": records,
        "bytes_per_record": current / records,
        "overhead_ratio": current / payload,
    }


def bench_gui_latency(jogs: int) -> dict[str, float]:
    """Event-loop gaps of the window while jogging (bench/gui_latency.py), on a display."""
    return _script(
        str(ROOT / "bench" / "gui_latency.py"), "--jogs", str(jogs), gui=True, timeout=300
    )


def _script(*args: str, timeout: float = 600, gui: bool = False) -> dict[str, float]:
    """Run a bench script in a process of its own; the JSON object it prints last.

    `gui`: the window is on a display (`--display`; under xvfb-run with Mesa's OpenGL when
    there is none): offscreen, no window is ever active, so its jog keys would do nothing.
    """
    command = [sys.executable, *args]
    if gui:
        command.append("--display")
        if not os.environ.get("DISPLAY"):
            command = ["xvfb-run", "-a", "-s", "-screen 0 1600x1000x24 +extension GLX", *command]
    out = subprocess.run(command, capture_output=True, text=True, timeout=timeout, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def bench_console(lines: int, memory_lines: int, flood_s: float) -> dict[str, float]:
    """The traffic console: ingest rate, memory for many lines, window stalls in a flood."""
    script = str(ROOT / "bench" / "console_flood.py")
    ingest = _script(script, "ingest", "--lines", str(lines))
    memory = _script(script, "memory", "--lines", str(memory_lines))
    burst = _script(script, "backlog", "--lines", str(lines * 5 // 2), "--seconds", str(flood_s))
    flood = _script(script, "flood", "--seconds", str(flood_s), gui=True)
    return {
        "console_lines_per_s": ingest["console_lines_per_s"],
        "memory_lines": memory["lines"],
        "memory_mb_per_million_lines": memory["rss_gain_mb"] * 1e6 / memory["lines"],
        "spool_mb_per_million_lines": memory["spool_mb"] * 1e6 / memory["lines"],
        "show_poll_ms_at_memory_lines": memory["show_poll_ms"],
        "filter_regex_ms_at_memory_lines": memory["filter_regex_ms"],
        "search_ms_at_memory_lines": memory["search_ms"],
        "jump_ms_at_memory_lines": memory["jump_middle_ms"],
        "flood_lines_per_s": flood["debug_lines_per_s"],
        "flood_max_stall_ms": flood["gui_max_stall_ms"],
        "flood_p99_gap_ms": flood["p99_gap_ms"],
        "flood_backlog_lines": flood["backlog_lines"],
        "backlog_lines": burst["backlog_lines"],
        "backlog_max_gap_ms": burst["max_gap_ms"],
        "backlog_p99_gap_ms": burst["p99_gap_ms"],
        "backlog_taken_lines_per_s": burst["taken_lines_per_s"],
        "backlog_drained_s_after_flood": burst["drained_s_after_flood"],
    }


def bench_trail(points: int) -> dict[str, float]:
    """One 3D and 2D view frame with a trail of `points` points (bench/trail_frame.py, OpenGL):
    under xvfb-run when there is no display, skipped when there is neither."""
    import shutil

    args = [str(ROOT / "bench" / "trail_frame.py"), "--points", str(points)]
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run"):
        args.append("--xvfb")  # the script runs itself again under xvfb-run
    return _script(*args, timeout=600)


def bench_program_preview(lines: int) -> dict[str, float]:
    """A `lines`-line G-code program read, checked and drawn, and the 3D frame with it beside
    the 1,000,000-point trail (bench/program_preview.py, OpenGL; skipped without a display)."""
    import shutil

    args = [str(ROOT / "bench" / "program_preview.py"), "--lines", str(lines)]
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run"):
        args.append("--xvfb")
    return _script(*args, timeout=600)


def bench_bridge(count: int) -> dict[str, float]:
    """Latency the bridge adds to a round trip (bare, and motionctl bridge with log and print)."""
    figures = {}
    for via in ("bridge", "motionctl"):
        result = bridge_latency.measure(count, 8, 4, via)
        figures[f"{via}_added_median_ms"] = float(result["added_median_ms"])  # type: ignore[arg-type]
        figures[f"{via}_added_p99_ms"] = float(result["added_p99_ms"])  # type: ignore[arg-type]
    return figures


def bench_ser2net(count: int) -> dict[str, float | None]:
    """What ser2net (RFC 2217 on this host) adds to a round trip; None where it is missing."""
    try:
        return dict(ser2net_latency.measure(count, 4))
    except RuntimeError as exc:  # ser2net is not installed
        logging.warning("ser2net: %s", exc)
        return {"ser2net_added_ms_p50": None, "ser2net_added_ms_p95": None}


def main() -> int:
    """Run every benchmark and print the figures."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--quick", action="store_true", help="smaller sizes (for a smoke run)")
    options = parser.parse_args()
    scale = 10 if options.quick else 1
    os.chdir(ROOT)
    results = {
        "line_framer": bench_line_framer(200_000 // scale),
        "round_trips": bench_round_trips(200 // scale),
        "move_overhead": bench_move_overhead(100 // scale),
        "traffic_memory": bench_traffic_memory(100_000 // scale),
        "gui_latency": bench_gui_latency(40 // scale),
        "visiomex_profile_write": bench_visiomex_write(5 if options.quick else 27),
        "laser_stream": bench_laser_stream(
            200 if options.quick else 2000, 1000 if options.quick else 10_000
        ),
        "console": bench_console(
            200_000 // scale,
            100_000 if options.quick else 1_000_000,
            3.0 if options.quick else 10.0,
        ),
        "bridge": bench_bridge(400 if options.quick else 2000),
        "ser2net": bench_ser2net(40 if options.quick else 200),
        "startup": startup.measure(3 if options.quick else 5),
        "trail": bench_trail(1_000_000),  # --quick too: about 10 s
        "program_preview": bench_program_preview(100_000),  # --quick too: about 20 s
        "bluesky_scan": bluesky_scan.measure(1 if options.quick else 3),
    }
    results["console_lines_per_s"] = results["console"]["console_lines_per_s"]
    trips = results["round_trips"]
    results["wire_efficiency_coxiris"] = trips["wire_time_ms"] / trips["pty_median_ms"]
    results["commands_per_jog"] = results["move_overhead"]["commands_per_jog"]
    results["startup_ratio"] = results["startup"]["startup_ratio"]
    results["trail_frame_ms_1e6"] = results["trail"].get("trail_frame_ms")  # None: no display
    results["gui_max_stall_ms"] = results["console"]["flood_max_stall_ms"]
    results["ser2net_added_ms_p50"] = results["ser2net"]["ser2net_added_ms_p50"]
    preview = results["program_preview"]
    results["program_parse_preview_s_1e5"] = preview.get("parse_preview_s")  # None: no display
    results["program_frame_ratio"] = preview.get("frame_ratio")
    results["bluesky_grid_overhead"] = results["bluesky_scan"]["bluesky_grid_overhead"]
    if options.json:
        print(json.dumps(results, indent=None))
    else:
        for name, figures in results.items():
            rows = figures.items() if isinstance(figures, dict) else [("", figures)]
            print(name)
            for key, value in rows:
                print(
                    f"  {key:24} {value:,.3f}"
                    if isinstance(value, float)
                    else f"  {key:24} {value}"
                )
    return 0


if __name__ == "__main__":
    sys.exit(main())
