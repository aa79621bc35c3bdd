"""Help → About: the application's icon, name, version, licence, purpose and components."""

from __future__ import annotations

import logging
import platform
import tomllib
from importlib import metadata
from pathlib import Path
from typing import Any

import PySide6
from PySide6.QtCore import Qt, qVersion
from PySide6.QtGui import QGuiApplication, QIcon
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QVBoxLayout,
    QWidget,
)

log = logging.getLogger(__name__)

DISTRIBUTION = "motion-panel"  # [project] name in pyproject.toml
PYPROJECT = Path(__file__).resolve().parent.parent / "pyproject.toml"  # in a source checkout
ICON_SIZE = 96
UNKNOWN = "unknown"  # the version when neither the metadata nor pyproject.toml gives one


def _pyproject(path: Path = PYPROJECT) -> dict[str, Any]:
    """The [project] table of pyproject.toml, or {} when there is none (an installed copy)."""
    try:
        with path.open("rb") as file:
            return dict(tomllib.load(file).get("project", {}))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        log.debug("no pyproject.toml to read (%s)", exc)
        return {}


def app_version(distribution: str = DISTRIBUTION, pyproject: Path = PYPROJECT) -> str:
    """The installed version, else pyproject.toml's, else "unknown"."""
    try:
        return metadata.version(distribution)
    except metadata.PackageNotFoundError:
        version = _pyproject(pyproject).get("version")
        return str(version) if version else UNKNOWN


def _licence_from_pyproject(project: dict[str, Any]) -> str | None:
    """[project] license: an SPDX string (PEP 639) or a {text = ...} table."""
    licence = project.get("license")
    if isinstance(licence, str) and licence.strip():
        return licence.strip()
    if isinstance(licence, dict) and str(licence.get("text", "")).strip():
        return str(licence["text"]).strip()
    return None


def app_licence(distribution: str = DISTRIBUTION, pyproject: Path = PYPROJECT) -> str | None:
    """The declared licence (package metadata, else pyproject.toml), or None if none is."""
    try:
        info = metadata.metadata(distribution)
    except metadata.PackageNotFoundError:
        info = None
    if info is not None:
        for key in ("License-Expression", "License"):
            value = info.get(key)
            if value and value.strip() and value.strip().upper() != "UNKNOWN":
                return value.strip().splitlines()[0]
        for classifier in info.get_all("Classifier") or []:
            if classifier.startswith("License ::"):
                return classifier.rsplit("::", 1)[-1].strip()
    return _licence_from_pyproject(_pyproject(pyproject))


def _installed(distribution: str) -> str | None:
    try:
        return metadata.version(distribution)
    except metadata.PackageNotFoundError:
        return None


def component_versions() -> list[tuple[str, str | None]]:
    """(component, version or None if missing) for Qt, PySide6, pyqtgraph, pyserial, Python."""
    return [
        ("Qt", qVersion()),
        ("PySide6", PySide6.__version__),
        ("pyqtgraph", _installed("pyqtgraph")),  # not imported: the dialog pulls in no plots
        ("pyserial", _installed("pyserial")),
        ("Python", platform.python_version()),
    ]


class AboutDialog(QDialog):
    """The About box (icon: `icon`, else the application's window icon); "Copy details" puts
    the versions on the clipboard for a bug report."""

    def __init__(self, parent: QWidget | None = None, icon: QIcon | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("aboutDialog")
        self.setWindowTitle(self.tr("About Motion Panel"))
        if icon is None:  # the application's (main sets it: app.setWindowIcon(app_icon()))
            icon = QGuiApplication.windowIcon()
        self.setWindowIcon(icon)
        self.version = app_version()
        self.licence = app_licence()
        self.components = component_versions()

        self.icon_label = QLabel(self)
        self.icon_label.setObjectName("aboutIcon")
        self.icon_label.setPixmap(icon.pixmap(ICON_SIZE, ICON_SIZE))
        self.icon_label.setAlignment(Qt.AlignmentFlag.AlignTop | Qt.AlignmentFlag.AlignHCenter)

        self.name_label = self._label("aboutName", self.tr("Motion Panel"))
        font = self.name_label.font()
        font.setPointSizeF(font.pointSizeF() * 1.6)
        font.setBold(True)
        self.name_label.setFont(font)
        self.version_label = self._label(
            "aboutVersion",
            self.tr("Version %1").replace(
                "%1", self.version if self.version != UNKNOWN else self.tr("unknown")
            ),
        )
        self.description_label = self._label(
            "aboutDescription",
            self.tr("A desktop control panel for serial stepper-motor positioning stages."),
        )
        self.description_label.setWordWrap(True)
        self.description_label.setMinimumWidth(self.fontMetrics().averageCharWidth() * 44)
        licence = self.licence if self.licence else self.tr("see LICENSE")
        self.licence_label = self._label(
            "aboutLicence", self.tr("Licence: %1").replace("%1", licence)
        )

        box = QGroupBox(self.tr("Components"), self)
        box.setObjectName("aboutComponents")
        form = QFormLayout(box)
        self.component_labels: dict[str, QLabel] = {}
        for name, version in self.components:
            value = self._label(
                f"aboutComponent{name}", version if version else self.tr("not installed")
            )
            self.component_labels[name] = value
            form.addRow(self.tr("%1:").replace("%1", name), value)

        text = QVBoxLayout()
        for label in (self.name_label, self.version_label, self.description_label):
            text.addWidget(label)
        text.addWidget(self.licence_label)
        text.addWidget(box)
        top = QHBoxLayout()
        top.addWidget(self.icon_label)
        top.addLayout(text, 1)

        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close, self)
        self.copy_button = buttons.addButton(
            self.tr("&Copy details"), QDialogButtonBox.ButtonRole.ActionRole
        )
        self.copy_button.setObjectName("aboutCopy")
        self.copy_button.setToolTip(self.tr("Copy the versions, e.g. for a bug report"))
        self.copy_button.clicked.connect(self.copy_details)
        buttons.rejected.connect(self.reject)
        close = buttons.button(QDialogButtonBox.StandardButton.Close)
        close.setDefault(True)

        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(buttons)
        layout.setSizeConstraint(QVBoxLayout.SizeConstraint.SetFixedSize)

    def _label(self, name: str, text: str) -> QLabel:
        label = QLabel(text, self)
        label.setObjectName(name)
        label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        label.setTextFormat(Qt.TextFormat.PlainText)
        return label

    def details(self) -> str:
        """The name, version, licence and component versions as plain text, one per line."""
        lines = [
            f"Motion Panel {self.version}",
            f"Licence: {self.licence or 'see LICENSE'}",
        ]
        lines += [f"{name} {version or '-'}" for name, version in self.components]
        lines.append(f"{platform.system()} {platform.release()} ({platform.machine()})")
        return "\n".join(lines)

    def copy_details(self) -> None:
        """Put `details()` on the clipboard."""
        QGuiApplication.clipboard().setText(self.details())
