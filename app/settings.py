"""Saved settings: window layout, last port, protocol, baud and jog step (QSettings)."""

from __future__ import annotations

import os

from PySide6.QtCore import QSettings

ORGANISATION = "MotionPanel"
APPLICATION = "motionpanel"
DEFAULT_PORT = "sim://coxiris"
DEFAULT_PROTOCOL = "coxiris"


def open_settings() -> QSettings:
    """The application's settings; MOTIONPANEL_SETTINGS=FILE keeps them in an INI file instead."""
    path = os.environ.get("MOTIONPANEL_SETTINGS")
    if path:
        return QSettings(path, QSettings.Format.IniFormat)
    return QSettings(ORGANISATION, APPLICATION)


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
