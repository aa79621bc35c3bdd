"""Reading files from others (profiles, programs, macros, logs, settings) as data: bounded, text.

Every reader of a file a user hands the panel goes through here, so all get the same checks,
made before a byte is read: the path must name a regular file (a directory, a FIFO, a socket or
a device such as /dev/zero is refused without being opened: opening a serial port's device
would reset the board behind it) no larger than the reader's limit below (a sparse 10 GB file
is refused by its size alone), and what is read must be UTF-8 text without NUL bytes. The reads
are bounded too, should the file grow meanwhile. A refusal is the reader's own `BadFile`,
naming the file, the line where there is one, and why. Nothing here evaluates anything, and the
readers parse with tomllib, json, csv and regular expressions only. `what`, the kind of file
the refusals name, is a Message (`Message("program")`) so that the window translates it.
"""

from __future__ import annotations

import codecs
import os
import stat
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO

from drivers.errors import BadFile
from drivers.messages import Message

KiB = 1024
MiB = 1024 * KiB

# The limits, each with its reason.
PROFILE_MAX_BYTES = 64 * KiB  # a profile is some thirty `name = value  # comment` lines: ~3 KiB
PROGRAM_MAX_BYTES = 64 * MiB  # a CSV point is 20 to 60 bytes: room for program.MAX_POINTS
LOG_MAX_BYTES = 512 * MiB  # streamed, so this bounds the time taken, not memory; a session log
# is pruned to 200 MiB, `motionctl --log` appends to its file without end
LOG_MAX_LINE = 64 * KiB  # our lines are ~90 characters and spy's ~80: a longer one is no log's
MACRO_MAX_BYTES = 1 * MiB  # macros are a few KiB: room for hundreds of long ones
BENCH_MAX_BYTES = 64 * KiB  # a bench names a few devices in some ten lines each: ~1 KiB
SETTINGS_MAX_BYTES = 1 * MiB  # the panel writes a few KiB: its window layout, numbers per device
CHUNK_BYTES = 1 * MiB  # a streamed file is read this much at a time

_KINDS = (
    (stat.S_ISDIR, Message("a directory")),
    (stat.S_ISFIFO, Message("a named pipe (FIFO)")),
    (stat.S_ISCHR, Message("a character device")),
    (stat.S_ISBLK, Message("a block device")),
    (stat.S_ISSOCK, Message("a socket")),
)
_LINE_ENDS = frozenset("\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029")  # where str.splitlines cuts
_OPEN_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)


def _size(count: int) -> str:
    return f"{count // MiB} MiB" if count >= MiB else f"{count // KiB} KiB"


def _unreadable(file: Path, what: str, error: type[BadFile], why: str) -> BadFile:
    return error(Message("cannot read the {what} {file}: {why}", what=what, file=file, why=why))


def _check_status(
    file: Path, info: os.stat_result, max_bytes: int, what: str, error: type[BadFile]
) -> None:
    if not stat.S_ISREG(info.st_mode):
        kind = next((name for test, name in _KINDS if test(info.st_mode)), None)
        why = Message("{kind}, not a regular file", kind=kind or Message("a special file"))
        raise _unreadable(file, what, error, why)
    if info.st_size > max_bytes:
        raise _too_large(file, max_bytes, what, error, info.st_size)


def _too_large(
    file: Path, max_bytes: int, what: str, error: type[BadFile], size: int | None = None
) -> BadFile:
    if size is not None:
        return error(
            Message(
                "{file}: larger than {limit} ({size:,} bytes), too large for a {what}",
                file=file,
                limit=_size(max_bytes),
                size=size,
                what=what,
            )
        )
    return error(
        Message(
            "{file}: larger than {limit}, too large for a {what}",
            file=file,
            limit=_size(max_bytes),
            what=what,
        )
    )


def check_user_file(
    path: str | Path, max_bytes: int, what: str, error: type[BadFile]
) -> os.stat_result:
    """The file's status once it is known to be a regular file of at most `max_bytes` (the file
    is not opened); `error` naming the file and why for a missing, special or larger one."""
    file = Path(path)
    try:
        info = os.stat(file)
    except OSError as exc:
        raise _unreadable(file, what, error, exc.strerror or str(exc)) from None
    _check_status(file, info, max_bytes, what, error)
    return info


def open_user_file(path: str | Path, max_bytes: int, what: str, error: type[BadFile]) -> BinaryIO:
    """The file, checked (`check_user_file`) and opened for reading in binary. It is opened
    without blocking and checked again, so a file swapped for a FIFO meanwhile cannot hang."""
    file = Path(path)
    check_user_file(file, max_bytes, what, error)
    try:
        descriptor = os.open(file, _OPEN_FLAGS)
    except OSError as exc:
        raise _unreadable(file, what, error, exc.strerror or str(exc)) from None
    try:
        _check_status(file, os.fstat(descriptor), max_bytes, what, error)
        return os.fdopen(descriptor, "rb")
    except BaseException:
        os.close(descriptor)
        raise


def _read(stream: BinaryIO, count: int, file: Path, what: str, error: type[BadFile]) -> bytes:
    try:
        return stream.read(count)
    except OSError as exc:
        raise _unreadable(file, what, error, exc.strerror or str(exc)) from None


def _check_text(text: str, lines_before: int, file: Path, what: str, error: type[BadFile]) -> None:
    """Refuse text that held bytes UTF-8 refuses (decoded with surrogateescape) or a NUL byte;
    the line is counted as str.splitlines counts, `lines_before` lines before the text."""
    if not text.isascii():
        try:
            text.encode("utf-8")  # fails at the first byte surrogateescape kept
        except UnicodeEncodeError as exc:
            raise error(
                Message(
                    "{file}: not UTF-8 text (line {line}), not a {what}",
                    file=file,
                    line=_line_at(text, exc.start, lines_before),
                    what=what,
                )
            ) from None
    if "\x00" in text:
        raise error(
            Message(
                "{file}: a NUL byte (line {line}), not a {what}",
                file=file,
                line=_line_at(text, text.index("\x00"), lines_before),
                what=what,
            )
        )


def _line_at(text: str, index: int, lines_before: int) -> int:
    """The line of `text[index]`, counted as str.splitlines counts."""
    return lines_before + len((text[:index] + "x").splitlines())


def read_bytes(path: str | Path, max_bytes: int, what: str, error: type[BadFile]) -> bytes:
    """The whole content of a file of at most `max_bytes`, undecoded (for a format with its own
    encodings or a binary form, such as DXF); checked and bounded as `read_text` is."""
    file = Path(path)
    with open_user_file(file, max_bytes, what, error) as stream:
        raw = _read(stream, max_bytes + 1, file, what, error)
    if len(raw) > max_bytes:  # it grew after its size was checked
        raise _too_large(file, max_bytes, what, error)
    return raw


def read_text(
    path: str | Path, max_bytes: int, what: str, error: type[BadFile], encoding: str = "utf-8"
) -> str:
    """The whole text of a file of at most `max_bytes` (`encoding` "utf-8" or "utf-8-sig")."""
    file = Path(path)
    with open_user_file(file, max_bytes, what, error) as stream:
        raw = _read(stream, max_bytes + 1, file, what, error)
    if len(raw) > max_bytes:  # it grew after its size was checked
        raise _too_large(file, max_bytes, what, error)
    text = raw.decode(encoding, errors="surrogateescape")
    _check_text(text, 0, file, what, error)
    return text


def read_lines(
    path: str | Path, max_bytes: int, max_line: int, what: str, error: type[BadFile]
) -> Iterator[str]:
    """A UTF-8 file's lines, without their ends, cut where str.splitlines cuts. The file is read
    `CHUNK_BYTES` at a time, so memory stays within a chunk and a line whatever its size; `error`
    comes when the reading reaches a line over `max_line` characters or a byte that is not text.
    The file is opened, and checked, when the first line is asked for."""
    file = Path(path)
    with open_user_file(file, max_bytes, what, error) as stream:
        decoder = codecs.getincrementaldecoder("utf-8")(errors="surrogateescape")
        carry, number, total = "", 0, 0
        while True:
            raw = _read(stream, CHUNK_BYTES, file, what, error)
            total += len(raw)
            if total > max_bytes:
                raise _too_large(file, max_bytes, what, error)
            text = carry + decoder.decode(raw, final=not raw)
            _check_text(text, number, file, what, error)
            lines = text.splitlines()
            carry = ""
            if raw and text and (text[-1] not in _LINE_ENDS or text[-1] == "\r"):
                # the last line has no end yet, or a CR whose LF may come with the next chunk
                carry = lines.pop() + ("\r" if text[-1] == "\r" else "")
            if max(max(map(len, lines), default=0), len(carry)) > max_line:
                at = next((n for n, line in enumerate(lines) if len(line) > max_line), len(lines))
                raise error(
                    Message(
                        "{file} line {line}: longer than {limit:,} characters, not a {what} line",
                        file=file,
                        line=number + at + 1,
                        limit=max_line,
                        what=what,
                    )
                )
            number += len(lines)
            yield from lines
            if not raw:
                return
