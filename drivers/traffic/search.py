"""Filters over the traffic index: by direction and kind on its codes, by regular expression
on its spool, one native scan of the span the candidate lines cover."""

from __future__ import annotations

import functools
import mmap
import re

import numpy as np

from drivers.errors import BadInput
from drivers.messages import Message
from drivers.traffic.lines import DIRECTION_CODE, KIND_CODE

_CHUNK = 8 << 20  # bytes of the spool lowered at a time for a literal search
_REGEX_SYNTAX = frozenset(b".^$*+?{}[]\\|()#")


class FilterError(BadInput):
    """A filter that cannot be used (a regular expression that does not compile)."""


def compile_filter(pattern: str) -> re.Pattern[bytes] | None:
    """A case-insensitive pattern over the spool's lines, `^` and `$` at each line's ends
    ("" → None); FilterError if invalid."""
    if not pattern:
        return None
    try:
        return re.compile(pattern.encode("utf-8"), re.IGNORECASE | re.MULTILINE)
    except re.error as exc:
        raise FilterError(
            Message(
                "{pattern!r} is not a regular expression: {error}", pattern=pattern, error=str(exc)
            )
        ) from None
    except UnicodeEncodeError:  # a lone surrogate: no line of the spool can hold it
        raise FilterError(Message("{pattern!r} is not valid text", pattern=pattern)) from None
    except (OverflowError, RecursionError) as exc:  # a{4294967296}, thousands of nested groups
        raise FilterError(
            Message(
                "{pattern!r}… is too large a regular expression: {error}",
                pattern=pattern[:40],
                error=str(exc),
            )
        ) from None


@functools.lru_cache(maxsize=64)
def wanted_codes(directions: frozenset[str], kinds: frozenset[str]) -> np.ndarray:
    """Which line codes (direction << 4 | kind) pass a direction and kind filter."""
    wanted = np.zeros(256, dtype=bool)
    for direction in directions:
        for kind in kinds:
            wanted[DIRECTION_CODE[direction] << 4 | KIND_CODE[kind]] = True
    return wanted


def _hit_spans(
    spool: mmap.mmap, begin: int, end: int, pattern: re.Pattern[bytes]
) -> tuple[np.ndarray, np.ndarray]:
    """Where the pattern matches in spool[begin:end] (starts, ends). A plain word (no regex
    syntax) is searched case-sensitively in lowered chunks: IGNORECASE makes the engine step
    byte by byte, a literal is found at memory-scan speed, about ten times faster."""
    text = pattern.pattern
    if any(byte in _REGEX_SYNTAX for byte in text):
        spans = [hit.span() for hit in pattern.finditer(spool, begin, end)]
        found = np.asarray(spans, dtype=np.int64).reshape(-1, 2)
        return found[:, 0], found[:, 1]
    literal = re.compile(re.escape(text.lower()))
    starts: list[np.ndarray] = []
    for start in range(begin, end, _CHUNK):
        chunk = spool[start : min(end, start + _CHUNK + len(text) - 1)].lower()
        hits = literal.finditer(chunk)
        starts.append(np.fromiter((start + hit.start() for hit in hits), dtype=np.int64))
    unique = np.unique(np.concatenate(starts)) if starts else np.zeros(0, dtype=np.int64)
    return unique, unique + len(text)


def matching_rows(
    fd: int, size: int, offsets: np.ndarray, rows: np.ndarray, pattern: re.Pattern[bytes]
) -> np.ndarray:
    """Those of `rows` (in order, at least one) whose line in the spool (`fd`, its first `size`
    bytes written; row i from offsets[i] to offsets[i + 1]) the pattern finds."""
    if pattern.search(b"") is not None:  # it matches the empty string: every line
        return rows
    first, last = int(rows[0]), int(rows[-1])
    begin, end = int(offsets[first]), int(offsets[last + 1])
    with mmap.mmap(fd, size, access=mmap.ACCESS_READ) as spool:
        if len(rows) * 64 < last - first:  # few candidates far apart: look at each
            keep = [
                row
                for row in rows.tolist()
                if pattern.search(spool, int(offsets[row]), int(offsets[row + 1]) - 1)
            ]
            return np.asarray(keep, dtype=np.int64)
        starts, ends = _hit_spans(spool, begin, end, pattern)
        first_row = np.searchsorted(offsets, starts, side="right") - 1
        last_row = np.searchsorted(offsets, np.maximum(ends - 1, starts), side="right") - 1
        inside = first_row == last_row  # a match across a line end belongs to neither:
        doubtful = np.unique(np.concatenate((first_row[~inside], last_row[~inside])))
        checked = [  # those rows are looked at alone (a match inside may have been eaten)
            row
            for row in doubtful.tolist()
            if pattern.search(spool, int(offsets[row]), int(offsets[row + 1]) - 1)
        ]
    hits = np.unique(np.concatenate((first_row[inside], np.asarray(checked, np.int64))))
    return hits[np.isin(hits, rows, assume_unique=True)]
