"""The user's preferences, typed: polling, console, session log, display, jog keys, looks.

`Preferences` is a frozen dataclass; each field's metadata holds its settings key, label, unit
and range (`spec(name)`), which `read_preferences`, `write_preferences`, `validate` and the
settings dialog share. Keys stay those the window reads today (`poll_moving_hz`, `poll_idle_s`,
`session_log`). Travel limits stay per device (`app.common.settings.read_travel`); `clamp_to_limits`
is only the choice a device without saved limits starts with.

Ranges, and why:
- `poll_moving_hz` 5 to 20 Hz: the position poll while a move is being confirmed
  (`Motion._wait_until_at`, once the device said DONE). Each period is also when a Stop is
  looked at and when a held jog's step is found finished, so below 5 Hz a Stop or the next
  held-jog step waits up to 200 ms more (5 Hz is the window's floor today). Above 20 Hz the
  views (redrawn at most 30 times a second) show nothing sooner, while each poll is a round
  trip (COXIRIS: about 66 bytes, 5.7 ms at 115200 baud) and three console and log lines; and
  `Motion` takes two equal readings in a row for "the stage stopped short", which stays safe
  only while the stage moves at least one resolution step a period: 0.01 mm x 20 Hz =
  0.2 mm/s, under COXIRIS's slowest speed (1 mm/s in the simulator). The window's ceiling
  today is 10 Hz; 20 Hz is still safe by those figures.
- `poll_idle_s` 0.2 to 10 s: the idle poll is how a device that restarted or stopped answering is
  noticed; slower than 10 s hides that for too long, faster than 0.2 s floods the console and
  the session log with polls for nothing (the window's range today).
- `console_max_lines`: the console keeps every line by design (a spool file on disk, about 33
  bytes a line in memory, README "A million lines"); this is the cap on the lines it keeps,
  0 (the default, as today) for no cap, else 10,000 to 10,000,000: past it the oldest lines are
  dropped in blocks (up to 10% more are held between trims: about 363 MB of memory at most).
"""

from __future__ import annotations

import dataclasses
import logging
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QSettings, Qt
from PySide6.QtGui import QKeySequence

from widgets._i18n import fill

log = logging.getLogger(__name__)

CONTEXT = "Preferences"  # the translation context of the labels and messages
BYTES_PER_CONSOLE_LINE = 33  # the console's memory per line (drivers/traffic/index.py)
CONSOLE_MIN_LINES = 10_000
CONSOLE_MAX_LINES = 10_000_000
UNITS = ("mm", "in")
THEMES = ("system", "light", "dark")
LANGUAGES = ("system", "en", "es", "fr", "zh_CN")
AS_DEVICE_RESOLVES = -1  # `decimals`: as many as the device resolves
JOG_KEY_FIELDS = (
    "jog_key_x_minus",
    "jog_key_x_plus",
    "jog_key_y_minus",
    "jog_key_y_plus",
    "jog_key_z_minus",
    "jog_key_z_plus",
    "jog_key_step_smaller",
    "jog_key_step_larger",
)
OPTIONAL_KEYS = frozenset({"jog_key_step_smaller", "jog_key_step_larger"})  # may be ""
# Keys the window uses for something else, with what for; a jog key must be none of them.
RESERVED_KEYS: dict[str, str] = {
    "Esc": QT_TRANSLATE_NOOP("Preferences", "Stop (Motion menu)"),
    "F3": QT_TRANSLATE_NOOP("Preferences", "the console's next match"),
    "Tab": QT_TRANSLATE_NOOP("Preferences", "moving the focus"),
    "Backtab": QT_TRANSLATE_NOOP("Preferences", "moving the focus"),
    "Return": QT_TRANSLATE_NOOP("Preferences", "connecting and sending"),
    "Enter": QT_TRANSLATE_NOOP("Preferences", "connecting and sending"),
    "Space": QT_TRANSLATE_NOOP("Preferences", "pressing the focused button"),
}
_MODIFIER_KEYS = {
    Qt.Key.Key_Shift,
    Qt.Key.Key_Control,
    Qt.Key.Key_Alt,
    Qt.Key.Key_AltGr,
    Qt.Key.Key_Meta,
    Qt.Key.Key_Super_L,
    Qt.Key.Key_Super_R,
    Qt.Key.Key_CapsLock,
    Qt.Key.Key_NumLock,
    Qt.Key.Key_unknown,
}
_NOT_ALLOWED = (
    Qt.KeyboardModifier.ShiftModifier
    | Qt.KeyboardModifier.ControlModifier
    | Qt.KeyboardModifier.AltModifier
    | Qt.KeyboardModifier.MetaModifier
)
_TRUE, _FALSE = ("true", "1", "yes", "on"), ("false", "0", "no", "off")


def _tr(text: str) -> str:
    return QCoreApplication.translate(CONTEXT, text)


@dataclass(frozen=True)
class Spec:
    """How a preference is kept and checked: settings key, label, unit, range or choices."""

    key: str
    label: str  # English; shown through QCoreApplication.translate(CONTEXT, label)
    unit: str = ""
    low: float | None = None
    high: float | None = None
    choices: tuple[str, ...] = ()
    special: int | None = None  # a value outside low..high that means something (0, -1)


def _pref(default: Any, spec: Spec) -> Any:
    return field(default=default, metadata={"spec": spec})


@dataclass(frozen=True)
class Preferences:
    """What the user may set in Settings; units are in each field's comment and `spec`."""

    poll_moving_hz: float = _pref(
        10.0,
        Spec(
            "poll_moving_hz", QT_TRANSLATE_NOOP("Preferences", "Poll while moving"), "Hz", 5.0, 20.0
        ),
    )  # Hz: position polls while a move is being confirmed
    poll_idle_s: float = _pref(
        1.0, Spec("poll_idle_s", QT_TRANSLATE_NOOP("Preferences", "Poll when idle"), "s", 0.2, 10.0)
    )  # s between position polls while nothing moves
    console_max_lines: int = _pref(
        0,
        Spec(
            "console_max_lines",
            QT_TRANSLATE_NOOP("Preferences", "Console lines kept"),
            QT_TRANSLATE_NOOP("Preferences", "lines"),
            CONSOLE_MIN_LINES,
            CONSOLE_MAX_LINES,
            special=0,
        ),
    )  # lines the console keeps (0: every line, as today)
    session_log: bool = _pref(
        True, Spec("session_log", QT_TRANSLATE_NOOP("Preferences", "Session log"))
    )  # every byte of every session to a file
    log_folder: str = _pref(
        "", Spec("log_folder", QT_TRANSLATE_NOOP("Preferences", "Session log folder"))
    )  # absolute path of a writable folder; "": the default location
    units: str = _pref(
        "mm", Spec("units", QT_TRANSLATE_NOOP("Preferences", "Units shown"), choices=UNITS)
    )  # lengths shown in mm or inches (the device is always spoken to in mm)
    decimals: int = _pref(
        AS_DEVICE_RESOLVES,
        Spec(
            "decimals",
            QT_TRANSLATE_NOOP("Preferences", "Decimals shown"),
            QT_TRANSLATE_NOOP("Preferences", "decimals"),
            0,
            6,
            special=AS_DEVICE_RESOLVES,
        ),
    )  # decimals of positions shown; -1: as many as the device resolves
    clamp_to_limits: bool = _pref(
        False,
        Spec("travel_clamp_default", QT_TRANSLATE_NOOP("Preferences", "Clamp moves to the limits")),
    )  # a device's starting choice: clamp a move at its travel limits (else refuse it)
    jog_key_x_minus: str = _pref("Left", Spec("jog_keys/x_minus", "X-"))
    jog_key_x_plus: str = _pref("Right", Spec("jog_keys/x_plus", "X+"))
    jog_key_y_minus: str = _pref("Down", Spec("jog_keys/y_minus", "Y-"))
    jog_key_y_plus: str = _pref("Up", Spec("jog_keys/y_plus", "Y+"))
    jog_key_z_minus: str = _pref("PgDown", Spec("jog_keys/z_minus", "Z-"))
    jog_key_z_plus: str = _pref("PgUp", Spec("jog_keys/z_plus", "Z+"))
    jog_key_step_smaller: str = _pref(
        "[", Spec("jog_keys/step_smaller", QT_TRANSLATE_NOOP("Preferences", "smaller step"))
    )  # the next smaller preset step; "": no key
    jog_key_step_larger: str = _pref(
        "]", Spec("jog_keys/step_larger", QT_TRANSLATE_NOOP("Preferences", "larger step"))
    )  # the next larger preset step; "": no key
    theme: str = _pref(
        "system",
        Spec("view/theme", QT_TRANSLATE_NOOP("Preferences", "Theme"), choices=THEMES),
    )  # app/window/theme.py's THEME_SETTING and choices
    language: str = _pref(
        "system",
        Spec("language", QT_TRANSLATE_NOOP("Preferences", "Language"), choices=LANGUAGES),
    )  # "system": --lang, $MOTIONPANEL_LANG or the locale decide

    def field_problems(self) -> list[tuple[str, str]]:
        """(field name, message) for each problem; none when the preferences can be used."""
        return _field_problems(self)

    def problems(self) -> list[str]:
        """One message per problem (see `validate`)."""
        return [message for _, message in _field_problems(self)]

    def jog_keys(self) -> dict[str, str]:
        """The jog keys by field name, as QKeySequence portable text ("" for none)."""
        return {name: getattr(self, name) for name in JOG_KEY_FIELDS}


DEFAULTS = Preferences()


def spec(name: str) -> Spec:
    """The settings key, label, unit and range of a `Preferences` field."""
    return _SPECS[name]


_SPECS: dict[str, Spec] = {f.name: f.metadata["spec"] for f in dataclasses.fields(Preferences)}


def label(name: str) -> str:
    """The field's label, translated; a jog key's reads "Jog key X-"."""
    text = _tr(_SPECS[name].label)
    if name in JOG_KEY_FIELDS:
        return fill(QCoreApplication.translate("Preferences", "Jog key %1"), text)
    return text


def _number(value: float) -> str:
    return f"{value:,g}" if abs(value) < 1e6 else f"{value:,.0f}"


def _range_problem(name: str, value: float) -> str:
    s = _SPECS[name]
    assert s.low is not None and s.high is not None
    if s.special is not None and value == s.special:
        return ""
    if s.low <= value <= s.high:
        return ""
    span = fill(
        QCoreApplication.translate("Preferences", "%1 to %2 %3"),
        _number(s.low),
        _number(s.high),
        _tr(s.unit),
    )
    if name == "console_max_lines":
        template = QCoreApplication.translate(
            "Preferences", "%1: %2 lines is out of range: 0 (keep every line) or %3"
        )
        return fill(template, label(name), _number(value), span)
    if name == "decimals":
        template = QCoreApplication.translate(
            "Preferences", "%1: %2 is out of range: -1 (as the device resolves) or %3"
        )
        return fill(template, label(name), _number(value), span)
    template = QCoreApplication.translate("Preferences", "%1: %2 %3 is out of range (%4)")
    return fill(template, label(name), _number(value), _tr(s.unit), span)


def folder_problem(path: str) -> str:
    """Why `path` cannot hold the session logs ("" when it can, or is "" for the default).

    It must be an existing folder that a file can be made in (tried: as root, permissions
    alone do not tell)."""
    if not path:
        return ""
    folder = Path(os.path.expanduser(path))
    if not folder.is_absolute():
        return QCoreApplication.translate("Preferences", "it must be an absolute path")
    if not folder.exists():
        return QCoreApplication.translate("Preferences", "it does not exist")
    if not folder.is_dir():
        return QCoreApplication.translate("Preferences", "it is not a folder")
    try:
        with tempfile.TemporaryFile(dir=folder, prefix=".motionpanel-probe-"):
            pass
    except OSError:
        return QCoreApplication.translate("Preferences", "it is not writable")
    return ""


def key_problem(text: str) -> str:
    """Why `text` cannot be a jog key ("" when it can): one key, no Shift/Ctrl/Alt/Meta."""
    sequence = QKeySequence(text)
    if sequence.count() != 1:
        return QCoreApplication.translate("Preferences", "it must be a single key")
    combination = sequence[0]
    if combination.key() in _MODIFIER_KEYS or not sequence.toString():
        return QCoreApplication.translate("Preferences", "it is not a key the panel can use")
    if combination.keyboardModifiers() & _NOT_ALLOWED:
        return QCoreApplication.translate(
            "Preferences", "no Shift, Ctrl, Alt or Meta: Shift makes the step ten times bigger"
        )
    use = RESERVED_KEYS.get(_without_keypad(text))
    if use is not None:
        return fill(
            QCoreApplication.translate("Preferences", "the window uses it for %1"), _tr(use)
        )
    return ""


def normalize_key(text: str) -> str:
    """A key as QKeySequence portable text ("pgdown" -> "PgDown"); "" stays ""."""
    return QKeySequence(text).toString(QKeySequence.SequenceFormat.PortableText) if text else ""


def _without_keypad(text: str) -> str:
    """The key alone: the jog map matches keys by their code, keypad or not."""
    sequence = QKeySequence(text)
    if sequence.count() != 1:
        return text
    return QKeySequence(sequence[0].key()).toString(QKeySequence.SequenceFormat.PortableText)


def _key_problems(prefs: Preferences) -> list[tuple[str, str]]:
    problems: list[tuple[str, str]] = []
    seen: dict[str, str] = {}
    for name in JOG_KEY_FIELDS:
        text = getattr(prefs, name)
        if not text:
            if name not in OPTIONAL_KEYS:
                problems.append(
                    (
                        name,
                        fill(
                            QCoreApplication.translate("Preferences", "%1: choose a key"),
                            label(name),
                        ),
                    )
                )
            continue
        why = key_problem(text)
        if why:
            message = fill(
                QCoreApplication.translate("Preferences", "%1: %2 cannot be used: %3"),
                label(name),
                text,
                why,
            )
            problems.append((name, message))
            continue
        bare = _without_keypad(text)
        if bare in seen:
            message = fill(
                QCoreApplication.translate("Preferences", "%1: %2 is already %3"),
                label(name),
                text,
                label(seen[bare]),
            )
            problems.append((name, message))
        else:
            seen[bare] = name
    return problems


def _field_problems(prefs: Preferences) -> list[tuple[str, str]]:
    problems: list[tuple[str, str]] = []
    for name in ("poll_moving_hz", "poll_idle_s", "console_max_lines", "decimals"):
        why = _range_problem(name, getattr(prefs, name))
        if why:
            problems.append((name, why))
    why = folder_problem(prefs.log_folder)
    if why:
        message = fill(
            QCoreApplication.translate("Preferences", "%1: %2: %3"),
            label("log_folder"),
            prefs.log_folder,
            why,
        )
        problems.append(("log_folder", message))
    for name in ("units", "theme", "language"):
        choices = _SPECS[name].choices
        if getattr(prefs, name) not in choices:
            value = repr(getattr(prefs, name))
            message = fill(
                QCoreApplication.translate("Preferences", "%1: %2 is not one of %3"),
                label(name),
                value,
                ", ".join(choices),
            )
            problems.append((name, message))
    return problems + _key_problems(prefs)


def validate(prefs: Preferences) -> list[str]:
    """One clear message per problem, naming the field, its unit and range; [] when valid."""
    return prefs.problems()


# -- settings ------------------------------------------------------------------------------


def _stored(settings: QSettings, name: str) -> Any:
    return settings.value(_SPECS[name].key)


def _fallback(name: str, raw: object, why: str) -> Any:
    default = getattr(DEFAULTS, name)
    log.warning("settings: %s=%r %s; using the default %r", _SPECS[name].key, raw, why, default)
    return default


def _read_value(settings: QSettings, name: str) -> Any:
    """One preference from the settings: missing -> default; unreadable -> default (logged);
    a number out of range -> the nearest end of the range (logged), as the window did."""
    raw = _stored(settings, name)
    default = getattr(DEFAULTS, name)
    if raw is None:
        return default
    s = _SPECS[name]
    if isinstance(default, bool):
        text = str(raw).strip().lower()
        if text in _TRUE or text in _FALSE:
            return text in _TRUE
        return _fallback(name, raw, "is not true or false")
    if isinstance(default, int | float):
        try:
            number = float(raw)  # type: ignore[arg-type]
        except (TypeError, ValueError):
            return _fallback(name, raw, "is not a number")
        if number != number or number in (float("inf"), float("-inf")):
            return _fallback(name, raw, "is not a finite number")
        if isinstance(default, int):
            if number != int(number):
                return _fallback(name, raw, "is not a whole number")
            number = int(number)
        if s.special is not None and number == s.special:
            return number
        assert s.low is not None and s.high is not None
        if not s.low <= number <= s.high:
            near = min(max(number, s.low), s.high)
            near = int(near) if isinstance(default, int) else float(near)
            log.warning("settings: %s=%r is out of range; using %r", s.key, raw, near)
            return near
        return number
    if not isinstance(raw, str):
        return _fallback(name, raw, "is not a text")
    if s.choices:
        return raw if raw in s.choices else _fallback(name, raw, f"is not one of {s.choices}")
    if name in JOG_KEY_FIELDS:
        if not raw:
            return raw if name in OPTIONAL_KEYS else _fallback(name, raw, "is empty")
        why = key_problem(raw)
        return normalize_key(raw) if not why else _fallback(name, raw, why)
    if name == "log_folder":
        why = folder_problem(raw)
        return raw if not why else _fallback(name, raw, why)
    return raw


def read_preferences(settings: QSettings) -> Preferences:
    """The saved preferences; anything unreadable is its default (logged). Always valid."""
    values = {f.name: _read_value(settings, f.name) for f in dataclasses.fields(Preferences)}
    prefs = Preferences(**values)
    if _key_problems(prefs):  # each key usable, but two the same: the default keys, all
        log.warning("settings: the jog keys %s clash; using the default keys", prefs.jog_keys())
        prefs = dataclasses.replace(prefs, **DEFAULTS.jog_keys())
    return prefs


def _text(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def write_preferences(settings: QSettings, prefs: Preferences) -> None:
    """Save the preferences (as text a person can edit) and sync the settings file."""
    for f in dataclasses.fields(Preferences):
        settings.setValue(_SPECS[f.name].key, _text(getattr(prefs, f.name)))
    settings.sync()


def session_log_folder(prefs: Preferences) -> Path:
    """Where session logs go: $MOTIONPANEL_LOG_DIR, else `log_folder`, else the default
    (created if missing)."""
    from app.common.session_log import log_folder

    if os.environ.get("MOTIONPANEL_LOG_DIR") or not prefs.log_folder:
        return log_folder()
    folder = Path(os.path.expanduser(prefs.log_folder))
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def console_memory_bytes(lines: int) -> int:
    """About how much memory the console takes for `lines` lines (the spool is on disk)."""
    return lines * BYTES_PER_CONSOLE_LINE


POLL_MOVING_HZ = (5.0, 20.0)  # the preferences' range
POLL_IDLE_S = (0.2, 10.0)


def poll_rates(settings: QSettings) -> tuple[float, float]:
    """The position poll rates the preferences give: Hz while moving, seconds when idle."""
    prefs = read_preferences(settings)
    moving = min(max(prefs.poll_moving_hz, POLL_MOVING_HZ[0]), POLL_MOVING_HZ[1])
    idle = min(max(prefs.poll_idle_s, POLL_IDLE_S[0]), POLL_IDLE_S[1])
    return moving, idle
