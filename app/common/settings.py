"""Saved settings: window layout, last port, protocol, baud and jog step (QSettings)."""

from __future__ import annotations

import atexit
import contextlib
import logging
import math
import os
import shutil
import sys
import tempfile
from pathlib import Path
from urllib.parse import quote, urlsplit

from PySide6.QtCore import QSettings, QStandardPaths

from app.common.kept_positions import positions_file, read_kept, write_kept
from app.common.messages import localized
from drivers.device.travel import TravelLimits, parse_travel
from drivers.errors import BadFile, BadInput
from drivers.files import SETTINGS_MAX_BYTES, check_user_file
from drivers.messages import Message, message_of, message_template
from drivers.protocols.registry import get_protocol_class

log = logging.getLogger(__name__)

ORGANISATION = "MotionPanel"
APPLICATION = "motionpanel"
DEFAULT_PORT = "sim://coxiris"
DEFAULT_PROTOCOL = "coxiris"
PROBLEM = "motionpanelSettingsProblem"  # the property of a stand-in: why the file was not used
_STATUS = {
    QSettings.Status.AccessError: message_template("it cannot be read"),
    QSettings.Status.FormatError: message_template("it is not an INI file Qt can read"),
}
_stand_ins: list[QSettings] = []  # synced at exit, before their folder is removed
_scratch: list[str] = []  # the stand-ins' folder, once made
_warned: set[str] = set()
_said: dict[str, Message] = {}  # a stand-in's problem (a property keeps only its text)
# Files Qt found malformed, by name: (size, modification time), why. Qt keeps a file it has read
# and does not say again that it is malformed, so until it changes it is not handed to Qt again.
_malformed: dict[str, tuple[tuple[int, int], str]] = {}


def open_settings() -> QSettings:
    """The application's settings; MOTIONPANEL_SETTINGS=FILE keeps them in an INI file instead.

    A settings file that is not a regular file (a FIFO, a device, a directory), is larger than
    SETTINGS_MAX_BYTES, cannot be read or is not INI is left as it is: the settings start from
    the defaults, in a scratch file, with a warning logged once; `settings_problem` says why."""
    path = os.environ.get("MOTIONPANEL_SETTINGS")
    for file in [Path(path)] if path else _native_files():
        if not os.path.lexists(file):
            continue
        try:
            info = check_user_file(file, SETTINGS_MAX_BYTES, Message("settings file"), BadFile)
        except BadFile as exc:
            return _stand_in(message_of(exc) or str(exc))
        seen = _malformed.get(os.path.abspath(file))
        if seen is not None and seen[0] == (info.st_size, info.st_mtime_ns):
            return _stand_in(seen[1])
    if path:
        settings = QSettings(path, QSettings.Format.IniFormat)
    else:
        settings = QSettings(ORGANISATION, APPLICATION)
    why = _STATUS.get(settings.status())
    if why is not None:
        problem = Message(
            "cannot read the settings file {file}: {why}",
            file=settings.fileName(),
            why=Message(why),
        )
        name = os.path.abspath(settings.fileName())
        with contextlib.suppress(OSError):
            info = os.stat(name)
            _malformed[name] = ((info.st_size, info.st_mtime_ns), problem)
        return _stand_in(problem)
    return settings


def settings_problem(settings: QSettings) -> str:
    """Why these settings are a stand-in with the defaults ("" when they are the user's own),
    in the interface's language."""
    problem = settings.property(PROBLEM)
    if not isinstance(problem, str):
        return ""
    return localized(_said.get(problem, problem))


def _native_files() -> list[Path]:
    """The INI files QSettings(ORGANISATION, APPLICATION) reads on Linux and the other Unixes
    (the user's, then the system's); none elsewhere, where the settings are not such a file."""
    if sys.platform in ("win32", "darwin"):
        return []
    folders = QStandardPaths.standardLocations(
        QStandardPaths.StandardLocation.GenericConfigLocation
    )
    return [
        Path(folder) / name
        for folder in folders
        for name in (f"{ORGANISATION}/{APPLICATION}.conf", f"{ORGANISATION}.conf")
    ]


def _stand_in(problem: str) -> QSettings:
    """Settings with the defaults, in a scratch file of this process's, for a file not used."""
    if problem not in _warned:
        _warned.add(problem)
        log.warning("%s; starting from the default settings, and leaving it as it is", problem)
    if not _scratch:
        _scratch.append(tempfile.mkdtemp(prefix="motionpanel-settings-"))
        atexit.register(_remove_stand_ins)
    file = Path(_scratch[0]) / f"defaults-{len(_stand_ins)}.ini"  # each starts from nothing
    settings = QSettings(str(file), QSettings.Format.IniFormat)
    settings.setProperty(PROBLEM, str(problem))
    if isinstance(problem, Message):
        _said[str(problem)] = problem
    _stand_ins.append(settings)
    return settings


def _remove_stand_ins() -> None:
    """At exit: the stand-ins written out (so they do not write again later), then removed."""
    for settings in _stand_ins:
        settings.sync()
    shutil.rmtree(_scratch[0], ignore_errors=True)


def read_str(settings: QSettings, key: str, default: str) -> str:
    """A string setting, or the default."""
    value = settings.value(key, default)
    return value if isinstance(value, str) and value else default


def read_number(settings: QSettings, key: str, default: float) -> float:
    """A numeric setting, or the default when missing or unreadable."""
    try:
        return float(settings.value(key, default))  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return default


def device_key(protocol: str, port: str) -> str:
    """The settings group of one device: its protocol and port (a URL's options left out)."""
    parts = urlsplit(port)
    where = f"{parts.scheme}://{parts.netloc}{parts.path}" if parts.scheme else port
    return f"devices/{protocol}/{quote(where, safe='')}"


def read_travel(
    settings: QSettings, protocol: str, port: str, clamp_default: bool = False
) -> TravelLimits | None:
    """The travel limits saved for a device, else the protocol's own (None: none known);
    `clamp_default` (the preference) is the clamp choice where none was saved."""
    key = device_key(protocol, port)
    text = settings.value(f"{key}/travel")
    if isinstance(text, str):
        try:
            limits = parse_travel(text)
        except BadInput:
            limits = None
        saved = str(settings.value(f"{key}/travel_clamp", "")).lower()
        clamp = saved == "true" if saved in ("true", "false") else clamp_default
        return TravelLimits(limits.box, clamp) if limits is not None else None
    try:
        box = get_protocol_class(protocol).capabilities.travel
    except LookupError:
        return None
    return TravelLimits(box, clamp_default) if box is not None else None


def write_travel(
    settings: QSettings, protocol: str, port: str, limits: TravelLimits | None
) -> None:
    """Save a device's travel limits (None: explicitly none)."""
    key = device_key(protocol, port)
    if limits is None:
        settings.setValue(f"{key}/travel", "none")
        return
    text = ",".join(f"{lo:g}:{hi:g}" for lo, hi in limits.box)
    settings.setValue(f"{key}/travel", text)
    settings.setValue(f"{key}/travel_clamp", "true" if limits.clamp else "false")


def _read_numbers(settings: QSettings, group: str) -> dict[str, float]:
    """The numbers kept under `group`; an unreadable one (an edited file) is forgotten."""
    values: dict[str, float] = {}
    settings.beginGroup(group)
    try:
        for name in settings.childKeys():
            try:
                values[name] = float(settings.value(name))  # type: ignore[arg-type]
            except (TypeError, ValueError):
                continue
        return values
    finally:
        settings.endGroup()


def _write_numbers(settings: QSettings, group: str, values: dict[str, float]) -> None:
    """Keep numbers under `group` (merged with those kept before)."""
    for name, value in values.items():
        settings.setValue(f"{group}/{name}", repr(float(value)))


def read_parameters(settings: QSettings, protocol: str, port: str) -> dict[str, float]:
    """The parameter values last written to a device and confirmed (the device has no read-back)."""
    return _read_numbers(settings, f"{device_key(protocol, port)}/parameters")


def write_parameters(
    settings: QSettings, protocol: str, port: str, values: dict[str, float]
) -> None:
    """Remember values the device confirmed (merged with those written before)."""
    _write_numbers(settings, f"{device_key(protocol, port)}/parameters", values)
    settings.sync()


def read_protocol_settings(settings: QSettings, protocol: str, port: str) -> dict[str, float]:
    """A device's protocol settings kept by the panel (ticks per mm, steps per mm...)."""
    return _read_numbers(settings, f"{device_key(protocol, port)}/settings")


def write_protocol_settings(
    settings: QSettings, protocol: str, port: str, values: dict[str, float]
) -> None:
    """Remember a device's protocol settings."""
    _write_numbers(settings, f"{device_key(protocol, port)}/settings", values)


def _kept_file(settings: QSettings) -> Path:
    """The file of kept positions beside these settings (the settings' folder where they are
    not a file, e.g. the Windows registry)."""
    name = settings.fileName()
    if settings.format() == QSettings.Format.NativeFormat and sys.platform == "win32":
        folder = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppConfigLocation)
        name = str(Path(folder) / APPLICATION)
    return positions_file(name)


def read_counted_position(
    settings: QSettings, protocol: str, port: str
) -> tuple[float, float, float] | None:
    """Where a device without position feedback was last counted, or commanded, to be (None:
    no position kept), read from the file as it is now (another panel or motionctl run may have
    written it)."""
    entry, kept = read_kept(_kept_file(settings), device_key(protocol, port))
    if entry:
        return kept
    values = _read_numbers(settings, f"{device_key(protocol, port)}/counted_position")  # (old)
    if not all(axis in values for axis in "xyz"):
        return None
    return (values["x"], values["y"], values["z"])


def write_counted_position(
    settings: QSettings, protocol: str, port: str, position: tuple[float, float, float] | None
) -> None:
    """Keep the position counted, or commanded, for a device (None: the count is lost, e.g. a
    failed move): that device's entry alone, safe against other writers (kept_positions)."""
    write_kept(_kept_file(settings), device_key(protocol, port), position)
    group = f"{device_key(protocol, port)}/counted_position"  # where older versions kept it
    if settings.contains(f"{group}/x"):
        settings.remove(group)
        settings.sync()


def read_speed(settings: QSettings, protocol: str, port: str) -> float | None:
    """The speed last set for a device whose moves carry it (None: none set)."""
    value = settings.value(f"{device_key(protocol, port)}/speed")
    try:
        speed = float(value)
    except (TypeError, ValueError):
        return None
    return speed if math.isfinite(speed) and speed > 0 else None


def write_speed(settings: QSettings, protocol: str, port: str, speed: float) -> None:
    """Remember the speed set for a device whose moves carry it (pi-frame, Firmata, laser)."""
    settings.setValue(f"{device_key(protocol, port)}/speed", repr(float(speed)))
    settings.sync()
