"""Saved settings: window layout, last port, protocol, baud and jog step (QSettings)."""

from __future__ import annotations

import os
from urllib.parse import quote, urlsplit

from PySide6.QtCore import QSettings

from drivers.errors import BadInput
from drivers.registry import get_protocol_class
from drivers.travel import TravelLimits, parse_travel

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


def device_key(protocol: str, port: str) -> str:
    """The settings group of one device: its protocol and port (a URL's options left out)."""
    parts = urlsplit(port)
    where = f"{parts.scheme}://{parts.netloc}{parts.path}" if parts.scheme else port
    return f"devices/{protocol}/{quote(where, safe='')}"


def read_travel(settings: QSettings, protocol: str, port: str) -> TravelLimits | None:
    """The travel limits saved for a device, else the protocol's own (None: none known)."""
    key = device_key(protocol, port)
    text = settings.value(f"{key}/travel")
    if isinstance(text, str):
        try:
            limits = parse_travel(text)
        except BadInput:
            limits = None
        clamp = str(settings.value(f"{key}/travel_clamp", "false")).lower() == "true"
        return TravelLimits(limits.box, clamp) if limits is not None else None
    try:
        box = get_protocol_class(protocol).capabilities.travel
    except LookupError:
        return None
    return TravelLimits(box) if box is not None else None


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
