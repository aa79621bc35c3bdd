"""Issue 28 item 12: what Pause says of a laser-frame program reaches the session log at once,
while the worker is still busy running the program, in order with the traffic."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from app.window.main_window import MainWindow
from drivers.protocols.registry import create_protocol
from drivers.traffic.decoding import StreamDecoder
from drivers.traffic.log_reader import parse_log
from drivers.traffic.log_records import LogRecord
from tests.app.window.device.test_status_truth import pause_a_laser_zigzag
from widgets import status_line as status

pytestmark = pytest.mark.timeout(60)

_HOLDS = re.compile(r"the device still holds (\d+) move\(s\) .* in about (\d+) s")
_STILL = "paused: the device has run what it held; the stage stands still"
_STATUS = re.compile(r"^GET_STATUS \[(\d+), (\d+)\]")


def _records(path: Path) -> list[LogRecord]:
    """The session log's complete records (a line being written is left for the next read)."""
    text = path.read_text(encoding="utf-8")
    return parse_log(text[: text.rfind("\n") + 1], str(path))


def _statuses(records: list[LogRecord]) -> list[tuple[int, tuple[int, int]]]:
    """(index of its record, (queue, state)) of each GET_STATUS reply in the log."""
    decoder = StreamDecoder(create_protocol("laser-frame"))
    found = []
    for number, record in enumerate(records):
        if record.direction == "rx":
            for frame in decoder.feed_bytes("rx", record.data, record.time):
                hit = _STATUS.match(str(frame.meaning))
                if hit is not None:
                    found.append((number, (int(hit.group(1)), int(hit.group(2)))))
    return found


def _held(reply: tuple[int, int]) -> int:
    """What a GET_STATUS reply says the device holds: its queue, or the move under way."""
    queue, state = reply
    return queue + (1 if state else 0)  # the move under way has left the queue


def test_the_held_moves_note_reaches_the_session_log_while_the_program_runs(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    """Pause mid-program: the "still holds N moves" note is in the session log before Stop
    (the worker is busy with the program until then), N as the device's last GET_STATUS
    before it says, and before the queue's 0; the "has run what it held" note after that."""
    pause_a_laser_zigzag(qtbot, window, tmp_path)
    log = window.link.session_log_path
    assert log is not None
    paused_at = len(_records(log))

    def noted(text: str) -> int | None:
        for number, record in enumerate(_records(log)):
            if number >= paused_at and text in record.note:
                return number
        return None

    qtbot.waitUntil(lambda: noted("still holds") is not None, timeout=5000)
    qtbot.waitUntil(lambda: noted(_STILL) is not None, timeout=15000)
    assert window.machine.busy_job is not None  # the worker was running the program all along
    records = _records(log)
    holds, still = noted("still holds"), noted(_STILL)
    assert holds is not None and still is not None
    hit = _HOLDS.search(records[holds].note)
    assert hit is not None, records[holds].note
    said = int(hit.group(1))
    before = [reply for number, reply in _statuses(records) if number < holds]
    assert said in {_held(reply) for reply in before[-2:]}, (said, before[-2:])
    empty = [n for n, reply in _statuses(records) if n > paused_at and _held(reply) == 0]
    assert empty and holds < empty[0] < still, (holds, empty[:1], still)
    window.stop_action.trigger()
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=10000)
