"""Keeps a traffic timeline fed from a console's lines, and a click on it going to the line."""

from __future__ import annotations

from PySide6.QtCore import QObject, Slot

from app.traffic_console import RawConsole
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
        """Put lines first..first+count-1 on the timeline."""
        index, origin = self.console.index, self.console.time_origin()
        end = first + count
        times = (index.times()[first:end] - origin).tolist()
        sizes = index.sizes(first, end).tolist()
        for offset, direction in enumerate(index.directions(first, end)):
            if direction and sizes[offset]:
                self.timeline.add_bytes(times[offset], direction, sizes[offset], first + offset)
        for line, when, latency in index.take_latencies():
            self.timeline.add_latency(when - origin, latency, line)

    @Slot()
    def on_reset(self) -> None:
        """The console was cleared or shows another session: start again."""
        self.timeline.clear()
        self.on_lines(0, len(self.console.index))

    @Slot(int)
    def on_click(self, line: int) -> None:
        """Show the clicked point's line in the console."""
        self.console.jump_to_line(line, reveal=True)
