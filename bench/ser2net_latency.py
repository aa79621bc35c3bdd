"""ser2net's added latency: COXIRIS position queries to a motionsim pty, directly and through
ser2net over RFC 2217 (`rfc2217://127.0.0.1:PORT`, as a user on another machine types it).

`count` round trips of `GET_POSITION` (sent, then read until its `DONE` line) are timed on the
pty itself and through ser2net, in `rounds` alternating blocks so that drift on a noisy machine
falls on both alike. The figures are the median and p95 of each in ms, and what ser2net adds
(the difference of the medians and of the p95s); the same host runs both ends, so a real
network adds its own round trip on top. `open_s` is how long opening the rfc2217:// port takes.

Usage: .venv/bin/python bench/ser2net_latency.py [--count N] [--rounds N]
                                                 [--ser2net-option TEXT] [--json]
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from drivers.link.transport import Link, open_link  # noqa: E402
from tests.support.ser2net_proc import SER2NET, Ser2netProcess  # noqa: E402
from tests.support.simproc import SimProcess  # noqa: E402

QUERY = b"GET_POSITION\n"
ANSWER_END = b"\r\n"
WARM_UP = 10  # round trips not counted at the start of each block
DEADLINE = 5.0  # seconds one round trip may take before the benchmark gives up
BAUD = 115200


def _round_trips(link: Link, count: int) -> list[float]:
    """Seconds each of `count` GET_POSITION round trips took (after WARM_UP not counted)."""
    times: list[float] = []
    for index in range(WARM_UP + count):
        started = time.perf_counter()
        link.write(QUERY)
        received = b""
        while not (b"DONE GET_POSITION" in received and received.endswith(ANSWER_END)):
            received += link.read()
            if time.perf_counter() - started > DEADLINE:
                raise TimeoutError(f"no answer within {DEADLINE} s: {received!r}")
        if index >= WARM_UP:
            times.append(time.perf_counter() - started)
    return times


def _p95(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(0.95 * len(ordered)))]


def measure(count: int = 200, rounds: int = 4, options: tuple[str, ...] = ()) -> dict[str, float]:
    """Round trips direct and through ser2net (its connection `options`, e.g. "chardelay:
    false"); ms figures (`ser2net_added_ms_p50`...)."""
    if SER2NET is None:
        raise RuntimeError("ser2net is not installed (Debian: apt-get install ser2net)")
    direct: list[float] = []
    through: list[float] = []
    opens: list[float] = []
    per_block = max(1, count // rounds)
    sim = SimProcess("coxiris")
    try:
        with tempfile.TemporaryDirectory(prefix="ser2net-bench-") as folder:
            server = Ser2netProcess(sim.path, Path(folder), BAUD, options)
            try:
                for _ in range(rounds):
                    link = open_link(sim.path, BAUD)
                    try:
                        direct += _round_trips(link, per_block)
                    finally:
                        link.close()
                    started = time.perf_counter()
                    link = open_link(server.url, BAUD)
                    opens.append(time.perf_counter() - started)
                    try:
                        through += _round_trips(link, per_block)
                    finally:
                        link.close()
            finally:
                server.stop()
    finally:
        sim.stop()
    ms = 1000.0
    result = {
        "ser2net_direct_ms_p50": statistics.median(direct) * ms,
        "ser2net_direct_ms_p95": _p95(direct) * ms,
        "ser2net_rfc2217_ms_p50": statistics.median(through) * ms,
        "ser2net_rfc2217_ms_p95": _p95(through) * ms,
        "ser2net_open_s": statistics.median(opens),
        "ser2net_round_trips": float(len(through)),
    }
    result["ser2net_added_ms_p50"] = (
        result["ser2net_rfc2217_ms_p50"] - result["ser2net_direct_ms_p50"]
    )
    result["ser2net_added_ms_p95"] = (
        result["ser2net_rfc2217_ms_p95"] - result["ser2net_direct_ms_p95"]
    )
    return result


def main() -> int:
    """Run the benchmark and print its figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=200, help="round trips each way")
    parser.add_argument("--rounds", type=int, default=4, help="alternating blocks")
    parser.add_argument(
        "--ser2net-option",
        action="append",
        default=[],
        metavar="TEXT",
        help='a ser2net connection option, e.g. "chardelay: false" (repeatable)',
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    options = parser.parse_args()
    result = measure(options.count, options.rounds, tuple(options.ser2net_option))
    if options.json:
        print(json.dumps(result))
    else:
        for key, value in result.items():
            print(f"{key:26} {value:8.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
