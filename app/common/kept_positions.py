"""The positions kept for devices that cannot be asked where they are, in a file of their own
beside the settings file, safe against several panels and motionctl runs writing at once.

Each write is a read-modify-write of one device's entry under an exclusive lock (a lock file
beside it, never removed), the file then replaced whole (written aside, flushed, renamed), so
a reader sees one writer's entry or another's, never a mix, and a writer never loses another
device's entry. The count is not kept in the settings file itself: QSettings caches that file
and, when it was rewritten with the same size within one tick of the file clock, writes its
stale copy back at its next sync (a panel's geometry at Quit), which turned a count of
(1, 2, 0) back to (0, 0, 0).
"""

from __future__ import annotations

import contextlib
import json
import logging
import os
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

log = logging.getLogger(__name__)

SUFFIX = ".positions.json"
MAX_BYTES = 4 * 1024 * 1024  # a file larger than this is not read (an edited or foreign one)
_VERSION = 1
Point = tuple[float, float, float]


def positions_file(settings_file: str) -> Path:
    """The file of kept positions that goes with a settings file."""
    return Path(settings_file + SUFFIX)


@contextlib.contextmanager
def _locked(path: Path) -> Iterator[None]:
    """Hold the exclusive lock of `path` (its `.lock` file, made if missing)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(f"{path}.lock", "a+b") as lock:
        _lock(lock)
        try:
            yield
        finally:
            _unlock(lock)


def _lock(stream: IO[bytes]) -> None:
    if sys.platform == "win32":
        import msvcrt

        msvcrt.locking(stream.fileno(), msvcrt.LK_LOCK, 1)
    else:
        import fcntl

        fcntl.flock(stream.fileno(), fcntl.LOCK_EX)


def _unlock(stream: IO[bytes]) -> None:
    if sys.platform == "win32":
        import msvcrt

        stream.seek(0)
        msvcrt.locking(stream.fileno(), msvcrt.LK_UNLCK, 1)
    else:
        import fcntl

        fcntl.flock(stream.fileno(), fcntl.LOCK_UN)


def _entries(path: Path) -> dict[str, Any]:
    """The entries of the file (none where it is missing, too large or unreadable: said)."""
    try:
        with open(path, "rb") as stream:
            data = stream.read(MAX_BYTES + 1)
    except FileNotFoundError:
        return {}
    except OSError as exc:
        log.warning("cannot read the kept positions %s: %s", path, exc)
        return {}
    try:
        if len(data) > MAX_BYTES:
            raise ValueError(f"larger than {MAX_BYTES} bytes")
        document = json.loads(data.decode("utf-8"))
        entries = document["positions"]
        if not isinstance(entries, dict):
            raise ValueError("no positions")
    except (ValueError, KeyError, TypeError, UnicodeDecodeError) as exc:
        log.warning("the kept positions %s are not readable (%s): none is used", path, exc)
        return {}
    return entries


def _point(entry: object) -> Point | None:
    """An entry as a point (None: lost, or not three numbers)."""
    if not isinstance(entry, list) or len(entry) != 3:
        return None
    try:
        x, y, z = (float(value) for value in entry)
    except (TypeError, ValueError):
        return None
    return (x, y, z)


def read_kept(path: Path, key: str) -> tuple[bool, Point | None]:
    """Whether an entry is kept for `key` (a lost count is one), and its position (None: lost
    or never kept)."""
    entries = _entries(path)
    if key not in entries:
        return False, None
    return True, _point(entries[key])


def write_kept(path: Path, key: str, position: Point | None) -> None:
    """Keep `position` for `key` (None: lost), leaving every other entry as it is on disk."""
    with _locked(path):
        entries = _entries(path)
        entries[key] = None if position is None else [float(value) for value in position]
        text = json.dumps({"version": _VERSION, "positions": entries}, indent=1, sort_keys=True)
        handle, aside = tempfile.mkstemp(prefix=path.name + ".", dir=path.parent)
        try:
            with os.fdopen(handle, "w", encoding="utf-8") as stream:
                stream.write(text + "\n")
                stream.flush()
                os.fsync(stream.fileno())
            os.replace(aside, path)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(aside)
            raise
