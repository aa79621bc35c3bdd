"""RawConsole: buffered rendering, text/hex, colours, autoscroll, bounds, export, send line."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor

from widgets.raw_console import COLOURS, DEFAULT_MAX_LINES, RawConsole

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def console(qtbot) -> RawConsole:
    widget = RawConsole()
    qtbot.addWidget(widget)
    widget.resize(700, 300)
    widget.show()
    widget.set_time_origin(0.0)
    return widget


def _lines(console: RawConsole) -> list[str]:
    return console.text().splitlines()


def test_object_name_and_defaults(console: RawConsole) -> None:
    assert console.objectName() == "rawConsole"
    assert console.view.maximumBlockCount() == DEFAULT_MAX_LINES == 5000
    assert console.display_mode() == "text"
    assert console.timestamps()


def test_appends_are_buffered_until_flush(console: RawConsole, qtbot) -> None:
    console.append_traffic("tx", b"GET_POSITION\n", 1.0)
    assert console.text() == ""
    console.flush()
    assert _lines(console) == ["000001.000 TX  GET_POSITION\\n"]
    console.append_traffic("rx", b"OK\r\n", 1.25)
    qtbot.waitUntil(lambda: len(_lines(console)) == 2, timeout=1000)  # the ~20 Hz timer


def test_text_mode_escapes(console: RawConsole) -> None:
    console.append_traffic("rx", b"POS 1.00\r\n\x02\xff\\", 3.001)
    console.flush()
    assert _lines(console) == ["000003.001 RX  POS 1.00\\r\\n", "000003.001 RX  \\x02\\xff\\\\"]


def test_text_mode_joins_reads_into_lines(console: RawConsole) -> None:
    for when, chunk in enumerate([b"A", b"CK GET_POSITIO", b"N\r\nDONE GET_POS", b"ITION\r\n"]):
        console.append_traffic("rx", chunk, float(when))
        console.flush()  # also across flushes
    console.append_traffic("tx", b"GET_SPEED\n", 5.0)
    console.append_traffic("rx", b"A", 6.0)
    console.append_note("busy", 6.5)
    console.append_traffic("rx", b"CK\r\n", 7.0)
    console.flush()
    assert _lines(console) == [
        "000000.000 RX  ACK GET_POSITION\\r\\n",
        "000002.000 RX  DONE GET_POSITION\\r\\n",
        "000005.000 TX  GET_SPEED\\n",
        "000006.000 RX  A",
        "000006.500 --  busy",
        "000007.000 RX  CK\\r\\n",
    ]
    console.set_display_mode("hex")  # reads 1 s apart (>= HEX_IDLE): a hexdump block each
    assert [line[:13] for line in _lines(console)] == [
        "000000.000 RX",  # A
        "000001.000 RX",  # CK GET_POSITIO (1 s later: a new block)
        "000002.000 RX",  # N\r\n
        "000002.000 RX",  # DONE GET_POS
        "000003.000 RX",  # ITION\r\n
        "000005.000 TX",
        "000006.000 RX",  # A, ended by the note
        "000006.500 --",
        "000007.000 RX",
    ]


def test_hex_mode(console: RawConsole, qtbot) -> None:
    console.set_display_mode("hex")
    console.append_traffic("tx", b"HELLO", 3.001)
    console.flush()
    assert console.text() == ""  # no LF: held in case more of the line comes...
    qtbot.waitUntil(lambda: len(_lines(console)) == 1, timeout=2000)  # ...for HEX_IDLE s
    (line,) = _lines(console)
    assert line.startswith("000003.001 TX  48 45 4C 4C 4F ")
    assert line.endswith("  HELLO")
    assert console.mode_combo.currentText() == "hex"


def test_switching_mode_and_timestamps_rerenders(console: RawConsole) -> None:
    console.append_traffic("tx", b"AB", 2.0)
    console.append_note("connected", 2.5)
    console.flush()
    console.mode_combo.setCurrentText("hex")  # as the user does
    assert _lines(console)[0].startswith("000002.000 TX  41 42 ")
    console.timestamps_check.setChecked(False)
    assert _lines(console)[0].startswith("TX  41 42")
    assert _lines(console)[1] == "--  connected"
    with pytest.raises(ValueError):
        console.set_display_mode("octal")


def test_tx_rx_and_notes_have_their_colours(console: RawConsole) -> None:
    console.append_traffic("tx", b"A", 0.0)
    console.append_traffic("rx", b"B", 0.1)
    console.append_note("info", 0.2)
    console.flush()
    document = console.view.document()
    colours = []
    for index in range(3):
        block = document.findBlockByNumber(index)
        char_format = block.begin().fragment().charFormat()
        colours.append(char_format.foreground().color())
    assert colours == [QColor(COLOURS["tx"]), QColor(COLOURS["rx"]), QColor(COLOURS["note"])]
    assert document.findBlockByNumber(2).begin().fragment().charFormat().fontItalic()


def test_bad_direction(console: RawConsole) -> None:
    with pytest.raises(ValueError):
        console.append_traffic("up", b"x", 0.0)


def test_memory_is_bounded_and_appends_are_cheap(qtbot) -> None:
    console = RawConsole(max_records=20_000)
    qtbot.addWidget(console)
    started = time.perf_counter()
    for i in range(50_000):
        console.append_traffic("rx" if i % 2 else "tx", b"line %d\n" % i, i * 1e-4)
    appended = time.perf_counter() - started
    console.flush()
    assert console.view.document().blockCount() <= DEFAULT_MAX_LINES
    assert console.text().splitlines()[-1].endswith("line 49999\\n")
    assert len(console.records()) == 20_000
    assert console.records()[0][1] == b"line 30000\n"
    assert appended < 1.0  # well over 10k appends per second


def test_a_flood_says_what_it_skipped(qtbot) -> None:
    console = RawConsole(max_lines=10)
    qtbot.addWidget(console)
    for i in range(25):
        console.append_traffic("tx", b"%d\n" % i, 0.0)
    console.flush()
    lines = console.text().splitlines()
    assert "16 records not shown here" in lines[0]
    assert lines[-1].endswith("TX  24\\n")
    assert len(console.records()) == 25


def test_export_writes_everything_retained(qtbot, tmp_path: Path) -> None:
    console = RawConsole(max_lines=10)
    qtbot.addWidget(console)
    console.set_time_origin(0.0)
    for i in range(100):
        console.append_traffic("tx", b"%d\n" % i, float(i))
    console.flush()
    assert console.view.document().blockCount() == 10  # the view is bounded...
    path = tmp_path / "log.txt"
    console.set_timestamps(False)  # the export keeps its timestamps anyway
    assert console.export(path) == 100  # ...the export is complete
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0] == "000000.000 TX  0\\n"
    assert lines[99] == "000099.000 TX  99\\n"


def test_export_and_clear_buttons(console: RawConsole, qtbot, tmp_path: Path) -> None:
    console.append_traffic("rx", b"OK\n", 0.5)
    console.flush()
    console.ask_export_path = lambda: ""  # cancelled
    qtbot.mouseClick(console.findChild(type(console.send_button), "consoleExport"), LEFT)
    path = tmp_path / "out.txt"
    console.ask_export_path = lambda: str(path)
    qtbot.mouseClick(console.findChild(type(console.send_button), "consoleExport"), LEFT)
    assert path.read_text(encoding="utf-8") == "000000.500 RX  OK\\n\n"
    console.ask_export_path = lambda: str(tmp_path / "missing" / "dir" / "x.txt")
    qtbot.mouseClick(console.findChild(type(console.send_button), "consoleExport"), LEFT)
    assert "export failed" in console.error_label.text()
    qtbot.mouseClick(console.findChild(type(console.send_button), "consoleClear"), LEFT)
    console.flush()
    assert console.text() == ""
    assert console.records() == []


def test_autoscroll_pauses_when_scrolled_up(console: RawConsole) -> None:
    bar = console.view.verticalScrollBar()
    for i in range(300):
        console.append_traffic("rx", b"%d\n" % i, 0.0)
    console.flush()
    assert bar.maximum() > 0
    assert bar.value() == bar.maximum()
    bar.setValue(0)  # the user scrolls up
    assert not console.is_following()
    assert console.paused_label.isVisible()
    console.append_traffic("rx", b"more\n", 0.0)
    console.flush()
    assert bar.value() == 0
    bar.setValue(bar.maximum())  # back at the bottom: follow again
    assert console.is_following()
    assert not console.paused_label.isVisible()
    console.append_traffic("rx", b"even more", 0.0)
    console.flush()
    assert bar.value() == bar.maximum()


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


# -- time order ---------------------------------------------------------------------------


def test_a_note_is_shown_and_exported_after_earlier_traffic_that_comes_late(
    console: RawConsole, tmp_path: Path
) -> None:
    console.append_traffic("tx", b"MOVE 1\n", 1.0)
    console.flush()
    console.append_note("moving", 3.0)  # stamped when the GUI adds it...
    console.flush()
    console.append_traffic("rx", b"OK\n", 2.0)  # ...the traffic of before comes in a later batch
    console.append_traffic("rx", b"DONE\n", 4.0)
    console.flush()
    expected = [
        "000001.000 TX  MOVE 1\\n",
        "000002.000 RX  OK\\n",
        "000003.000 --  moving",
        "000004.000 RX  DONE\\n",
    ]
    assert _lines(console) == expected
    assert [when for _, _, when in console.records()] == [1.0, 2.0, 3.0, 4.0]
    path = tmp_path / "log.txt"
    assert console.export(path) == 4
    assert path.read_text(encoding="utf-8").splitlines() == expected


def test_time_order_within_one_flush_and_with_the_default_note_time(
    console: RawConsole, tmp_path: Path
) -> None:
    console.clock = lambda: 10.0
    console.append_note("error: timeout")  # now, 10.0
    console.append_traffic("rx", b"PART", 9.5)
    console.append_traffic("rx", b"IAL\r\n", 9.9)
    console.flush()
    expected = ["000009.500 RX  PARTIAL\\r\\n", "000010.000 --  error: timeout"]
    assert _lines(console) == expected
    console.export(tmp_path / "log.txt")
    assert (tmp_path / "log.txt").read_text(encoding="utf-8").splitlines() == expected


def test_a_late_read_still_joins_its_line(console: RawConsole) -> None:
    console.append_traffic("rx", b"A", 1.0)
    console.append_note("busy", 1.5)
    console.flush()
    assert _lines(console) == ["000001.000 RX  A", "000001.500 --  busy"]
    console.append_traffic("rx", b"CK\r\n", 1.2)
    console.flush()
    assert _lines(console) == ["000001.000 RX  ACK\\r\\n", "000001.500 --  busy"]
    console.append_traffic("rx", b"OK\n", 2.0)  # in order again: appended
    console.flush()
    assert _lines(console)[-1] == "000002.000 RX  OK\\n"


def test_in_order_flushes_append_without_rerendering(console: RawConsole, monkeypatch) -> None:
    calls: list[int] = []
    original = console._rerender
    monkeypatch.setattr(console, "_rerender", lambda: calls.append(1) or original())
    for i in range(5):
        console.append_traffic("rx", b"%d\n" % i, float(i))
        console.append_note(f"n{i}", i + 0.5)
        console.flush()
    assert calls == []
    console.append_traffic("rx", b"late\n", 0.2)
    console.flush()
    assert calls == [1]
    assert _lines(console)[1] == "000000.200 RX  late\\n"


def test_the_time_origin_is_the_earliest_record(qtbot) -> None:
    console = RawConsole()
    qtbot.addWidget(console)
    console.append_note("connecting", 100.0)
    console.flush()
    console.append_traffic("tx", b"HELLO\n", 99.5)
    console.flush()
    assert _lines(console) == ["000000.000 TX  HELLO\\n", "000000.500 --  connecting"]


def test_a_late_record_in_a_full_log_keeps_it_bounded_and_sorted(qtbot) -> None:
    console = RawConsole(max_records=3)
    qtbot.addWidget(console)
    for when in (1.0, 2.0, 3.0):
        console.append_traffic("rx", b"x", when)
    console.append_traffic("rx", b"y", 2.5)
    assert [when for _, _, when in console.records()] == [2.0, 2.5, 3.0]


# -- hex blocks across reads ------------------------------------------------------------

REPLY = b"ACK GET_POSITION\r\nDONE GET_POSITION: 0.00 0.00 0.00\r\n"
CHUNKS = [b"ACK GET_PO", b"SITION\r\nDONE", b" GET_POSITION: 0.0", b"0 0.00 0.0", b"0\r\n"]


def _bytes_of_rows(rows: list[str]) -> bytes:
    """The bytes of hexdump rows, read back from their hex columns."""
    return b"".join(bytes.fromhex(row[15 : 15 + 47]) for row in rows)


def test_a_reply_in_several_reads_is_one_hex_block_per_line(
    console: RawConsole, tmp_path: Path
) -> None:
    assert b"".join(CHUNKS) == REPLY
    console.set_display_mode("hex")
    for i, chunk in enumerate(CHUNKS):
        console.append_traffic("rx", chunk, 1.0 + i * 0.01)
        if i % 2:
            console.flush()  # across flushes too
    console.flush()
    rows = _lines(console)
    # 18 bytes: 2 rows; 35 bytes: 3 rows; each line's rows carry the time of its first byte
    assert [row[:13] for row in rows] == ["000001.000 RX"] * 2 + ["000001.010 RX"] * 3
    assert _bytes_of_rows(rows) == REPLY
    assert rows[1].endswith("..")  # \r\n: the first line ends its block
    assert rows[2].endswith("DONE GET_POSITIO")
    path = tmp_path / "hex.txt"
    assert console.export(path) == 5
    assert path.read_text(encoding="utf-8").splitlines() == rows


def test_hex_block_ends_at_the_other_direction_or_a_note(console: RawConsole) -> None:
    console.set_display_mode("hex")
    console.append_traffic("rx", b"\x02\x10", 1.0)
    console.append_traffic("rx", b"\x03", 1.01)  # binary frame: no LF, same direction: one block
    console.append_traffic("tx", b"\x06", 1.02)  # the other direction ends it
    console.append_note("ack sent", 1.03)  # a note ends the TX block
    console.flush()
    rows = _lines(console)
    assert [row[:13] for row in rows] == ["000001.000 RX", "000001.020 TX", "000001.030 --"]
    assert rows[0].startswith("000001.000 RX  02 10 03 ")
    colours = [
        console.view.document().findBlockByNumber(i).begin().fragment().charFormat()
        for i in range(3)
    ]
    assert [c.foreground().color() for c in colours] == [
        QColor(COLOURS["rx"]),
        QColor(COLOURS["tx"]),
        QColor(COLOURS["note"]),
    ]


def test_an_unterminated_hex_tail_is_shown_when_no_more_bytes_come(console: RawConsole) -> None:
    now = [100.0]
    console.clock = lambda: now[0]
    console.set_display_mode("hex")
    console.append_traffic("rx", bytes(range(0x20, 0x34)), 1.0)
    console.flush()
    assert len(_lines(console)) == 1  # the full row; 4 bytes wait for more
    now[0] += 0.1
    console.append_traffic("rx", b"\x14", 1.1)  # more of the same block
    console.flush()
    now[0] += 0.15
    console.flush()
    assert len(_lines(console)) == 1  # 0.15 s since the last bytes: still waiting
    now[0] += 0.1
    console.flush()
    rows = _lines(console)
    assert len(rows) == 2
    assert rows[1].startswith("000001.000 RX  30 31 32 33 14 ")
    console.append_traffic("rx", b"\x15", 1.5)
    console.flush()
    now[0] += 0.3
    console.flush()
    assert _lines(console)[-1].startswith("000001.500 RX  15 ")  # a new block


def test_switching_to_hex_shows_the_held_tail_in_time(console: RawConsole, qtbot) -> None:
    console.append_traffic("rx", REPLY + b"\x02\x03", 1.0)
    console.flush()
    console.set_display_mode("hex")
    assert len(_lines(console)) == 5
    qtbot.waitUntil(lambda: len(_lines(console)) == 6, timeout=2000)
    assert _lines(console)[-1].startswith("000001.000 RX  02 03 ")
