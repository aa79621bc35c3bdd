"""The console's line limit as a scrollback buffer: the newest lines kept, the oldest dropped a
block at a time, numbering, pairing, filters, search and the view's place kept sane."""

from __future__ import annotations

import os
import sys

import numpy as np
import pytest
from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QAbstractItemView

from app.window.console.table import BYTES, REPLY
from app.window.console.traffic_console import TRIM_MARGIN, RawConsole
from drivers.link.records import Traffic
from drivers.protocols.registry import create_protocol
from drivers.traffic.index import TrafficIndex
from drivers.traffic.search import compile_filter

pytestmark = pytest.mark.timeout(60)

EXCHANGE = [  # 7 lines: a poll answered in two, a move answered in three, a debug line
    ("tx", b"GET_POSITION\n"),
    ("rx", b"ACK GET_POSITION\r\nDONE GET_POSITION: 12.50 -3.25 0.00\r\n"),
    ("tx", b"DELTA_MOVE 1 0 0\n"),
    ("rx", b"ACK DELTA_MOVE\r\n"),
    ("rx", b"dbg 1234 loop ok\r\n"),
    ("rx", b"DONE DELTA_MOVE\r\n"),
]


@pytest.fixture
def console(console: RawConsole) -> RawConsole:
    console.show_poll(True)  # every line shown: rows and lines the same
    return console


def _feed(console: RawConsole, rounds: int, start: float = 0.0, flush_every: int = 5) -> float:
    """`rounds` exchanges (7 lines each), flushed as the worker's batches would be."""
    t = start
    for n in range(rounds):
        for direction, data in EXCHANGE:
            t += 0.001
            console.append_traffic(direction, data, t, 1.7e9 + t)
        if n % flush_every == flush_every - 1:
            console.flush()
    console.flush()
    return t


def _settle() -> None:
    """Let the view lay itself out (its scroll bar's range follows the rows a turn later)."""
    QCoreApplication.processEvents()
    QCoreApplication.processEvents()


def _index_with(lines: int) -> TrafficIndex:
    index = TrafficIndex(create_protocol("coxiris"))
    t, items = 0.0, []
    while len(items) < lines:
        for direction, data in EXCHANGE:
            t += 0.001
            items.append(Traffic(direction, data, t, None))
    index.add_many(items)
    index.commit()
    return index


# -- the index -------------------------------------------------------------------------------


def test_the_index_drops_its_oldest_lines_and_keeps_their_numbers() -> None:
    index = _index_with(7_000)  # 7,000 records: 7,000 × 7/6 lines
    total = len(index)
    kinds_before = {kind: n for kind, n in index.counts.items()}
    newest = [repr(index.read(n)) for n in range(total - 50, total)]  # (repr: NaN latencies)
    assert index.drop_oldest(total - 1_000) == total - 1_000
    assert index.first == total - 1_000 and index.kept == 1_000 and len(index) == total
    assert [repr(index.read(n)) for n in range(total - 50, total)] == newest  # same numbers
    assert sum(index.counts.values()) == 1_000  # the counts are of the lines kept
    assert all(index.counts[k] <= kinds_before[k] for k in kinds_before)
    with pytest.raises(IndexError):
        index.read(index.first - 1)
    with pytest.raises(IndexError):
        index.pairing(0)
    assert index.select()[0] == index.first and len(index.select()) == 1_000
    assert len(index.times(0, total)) == 1_000  # the lines dropped are left out
    hits = index.select(None, None, compile_filter("dbg 1234"))
    assert len(hits) and hits.min() >= index.first
    assert all("dbg 1234" in index.line(int(n)).meaning for n in hits)
    index.add("tx", b"GET_SPEED\n", 100.0)
    index.add("rx", b"ACK GET_SPEED\r\nDONE GET_SPEED: 5.00\r\n", 100.002)
    request = index.line(total)
    assert request.number == total and request.pair == total + 1  # numbering goes on
    assert index.line(total + 1).pair == total and index.line(total + 1).latency_ms == (
        pytest.approx(2.0, abs=0.01)
    )
    kept = index.kept
    assert index.drop_oldest(10**9) == kept and index.kept == 0 and index.select().size == 0
    index.close()


def test_a_reply_whose_request_was_dropped_still_names_it() -> None:
    index = TrafficIndex(create_protocol("coxiris"))
    index.add("tx", b"DELTA_MOVE 1 0 0\n", 1.0)
    index.add("rx", b"dbg a\r\n", 1.001)
    index.drop_oldest(1)  # the request goes; its reply has not come yet
    index.add("rx", b"ACK DELTA_MOVE\r\n", 1.002)
    reply = index.line(2)
    assert reply.pair == 0  # "↩ #0": gone from the console, in the session log
    assert index.take_latencies() == []  # none can be shown for a request not kept
    index.close()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="holes are punched on Linux")
def test_the_spool_gives_the_dropped_bytes_back_to_the_disk() -> None:
    index = _index_with(60_000)  # about 6 MB of spool
    size = os.fstat(index._spool.fd).st_size
    newest = repr(index.read(len(index) - 1))
    index.drop_oldest(index.kept - 1_000)
    if index._spool.punched == 0:
        pytest.skip("this file system cannot punch holes")
    stat = os.fstat(index._spool.fd)
    assert stat.st_size == size  # offsets stay
    assert stat.st_blocks * 512 < size // 2  # the dropped megabytes are free
    assert repr(index.read(len(index) - 1)) == newest
    assert len(index.select(None, None, compile_filter("DELTA"))) > 0
    index.close()


# -- the console -----------------------------------------------------------------------------


def test_trimming_keeps_the_newest_lines(console: RawConsole) -> None:
    console.set_max_lines(200)
    margin = int(200 * TRIM_MARGIN)
    t = 0.0
    for _ in range(20):  # 20 × 10 rounds × 7 lines: 1,400 lines, trimmed several times
        t = _feed(console, 10, t)
        assert console.index.kept <= 200 + margin
    index = console.index
    assert index.first > 0
    shown = console.shown_lines()
    assert shown == list(range(index.first, len(index)))  # the newest, every one shown
    assert shown[-1] == len(index) - 1
    assert console.text().count("the console keeps the newest 200 lines") <= 1  # noted once
    status = console.status_text()
    assert f"{index.kept:,} lines" in status and "older in the session log" in status
    assert "session log on disk keeps every line" in console.status_label.toolTip()


def test_a_limit_set_lower_trims_at_once_and_zero_keeps_everything(console: RawConsole) -> None:
    _feed(console, 100)  # 700 lines, no limit
    assert console.index.kept == 700
    console.set_max_lines(300)
    assert console.index.kept == 300 and console.shown_lines()[0] == 400
    console.set_max_lines(0)
    _feed(console, 100, 10.0)
    assert console.index.kept == 300 + 700 + 1  # the note included
    assert console.index.first == 400


def test_numbering_and_pairing_survive_a_trim(console: RawConsole, qtbot) -> None:
    console.set_max_lines(100)
    _feed(console, 40)
    index = console.index
    assert index.first > 0
    for row, number in enumerate(console.shown_lines()):
        line = index.line(number)
        assert console._model.cell(row, 0) == str(number)  # the Line column: its own number
        if line.direction == "tx" and line.pair >= 0:
            assert console._model.cell(row, REPLY) == f"→ #{line.pair}"
            assert index.line(line.pair).pair == number  # and the reply names its request
    # a request whose reply is kept: double-click goes to the reply
    requests = [n for n in console.shown_lines() if index.line(n).direction == "tx"]
    request = requests[-1]
    console._double_clicked(console._model.index(console._model.row_of(request), BYTES))
    assert console.current_line() == index.line(request).pair
    # a reply whose request was dropped: going there says so and shows the oldest line kept
    orphans = [
        n for n in console.shown_lines() if 0 <= index.line(n).pair < index.first
    ]  # (the first lines kept may be replies of a request dropped)
    assert orphans
    console._double_clicked(console._model.index(console._model.row_of(orphans[0]), BYTES))
    assert console.current_line() == index.first
    console.jump_to_line(0)
    assert "line 0 is no longer in the console" in console.error_label.text()
    assert console.current_line() == index.first


def test_a_filter_and_a_search_after_a_trim(console: RawConsole) -> None:
    console.set_max_lines(150)
    _feed(console, 60)
    index = console.index
    assert index.first > 0
    console.set_filter(pattern="DELTA_MOVE")
    shown = console.shown_lines()
    assert shown and min(shown) >= index.first
    assert all("DELTA_MOVE" in index.line(n).meaning for n in shown)
    console.set_filter(pattern="")
    debug = [n for n in range(index.first, len(index)) if index.line(n).kind == "debug"]
    assert console.search("dbg 1234") == len(debug)
    found = console.find_next()
    assert found in debug
    # more traffic, trimmed again: the search's hits and the filter follow
    console.set_filter(pattern="dbg")
    _feed(console, 30, 100.0)
    shown = console.shown_lines()
    assert min(shown) >= index.first and len(shown) == len(
        [n for n in range(index.first, len(index)) if index.line(n).kind == "debug"]
    )
    matches = console._model.matches
    assert len(matches) and matches.min() >= index.first
    assert console.find_previous() in shown


def test_a_view_following_the_tail_keeps_following(console: RawConsole) -> None:
    console.set_max_lines(200)
    t = 0.0
    for _ in range(12):
        t = _feed(console, 10, t)
        _settle()
        bar = console.view.verticalScrollBar()
        assert console.is_following()
        assert bar.value() == bar.maximum()
    assert console.index.first > 0
    last_row = len(console.shown_lines()) - 1
    assert console.view.rowAt(console.view.viewport().height() - 1) in (last_row, -1)


def test_a_view_scrolled_up_keeps_its_lines_in_place(console: RawConsole) -> None:
    console.set_max_lines(300)
    _feed(console, 40)  # 280 lines: under the limit
    _settle()
    model, view = console._model, console.view
    target = 200  # a line that the next trim keeps
    view.scrollTo(
        model.index(model.row_of(target), BYTES), QAbstractItemView.ScrollHint.PositionAtTop
    )
    _settle()
    console.navigator.scrolled(view.verticalScrollBar().value())  # (as the user's scrolling does)
    assert not console.is_following()
    top = int(model.rows[view.rowAt(0)])
    view.setCurrentIndex(model.index(model.row_of(top + 2), BYTES))
    _feed(console, 20, 10.0)  # 420 lines: past 330, down to the newest 300
    _settle()
    assert console.index.first > 0 and top >= console.index.first
    assert int(model.rows[view.rowAt(0)]) == top  # the same line at the top
    assert console.current_line() == top + 2  # the selection stayed on its line
    assert not console.is_following()
    # its lines dropped too: the oldest line kept at the top, still not following
    _feed(console, 60, 20.0)
    _settle()
    assert top < console.index.first
    assert int(model.rows[view.rowAt(0)]) == console.index.first
    assert not console.is_following()
    assert console.current_line() is None or console.current_line() >= console.index.first


def test_the_timeline_starts_again_from_the_oldest_line_kept(console: RawConsole, qtbot) -> None:
    from app.window.console.feed import TimelineFeed
    from widgets.traffic_timeline import TrafficTimeline

    timeline = TrafficTimeline()
    qtbot.addWidget(timeline)
    feed = TimelineFeed(console, timeline)
    console.set_max_lines(100)
    _feed(console, 50)
    feed.on_reset()  # the timeline rebuilt from the lines kept
    sizes = console.index.sizes(0, len(console.index))
    rx = timeline.bytes_per_second("rx")
    tx = timeline.bytes_per_second("tx")
    assert int(np.sum(rx) + np.sum(tx)) == int(sizes.sum())
