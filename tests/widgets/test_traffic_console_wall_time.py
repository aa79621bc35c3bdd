"""The console's absolute times are wall-clock times, and the CSV export carries them (issue 19,
item 15): the traffic's own clock is time.monotonic(), which counts from the machine's boot."""

from __future__ import annotations

import csv
import time
from datetime import datetime, timedelta
from pathlib import Path

import pytest

from app.window.console.traffic_console import RawConsole
from drivers.link.records import Traffic

pytestmark = pytest.mark.timeout(60)

OLD_COLUMNS = [
    "line", "time_s", "direction", "kind", "hex", "text", "meaning", "pair", "latency_ms",
    "first_copy",
]  # fmt: skip


@pytest.fixture
def live_console(qtbot) -> RawConsole:
    """A console as the window has it: times from its first line, on the monotonic clock."""
    widget = RawConsole()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def _shown_time(text: str) -> datetime:
    """`HH:MM:SS.mmm` as today's (or, just after midnight, yesterday's) local time."""
    now = datetime.now()
    clock = datetime.strptime(text, "%H:%M:%S.%f").time()
    shown = datetime.combine(now.date(), clock)
    return shown - timedelta(days=1) if shown - now > timedelta(hours=12) else shown


def _feed_now(console: RawConsole) -> None:
    """A line sent now and its reply, stamped as the worker stamps traffic."""
    for direction, data in (("tx", b"GET_POSITION\n"), ("rx", b"ACK GET_POSITION\r\n")):
        record = Traffic(direction, data, time.monotonic())
        console.append_traffic(record.direction, record.data, record.time, record.wall)
    console.append_note("connected")
    console.flush()


def test_absolute_times_are_the_wall_clock(live_console: RawConsole) -> None:
    assert time.monotonic() > 5  # (else the bug this guards against could not show)
    _feed_now(live_console)
    live_console.set_time_mode("absolute")
    live_console.set_filter(kinds={"query", "poll", "note"})
    lines = live_console.text().splitlines()
    assert len(lines) == 3, lines
    for line in lines:
        shown = _shown_time(line.split(" ")[0])
        assert abs((shown - datetime.now()).total_seconds()) < 2.0, line
    live_console.set_time_mode("delta")
    gaps = [float(line.split(" ")[0]) for line in live_console.text().splitlines()]
    assert live_console.text().startswith("+0.000 ")
    assert all(0 <= gap < 2.0 for gap in gaps), gaps
    live_console.set_time_mode("relative")
    assert live_console.text().splitlines()[0].startswith("000000.000 ")


def test_the_csv_has_the_wall_clock_time_as_its_last_column(
    live_console: RawConsole, tmp_path: Path
) -> None:
    _feed_now(live_console)
    live_console.set_filter(kinds={"query", "poll", "note"})
    target = tmp_path / "traffic.csv"
    assert live_console.export(target) == 3
    with target.open(encoding="utf-8", newline="") as stream:
        rows = list(csv.reader(stream))
    assert rows[0] == [*OLD_COLUMNS, "time_iso"]  # the old columns keep their places
    now = datetime.now().astimezone()
    for row in rows[1:]:
        stamp = datetime.fromisoformat(row[-1])
        assert stamp.tzinfo is not None, row[-1]
        assert abs((stamp - now).total_seconds()) < 2.0, row
        assert len(row[-1].split("T")[1].split(".")[1]) >= 3  # milliseconds
        assert 0.0 <= float(row[1]) < 2.0  # time_s: still seconds since the first line
