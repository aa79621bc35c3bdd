"""Files from others (profiles, programs, logs, settings) are data only, size-bounded, refused with
a clear error naming the file (and the line), and nothing is sent when one is bad (issue 11)."""

from __future__ import annotations

import ast
import logging
import os
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from drivers import files
from drivers.device.param_profile import ProfileError, parse_profile, read_profile
from drivers.errors import BadFile
from drivers.files import (
    LOG_MAX_BYTES,
    LOG_MAX_LINE,
    PROFILE_MAX_BYTES,
    PROGRAM_MAX_BYTES,
    SETTINGS_MAX_BYTES,
    read_lines,
    read_text,
)
from drivers.protocols.visiomex.params import PARAMETERS as VISIOMEX_PARAMETERS
from drivers.toolpath.point_program import ProgramError, parse_json, read_program
from drivers.traffic.log_reader import LogError, open_any_log, parse_log, read_any_log, read_log
from drivers.traffic.spy_log import _row, parse_spy
from tests.support.e2e import motionctl, sent
from tests.support.simproc import ROOT

pytestmark = [pytest.mark.timeout(30)]

GOOD_PROFILE = 'protocol = "visiomex"\n\n[parameters]\nthread_distance_x = 10\n'
GOOD_PROGRAM = "x,y,z,speed\n1,2,0,10\n"
GOOD_LOG = (
    "# Motion Panel session log\n"
    "000000.001 TX   47 45 54 5F 49 44 0A                                GET_ID.\n"
)


def _profile(path: Path) -> object:
    return read_profile(path, VISIOMEX_PARAMETERS, "visiomex")


def _open_any(path: Path) -> object:
    return list(open_any_log(path)[1])


# (name, reader, its error, its limit, what it calls the file, a good file's text, suffix)
READERS = [
    ("profile", _profile, ProfileError, PROFILE_MAX_BYTES, "profile", GOOD_PROFILE, ".toml"),
    ("program-csv", read_program, ProgramError, PROGRAM_MAX_BYTES, "program", GOOD_PROGRAM, ".csv"),
    (
        "program-json",
        read_program,
        ProgramError,
        PROGRAM_MAX_BYTES,
        "program",
        '{"points": [[1, 2, 0, 10]]}',
        ".json",
    ),
    ("read_log", read_log, LogError, LOG_MAX_BYTES, "traffic log", GOOD_LOG, ".log"),
    ("read_any_log", read_any_log, LogError, LOG_MAX_BYTES, "traffic log", GOOD_LOG, ".log"),
    ("open_any_log", _open_any, LogError, LOG_MAX_BYTES, "traffic log", GOOD_LOG, ".log"),
]
READER_IDS = [r[0] for r in READERS]
Reader = Callable[[Path], object]


def _refused(read: Reader, error: type[BadFile], path: Path | str) -> str:
    """The refusal's message: the reader's own error (a BadFile), naming the file."""
    with pytest.raises(error) as refused:
        read(Path(path))
    assert isinstance(refused.value, BadFile)
    message = str(refused.value)
    assert str(path) in message, message
    return message


@pytest.mark.parametrize(("name", "read", "error", "limit", "what", "good", "suffix"), READERS)
def test_a_good_file_is_read(tmp_path: Path, name, read, error, limit, what, good, suffix) -> None:
    path = tmp_path / f"good{suffix}"
    path.write_text(good, encoding="utf-8")
    assert read(path)


@pytest.mark.parametrize(("name", "read", "error", "limit", "what", "good", "suffix"), READERS)
def test_special_files_are_refused_without_blocking(
    tmp_path: Path, name, read, error, limit, what, good, suffix
) -> None:
    """A FIFO with no writer (would block an open() for ever), a directory, /dev/zero."""
    fifo = tmp_path / f"pipe{suffix}"
    os.mkfifo(fifo)
    assert "a named pipe (FIFO), not a regular file" in _refused(read, error, fifo)
    folder = tmp_path / f"folder{suffix}"
    folder.mkdir()
    assert "a directory, not a regular file" in _refused(read, error, folder)
    assert f"cannot read the {what} /dev/zero: a character device" in _refused(
        read, error, "/dev/zero"
    )
    assert "No such file" in _refused(read, error, tmp_path / f"missing{suffix}")


@pytest.mark.parametrize(("name", "read", "error", "limit", "what", "good", "suffix"), READERS)
def test_a_huge_sparse_file_is_refused_by_its_size_before_reading(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name, read, error, limit, what, good, suffix
) -> None:
    path = tmp_path / f"huge{suffix}"
    with path.open("wb") as stream:
        stream.truncate(10 << 30)  # 10 GiB of holes: no disk used, nothing written

    def no_read(*args: object) -> None:
        raise AssertionError("a file over the limit was opened")

    monkeypatch.setattr(files.os, "open", no_read)
    message = _refused(read, error, path)
    assert "larger than" in message and "(10,737,418,240 bytes)" in message
    assert f"too large for a {what}" in message


@pytest.mark.parametrize(("name", "read", "error", "limit", "what", "good", "suffix"), READERS)
def test_a_file_grown_past_its_limit_after_the_check_is_read_no_further(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name, read, error, limit, what, good, suffix
) -> None:
    """The reads are bounded too: as if the file grew between its stat and its reading."""
    path = tmp_path / f"grown{suffix}"
    path.write_text(good + "\n" * 4096, encoding="utf-8")
    monkeypatch.setattr(files, "_check_status", lambda *args: None)
    for constant in ("PROFILE_MAX_BYTES", "PROGRAM_MAX_BYTES", "LOG_MAX_BYTES"):
        monkeypatch.setattr(f"{_module(constant)}.{constant}", 1024)
    monkeypatch.setattr(files, "CHUNK_BYTES", 256)
    assert "larger than 1 KiB" in _refused(read, error, path)


def _module(constant: str) -> str:
    return {
        "PROFILE": "drivers.device.param_profile",
        "PROGRAM": "drivers.toolpath.point_program",
        "LOG": "drivers.traffic.log_reader",
    }[constant.split("_")[0]]


def test_a_file_swapped_for_a_fifo_after_the_check_does_not_block(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Opened without blocking, then checked again: the open of a FIFO returns at once."""
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    monkeypatch.setattr(files, "check_user_file", lambda *args: None)  # as if it was a file then
    message = _refused(_profile, ProfileError, fifo)
    assert "a named pipe (FIFO)" in message


@pytest.mark.parametrize(("name", "read", "error", "limit", "what", "good", "suffix"), READERS)
@pytest.mark.parametrize(
    ("tail", "why"),
    [
        (b"\xff\xfe oops\n", "not UTF-8 text (line 3)"),
        (b"\xe2\x82\n", "not UTF-8 text (line 3)"),  # a character cut short
        (b"\xed\xa0\x80\n", "not UTF-8 text (line 3)"),  # an encoded surrogate
        (b"a\x00b\n", "a NUL byte (line 3)"),
    ],
    ids=["invalid", "truncated", "surrogate", "NUL"],
)
def test_binary_bytes_are_refused_naming_the_line(
    tmp_path: Path, name, read, error, limit, what, good, suffix, tail: bytes, why: str
) -> None:
    path = tmp_path / f"binary{suffix}"
    path.write_bytes(b"\n\n" + tail + good.encode())
    message = _refused(read, error, path)
    assert f"{path}: {why}, not a {what}" in message


@pytest.mark.parametrize("chunk", [1, 2, 3, 5, 64])
def test_a_streamed_file_cuts_its_lines_as_splitlines_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, chunk: int
) -> None:
    """Line ends split over two chunks (CR | LF, a character's bytes) are read as one."""
    text = "a\r\nb\rc\n\nd\x85é€\u2028e\r\r\nf\x0bg\x1c\r"
    path = tmp_path / "lines.log"
    path.write_bytes(text.encode())
    monkeypatch.setattr(files, "CHUNK_BYTES", chunk)
    assert list(read_lines(path, 1 << 20, 100, "log", LogError)) == text.splitlines()


def test_a_streamed_file_names_the_line_of_a_bad_byte_in_a_later_chunk(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "late.log"
    path.write_bytes(b"x\n" * 500 + b"\xff\n")
    monkeypatch.setattr(files, "CHUNK_BYTES", 64)
    with pytest.raises(LogError, match=r"not UTF-8 text \(line 501\)"):
        list(read_lines(path, 1 << 20, 100, "traffic log", LogError))


def test_a_log_line_over_the_limit_is_refused_without_holding_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "long.log"
    path.write_text(GOOD_LOG + "000000.002 # " + "x" * (LOG_MAX_LINE + 1) + "\n")
    message = _refused(read_log, LogError, path)
    assert f"{path} line 3: longer than {LOG_MAX_LINE:,} characters" in message
    # the same without an end, in chunks shorter than the line
    monkeypatch.setattr(files, "CHUNK_BYTES", 4096)
    path.write_text("0" * (LOG_MAX_LINE * 2))
    assert "line 1: longer than" in _refused(read_any_log, LogError, path)


def test_a_log_is_read_as_a_stream(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Records come while the file is being read; a bad line far on fails only when reached."""
    monkeypatch.setattr(files, "CHUNK_BYTES", 4096)
    line = "000000.001 TX   47 45 54 5F 49 44 0A                                GET_ID.\n"
    path = tmp_path / "long.log"
    path.write_text(line * 5000 + "garbage\n")
    log_format, records = open_any_log(path)
    assert log_format == "motionpanel"
    assert next(records).data == b"GET_ID\n"
    with pytest.raises(LogError, match=r"line 5001: not a traffic log line"):
        list(records)


def test_json_and_toml_bombs_are_refused() -> None:
    deep = '{"points": ' + "[" * 100_000 + "]" * 100_000 + "}"
    with pytest.raises(ProgramError, match="nested too deeply"):
        parse_json(deep, "deep.json")
    toml = "protocol = " + "[" * 30_000 + "]" * 30_000 + "\n"
    assert len(toml) <= PROFILE_MAX_BYTES
    with pytest.raises(ProfileError, match=r"deep\.toml"):
        parse_profile(toml, VISIOMEX_PARAMETERS, "visiomex", "deep.toml")


def test_a_csv_field_of_a_megabyte_is_refused_naming_the_line(tmp_path: Path) -> None:
    path = tmp_path / "field.csv"
    path.write_text("x,y,z,speed\n1,2,0,10\n" + "1" * (1 << 20) + ",1,1,1\n")
    message = _refused(read_program, ProgramError, path)
    assert f"{path} line 3: not CSV" in message


def test_nothing_in_a_file_is_evaluated(tmp_path: Path) -> None:
    """Code in a profile, a program or a log stays text: refused, and never run."""
    canary = tmp_path / "ran"
    code = f"__import__('pathlib').Path({str(canary)!r}).touch()"
    for name, content, read, error in (
        ("p.toml", GOOD_PROFILE + f"thread_distance_y = {code}\n", _profile, ProfileError),
        ("p.csv", f"x,y,z,speed\n{code},1,1,1\n", read_program, ProgramError),
        ("p.json", f'{{"points": [[{code}, 1, 1, 1]]}}', read_program, ProgramError),
        ("p.log", GOOD_LOG + code + "\n", read_log, LogError),
    ):
        path = tmp_path / name
        path.write_text(content)
        _refused(read, error, path)
    assert not canary.exists()


READER_SOURCES = [
    "drivers/files.py",
    "drivers/device/param_profile.py",
    "drivers/toolpath/point_program.py",
    "drivers/traffic/log_reader.py",
    "drivers/traffic/spy_log.py",
    "app/common/settings.py",
    "app/window/console/log_viewer.py",
    "app/cli/log.py",
    "app/cli/params.py",
]
UNSAFE_CALLS = {"eval", "exec", "compile", "__import__", "open"}
UNSAFE_MODULES = {"pickle", "marshal", "shelve", "yaml", "dill", "jsonpickle", "runpy"}


@pytest.mark.parametrize("source", READER_SOURCES)
def test_the_readers_parse_only(source: str) -> None:
    """No eval/exec, no unpickling, and no open() of a user's file but drivers/files.py's."""
    tree = ast.parse((ROOT / source).read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
            assert node.func.id not in UNSAFE_CALLS, (source, node.lineno, node.func.id)
        if isinstance(node, ast.Attribute) and node.attr in ("read_text", "read_bytes"):
            raise AssertionError(f"{source}:{node.lineno}: reads a file past drivers/files.py")
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [a.name for a in node.names] + [getattr(node, "module", None) or ""]
            assert not UNSAFE_MODULES & {n.split(".")[0] for n in names}, (source, node.lineno)


def test_read_text_is_the_only_way_in_and_it_keeps_a_byte_order_mark_out(tmp_path: Path) -> None:
    path = tmp_path / "bom.csv"
    path.write_bytes(b"\xef\xbb\xbfx,y,z,speed\r\n1,2,0,10\r\n")
    assert read_text(path, 1024, "program", ProgramError, "utf-8-sig").startswith("x,y")
    assert read_program(path)[0].speed == 10


def test_the_spy_reader_streams_calls_in_order() -> None:
    """A call is handed over only once no later line can continue it (its order is kept)."""
    text = "\n".join(
        [
            f"000001.000 TX   0000  {_row(b'A' * 16)}",
            f"000001.001 RX   0000  {_row(b'B')}",
            f"000001.002 TX   0010  {_row(b'C')}",
        ]
    )
    records = parse_spy(text, "spy.txt")
    assert [(r.direction, r.data) for r in records] == [("tx", b"A" * 16 + b"C"), ("rx", b"B")]
    assert parse_log(GOOD_LOG)[1].data == b"GET_ID\n"


# -- the settings file ------------------------------------------------------------------------
def _settings_cases(tmp_path: Path) -> dict[str, tuple[Path, str]]:
    fifo = tmp_path / "fifo.ini"
    os.mkfifo(fifo)
    folder = tmp_path / "folder.ini"
    folder.mkdir()
    huge = tmp_path / "huge.ini"
    with huge.open("wb") as stream:
        stream.truncate(SETTINGS_MAX_BYTES + 1)
    corrupt = tmp_path / "corrupt.ini"
    corrupt.write_bytes(b"[General]\nport=sim://visiomex\n\xff\xfe\x00garbage\n[[[\n=\n")
    return {
        "fifo": (fifo, "a named pipe (FIFO)"),
        "folder": (folder, "a directory"),
        "device": (Path("/dev/zero"), "a character device"),
        "huge": (huge, "larger than 1 MiB"),
        "corrupt": (corrupt, "not an INI file Qt can read"),
    }


@pytest.mark.parametrize("case", ["fifo", "folder", "device", "huge", "corrupt"])
def test_a_bad_settings_file_gives_the_defaults_a_warning_and_is_left_alone(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture, case: str
) -> None:
    from app.common.settings import DEFAULT_PORT, open_settings, read_str, settings_problem

    path, why = _settings_cases(tmp_path)[case]
    before = path.read_bytes() if path.is_file() and case != "huge" else None
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(path))
    with caplog.at_level(logging.WARNING, logger="app.common.settings"):
        settings = open_settings()
    assert read_str(settings, "port", DEFAULT_PORT) == DEFAULT_PORT
    assert str(path.name) in settings_problem(settings) and why in settings_problem(settings)
    assert any(why in record.getMessage() for record in caplog.records)
    settings.setValue("port", "sim://coxiris")  # kept for the session, in the stand-in only
    settings.sync()
    assert read_str(settings, "port", "") == "sim://coxiris"
    if before is not None:
        assert path.read_bytes() == before
    again = open_settings()  # a second stand-in starts from the defaults again
    assert read_str(again, "port", DEFAULT_PORT) == DEFAULT_PORT


def test_a_good_settings_file_is_the_users(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    from app.common.settings import open_settings, settings_problem

    path = tmp_path / "settings.ini"
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(path))
    settings = open_settings()
    settings.setValue("port", "sim://visiomex")
    settings.sync()
    assert settings_problem(settings) == ""
    assert "sim://visiomex" in path.read_text()


def test_the_default_settings_files_are_checked_too(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from app.common import settings as settings_module

    if sys.platform.startswith("linux"):
        real = settings_module._native_files()
        assert any(str(p).endswith("MotionPanel/motionpanel.conf") for p in real), real
    fifo = tmp_path / "MotionPanel.conf"
    os.mkfifo(fifo)
    monkeypatch.delenv("MOTIONPANEL_SETTINGS", raising=False)
    monkeypatch.setattr(settings_module, "_native_files", lambda: [tmp_path / "none.conf", fifo])
    settings = settings_module.open_settings()
    assert "a named pipe (FIFO)" in settings_module.settings_problem(settings)


def test_the_window_starts_with_a_fifo_for_its_settings(
    qtbot, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from app.common.settings import settings_problem
    from app.window.main_window import MainWindow

    fifo = tmp_path / "settings.ini"
    os.mkfifo(fifo)
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(fifo))
    window = MainWindow()
    qtbot.addWidget(window)
    window.show()
    assert "a named pipe (FIFO)" in settings_problem(window.settings)
    window.close()
    assert not window.worker_thread.thread.isRunning()


# -- the log viewer: streamed into its index, a clear error in its status ---------------------
@pytest.fixture
def viewer(qtbot):
    from app.window.console.log_viewer import LogViewer

    window = LogViewer(None, "coxiris")
    qtbot.addWidget(window)
    window.show()
    return window


def _view(qtbot, viewer, path: Path) -> str:
    viewer.open(path)
    qtbot.waitUntil(lambda: not viewer.busy(), timeout=20_000)
    return viewer.status_text()


@pytest.mark.parametrize("case", ["fifo", "device", "folder", "huge", "binary", "late"])
def test_the_log_viewer_shows_a_clear_error_for_a_bad_file(
    qtbot, viewer, tmp_path: Path, case: str
) -> None:
    if case == "late":
        path, why = tmp_path / "late.log", "line 2000: not a traffic log line"
        path.write_text(GOOD_LOG.splitlines()[1] + "\n" * 1999 + "garbage\n" + GOOD_LOG)
    else:
        path, why = _hostile(tmp_path, case, ".log")
    status = _view(qtbot, viewer, path)
    assert str(path) in status and why in status, status
    assert "c62828" in viewer.status.styleSheet()


def test_the_log_viewer_takes_a_log_in_batches(
    qtbot, viewer, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from app.window.console import log_viewer

    monkeypatch.setattr(log_viewer, "LOOKAHEAD", 3)
    monkeypatch.setattr(log_viewer, "BATCH", 5)
    monkeypatch.setattr(files, "CHUNK_BYTES", 100)
    line = GOOD_LOG.splitlines()[1]
    path = tmp_path / "session.log"
    path.write_text(
        "000000.000 # connected to /dev/ttyUSB0 (visiomex, 115200 baud)\n"
        + "".join(line.replace("000000.001", f"{n:06d}.001") + "\n" for n in range(1, 41))
    )
    status = _view(qtbot, viewer, path)
    assert "41 lines" in status and "decoded as visiomex" in status, status


# -- through motionctl: exit 2, one line on stderr, nothing sent ------------------------------
def _hostile(tmp_path: Path, case: str, suffix: str) -> tuple[Path, str]:
    """A hostile file of the kind `case` and what its refusal says."""
    path = tmp_path / f"{case}{suffix}"
    if case == "fifo":
        os.mkfifo(path)
        return path, "a named pipe (FIFO), not a regular file"
    if case == "device":
        return Path("/dev/zero"), "a character device, not a regular file"
    if case == "folder":
        path.mkdir()
        return path, "a directory, not a regular file"
    if case == "huge":
        with path.open("wb") as stream:
            stream.truncate(10 << 30)
        return path, "(10,737,418,240 bytes), too large"
    if case == "binary":
        path.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00")
        return path, "not UTF-8 text (line 1)"
    assert case == "nul"
    path.write_bytes(b"x\x00\n")
    return path, "a NUL byte (line 1)"


# command: (protocol, port, its words before FILE, suffix, a good file, a malformed one, why)
SENDERS = {
    "param-write": (
        "visiomex",
        "sim://visiomex?instant=1",
        ("param", "write"),
        ".toml",
        GOOD_PROFILE,
        GOOD_PROFILE.replace("thread_distance_x", "nope"),
        "line 4: unknown parameter 'nope'",
    ),
    "run": (
        "laser-frame",
        "sim://laser-frame?instant=1",
        ("run",),
        ".csv",
        GOOD_PROGRAM,
        GOOD_PROGRAM + "abc,1,1,1\n",
        "line 3: x 'abc' is not a number",
    ),
}


@pytest.mark.e2e
@pytest.mark.parametrize("case", ["fifo", "device", "folder", "huge", "binary", "nul", "malformed"])
@pytest.mark.parametrize("command", SENDERS)
def test_motionctl_refuses_a_bad_file_and_sends_nothing(
    tmp_path: Path, settings_file: Path, command: str, case: str
) -> None:
    protocol, port, words, suffix, _, malformed, why = SENDERS[command]
    if case == "malformed":
        path = tmp_path / f"bad{suffix}"
        path.write_text(malformed)
    else:
        path, why = _hostile(tmp_path, case, suffix)
    log = tmp_path / "host.log"
    result = motionctl(protocol, port, *words, str(path), log=log, timeout=25)
    assert result.returncode == 2, (result.stdout, result.stderr)
    assert result.stdout == ""
    [line] = result.stderr.splitlines()
    assert line.startswith("motionctl: ") and why in line and str(path) in line, line
    assert not log.exists() or sent(log) == []  # the link was never opened: nothing sent


@pytest.mark.e2e
@pytest.mark.parametrize("command", SENDERS)
def test_motionctl_sends_a_good_file(tmp_path: Path, settings_file: Path, command: str) -> None:
    """The check above sees a send: the same run with a good file logs its TX."""
    protocol, port, words, suffix, good, _, _ = SENDERS[command]
    path = tmp_path / f"good{suffix}"
    path.write_text(good)
    log = tmp_path / "host.log"
    result = motionctl(protocol, port, *words, str(path), log=log, timeout=25)
    assert result.returncode == 0, result.stderr
    assert sent(log)


@pytest.mark.e2e
@pytest.mark.parametrize("case", ["fifo", "device", "huge", "binary"])
def test_motionctl_log_decode_refuses_a_bad_log(
    tmp_path: Path, settings_file: Path, case: str
) -> None:
    path, why = _hostile(tmp_path, case, ".log")
    result = motionctl("coxiris", "none", "log", "decode", str(path), timeout=25)
    assert result.returncode == 2, result.stderr
    [line] = result.stderr.splitlines()
    assert line.startswith("motionctl: ") and why in line and str(path) in line, line


@pytest.mark.e2e
def test_motionctl_runs_with_defaults_and_one_warning_when_its_settings_are_a_fifo(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    fifo = tmp_path / "settings.ini"
    os.mkfifo(fifo)
    monkeypatch.setenv("MOTIONPANEL_SETTINGS", str(fifo))
    result = motionctl("coxiris", "sim://coxiris?instant=1", "--json", "position", timeout=25)
    assert result.returncode == 0, result.stderr
    [warning] = result.stderr.splitlines()
    assert warning.startswith(f"motionctl: cannot read the settings file {fifo}: a named pipe")
    assert "starting from the default settings" in warning
