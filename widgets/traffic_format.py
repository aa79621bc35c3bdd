"""What the send line reads: text with escapes (the console's text form), or hex."""

from __future__ import annotations

import re

from PySide6.QtCore import QCoreApplication

from widgets._i18n import fill

_UNESCAPES = {"r": b"\r", "n": b"\n", "t": b"\t", "\\": b"\\", "0": b"\0"}
_HEX_SEPARATORS = re.compile(r"[\s,:;-]+")
_HEX_DIGITS = re.compile(r"[0-9a-fA-F]+")


def unescape(text: str) -> bytes:
    """The bytes of a send line in text mode: UTF-8, with \\r \\n \\t \\0 \\\\ and \\xNN escapes.

    Raises ValueError naming the bad escape.
    """
    out = bytearray()
    i = 0
    while i < len(text):
        char = text[i]
        if char != "\\":
            out += char.encode("utf-8")
            i += 1
            continue
        code = text[i + 1 : i + 2]
        if code in _UNESCAPES:
            out += _UNESCAPES[code]
            i += 2
        elif code == "x":
            digits = text[i + 2 : i + 4]
            if len(digits) != 2 or not _HEX_DIGITS.fullmatch(digits):
                raise ValueError(
                    fill(
                        QCoreApplication.translate(
                            "TrafficFormat", "\\x needs two hex digits at column %1: %2"
                        ),
                        i + 1,
                        repr(text[i : i + 4]),
                    )
                )
            out.append(int(digits, 16))
            i += 4
        elif not code:
            raise ValueError(
                QCoreApplication.translate(
                    "TrafficFormat", "a lone backslash ends the line: write \\\\ for a backslash"
                )
            )
        else:
            raise ValueError(
                fill(
                    QCoreApplication.translate(
                        "TrafficFormat",
                        "unknown escape \\%1 at column %2 (use \\r \\n \\t \\0 \\\\ \\xNN)",
                    ),
                    code,
                    i + 1,
                )
            )
    return bytes(out)


def parse_hex(text: str) -> bytes:
    """Bytes from hex like "48 45 4c", "48454C", "0x48,0x45" or "48:45"; raises ValueError."""
    out = bytearray()
    for token in _HEX_SEPARATORS.split(text.strip()):
        if not token:
            continue
        digits = token[2:] if token[:2].lower() == "0x" else token
        if not digits or not _HEX_DIGITS.fullmatch(digits):
            raise ValueError(
                fill(QCoreApplication.translate("TrafficFormat", "not hex: %1"), repr(token))
            )
        if len(digits) % 2:
            raise ValueError(
                fill(
                    QCoreApplication.translate(
                        "TrafficFormat", "odd number of hex digits in %1: write 0%2 or pairs"
                    ),
                    repr(token),
                    digits,
                )
            )
        out += bytes.fromhex(digits)
    return bytes(out)
