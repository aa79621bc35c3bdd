"""RawConsole: decoded lines, filters, poll hiding, search, modes, pairing, export, send line."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor

from app.window.console.table import BYTES, ERROR_BACKGROUND, MATCH_BACKGROUND, REPLY
from app.window.console.traffic_console import RawConsole
from drivers.protocols.registry import create_protocol
from drivers.traffic.lines import KINDS

pytestmark = pytest.mark.timeout(60)
LEFT = Qt.MouseButton.LeftButton


def _lines(console: RawConsole) -> list[str]:
    console.flush()
    return console.text().splitlines()


def _session(console: RawConsole) -> None:
    """A COXIRIS session: a poll, a move, a refused speed, an unknown command."""
    feed = [
        ("tx", b"GET_POSITION\n", 1.0),
        ("rx", b"ACK GET_POSITION\r\nDONE GET_POSITION: 0.00 0.00 0.00\r\n", 1.005),
        ("tx", b"DELTA_MOVE 1 0 0\n", 2.0),
        ("rx", b"ACK DELTA_MOVE\r\n", 2.012),
        ("rx", b"DONE DELTA_MOVE\r\n", 2.5),
        ("tx", b"SET_SPEED 0\n", 3.0),
        ("rx", b"ACK SET_SPEED\r\nERROR: Speed must be positive\r\nDONE SET_SPEED\r\n", 3.004),
        ("tx", b"GET_POSITION\n", 4.0),
        ("rx", b"ACK GET_POSITION\r\nDONE GET_POSITION: 1.00 0.00 0.00\r\n", 4.003),
    ]
    for direction, data, when in feed:
        console.append_traffic(direction, data, when, 1_700_000_000.0 + when)
    console.flush()


def test_object_names_and_defaults(console: RawConsole) -> None:
    assert console.objectName() == "rawConsole"
    assert console.view.objectName() == "consoleView"
    assert console.display_mode() == "text"
    assert console.time_mode() == "relative"
    assert console.kinds() == set(KINDS) - {"poll"}  # the poll is hidden by default
    assert not console.poll_check.isChecked()


def test_lines_are_decoded_paired_and_timed(console: RawConsole) -> None:
    _session(console)
    lines = _lines(console)
    assert lines[0] == "000002.000 TX  DELTA_MOVE 1 0 0\\n  [→ #4]"
    assert lines[1] == "000002.012 RX  ACK DELTA_MOVE\\r\\n  [↩ #3  12.0 ms]"
    assert lines[2] == "000002.500 RX  DONE DELTA_MOVE\\r\\n  [↩ #3]"
    assert (
        "000003.004 RX  ERROR: Speed must be positive\\r\\n  error: Speed must be positive"
        in (lines[5])
    )
    model = console.view.model()
    error_row = console.shown_lines().index(8)
    assert model.data(model.index(error_row, BYTES), Qt.ItemDataRole.BackgroundRole) == (
        ERROR_BACKGROUND
    )
    tx = model.data(model.index(0, BYTES), Qt.ItemDataRole.ForegroundRole).color()
    rx = model.data(model.index(1, BYTES), Qt.ItemDataRole.ForegroundRole).color()
    assert tx == QColor("#1565c0") and rx == QColor("#2e7d32")


def test_the_poll_is_hidden_counted_and_shown_on_demand(console: RawConsole, qtbot) -> None:
    _session(console)
    assert not any("GET_POSITION" in line for line in _lines(console))
    assert "6 poll hidden" in console.status_text()
    qtbot.mouseClick(console.poll_check, LEFT)
    lines = _lines(console)
    assert lines[0] == "000001.000 TX  GET_POSITION\\n  [→ #1]"
    assert lines[1].startswith("000001.005 RX  ACK GET_POSITION")
    assert "poll hidden" not in console.status_text()
    assert console.kind_actions["poll"].isChecked()


def test_filters_by_direction_kind_and_expression(console: RawConsole, qtbot) -> None:
    _session(console)
    console.show_poll(True)
    qtbot.mouseClick(console.rx_check, LEFT)  # RX off
    assert all(" TX " in line for line in _lines(console))
    qtbot.mouseClick(console.rx_check, LEFT)
    console.set_filter(kinds={"error"})
    assert [line.split("  ")[0] for line in _lines(console)] == ["000003.004 RX"]
    console.set_filter(kinds=set(KINDS))
    qtbot.keyClicks(console.filter_edit, "move|speed")
    lines = _lines(console)
    assert len(lines) == 7 and all(("MOVE" in x or "SPEED" in x or "Speed" in x) for x in lines)
    console.filter_edit.setText("(unclosed")  # applied when typing pauses
    qtbot.waitUntil(lambda: bool(console.filter_edit.styleSheet()), timeout=2000)  # red
    assert "is not a regular expression" in console.filter_edit.toolTip()
    assert len(_lines(console)) == 7
    console.filter_edit.clear()
    assert len(_lines(console)) == 13


def test_new_traffic_passes_the_filter_as_it_comes(console: RawConsole) -> None:
    console.set_filter(pattern="DELTA")
    _session(console)
    console.append_traffic("tx", b"DELTA_MOVE 0 1 0\n", 5.0)
    console.append_traffic("tx", b"GET_SPEED\n", 5.1)
    lines = _lines(console)
    assert len(lines) == 4 and lines[-1].startswith("000005.000 TX  DELTA_MOVE 0 1 0")


def test_search_highlights_and_goes_next_and_previous(console: RawConsole, qtbot) -> None:
    _session(console)
    assert console.search("done") == 2  # shown; 2 more DONE lines are hidden with the poll
    model = console.view.model()
    first = console.find_next()
    assert first == 5
    row = console.view.currentIndex().row()
    assert model.data(model.index(row, BYTES), Qt.ItemDataRole.BackgroundRole) == MATCH_BACKGROUND
    assert console.find_next() == 9
    assert console.find_next() == 5  # wraps around
    assert console.find_previous() == 9
    console.activateWindow()
    console.view.setFocus()
    qtbot.waitUntil(console.view.hasFocus, timeout=3000)  # a shortcut acts where the focus is
    qtbot.keyClick(console.view, Qt.Key.Key_F3)
    assert console.current_line() == 5
    qtbot.keyClick(console.view, Qt.Key.Key_F3, Qt.KeyboardModifier.ShiftModifier)
    assert console.current_line() == 9
    assert "2 matches · 2 more hidden by the filters" in console.status_text()


def test_display_modes(console: RawConsole) -> None:
    console.append_traffic("tx", b"A\x00B\n", 1.0)
    console.flush()
    assert _lines(console)[0].startswith("000001.000 TX  A\\x00B\\n")
    console.set_display_mode("hex")
    assert _lines(console)[0].startswith("000001.000 TX  41 00 42 0A")
    console.set_display_mode("mixed")
    assert _lines(console)[0].startswith("000001.000 TX  A<00>B<0A>")
    assert console.mode_combo.currentText() == "mixed"
    with pytest.raises(ValueError):
        console.set_display_mode("octal")


def test_time_modes(console: RawConsole) -> None:
    _session(console)
    console.set_time_mode("delta")
    assert [line.split(" ")[0] for line in _lines(console)[:3]] == ["+0.000", "+0.012", "+0.488"]
    console.set_time_mode("absolute")
    first = _lines(console)[0].split(" ")[0]
    assert len(first) == 12 and first[2] == ":" and first.endswith(".000")
    console.set_timestamps(False)
    assert _lines(console)[0].startswith("TX  DELTA_MOVE")


def test_a_retransmission_links_to_its_first_copy(qtbot) -> None:
    console = RawConsole()
    qtbot.addWidget(console)
    console.set_protocol(create_protocol("laser-frame"))
    from drivers.protocols.commands import GetPosition

    frame = create_protocol("laser-frame").encode(GetPosition())
    console.append_traffic("tx", frame, 1.0)  # no answer
    console.append_traffic("tx", frame, 1.3)  # sent again
    console.flush()
    console.show_poll(True)
    lines = _lines(console)
    assert "[↻ copy of #0]" in lines[1]
    model = console.view.model()
    assert model.data(model.index(1, REPLY)) == "↻ copy of #0"
    console.view.doubleClicked.emit(model.index(1, REPLY))
    assert console.current_line() == 0


def test_double_click_goes_to_the_reply(console: RawConsole) -> None:
    _session(console)
    model = console.view.model()
    console.view.doubleClicked.emit(model.index(0, BYTES))  # DELTA_MOVE
    assert console.current_line() == 4
    assert not console.is_following()


def test_export_text_and_csv_of_the_filtered_view(console: RawConsole, tmp_path: Path) -> None:
    _session(console)
    console.set_filter(pattern="speed")
    text_file, csv_file = tmp_path / "view.txt", tmp_path / "view.csv"
    assert console.export(text_file) == 4
    assert text_file.read_text().splitlines()[0] == "000003.000 TX  SET_SPEED 0\\n  [→ #7]"
    assert console.export(csv_file) == 4
    rows = list(csv.DictReader(csv_file.open(encoding="utf-8")))
    assert [r["line"] for r in rows] == ["6", "7", "8", "9"]
    assert rows[0]["hex"].startswith("53 45 54 5F") and rows[0]["kind"] == "setting"
    assert rows[1]["latency_ms"] == "4.0" and rows[1]["pair"] == "6"
    assert rows[2]["kind"] == "error" and rows[3]["kind"] == "setting"


def test_export_and_clear_buttons(console: RawConsole, qtbot, tmp_path: Path) -> None:
    _session(console)
    target = tmp_path / "out.txt"
    console.ask_export_path = lambda: str(target)
    qtbot.mouseClick(console.findChild(type(console.send_button), "consoleExport"), LEFT)
    assert "DELTA_MOVE" in target.read_text()
    qtbot.mouseClick(console.findChild(type(console.send_button), "consoleClear"), LEFT)
    assert _lines(console) == []
    assert console.status_text().startswith("0 lines")


def test_notes_and_late_traffic_are_put_in_time_order(console: RawConsole) -> None:
    console.append_traffic("tx", b"DELTA_MOVE 1 0 0\n", 1.0)
    console.append_note("moving", 3.0)  # stamped when the GUI adds it...
    console.append_traffic("rx", b"ACK DELTA_MOVE\r\n", 2.0)  # ...earlier traffic comes later
    console.append_traffic("rx", b"DONE DELTA_MOVE\r\n", 4.0)
    assert [line.split("  ")[0] for line in _lines(console)] == [
        "000001.000 TX",
        "000002.000 RX",
        "000003.000 --",
        "000004.000 RX",
    ]


def test_without_a_protocol_each_read_is_a_line(qtbot) -> None:
    console = RawConsole()
    qtbot.addWidget(console)
    console.append_traffic("rx", b"\x01\x02", 1.0)
    assert _lines(console)[0].endswith("RX  \\x01\\x02")


def test_many_lines_stay_scrollable_and_filterable(console: RawConsole) -> None:
    for i in range(20_000):
        console.append_traffic("tx", b"GET_POSITION\n", i * 0.01)
        console.append_traffic("rx", b"ACK GET_POSITION\r\nDONE GET_POSITION: 1 2 3\r\n", i * 0.01)
    console.append_traffic("tx", b"GO_HOME\n", 999.0)
    console.flush()
    assert len(console.index) == 60_001
    assert console.shown_lines() == [60_000]  # every poll line hidden
    console.show_poll(True)
    assert len(console.shown_lines()) == 60_001
    console.jump_to_line(30_000)
    assert console.current_line() == 30_000
    assert console.search("GO_HOME") == 1 and console.find_next() == 60_000


def test_autoscroll_pauses_when_scrolled_up(console: RawConsole) -> None:
    for i in range(200):
        console.append_traffic("tx", f"GET_SPEED {i}\n".encode(), i * 0.1)
    console.flush()
    bar = console.view.verticalScrollBar()
    assert bar.value() == bar.maximum() and console.is_following()
    bar.setValue(0)
    assert not console.is_following() and console.paused_label.isVisibleTo(console)
    console.append_traffic("tx", b"GET_SPEED\n", 30.0)
    console.flush()
    assert bar.value() == 0
    bar.setValue(bar.maximum())
    assert console.is_following()


def test_bad_direction(console: RawConsole) -> None:
    with pytest.raises(ValueError):
        console.append_traffic("up", b"x", 0.0)


def _type_and_enter(console: RawConsole, qtbot, text: str) -> None:
    qtbot.keyClicks(console.send_edit, text)
    qtbot.keyClick(console.send_edit, Qt.Key.Key_Return)


def test_send_text_with_line_ending(console: RawConsole, qtbot, record) -> None:
    calls = record(console.send_requested)
    _type_and_enter(console, qtbot, "GET_POSITION")
    console.set_line_ending(b"\r\n")
    _type_and_enter(console, qtbot, "A\\x02")
    console.set_line_ending(b"")
    console.send_edit.setText("raw")
    qtbot.mouseClick(console.send_button, LEFT)
    assert calls == [(b"GET_POSITION\n",), (b"A\x02\r\n",), (b"raw",)]
    assert console.send_edit.text() == ""


def test_send_hex_and_errors(console: RawConsole, qtbot, record) -> None:
    calls = record(console.send_requested)
    console.set_send_mode("hex")
    assert not console.ending_combo.isEnabled()
    _type_and_enter(console, qtbot, "48 45 4c")
    assert calls == [(b"HEL",)]
    _type_and_enter(console, qtbot, "48 4G")
    assert calls == [(b"HEL",)]  # nothing sent
    assert console.error_label.isVisible()
    assert "not hex" in console.error_label.text()
    assert console.send_edit.text() == "48 4G"  # kept for correction
    qtbot.keyClick(console.send_edit, Qt.Key.Key_Backspace)  # editing clears the error
    assert not console.error_label.isVisible()
    console.send_edit.clear()
    _type_and_enter(console, qtbot, " ")
    assert "nothing to send" in console.error_label.text()
    assert calls == [(b"HEL",)]


def test_bad_escape_in_text_mode(console: RawConsole, qtbot, record) -> None:
    calls = record(console.send_requested)
    _type_and_enter(console, qtbot, "A\\q")
    assert calls == []
    assert "unknown escape" in console.error_label.text()


def test_history(console: RawConsole, qtbot) -> None:
    edit = console.send_edit
    for text in ("one", "two", "two"):
        _type_and_enter(console, qtbot, text)
    assert edit.history() == ["one", "two"]  # no repeats
    qtbot.keyClicks(edit, "dr")
    qtbot.keyClick(edit, Qt.Key.Key_Up)
    assert edit.text() == "two"
    qtbot.keyClick(edit, Qt.Key.Key_Up)
    assert edit.text() == "one"
    qtbot.keyClick(edit, Qt.Key.Key_Up)
    assert edit.text() == "one"
    qtbot.keyClick(edit, Qt.Key.Key_Down)
    assert edit.text() == "two"
    qtbot.keyClick(edit, Qt.Key.Key_Down)
    assert edit.text() == "dr"  # the draft comes back


def test_send_disabled(console: RawConsole, qtbot, record) -> None:
    calls = record(console.send_requested)
    console.set_send_enabled(False)
    console.send_edit.setText("X")
    console.send()
    assert calls == []
    console.set_send_enabled(True)
    console.send()
    assert calls == [(b"X\n",)]


def test_the_timeline_gets_the_bytes_of_each_second_and_its_first_line(console, qtbot) -> None:
    """TimelineFeed adds a second's bytes of a direction in one call: the same bins and first
    lines as a call a line, and the latencies."""
    from app.window.console.feed import TimelineFeed
    from widgets.traffic_timeline import TrafficTimeline

    timeline = TrafficTimeline()
    qtbot.addWidget(timeline)
    TimelineFeed(console, timeline)
    _session(console)  # seconds 1-4, a request and replies in each
    for i in range(300):  # 2.5 s of debug lines, 3 lines a record
        console.append_traffic("rx", b"dbg a\r\ndbg bb\r\ndbg ccc\r\n", 5.0 + i / 120)
    console.append_note("a note has no bytes", 6.0)
    console.flush()
    index, expected = console.index, {"tx": {}, "rx": {}}
    for number in range(len(index)):
        line = index.line(number)
        if line.direction and line.data:
            bins = expected[line.direction]
            second = int(line.time)
            size, first = bins.get(second, (0, number))
            bins[second] = (size + len(line.data), min(first, number))
    for direction, bins in expected.items():
        got = timeline.bytes_per_second(direction)
        assert {s: got[s] for s in range(len(got)) if got[s]} == {
            s: size for s, (size, _) in bins.items()
        }
        for second, (_, first) in bins.items():
            assert timeline._bins.first_line[("tx", "rx").index(direction), second] == first
    _, latencies, lines = timeline.latency_points()
    assert len(lines) == 4 and 12.0 in latencies.round(3).tolist()  # every request answered


def test_the_table_paints_rows_itself_with_their_colours(console: RawConsole, qtbot) -> None:
    """The view paints from the model's row views: no data() call a cell, and each row's
    background (an error's red, a search hit's yellow, the selection) across the row."""
    console.resize(900, 700)  # every line on screen
    _session(console)
    console.show_poll(True)
    console.search("ACK DELTA")
    console.view.scrollToTop()
    calls = []
    model = console.view.model()
    original = type(model).data
    type(model).data = lambda self, *args: calls.append(args) or original(self, *args)
    try:
        console.view.viewport().repaint()
    finally:
        type(model).data = original
    assert calls == []
    image = console.view.viewport().grab().toImage()
    height = console.view.verticalHeader().defaultSectionSize()
    x = console.view.columnViewportPosition(REPLY) + console.view.columnWidth(REPLY) - 4

    def background(line: int) -> QColor:
        row = console.shown_lines().index(line)
        y = console.view.rowViewportPosition(row) + height // 2
        return image.pixelColor(x, y)

    assert background(8) == ERROR_BACKGROUND  # the refused speed
    assert background(4) == MATCH_BACKGROUND  # ACK DELTA_MOVE
    console.jump_to_line(5)
    image = console.view.viewport().grab().toImage()
    palette = console.view.palette()
    groups = (palette.ColorGroup.Active, palette.ColorGroup.Inactive)
    highlights = [palette.color(group, palette.ColorRole.Highlight) for group in groups]
    assert background(5) in highlights  # the selected row (active or not)


@pytest.mark.timeout(30)
def test_traffic_is_decoded_and_shown_in_turns_of_their_own(qtbot, monkeypatch) -> None:
    from PySide6.QtCore import QCoreApplication

    from widgets._pacer import pacer

    monkeypatch.setattr(pacer(), "spacing", 0.0)  # turns, not time, in this test
    console = RawConsole()
    qtbot.addWidget(console)
    console.set_protocol(create_protocol("coxiris"))
    for i in range(20):  # few enough to be decoded in one turn
        console.append_traffic("rx", b"dbg 1234 loop ok\r\n", i * 0.0002)
    QCoreApplication.sendPostedEvents()  # the pacer's turn is free
    console.feed.shown_at = 0.0  # the table was last updated long ago: its update is due
    console.feed.timer.stop()  # as when its (single-shot) timer calls it
    console.feed.timed_flush()  # a decoding turn (at most FLUSH_BUDGET), the table not yet
    assert console.feed.show_due and console.feed.timer.isActive()
    assert console.shown_lines() == []
    console.append_traffic("rx", b"dbg late\r\n", 1.0)  # arrives between the turns
    QCoreApplication.sendPostedEvents()
    console.feed.timer.stop()
    console.feed.timed_flush()  # the table's turn
    assert not console.feed.show_due
    assert console.shown_lines()
    assert console.feed.timer.isActive()  # what came meanwhile gets its turn too
    qtbot.waitUntil(lambda: console.backlog() == 0 and not console.feed.show_due, timeout=10000)
    assert len(console.index) == 21
    assert console.shown_lines()[-1] == 20  # every line kept and shown


def test_past_its_line_limit_the_console_drops_its_oldest_lines(console: RawConsole) -> None:
    console.set_max_lines(5)  # (scrollback: tests/widgets/test_console_scrollback.py)
    for n in range(8):
        console.append_traffic("tx", f"DELTA_MOVE {n} 0 0\n".encode(), float(n))
    console.flush()
    assert console.index.kept == 5 and console.index.first == 3  # the newest five
    assert console.shown_lines() == [3, 4, 5, 6, 7]
    console.flush()  # the note saying so, once
    assert "the console keeps the newest 5 lines" in console.text()
    console.set_max_lines(0)
    for n in range(20):
        console.append_traffic("tx", b"GET_SPEED\n", 10.0 + n)
    console.flush()
    assert console.index.kept == 25  # 0: every line
