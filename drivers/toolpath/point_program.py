"""Programs: a list of points (x, y, z mm, speed mm/s) read from CSV or from the panel's JSON.

CSV: a header line `x,y,z,speed` (any order, case and spaces ignored), then one point per line;
blank lines and lines starting with `#` are skipped. JSON: `{"points": [[x, y, z, speed], ...]}`.
A file is data: it is refused whole, naming the line, if anything in it is wrong, or if it is not a
regular file of at most `PROGRAM_MAX_BYTES` of UTF-8 text (drivers/files.py); nothing is sent.
"""

from __future__ import annotations

import csv
import io
import json
import math
from collections.abc import Callable, Iterator
from pathlib import Path

from drivers.device.program_steps import ProgramDwell as ProgramDwell
from drivers.device.program_steps import ProgramPoint as ProgramPoint
from drivers.errors import BadFile
from drivers.files import PROGRAM_MAX_BYTES, read_text
from drivers.messages import Message

MAX_POINTS = 1_000_000
FLOAT32_MAX = 3.4028234663852886e38
COLUMNS = ("x", "y", "z", "speed")


class ProgramError(BadFile):
    """A program file that cannot be used (which file, which line, why)."""


def _point(values: list[str | float], place: Callable[[], Message]) -> ProgramPoint:
    """The point of one line (or JSON entry); `place()` names it for people, made only when a
    value is refused (a program has up to a million points)."""
    numbers = []
    for name, value in zip(COLUMNS, values, strict=True):
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise ProgramError(
                Message(
                    "{where}: {name} {value!r} is not a number",
                    where=place(),
                    name=name,
                    value=value,
                )
            ) from None
        except OverflowError:  # a JSON integer too large for a float
            raise ProgramError(
                Message("{where}: {name} is not a finite float32 number", where=place(), name=name)
            ) from None
        if not math.isfinite(number) or abs(number) > FLOAT32_MAX:
            raise ProgramError(
                Message(
                    "{where}: {name} {value!r} is not a finite float32 number",
                    where=place(),
                    name=name,
                    value=value,
                )
            )
        numbers.append(number)
    if numbers[3] <= 0:
        raise ProgramError(
            Message(
                "{where}: speed {speed:g} mm/s must be above 0", where=place(), speed=numbers[3]
            )
        )
    return ProgramPoint(*numbers)


def parse_csv(text: str, source: str = "program") -> list[ProgramPoint]:
    """Points from CSV text with an `x,y,z,speed` header."""
    rows = csv.reader(io.StringIO(text, newline=""))  # csv itself takes CR, LF and CR LF
    try:
        return _csv_points(rows, source)
    except csv.Error as exc:  # a field over csv's 128 KiB limit
        raise ProgramError(
            Message(
                "{source} line {line}: not CSV: {error}",
                source=source,
                line=rows.line_num,
                error=exc,
            )
        ) from None


def _csv_points(rows: Iterator[list[str]], source: str) -> list[ProgramPoint]:
    header: list[str] | None = None
    points: list[ProgramPoint] = []
    for number, row in enumerate(rows, start=1):
        if not row or not "".join(row).strip() or row[0].lstrip().startswith("#"):
            continue
        if header is None:
            header = [c.strip().lower() for c in row]
            if sorted(header) != sorted(COLUMNS):
                got = ", ".join(header)
                if not got:
                    raise ProgramError(
                        Message(
                            "{source} line {line}: the header must name x, y, z and speed "
                            "(got nothing)",
                            source=source,
                            line=number,
                        )
                    )
                raise ProgramError(
                    Message(
                        "{source} line {line}: the header must name x, y, z and speed "
                        "(got {columns})",
                        source=source,
                        line=number,
                        columns=got,
                    )
                )
            continue
        if len(row) != len(header):
            raise ProgramError(
                Message(
                    "{source} line {line}: {count} values, expected 4",
                    source=source,
                    line=number,
                    count=len(row),
                )
            )
        by_name = dict(zip(header, row, strict=True))
        points.append(_point([by_name[c].strip() for c in COLUMNS], _line(source, number)))
        if len(points) > MAX_POINTS:
            raise ProgramError(_too_many(source))
    if header is None:
        raise ProgramError(Message("{source}: no header line (x,y,z,speed)", source=source))
    if not points:
        raise ProgramError(Message("{source}: no points", source=source))
    return points


def parse_json(text: str, source: str = "program") -> list[ProgramPoint]:
    """Points from the panel's JSON."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ProgramError(
            Message(
                "{source} line {line}: not JSON ({reason})",
                source=source,
                line=exc.lineno,
                reason=exc.msg,
            )
        ) from None
    except ValueError:  # an integer of over 4300 digits, which int() refuses
        raise ProgramError(
            Message("{source}: not JSON the panel reads (a number too long)", source=source)
        ) from None
    except RecursionError:
        raise ProgramError(
            Message("{source}: not JSON the panel reads (nested too deeply)", source=source)
        ) from None
    points = data.get("points") if isinstance(data, dict) else None
    if not isinstance(points, list) or not points:
        raise ProgramError(Message('{source}: no "points" list', source=source))
    if len(points) > MAX_POINTS:
        raise ProgramError(_too_many(source))
    result = []
    for index, point in enumerate(points):
        place = _entry(source, index + 1)
        if not isinstance(point, list) or len(point) != 4:
            raise ProgramError(Message("{where}: expected [x, y, z, speed]", where=place()))
        result.append(_point(point, place))
    return result


def _line(source: str, number: int) -> Callable[[], Message]:
    return lambda: Message("{source} line {line}", source=source, line=number)


def _entry(source: str, number: int) -> Callable[[], Message]:
    return lambda: Message("{source} point {number}", source=source, number=number)


def _too_many(source: str) -> Message:
    return Message("{source}: more than {count} points", source=source, count=MAX_POINTS)


def read_program(path: str | Path) -> list[ProgramPoint]:
    """A program file's points (`.json`: the panel's JSON, anything else: CSV)."""
    file = Path(path)
    # a spreadsheet's "CSV UTF-8" starts with a BOM
    text = read_text(file, PROGRAM_MAX_BYTES, Message("program"), ProgramError, "utf-8-sig")
    if file.suffix.lower() == ".json":
        return parse_json(text, str(file))
    return parse_csv(text, str(file))


def write_program(path: str | Path, points: list[ProgramPoint]) -> None:
    """Save points as the panel's JSON."""
    data = {"points": [[p.x, p.y, p.z, p.speed] for p in points]}
    try:
        Path(path).write_text(json.dumps(data), encoding="utf-8")
    except OSError as exc:
        raise ProgramError(
            Message(
                "cannot write the program {path}: {error}", path=path, error=exc.strerror or exc
            )
        ) from None
