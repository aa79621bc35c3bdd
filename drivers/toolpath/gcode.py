"""G-code read into a Toolpath: what CAM programs and senders' files hold; the rest refused.

Understood: G0 (a rapid), G1, G2/G3 (clockwise/counter-clockwise arcs in XY, the centre from
I/J, incremental from the start point (G91.1, the default) or absolute (G90.1), or from R:
positive the short arc, negative the long one; I/J with the end at the start, a full circle; Z
on an arc, a helix; K ignored), G4 (a dwell of P *seconds*, as LinuxCNC and grbl read it, not
milliseconds), G17 (G18 and G19 are kept as states, but an arc in them is refused), G20/G21,
G90/G91, and F (units per minute, made mm/s). Motion is modal: a line of axis words repeats
the last G0-G3. The preamble codes G94, G40, G49, G54, G61, G64 (with its P/Q) change nothing
here, and G80 cancels the motion mode. M-codes and S and T words are skipped, with one notice
naming them. Comments `;…` and `(…)`, `%` lines, line numbers `N10` and checksums `*71` (not
verified) are tolerated, in either case, with spaces or without. As LinuxCNC, an arc whose
centre is not as far from its end as from its start (by 0.005 mm and 0.1 %, or by 0.5 mm) is
refused. Anything else refuses the whole file, naming the line and the word.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from drivers.files import PROGRAM_MAX_BYTES, read_text
from drivers.messages import Message
from drivers.toolpath.model import ArcTo, Dwell, Line, Source, Step, Toolpath, ToolpathError
from drivers.toolpath.point_program import FLOAT32_MAX

MAX_LINES = 1_000_000
"""A program's lines at most, as many as a CSV program's points (program.MAX_POINTS): some
450 MB once read, each line a Source and most a step."""
_LINE_ENDS = "\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029"  # where str.splitlines cuts
INCH = 25.4
ARC_TOLERANCE = 0.005
"""mm: how much farther the centre may be from an arc's end than from its start (LinuxCNC),
and how much shorter than half the way to its end an R may be."""
ARC_TOLERANCE_RATIO = 0.001
ARC_TOLERANCE_MAX = 0.5
MAX_NAMED_SKIPPED = 10

# One findall per line: each word as (letter, what follows it up to the next letter); the text
# before the first letter, if any, comes as ("", text).
_WORDS = re.compile(r"([A-Z]|^)([^A-Z]*)")
_PARAMETERS = frozenset("XYZIJKRFPQ")
_SKIPPED = frozenset("MST")
_LONGEST_SAFE = 38  # a number of 38 characters or fewer is below FLOAT32_MAX

# The G-codes understood, by value: (modal group (a bit), setting: the code itself, ten times for
# G90.1/G91.1, -1 for G80: no motion mode).
_MOTION, _PLANE, _UNITS, _DISTANCE, _ARC_DISTANCE, _DWELL = 1, 2, 4, 8, 16, 32  # bits
_NOTHING = 0
_G_CODES: dict[float, tuple[int, int]] = {
    # a group may be on a line once; _NOTHING, having no bit, any number of times
    0.0: (_MOTION, 0),
    1.0: (_MOTION, 1),
    2.0: (_MOTION, 2),
    3.0: (_MOTION, 3),
    80.0: (_MOTION, -1),
    4.0: (_DWELL, 4),
    17.0: (_PLANE, 17),
    18.0: (_PLANE, 18),
    19.0: (_PLANE, 19),
    20.0: (_UNITS, 20),
    21.0: (_UNITS, 21),
    90.0: (_DISTANCE, 90),
    91.0: (_DISTANCE, 91),
    90.1: (_ARC_DISTANCE, 901),
    91.1: (_ARC_DISTANCE, 911),
    94.0: (_NOTHING, 94),
    40.0: (_NOTHING, 40),
    49.0: (_NOTHING, 49),
    54.0: (_NOTHING, 54),
    61.0: (_NOTHING, 61),
    64.0: (_NOTHING, 64),
}
_USED_ALWAYS = frozenset("XYZF")  # axis words make a move or are refused; F sets the feed
_USED_ON_ARCS = frozenset("XYZFIJKR")
_PLANES = {18: "XZ", 19: "YZ"}


def read_gcode(path: str | Path) -> Toolpath:
    """A G-code file's toolpath (named after the file); refused whole if anything is wrong."""
    file = Path(path)
    text = read_text(file, PROGRAM_MAX_BYTES, Message("program"), ToolpathError, "utf-8-sig")
    return parse_gcode(text, file.name)


def _where(name: str, index: int) -> Message:
    return Message("{name} line {number}", name=name, number=index + 1)


def _word(text: str, letter: str) -> str:
    """The first word of `letter` in a line's `text` as written."""
    words: list[tuple[str, str]] = _WORDS.findall(text)
    for found, following in words:
        if found == letter:
            return found + following
    return letter


def _uncommented(line: str, name: str, index: int) -> str:
    """The line without its `(…)` comments and its `;…` comment."""
    kept = []
    rest = line
    while True:
        semicolon = rest.find(";")
        opening = rest.find("(")
        if semicolon >= 0 and (opening < 0 or semicolon < opening):
            kept.append(rest[:semicolon])
            break
        if opening < 0:
            kept.append(rest)
            break
        closing = rest.find(")", opening)
        if closing < 0:
            raise ToolpathError(
                Message("{where}: a comment opened with ( is not closed", where=_where(name, index))
            )
        kept.append(rest[:opening])
        rest = rest[closing + 1 :]
    return " ".join(kept)


def _without_checksum(text: str) -> str:
    """The line without a trailing `*71` checksum (not verified)."""
    star = text.rfind("*")
    tail = text[star + 1 :].strip()
    if tail.isascii() and tail.isdigit():
        return text[:star]
    return text


def _centre_from_radius(
    start: tuple[float, float],
    end: tuple[float, float],
    radius: float,
    ccw: bool,
    refuse: tuple[str, int, str],
) -> tuple[float, float]:
    """The centre of the arc of `radius` (negative: the long arc) from `start` to `end`."""
    name, index, word = refuse
    dx, dy = end[0] - start[0], end[1] - start[1]
    chord = math.hypot(dx, dy)
    if chord <= 1e-9:
        raise ToolpathError(
            Message(
                "{where}: {word} with R: a full circle needs I/J",
                where=_where(name, index),
                word=word,
            )
        )
    half = chord / 2
    size = abs(radius)
    if size < half:
        if half - size > ARC_TOLERANCE:
            raise ToolpathError(
                Message(
                    "{where}: {word}: R {radius:g} mm is less than half the way to the end point "
                    "({half:g} mm)",
                    where=_where(name, index),
                    word=word,
                    radius=size,
                    half=half,
                )
            )
        offset = 0.0
    else:
        offset = math.sqrt((size - half) * (size + half))
    # to the left of the way from start to end for a short counter-clockwise arc
    side = offset / chord if ccw == (radius > 0) else -offset / chord
    return (start[0] + dx / 2 - dy * side, start[1] + dy / 2 + dx * side)


def parse_gcode(text: str, name: str = "program") -> Toolpath:
    """The toolpath of G-code `text` (`name` names it in messages); refused whole if anything
    in it is not understood."""
    # a line end is at most two characters (CR LF): too many are seen before the text is cut
    if sum(map(text.count, _LINE_ENDS)) > 2 * MAX_LINES:
        raise _too_many_lines(name)
    lines = text.splitlines()
    if len(lines) > MAX_LINES:
        raise _too_many_lines(name)
    steps: list[Step] = []
    sources = [Source("line", number, line) for number, line in enumerate(lines, start=1)]
    add = steps.append
    findall = _WORDS.findall
    g_codes = _G_CODES
    parameters = _PARAMETERS
    skipped_words: dict[tuple[str, str], None] = {}
    skipped_lines = 0
    more_skipped = False

    x = y = z = 0.0
    mode = -1  # the motion mode: 0 to 3, or -1 for none
    absolute = True
    arc_absolute = False
    unit = 1.0
    plane = 17
    feed: float | None = None  # as written: units per minute
    speed: float | None = None  # mm/s

    for index, line in enumerate(lines):
        if "(" in line or ";" in line:
            line = _uncommented(line, name, index)
        if "*" in line:
            line = _without_checksum(line)
        compact = line.upper().replace(" ", "").replace("\t", "")
        if not compact or compact[0] == "%":
            continue
        if not compact.isascii() or "_" in compact:  # float() takes "1_0" and other digits
            for letter, rest in findall(compact):
                if "_" in rest or not (letter + rest).isascii():
                    raise _not_a_word(name, index, letter + rest)
        params: dict[str, float] = {}
        motion: int | None = None  # a motion code on this line (-1: G80)
        seen = 0  # the modal groups of this line's G-codes, as bits
        dwell = False
        g64 = False
        skipping = False
        for letter, rest in findall(compact):
            try:
                value = float(rest)
            except ValueError:
                raise _not_a_word(name, index, letter + rest) from None
            if letter == "G":
                code = g_codes.get(value)
                if code is None:
                    raise _not_understood(name, index, "G" + rest)
                group, setting = code
                if seen & group:
                    raise _twice(name, index, compact, group, "G" + rest)
                seen |= group
                if group == _MOTION:
                    motion = setting
                elif group == _PLANE:
                    plane = setting
                elif group == _UNITS:
                    unit = INCH if setting == 20 else 1.0
                    if feed is not None:
                        speed = feed * unit / 60
                elif group == _DISTANCE:
                    absolute = setting == 90
                elif group == _ARC_DISTANCE:
                    arc_absolute = setting == 901
                elif group == _DWELL:
                    dwell = True
                elif setting == 64:
                    g64 = True
            elif letter in parameters:
                if letter in params:
                    raise ToolpathError(
                        Message(
                            "{where}: {first} and {second} cannot be on one line",
                            where=_where(name, index),
                            first=_word(compact, letter),
                            second=letter + rest,
                        )
                    )
                params[letter] = value
            elif letter in _SKIPPED:
                skipping = True
                if not more_skipped and (letter, rest) not in skipped_words:
                    if len(skipped_words) < 4 * MAX_NAMED_SKIPPED:
                        skipped_words[(letter, rest)] = None
                    else:
                        more_skipped = True
            elif letter != "N":
                if not letter:  # text before the first letter
                    raise _not_a_word(name, index, rest)
                raise _not_understood(name, index, letter + rest)
        if skipping:
            skipped_lines += 1
        if not params and motion is None and not dwell:
            continue
        if len(compact) > _LONGEST_SAFE:
            _check_finite(params, compact, name, index)

        if "F" in params:
            feed = params["F"]
            if feed <= 0:
                raise ToolpathError(
                    Message(
                        "{where}: {word}: the feed rate must be above 0",
                        where=_where(name, index),
                        word=_word(compact, "F"),
                    )
                )
            speed = feed * unit / 60
        if dwell:
            seconds = params.get("P")
            if seconds is None:
                raise ToolpathError(
                    Message(
                        "{where}: {word} needs P, the seconds to dwell",
                        where=_where(name, index),
                        word="G4",
                    )
                )
            if seconds < 0:
                raise ToolpathError(
                    Message(
                        "{where}: {word}: a dwell cannot be negative",
                        where=_where(name, index),
                        word=_word(compact, "P"),
                    )
                )
            add(Dwell(seconds, index))
        if motion is not None:
            mode = motion
        moves = "X" in params or "Y" in params or "Z" in params
        arc = False
        if moves or motion == 2 or motion == 3:
            if mode == -1:
                word = next(_word(compact, axis) for axis in "XYZ" if axis in params)
                raise ToolpathError(
                    Message(
                        "{where}: {word} with no motion mode (G0, G1, G2 or G3) set",
                        where=_where(name, index),
                        word=word,
                    )
                )
            if absolute:
                nx = params["X"] * unit if "X" in params else x
                ny = params["Y"] * unit if "Y" in params else y
                nz = params["Z"] * unit if "Z" in params else z
            else:
                nx = x + params.get("X", 0.0) * unit
                ny = y + params.get("Y", 0.0) * unit
                nz = z + params.get("Z", 0.0) * unit
            if mode == 0:
                add(Line((nx, ny, nz), None, index, True))
            else:
                if speed is None:
                    raise ToolpathError(
                        Message(
                            "{where}: no feed rate (F) set before this {word}",
                            where=_where(name, index),
                            word=f"G{mode}",
                        )
                    )
                if mode == 1:
                    add(Line((nx, ny, nz), speed, index))
                else:
                    arc = True
                    centre = _arc_centre(
                        (x, y),
                        (nx, ny),
                        params,
                        unit,
                        arc_absolute,
                        plane,
                        mode == 3,
                        (name, index, f"G{mode}"),
                        compact,
                    )
                    add(ArcTo((nx, ny, nz), centre, mode == 3, speed, index))
            x, y, z = nx, ny, nz
        if not params.keys() <= (_USED_ON_ARCS if arc else _USED_ALWAYS):
            _check_used(params, compact, arc, dwell, g64, name, index)

    if not steps:
        raise ToolpathError(Message("{name}: no moves and no dwells", name=name))
    toolpath = Toolpath(name, steps, sources)
    if skipped_lines:
        toolpath.notices.append(
            _skipped_notice(name, skipped_words, more_skipped, skipped_lines, len(lines))
        )
    return toolpath


def _arc_centre(
    start: tuple[float, float],
    end: tuple[float, float],
    params: dict[str, float],
    unit: float,
    arc_absolute: bool,
    plane: int,
    ccw: bool,
    refuse: tuple[str, int, str],
    text: str,
) -> tuple[float, float]:
    """The centre of a G2/G3 from its I/J or R, checked (`text`: the line, for messages)."""
    name, index, word = refuse
    if plane != 17:
        raise ToolpathError(
            Message(
                "{where}: {word}: arcs in the {plane} plane ({code}) are not supported: "
                "only G17 (XY)",
                where=_where(name, index),
                word=word,
                plane=_PLANES[plane],
                code=f"G{plane}",
            )
        )
    if "R" in params:
        for letter in "IJ":
            if letter in params:
                raise ToolpathError(
                    Message(
                        "{where}: {first} and {second} cannot be on one line",
                        where=_where(name, index),
                        first=_word(text, "R"),
                        second=_word(text, letter),
                    )
                )
        return _centre_from_radius(start, end, params["R"] * unit, ccw, refuse)
    if "I" not in params and "J" not in params:
        raise ToolpathError(
            Message("{where}: {word} needs I and J, or R", where=_where(name, index), word=word)
        )
    i = params.get("I", 0.0) * unit
    j = params.get("J", 0.0) * unit
    centre = (i, j) if arc_absolute else (start[0] + i, start[1] + j)
    from_start = math.hypot(start[0] - centre[0], start[1] - centre[1])
    from_end = math.hypot(end[0] - centre[0], end[1] - centre[1])
    gap = abs(from_start - from_end)
    if gap > ARC_TOLERANCE_MAX or (gap > ARC_TOLERANCE and gap > ARC_TOLERANCE_RATIO * from_start):
        raise ToolpathError(
            Message(
                "{where}: {word}: the centre is {start:g} mm from the start point and {end:g} mm "
                "from the end point, not on one circle",
                where=_where(name, index),
                word=word,
                start=from_start,
                end=from_end,
            )
        )
    if from_start <= 1e-9 or from_end <= 1e-9:
        raise ToolpathError(
            Message("{where}: {word}: an arc of radius 0", where=_where(name, index), word=word)
        )
    return centre


def _check_used(
    params: dict[str, float],
    text: str,
    arc: bool,
    dwell: bool,
    g64: bool,
    name: str,
    index: int,
) -> None:
    """Refuse a word nothing on the line uses: I, J, K, R but on an arc, P but with G4 or G64,
    Q but with G64."""
    for letter in params:
        if letter in "IJKR":
            used = arc
        elif letter == "P":
            used = dwell or g64
        elif letter == "Q":
            used = g64
        else:
            continue
        if not used:
            raise ToolpathError(
                Message(
                    "{where}: {word} is not used by anything on the line",
                    where=_where(name, index),
                    word=_word(text, letter),
                )
            )


def _twice(name: str, index: int, text: str, group: int, second: str) -> ToolpathError:
    """Two G-codes of one modal group on a line: `second` and the one before it."""
    words: list[tuple[str, str]] = _WORDS.findall(text)
    first = next(
        "G" + rest for letter, rest in words if letter == "G" and _G_CODES[float(rest)][0] == group
    )
    return ToolpathError(
        Message(
            "{where}: {first} and {second} cannot be on one line",
            where=_where(name, index),
            first=first,
            second=second,
        )
    )


def _check_finite(params: dict[str, float], text: str, name: str, index: int) -> None:
    """Refuse a number too large for a float32 (a long line may hold one)."""
    for letter, value in params.items():
        if not abs(value) <= FLOAT32_MAX:
            raise ToolpathError(
                Message(
                    "{where}: {name} {value!r} is not a finite float32 number",
                    where=_where(name, index),
                    name=letter,
                    value=_word(text, letter)[1:],
                )
            )


def _too_many_lines(name: str) -> ToolpathError:
    return ToolpathError(
        Message(
            "{name}: more than {count:,} lines, too many for a program", name=name, count=MAX_LINES
        )
    )


def _not_a_word(name: str, index: int, word: str) -> ToolpathError:
    return ToolpathError(
        Message(
            "{where}: {word!r} is not a G-code word (a letter and a number)",
            where=_where(name, index),
            word=word,
        )
    )


def _not_understood(name: str, index: int, word: str) -> ToolpathError:
    return ToolpathError(
        Message("{where}: {word} is not understood", where=_where(name, index), word=word)
    )


def _skipped_notice(
    name: str,
    words: dict[tuple[str, str], None],
    more: bool,
    count: int,
    total: int,
) -> Message:
    """The one notice naming what was skipped (at most MAX_NAMED_SKIPPED distinct words)."""
    named: list[str] = []
    for letter, rest in words:
        word = f"{letter}{float(rest):g}"
        if word not in named:
            named.append(word)
    if len(named) > MAX_NAMED_SKIPPED or more:
        named = [*named[:MAX_NAMED_SKIPPED], "…"]
    return Message(
        "{name}: skipped what the panel does not do: {words} (on {count} of {total} lines)",
        name=name,
        words=", ".join(named),
        count=count,
        total=total,
    )
