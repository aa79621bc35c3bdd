"""The application's icons: hand-drawn SVG files in resources/icons/, found next to the packages.

The setuptools configuration installs `resources/` as package data beside `app/` (see
pyproject.toml), so the same relative path works from a source checkout, an editable install
and an installed wheel. SVG is read through Qt's `svg` image-format and icon-engine plugins
(QtSvg, part of PySide6-Essentials).
"""

from __future__ import annotations

import logging
from importlib import resources
from pathlib import Path

from PySide6.QtCore import QByteArray, QRectF, Qt
from PySide6.QtGui import QColor, QGuiApplication, QIcon, QImageReader, QPainter, QPixmap
from PySide6.QtSvg import QSvgRenderer

log = logging.getLogger(__name__)

APP_ICON_NAME = "motionpanel"  # as Icon= in resources/motionpanel.desktop
ACTION_ICONS = (
    "connect",
    "disconnect",
    "home",
    "stop",
    "jog-left",
    "jog-right",
    "jog-up",
    "jog-down",
)
ACTION_ICON_SIZES = (16, 20, 24, 32, 48, 64)
APP_ICON_SIZES = (16, 24, 32, 48, 64, 128, 256)
THEMED_COLOUR = "currentColor"  # the action icons' strokes, replaced by the palette's text colour


def icon_dir() -> Path:
    """The folder holding the SVG icons (resources/icons beside the `app` package)."""
    beside = Path(__file__).resolve().parents[2] / "resources" / "icons"
    if beside.is_dir():
        return beside
    try:  # an unusual layout: ask the import system where `resources` went
        found = resources.files("resources") / "icons"
        if found.is_dir():
            return Path(str(found))
    except (ModuleNotFoundError, TypeError, ValueError):
        pass
    log.warning("icon folder not found (looked in %s)", beside)
    return beside


def icon_path(name: str) -> Path:
    """The SVG file of the icon `name` (without .svg)."""
    return icon_dir() / f"{name}.svg"


def svg_supported() -> bool:
    """Whether Qt's SVG image-format plugin is loaded (QIcon and QPixmap then read .svg)."""
    return b"svg" in {bytes(fmt.data()) for fmt in QImageReader.supportedImageFormats()}


def app_icon() -> QIcon:
    """The application icon (scalable; a null QIcon, with a warning, if it cannot be read)."""
    path = icon_path(APP_ICON_NAME)
    if not path.is_file():
        log.warning("application icon missing: %s", path)
        return QIcon()
    if not svg_supported():
        log.warning("Qt's SVG plugin is not available: no application icon")
        return QIcon()
    return QIcon(str(path))


def action_icon(name: str, colour: QColor | str | None = None) -> QIcon:
    """The small action icon `name` drawn in `colour` (default: the application's text colour).

    Line icons are drawn in `currentColor`, replaced here, so that they stay visible on a dark
    palette; call again (or on the theme's `changed` signal) after the palette changes.
    """
    path = icon_path(name)
    try:
        svg = path.read_text(encoding="utf-8")
    except OSError as exc:
        log.warning("action icon %r not readable: %s", name, exc)
        return QIcon()
    if colour is None:
        colour = QGuiApplication.palette().windowText().color()
    svg = svg.replace(THEMED_COLOUR, QColor(colour).name())
    renderer = QSvgRenderer(QByteArray(svg.encode("utf-8")))
    if not renderer.isValid():
        log.warning("action icon %r is not valid SVG", name)
        return QIcon()
    icon = QIcon()
    for size in ACTION_ICON_SIZES:
        pixmap = QPixmap(size, size)
        pixmap.fill(Qt.GlobalColor.transparent)
        painter = QPainter(pixmap)
        renderer.render(painter, QRectF(0, 0, size, size))
        painter.end()
        icon.addPixmap(pixmap)
    return icon
