"""Text forms of traffic: escapes, hexdump lines, parsing what is typed in the send line."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from widgets.traffic_format import (
    HEX_IDLE,
    HEX_WIDTH,
    TEXT_WIDTH,
    HexAssembler,
    TextAssembler,
    escape,
    hex_lines,
    note_line,
    parse_hex,
    stamp,
    unescape,
)


def test_escape() -> None:
    assert escape(b"OK\r\n") == "OK\\r\\n"
    assert escape(b"\x02A\tB\\\xff") == "\\x02A\\tB\\\\\\xff"


@given(st.binary(max_size=64))
def test_unescape_inverts_escape(data: bytes) -> None:
    assert unescape(escape(data)) == data


def test_unescape() -> None:
    assert unescape("MOVE 1 2") == b"MOVE 1 2"
    assert unescape("A\\x02B\\r\\0") == b"A\x02B\r\x00"
    assert unescape("µ") == "µ".encode()


@pytest.mark.parametrize("bad", ["\\q", "\\x0", "\\xZZ", "end\\"])
def test_unescape_rejects(bad: str) -> None:
    with pytest.raises(ValueError):
        unescape(bad)


@pytest.mark.parametrize(
    ("text", "data"),
    [
        ("48 45 4c 4C 4F", b"HELLO"),
        ("48454C", b"HEL"),
        ("0x48,0x45", b"HE"),
        ("48:45-4C", b"HEL"),
        ("  ", b""),
    ],
)
def test_parse_hex(text: str, data: bytes) -> None:
    assert parse_hex(text) == data


@pytest.mark.parametrize("bad", ["4G", "123", "0x", "hello"])
def test_parse_hex_rejects(bad: str) -> None:
    with pytest.raises(ValueError):
        parse_hex(bad)


def test_stamp() -> None:
    assert stamp(3.001) == "000003.001"


def test_hex_lines() -> None:
    assert hex_lines("tx", b"HELLO", 3.001) == [
        f"000003.001 TX  {'48 45 4C 4C 4F':<{HEX_WIDTH * 3 - 1}}  HELLO"
    ]
    long = hex_lines("rx", bytes(range(20)), None)
    assert len(long) == 2
    assert long[0].startswith("RX  00 01 02")
    assert long[1].startswith("RX  10 11 12 13")
    assert long[1].endswith("....")
    assert hex_lines("rx", b"", 0.0) == [f"000000.000 RX  {'':<{HEX_WIDTH * 3 - 1}}  "]


def test_text_assembler_cuts_at_lf() -> None:
    assembler = TextAssembler()
    assert assembler.feed("rx", b"OK\r\n", 1.5) == [(True, "000001.500 RX  OK\\r\\n")]
    assert assembler.feed("rx", b"PART", 2.0) == [(True, "000002.000 RX  PART")]
    assert assembler.feed("rx", b"IAL\nNEXT", 2.5) == [
        (False, "IAL\\n"),
        (True, "000002.500 RX  NEXT"),
    ]
    assert assembler.feed("tx", b"CMD\n", None) == [(True, "TX  CMD\\n")]  # other direction
    assert assembler.feed("rx", b"", 3.0) == []


def test_text_assembler_limits_line_length() -> None:
    assembler = TextAssembler()
    pieces = assembler.feed("tx", b"x" * (TEXT_WIDTH + 1), 0.0)
    assert [starts for starts, _ in pieces] == [True, True]
    pieces = assembler.feed("tx", b"y" * TEXT_WIDTH, 0.0)
    assert [starts for starts, _ in pieces] == [False, True]
    assembler.close()
    assert assembler.feed("tx", b"z", 0.0)[0][0] is True


def test_note_line() -> None:
    assert note_line("connected", 0.25) == "000000.250 --  connected"


def test_hex_assembler_joins_reads_until_lf() -> None:
    assembler = HexAssembler()
    assert assembler.feed("rx", b"ACK GET_PO", 1.0, 1.0) == []
    assert assembler.pending()
    rows = assembler.feed("rx", b"SITION\r\nDONE", 1.01, 1.01)
    assert rows == [
        ("rx", hex_lines("rx", b"ACK GET_POSITION", 1.0)[0]),
        ("rx", hex_lines("rx", b"\r\n", 1.0)[0]),
    ]
    assert assembler.feed("tx", b"X", 2.0, 2.0) == [("rx", hex_lines("rx", b"DONE", 1.01)[0])]
    assert assembler.close() == [("tx", hex_lines("tx", b"X", 2.0)[0])]
    assert not assembler.pending()
    assert assembler.close() == []


def test_hex_assembler_rows_of_exactly_the_width_and_idle_gaps() -> None:
    assembler = HexAssembler()
    rows = assembler.feed("rx", bytes(HEX_WIDTH), None, 0.0)
    assert rows == [("rx", hex_lines("rx", bytes(HEX_WIDTH), None)[0])]
    assert not assembler.pending()
    assert assembler.feed("rx", b"\n", None, 0.1) == [("rx", hex_lines("rx", b"\n", None)[0])]
    assembler.feed("rx", b"a", 1.0, 1.0)
    assert assembler.feed("rx", b"b", 1.0 + HEX_IDLE / 2, 1.0 + HEX_IDLE / 2) == []
    later = 1.0 + HEX_IDLE * 2
    rows = assembler.feed("rx", b"c", later, later)  # a pause ends the block
    assert rows == [("rx", hex_lines("rx", b"ab", 1.0)[0])]
    assert assembler.close() == [("rx", hex_lines("rx", b"c", later)[0])]
    assert assembler.feed("rx", b"", 9.0, 9.0) == []
