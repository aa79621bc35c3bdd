"""drivers/link/records.py: a session log written from two threads (the window's notes from the
GUI
thread, the traffic from the worker's) keeps each record's lines together."""

from __future__ import annotations

import io
import threading

import pytest

from drivers.link.records import TX, Traffic, TrafficLogWriter
from drivers.traffic.log_reader import parse_log

pytestmark = pytest.mark.timeout(10)

WAIT_S = 0.3  # how long the record's writer gives a note the chance to cut in


class _CutIn(io.StringIO):
    """A stream that, in the middle of a record's lines, lets another thread write a note."""

    def __init__(self) -> None:
        super().__init__()
        self.inside = threading.Event()  # the first line of a record is written
        self.noted = threading.Event()  # the other thread's note call returned

    def write(self, text: str) -> int:
        """Write; after a record's first line, wait (bounded) for the note."""
        written = super().write(text)
        if " TX " in text and not self.inside.is_set():
            self.inside.set()
            self.noted.wait(WAIT_S)  # with the lock, the note waits for the record instead
        return written


def test_a_note_from_another_thread_never_lands_inside_a_record() -> None:
    """A 40-byte record (three hexdump lines) while another thread notes: the note comes
    after the record's lines, and the record reads back whole."""
    stream = _CutIn()
    writer = TrafficLogWriter(stream, start=0.0)
    data = bytes(range(0x41, 0x41 + 40))

    def note() -> None:
        assert stream.inside.wait(5.0)
        writer.note("paused: the device still holds 3 move(s)")
        stream.noted.set()

    other = threading.Thread(target=note)
    other.start()
    writer(Traffic(TX, data, time=1.0))
    other.join(5.0)
    lines = stream.getvalue().splitlines()
    assert [line.split()[1] for line in lines] == ["TX", "TX", "TX", "#"], lines
    records = parse_log(stream.getvalue())
    assert [r.data for r in records if r.direction] == [data]
    assert [r.note for r in records if r.note] == ["paused: the device still holds 3 move(s)"]


def test_a_note_after_the_stream_closed_is_dropped() -> None:
    """The log turned off (its stream closed by the worker) as a note comes: nothing raised."""
    stream = io.StringIO()
    writer = TrafficLogWriter(stream, start=0.0)
    stream.close()
    writer.note("late")
