"""Keeps a traffic timeline fed from a console's lines, and a click on it going to the line."""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QObject, Slot

from app.window.console.traffic_console import RawConsole
from drivers.link.records import DIRECTIONS
from widgets.traffic_timeline import TrafficTimeline


class TimelineFeed(QObject):
    """Bytes and latencies of each new console line go to the timeline (GUI thread only)."""

    def __init__(self, console: RawConsole, timeline: TrafficTimeline) -> None:
        super().__init__(console)
        self.console = console
        self.timeline = timeline
        console.lines_added.connect(self.on_lines)
        console.reset.connect(self.on_reset)
        timeline.line_clicked.connect(self.on_click)

    @Slot(int, int)
    def on_lines(self, first: int, count: int) -> None:
        """Put lines first..first+count-1 on the timeline: their bytes a second and direction at
        a time (the timeline adds up seconds: one call each, not one a line), and latencies."""
        index, origin = self.console.index, self.console.time_origin()
        end = first + count
        first = min(max(first, index.first), end)  # (lines the console's limit dropped)
        times = index.times(first, end) - origin
        sizes = index.sizes(first, end)
        directions = index.direction_codes(first, end)
        for code, direction in enumerate(DIRECTIONS):
            if not direction:
                continue
            chosen = ((directions == code) & (sizes > 0)).nonzero()[0]
            if not len(chosen):
                continue
            seconds = np.floor(times[chosen])
            starts = np.flatnonzero(np.r_[True, seconds[1:] != seconds[:-1]])  # runs of a second
            totals = np.add.reduceat(sizes[chosen].astype(np.int64), starts).tolist()
            latest = np.maximum.reduceat(times[chosen], starts).tolist()
            lines = (chosen[starts] + first).tolist()  # each run's first line
            for when, total, line in zip(latest, totals, lines, strict=True):
                self.timeline.add_bytes(when, direction, total, line)
        for line, when, latency in index.take_latencies():
            self.timeline.add_latency(when - origin, latency, line)

    @Slot()
    def on_reset(self) -> None:
        """The console was cleared or shows another session: start again."""
        self.timeline.clear()
        index = self.console.index
        self.on_lines(index.first, len(index) - index.first)

    @Slot(int)
    def on_click(self, line: int) -> None:
        """Show the clicked point's line in the console."""
        self.console.jump_to_line(line, reveal=True)
