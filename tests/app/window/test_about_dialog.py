"""Help → About: version, licence and components."""

from __future__ import annotations

import tomllib
from importlib import metadata
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication, QIcon, QPixmap
from PySide6.QtWidgets import QLabel

from app.window.icons import app_icon
from widgets.about_dialog import (
    AboutDialog,
    app_licence,
    app_version,
    component_versions,
)

pytestmark = pytest.mark.timeout(30)

PYPROJECT = Path(__file__).resolve().parents[3] / "pyproject.toml"


def _project() -> dict:
    with PYPROJECT.open("rb") as file:
        return tomllib.load(file)["project"]


def _text(dialog: AboutDialog, name: str) -> str:
    label = dialog.findChild(QLabel, name)
    assert label is not None, name
    return label.text()


def test_version_is_the_installed_or_the_declared_one() -> None:
    assert app_version() == _project()["version"]


def test_version_falls_back_to_pyproject() -> None:
    assert app_version("no-such-distribution-here") == _project()["version"]


def test_version_unknown_without_metadata_or_pyproject(tmp_path: Path) -> None:
    assert app_version("no-such-distribution-here", tmp_path / "pyproject.toml") == "unknown"


def test_licence_from_pyproject_when_not_installed(tmp_path: Path) -> None:
    spdx = tmp_path / "spdx.toml"
    spdx.write_text('[project]\nname = "x"\nlicense = "GPL-3.0-or-later"\n', encoding="utf-8")
    table = tmp_path / "table.toml"
    table.write_text('[project]\nname = "x"\nlicense = {text = "MIT"}\n', encoding="utf-8")
    assert app_licence("no-such-distribution-here", spdx) == "GPL-3.0-or-later"
    assert app_licence("no-such-distribution-here", table) == "MIT"
    assert app_licence("no-such-distribution-here", tmp_path / "none.toml") is None


def test_licence_from_metadata(monkeypatch: pytest.MonkeyPatch) -> None:
    class Fake:  # only .get and .get_all of the metadata message are used
        def get(self, key: str) -> str | None:
            return {"License-Expression": "Apache-2.0"}.get(key)

        def get_all(self, key: str) -> list[str]:
            return []

    monkeypatch.setattr(metadata, "metadata", lambda name: Fake())
    assert app_licence() == "Apache-2.0"


def test_dialog_shows_name_version_licence(qtbot) -> None:
    dialog = AboutDialog(icon=app_icon())
    qtbot.addWidget(dialog)
    assert dialog.objectName() == "aboutDialog"
    assert _text(dialog, "aboutName") == "Motion Panel"
    version = _project()["version"]
    assert version in _text(dialog, "aboutVersion")
    licence = app_licence()
    assert (licence or "see LICENSE") in _text(dialog, "aboutLicence")
    assert _text(dialog, "aboutDescription")
    pixmap = dialog.findChild(QLabel, "aboutIcon").pixmap()
    assert isinstance(pixmap, QPixmap)
    assert not pixmap.isNull()


def test_dialog_shows_a_declared_licence(qtbot, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("widgets.about_dialog.app_licence", lambda: "MIT")
    dialog = AboutDialog(icon=QIcon())
    qtbot.addWidget(dialog)
    assert _text(dialog, "aboutLicence").endswith("MIT")


def test_dialog_lists_the_components(qtbot) -> None:
    dialog = AboutDialog(icon=QIcon())
    qtbot.addWidget(dialog)
    names = [name for name, _ in component_versions()]
    assert names == ["Qt", "PySide6", "pyqtgraph", "pyserial", "Python"]
    for name, version in component_versions():
        assert version, name  # all installed here
        assert _text(dialog, f"aboutComponent{name}") == version
    assert _text(dialog, "aboutComponentpyserial") == metadata.version("pyserial")


def test_copy_details(qtbot) -> None:
    dialog = AboutDialog(icon=QIcon())
    qtbot.addWidget(dialog)
    qtbot.mouseClick(dialog.copy_button, Qt.MouseButton.LeftButton)
    copied = QGuiApplication.clipboard().text()
    assert copied.startswith(f"Motion Panel {_project()['version']}\n")
    assert "pyqtgraph " in copied
