"""Benchmark: streaming programs over the laser link to its simulator at 115200 baud.

The rate with grouping (7 moves a frame) over the rate without (1 a frame), on a clean line; and
a 10,000-instruction program under 1% byte corruption and 0.5% dropped replies, checked to be
executed once each and in order.
"""

from __future__ import annotations

import math
import time

from drivers import ProgramPoint, open_device


def _program(count: int) -> list[ProgramPoint]:
    return [
        ProgramPoint(
            round(50 * math.cos(i / 500), 3), round(50 * math.sin(i / 500), 3), 0.0, 1000.0
        )
        for i in range(count)
    ]


def _stream(url: str, points: list[ProgramPoint], group: int) -> tuple[dict[str, float], object]:
    with open_device(url, "laser-frame", baud=115200) as session:
        start = time.perf_counter()
        state = session.run_program(points, group=group)
        seconds = time.perf_counter() - start
        device = session.simulator
    figures = {
        "instructions": len(points),
        "frames": state.frames,
        "retransmissions": state.retransmissions,
        "seconds": seconds,
        "per_second": len(points) / seconds,
    }
    return figures, device


def bench_laser_stream(count: int = 2000, faulty: int = 10_000) -> dict[str, float]:
    """Grouped over single-instruction rate, and a long program under faults."""
    grouped, _ = _stream("sim://laser-frame?instant=1", _program(count), 7)
    single, _ = _stream("sim://laser-frame?instant=1", _program(count), 1)
    points = _program(faulty)
    url = "sim://laser-frame?instant=1&corrupt=0.01&drop_reply=0.005&seed=7"
    noisy, device = _stream(url, points, 7)
    moves = [values for word, values, *_ in device.executed if word == 0x01]  # type: ignore[attr-defined]
    expected = [(p.x, p.y, p.z, p.speed) for p in points]
    in_order_once = [tuple(round(v, 3) for v in m) for m in moves] == expected
    return {
        "grouped_per_s": grouped["per_second"],
        "single_per_s": single["per_second"],
        "grouping_ratio": grouped["per_second"] / single["per_second"],
        "faulty_instructions": faulty,
        "faulty_executed_once_in_order": float(in_order_once),
        "faulty_retransmissions": noisy["retransmissions"],
        "faulty_frames": noisy["frames"],
        "faulty_seconds": noisy["seconds"],
        "faulty_per_s": noisy["per_second"],
    }
