"""The count kept for a device that cannot be asked where it is survives other writers: several
processes (panels, motionctl runs) writing counts and settings to one settings file at once
never lose a device's count nor mix two writers' axes, and a panel's stale copy of the
settings file, synced at Quit, does not bring an old count back."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings

from app.common.kept_positions import positions_file, read_kept, write_kept
from app.common.settings import read_counted_position, write_counted_position
from tests.support.simproc import ROOT

pytestmark = pytest.mark.timeout(120)
COUNTS = 150


def _start(*args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "tests.support.kept_count_proc", *args],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=ROOT,
    )


def _in_another_process(path: Path, port: str, position: tuple[float, float, float]) -> None:
    code = (
        "import sys; from PySide6.QtCore import QSettings; "
        "from app.common.settings import write_counted_position as w; "
        f"w(QSettings(sys.argv[1], QSettings.Format.IniFormat), 'visiomex', {port!r}, "
        f"{position!r})"
    )
    subprocess.run([sys.executable, "-c", code, str(path)], check=True, timeout=30, cwd=ROOT)


def test_several_processes_writing_at_once_lose_and_mix_nothing(tmp_path: Path) -> None:
    path = str(tmp_path / "settings.ini")
    ports = [f"/dev/ttyUSB{n}" for n in range(3)]
    writers = [_start("write", path, port, str(COUNTS)) for port in ports]
    shared = "/dev/ttyACM0"  # two writers on one port: one's count or the other's, never a mix
    writers += [_start("write", path, shared, str(COUNTS)) for _ in range(2)]
    others = [_start("panel", path, str(COUNTS)), _start("panel", path, str(COUNTS))]
    reader = _start("read", path, *ports, f"~{shared}", "--until", str(COUNTS))
    every = [*writers, *others, reader]
    for process in every:  # all at once
        assert process.stdin is not None
        process.stdin.write("go\n")
        process.stdin.flush()
    outputs = [process.communicate(timeout=90) for process in every]
    assert [p.returncode for p in every] == [0] * len(every), [o[1] for o in outputs]
    lines = outputs[-1][0].splitlines()
    assert [line for line in lines if not line.startswith("seen")] == []  # never mixed
    assert lines[-1] == "seen " + " ".join(f"{p}={COUNTS}" for p in [*ports, shared])
    settings = QSettings(path, QSettings.Format.IniFormat)
    for port in [*ports, shared]:  # each port's last count, whatever the others wrote meanwhile
        assert read_counted_position(settings, "visiomex", port) == (COUNTS,) * 3
    assert settings.value("geometry") == f"{COUNTS - 1:06d}"


def test_a_panels_stale_settings_do_not_bring_an_old_count_back(tmp_path: Path) -> None:
    """The panel read the settings (count 0, 0, 0 after Set Home); another process counted
    (1, 2, 0), rewriting the file within the same tick of the file clock; the panel's Quit syncs
    its geometry: the count stays (1, 2, 0)."""
    path = tmp_path / "settings.ini"
    panel = QSettings(str(path), QSettings.Format.IniFormat)
    write_counted_position(panel, "visiomex", "/dev/ttyUSB0", (0.0, 0.0, 0.0))
    panel.setValue("geometry", "before")
    panel.sync()
    files = [p for p in tmp_path.iterdir() if not p.name.endswith(".lock")]
    stamps = {p: os.stat(p) for p in files}
    _in_another_process(path, "/dev/ttyUSB0", (1.0, 2.0, 0.0))
    for file, stamp in stamps.items():  # the same size, the same coarse tick
        if file.exists():
            os.utime(file, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
    panel.setValue("geometry", "at quit")
    panel.sync()
    fresh = QSettings(str(path), QSettings.Format.IniFormat)
    assert read_counted_position(fresh, "visiomex", "/dev/ttyUSB0") == (1.0, 2.0, 0.0)
    assert read_counted_position(panel, "visiomex", "/dev/ttyUSB0") == (1.0, 2.0, 0.0)


def test_a_count_kept_by_an_older_version_is_read_then_replaced(tmp_path: Path) -> None:
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    group = "devices/visiomex/%2Fdev%2Fa/counted_position"
    for axis, value in zip("xyz", ("1.5", "2.0", "0.0"), strict=True):
        settings.setValue(f"{group}/{axis}", value)
    assert read_counted_position(settings, "visiomex", "/dev/a") == (1.5, 2.0, 0.0)
    write_counted_position(settings, "firmata", "/dev/b", (5.0, 0.0, 0.0))
    write_counted_position(settings, "visiomex", "/dev/a", None)  # lost: not the old one again
    assert read_counted_position(settings, "visiomex", "/dev/a") is None
    assert not settings.contains(f"{group}/x")
    assert read_counted_position(settings, "firmata", "/dev/b") == (5.0, 0.0, 0.0)


def test_an_unreadable_positions_file_keeps_nothing_and_is_rewritten(tmp_path: Path) -> None:
    path = positions_file(str(tmp_path / "settings.ini"))
    path.write_text("{not json")
    assert read_kept(path, "k") == (False, None)
    write_kept(path, "k", (1.0, 0.0, 0.0))
    assert read_kept(path, "k") == (True, (1.0, 0.0, 0.0))
