"""Text forms of traffic: escapes, hexdump lines, parsing what is typed in the send line."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from drivers.traffic.lines import escape
from widgets.traffic_format import parse_hex, unescape


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
