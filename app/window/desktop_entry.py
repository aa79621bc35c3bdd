"""Put the launcher (.desktop file) and the icon where the desktop looks for them.

pip and pipx install only the Python side: `install_desktop_entry()` copies
resources/motionpanel.desktop to $XDG_DATA_HOME/applications/ and the SVG icon to
$XDG_DATA_HOME/icons/hicolor/scalable/apps/ (~/.local/share when XDG_DATA_HOME is unset), so the
application appears in the desktop's menu with its icon; `uninstall_desktop_entry()` removes them.
"""

from __future__ import annotations

import logging
import os
import shutil
from pathlib import Path

from app.window.icons import APP_ICON_NAME, icon_dir, icon_path

log = logging.getLogger(__name__)

DESKTOP_FILE_NAME = "motionpanel.desktop"


def desktop_file_path() -> Path:
    """The packaged .desktop file (resources/motionpanel.desktop beside the icons' folder)."""
    return icon_dir().parent / DESKTOP_FILE_NAME


def data_home() -> Path:
    """$XDG_DATA_HOME, else ~/.local/share."""
    value = os.environ.get("XDG_DATA_HOME", "")
    return Path(value) if os.path.isabs(value) else Path.home() / ".local" / "share"


def quote_exec(program: str) -> str:
    """`program` as the Exec= key wants it (Desktop Entry specification): "%" doubled; when it
    holds a space or a reserved character, double-quoted with `"`, `` ` ``, `$` and `\\`
    backslash-escaped; then, as in any string value, each backslash doubled."""
    value = program.replace("%", "%%")
    if any(c in value for c in " \t\n\"'\\><~|&;$*?#()`"):
        value = '"' + "".join(f"\\{c}" if c in '"`$\\' else c for c in value) + '"'
    return value.replace("\\", "\\\\")


def _targets(root: Path) -> tuple[Path, Path]:
    return (
        root / "applications" / DESKTOP_FILE_NAME,
        root / "icons" / "hicolor" / "scalable" / "apps" / f"{APP_ICON_NAME}.svg",
    )


def install_desktop_entry(root: Path | None = None, exec_path: str | None = None) -> list[Path]:
    """Copy the .desktop file and the icon under `root` (default: data_home()); return them.

    `exec_path` replaces Exec= (and TryExec=), e.g. the absolute path of the motionpanel script
    when its folder is not on the desktop session's PATH.
    """
    desktop, icon = _targets(root or data_home())
    text = desktop_file_path().read_text(encoding="utf-8")
    if exec_path:
        lines = []
        for line in text.splitlines():
            if line.startswith("Exec="):
                line = f"Exec={quote_exec(exec_path)}"
            elif line.startswith("TryExec="):
                line = f"TryExec={exec_path}"
            lines.append(line)
        text = "\n".join(lines) + "\n"
    for path in (desktop, icon):
        path.parent.mkdir(parents=True, exist_ok=True)
    desktop.write_text(text, encoding="utf-8")
    shutil.copyfile(icon_path(APP_ICON_NAME), icon)
    log.info("installed %s and %s", desktop, icon)
    return [desktop, icon]


def uninstall_desktop_entry(root: Path | None = None) -> list[Path]:
    """Remove what install_desktop_entry put under `root`; return what was removed."""
    removed = []
    for path in _targets(root or data_home()):
        if path.is_file():
            path.unlink()
            removed.append(path)
    return removed
