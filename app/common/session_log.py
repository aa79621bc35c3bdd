"""The session log: every byte that crosses the port, on disk as it crosses, one file a session.

Files live in a per-user folder (`MOTIONPANEL_LOG_DIR`, else Qt's app-data location + `logs`),
named `session-YYYYmmdd-HHMMSS-<pid>.log`, in the hexdump format of `motionctl --log` after a
`#` header. Each record is written and flushed (handed to the operating system) as it crosses,
so a killed panel loses nothing; there is no fsync, so a power cut may lose the last seconds.
At start, the oldest sessions are deleted until the folder is within `BUDGET_BYTES`.
"""

from __future__ import annotations

import logging
import os
import time
from pathlib import Path
from typing import TextIO

from PySide6.QtCore import QStandardPaths

log = logging.getLogger(__name__)

BUDGET_BYTES = 200 * 1024 * 1024  # all sessions together; the oldest go first
PATTERN = "session-*.log"


def log_folder() -> Path:
    """Where session logs go (created if missing)."""
    override = os.environ.get("MOTIONPANEL_LOG_DIR")
    if override:
        folder = Path(override)
    else:
        base = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppDataLocation)
        folder = Path(base or Path.home() / ".motionpanel") / "logs"
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def prune(folder: Path, budget: int = BUDGET_BYTES, keep: Path | None = None) -> list[Path]:
    """Delete the oldest session logs until the rest fit `budget` bytes; returns those deleted."""
    files = sorted(folder.glob(PATTERN), key=lambda p: p.stat().st_mtime)
    total = sum(p.stat().st_size for p in files)
    deleted = []
    for path in files:
        if total <= budget:
            break
        if path == keep:
            continue
        total -= path.stat().st_size
        try:
            path.unlink()
            deleted.append(path)
        except OSError as exc:
            log.warning("could not delete the old session log %s: %s", path, exc)
    return deleted


def open_session_log(folder: Path | None = None) -> tuple[Path, TextIO]:
    """A new session file (its header written), after pruning old ones."""
    folder = folder or log_folder()
    stamp = time.strftime("%Y%m%d-%H%M%S")
    path = folder / f"session-{stamp}-{os.getpid()}.log"
    stream = path.open("a", encoding="utf-8")
    wall = time.strftime("%Y-%m-%d %H:%M:%S %z")
    stream.write(f"# Motion Panel session log, started {wall}; times are seconds since then\n")
    stream.flush()
    prune(folder, keep=path)
    return path, stream
