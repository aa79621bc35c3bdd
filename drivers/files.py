"""Reading files from others (profiles, programs, logs) as data: bounded in size, text only."""

from __future__ import annotations

from pathlib import Path

from drivers.errors import BadInput


def read_text(
    path: str | Path, max_bytes: int, what: str, error: type[BadInput], encoding: str = "utf-8"
) -> str:
    """The file's text; `error` naming the file and why for a missing, huge or binary one."""
    file = Path(path)
    try:
        with file.open("rb") as stream:
            raw = stream.read(max_bytes + 1)
    except OSError as exc:
        raise error(f"cannot read the {what} {file}: {exc.strerror or exc}") from None
    if len(raw) > max_bytes:
        size = f"{max_bytes // 2**20} MiB" if max_bytes >= 2**20 else f"{max_bytes // 1024} KiB"
        raise error(f"{file}: larger than {size}, not a {what}")
    try:
        return raw.decode(encoding)
    except UnicodeDecodeError:
        raise error(f"{file}: not UTF-8 text, not a {what}") from None
