"""Preferences: defaults, the settings file both ways, bad values, and the validation messages."""

from __future__ import annotations

import dataclasses
import logging
import os
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtGui import QKeySequence

from app.common.settings import read_number
from app.window.preferences import (
    DEFAULTS,
    JOG_KEY_FIELDS,
    Preferences,
    folder_problem,
    read_preferences,
    session_log_folder,
    spec,
    validate,
    write_preferences,
)
from widgets.jog_panel import KEY_MAP

pytestmark = pytest.mark.timeout(30)

CHANGED = Preferences(
    poll_moving_hz=12.5,
    poll_idle_s=0.25,
    console_max_lines=250_000,
    session_log=False,
    log_folder="",  # set per test (a folder of its own)
    units="in",
    decimals=3,
    clamp_to_limits=True,
    jog_key_x_minus="A",
    jog_key_x_plus="D",
    jog_key_y_minus="S",
    jog_key_y_plus="W",
    jog_key_z_minus=",",  # a comma: quoted in the INI file
    jog_key_z_plus="Num+9",
    jog_key_step_smaller="",
    jog_key_step_larger="F5",
    theme="dark",
    language="zh_CN",
)


def _ini(path: Path, text: str = "") -> QSettings:
    path.write_text(text, encoding="utf-8")
    return QSettings(str(path), QSettings.Format.IniFormat)


def test_defaults_are_valid_and_are_todays_behaviour() -> None:
    assert validate(DEFAULTS) == []
    assert Preferences() == DEFAULTS
    assert (DEFAULTS.poll_moving_hz, DEFAULTS.poll_idle_s) == (10.0, 1.0)  # the worker's
    assert DEFAULTS.session_log is True and DEFAULTS.log_folder == ""
    assert DEFAULTS.console_max_lines == 0  # every line kept, as the console does
    assert (DEFAULTS.units, DEFAULTS.decimals) == ("mm", -1)
    assert (DEFAULTS.theme, DEFAULTS.language) == ("system", "system")
    by_move = {
        (axis, direction): QKeySequence(key).toString()
        for key, (axis, direction) in KEY_MAP.items()
    }
    assert DEFAULTS.jog_key_x_minus == by_move["x", -1.0]
    assert DEFAULTS.jog_key_x_plus == by_move["x", 1.0]
    assert DEFAULTS.jog_key_y_minus == by_move["y", -1.0]
    assert DEFAULTS.jog_key_y_plus == by_move["y", 1.0]
    assert DEFAULTS.jog_key_z_minus == by_move["z", -1.0]
    assert DEFAULTS.jog_key_z_plus == by_move["z", 1.0]


def test_keys_the_window_reads_today_are_kept() -> None:
    assert spec("poll_moving_hz").key == "poll_moving_hz"
    assert spec("poll_idle_s").key == "poll_idle_s"
    assert spec("session_log").key == "session_log"
    keys = [spec(f.name).key for f in dataclasses.fields(Preferences)]
    assert len(keys) == len(set(keys))


def test_an_empty_file_gives_the_defaults(tmp_path: Path) -> None:
    assert read_preferences(_ini(tmp_path / "empty.ini")) == DEFAULTS


def test_round_trip_through_an_ini_file(settings_file: Path, tmp_path: Path) -> None:
    folder = tmp_path / "logs, here"  # a comma too
    folder.mkdir()
    prefs = dataclasses.replace(CHANGED, log_folder=str(folder))
    assert validate(prefs) == []
    write_preferences(QSettings(str(settings_file), QSettings.Format.IniFormat), prefs)
    again = QSettings(str(settings_file), QSettings.Format.IniFormat)
    assert read_preferences(again) == prefs
    # What the window reads today reads the same values.
    assert str(again.value("session_log")).lower() == "false"
    assert read_number(again, "poll_moving_hz", 10.0) == 12.5
    assert read_number(again, "poll_idle_s", 1.0) == 0.25


def test_the_windows_hand_written_rates_are_clamped_as_it_did(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    settings = _ini(tmp_path / "rates.ini", "[General]\npoll_moving_hz=5\npoll_idle_s=50\n")
    with caplog.at_level(logging.WARNING, logger="app.window.preferences"):
        prefs = read_preferences(settings)
    assert (prefs.poll_moving_hz, prefs.poll_idle_s) == (5.0, 10.0)
    assert "poll_idle_s" in caplog.text


@pytest.mark.parametrize(
    ("line", "name"),
    [
        ("poll_moving_hz=fast", "poll_moving_hz"),
        ("poll_idle_s=nan", "poll_idle_s"),
        ("console_max_lines=1.5", "console_max_lines"),
        ("decimals=two", "decimals"),
        ("session_log=maybe", "session_log"),
        ("travel_clamp_default=2", "clamp_to_limits"),
        ("units=furlongs", "units"),
        ("view\\theme=neon", "theme"),
        ("language=tlh", "language"),
        ("log_folder=relative/logs", "log_folder"),
        ("log_folder=/no/such/folder/anywhere", "log_folder"),
        ("log_folder=a, b", "log_folder"),  # unquoted: a list, not a text
        ("jog_keys\\x_minus=Ctrl+Left", "jog_key_x_minus"),
        ("jog_keys\\x_plus=Esc", "jog_key_x_plus"),
        ("jog_keys\\y_plus=", "jog_key_y_plus"),
        ("jog_keys\\z_plus=NotAKey", "jog_key_z_plus"),
    ],
)
def test_an_unreadable_value_falls_back_to_its_default(
    tmp_path: Path, caplog: pytest.LogCaptureFixture, line: str, name: str
) -> None:
    settings = _ini(tmp_path / "bad.ini", f"[General]\n{line}\n")
    with caplog.at_level(logging.WARNING, logger="app.window.preferences"):
        prefs = read_preferences(settings)
    assert getattr(prefs, name) == getattr(DEFAULTS, name)
    assert prefs == DEFAULTS
    assert spec(name).key in caplog.text.replace("\\", "/")


def test_out_of_range_console_lines_are_brought_into_range(tmp_path: Path) -> None:
    settings = _ini(tmp_path / "lines.ini", "[General]\nconsole_max_lines=500\n")
    assert read_preferences(settings).console_max_lines == 10_000


def test_clashing_saved_keys_give_the_default_keys(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    text = "[jog_keys]\nx_minus=A\nx_plus=A\ny_plus=W\n"
    with caplog.at_level(logging.WARNING, logger="app.window.preferences"):
        prefs = read_preferences(_ini(tmp_path / "keys.ini", text))
    assert prefs.jog_keys() == DEFAULTS.jog_keys()
    assert "clash" in caplog.text
    assert validate(prefs) == []


def test_saved_keys_are_normalised(tmp_path: Path) -> None:
    prefs = read_preferences(_ini(tmp_path / "k.ini", "[jog_keys]\nz_minus=page down\n"))
    assert prefs.jog_key_z_minus == "PgDown"


def _problems(**changes: object) -> list[str]:
    return validate(dataclasses.replace(DEFAULTS, **changes))


@pytest.mark.parametrize(
    ("changes", "expected"),
    [
        ({"poll_moving_hz": 30.0}, "Poll while moving: 30 Hz is out of range (5 to 20 Hz)"),
        ({"poll_moving_hz": 4.0}, "Poll while moving: 4 Hz is out of range (5 to 20 Hz)"),
        ({"poll_idle_s": 0.1}, "Poll when idle: 0.1 s is out of range (0.2 to 10 s)"),
        ({"poll_idle_s": 11.0}, "Poll when idle: 11 s is out of range (0.2 to 10 s)"),
        (
            {"console_max_lines": 500},
            "Console lines kept: 500 lines is out of range: 0 (keep every line) or "
            "10,000 to 10,000,000 lines",
        ),
        (
            {"decimals": 7},
            "Decimals shown: 7 is out of range: -1 (as the device resolves) or 0 to 6 decimals",
        ),
        ({"units": "ft"}, "Units shown: 'ft' is not one of mm, in"),
        ({"theme": "neon"}, "Theme: 'neon' is not one of system, light, dark"),
        ({"language": "de"}, "Language: 'de' is not one of system, en, es, fr, zh_CN"),
    ],
)
def test_out_of_range_messages_name_the_field_unit_and_range(
    changes: dict[str, object], expected: str
) -> None:
    assert _problems(**changes) == [expected]


def test_range_ends_and_special_values_are_valid() -> None:
    for changes in (
        {"poll_moving_hz": 5.0},
        {"poll_moving_hz": 20.0},
        {"poll_idle_s": 0.2},
        {"poll_idle_s": 10.0},
        {"console_max_lines": 0},
        {"console_max_lines": 10_000},
        {"console_max_lines": 10_000_000},
        {"decimals": -1},
        {"decimals": 0},
        {"decimals": 6},
    ):
        assert _problems(**changes) == [], changes


def test_a_duplicate_jog_key_is_refused() -> None:
    assert _problems(jog_key_x_plus="Left") == ["Jog key X+: Left is already Jog key X-"]
    # The window matches keys by their code, keypad or not.
    assert _problems(jog_key_step_larger="Num+Up") == [
        "Jog key larger step: Num+Up is already Jog key Y+"
    ]


@pytest.mark.parametrize(
    ("key", "why"),
    [
        ("Esc", "the window uses it for Stop (Motion menu)"),
        ("F3", "the window uses it for the console's next match"),
        ("Return", "the window uses it for connecting and sending"),
        ("Space", "the window uses it for pressing the focused button"),
        ("Tab", "the window uses it for moving the focus"),
        ("Ctrl+E", "no Shift, Ctrl, Alt or Meta"),
        ("Shift+Left", "no Shift, Ctrl, Alt or Meta"),
        ("A, B", "it must be a single key"),
        ("Shift", "it is not a key the panel can use"),
    ],
)
def test_keys_the_window_uses_or_cannot_jog_with_are_refused(key: str, why: str) -> None:
    (message,) = _problems(jog_key_z_plus=key)
    assert message.startswith(f"Jog key Z+: {key} cannot be used: {why}")


def test_step_keys_may_be_none_but_jog_keys_may_not() -> None:
    assert _problems(jog_key_step_smaller="", jog_key_step_larger="") == []
    assert _problems(jog_key_y_minus="") == ["Jog key Y-: choose a key"]
    assert set(JOG_KEY_FIELDS) == set(DEFAULTS.jog_keys())


def test_log_folder_must_be_an_existing_writable_folder(tmp_path: Path) -> None:
    assert _problems(log_folder=str(tmp_path)) == []
    a_file = tmp_path / "file.txt"
    a_file.write_text("x")
    assert _problems(log_folder=str(a_file)) == [
        f"Session log folder: {a_file}: it is not a folder"
    ]
    missing = tmp_path / "missing"
    assert _problems(log_folder=str(missing)) == [
        f"Session log folder: {missing}: it does not exist"
    ]
    assert _problems(log_folder="logs") == ["Session log folder: logs: it must be an absolute path"]


def test_an_unwritable_log_folder_is_refused(tmp_path: Path) -> None:
    if os.geteuid() == 0:  # root writes anywhere permissions allow nothing; /proc refuses all
        folder = Path("/proc")
    else:
        folder = tmp_path / "read-only"
        folder.mkdir()
        folder.chmod(0o555)
    try:
        assert folder_problem(str(folder)) == "it is not writable"
        assert _problems(log_folder=str(folder)) == [
            f"Session log folder: {folder}: it is not writable"
        ]
    finally:
        if folder != Path("/proc"):
            folder.chmod(0o755)


def test_several_problems_give_one_message_each() -> None:
    problems = _problems(poll_moving_hz=50.0, jog_key_x_plus="Esc", console_max_lines=1)
    assert len(problems) == 3


def test_session_log_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    chosen = tmp_path / "chosen"
    chosen.mkdir()
    prefs = dataclasses.replace(DEFAULTS, log_folder=str(chosen))
    monkeypatch.setenv("MOTIONPANEL_LOG_DIR", str(tmp_path / "env"))
    assert session_log_folder(prefs) == tmp_path / "env"  # the environment comes first
    monkeypatch.delenv("MOTIONPANEL_LOG_DIR")
    assert session_log_folder(prefs) == chosen


def test_the_clamp_default_applies_only_where_a_device_saved_none(tmp_path: Path) -> None:
    from app.common.settings import device_key, read_travel

    key = device_key("coxiris", "sim://coxiris")
    settings = _ini(tmp_path / "travel.ini")
    settings.setValue(f"{key}/travel", "-10:10,-10:10,0:5")  # box saved, no clamp choice
    limits = read_travel(settings, "coxiris", "sim://coxiris", clamp_default=True)
    assert limits is not None and limits.clamp
    assert not read_travel(settings, "coxiris", "sim://coxiris").clamp  # type: ignore[union-attr]
    settings.setValue(f"{key}/travel_clamp", "false")  # the device's own choice wins
    limits = read_travel(settings, "coxiris", "sim://coxiris", clamp_default=True)
    assert limits is not None and not limits.clamp
