"""Benchmark: a Visiomex parameter profile written over a real pty, against the firmware's minimum.

The firmware ends a packet after 1 s of silence, so N parameters need at least N seconds; the
figure is the wall time over that minimum (the goal is at most 1.05).
"""

from __future__ import annotations

import time

from bench.motionsim import motionsim
from drivers.protocols.visiomex.model import SILENCE
from drivers.protocols.visiomex.params import PARAMETERS
from drivers.session.device_session import open_device


def bench_visiomex_write(count: int = len(PARAMETERS)) -> dict[str, float]:
    """Write `count` parameters (defaults) to `motionsim visiomex` over a pty at 9600 baud."""
    with motionsim("visiomex") as path, open_device(path, "visiomex", baud=9600) as session:
        start = time.perf_counter()
        for parameter in PARAMETERS[:count]:
            session.parameters.set(parameter.id, parameter.default)
        seconds = time.perf_counter() - start
    minimum = count * SILENCE
    return {
        "parameters": count,
        "seconds": seconds,
        "firmware_minimum_s": minimum,
        "ratio_to_minimum": seconds / minimum,
        "seconds_per_packet": seconds / count,
    }
