"""The application icon, the action icons, the .desktop file and the packaging of both."""

from __future__ import annotations

import configparser
import shutil
import subprocess
import tomllib
from pathlib import Path

import pytest
from PySide6.QtGui import QColor, QIcon, QImage

from app.window.desktop_entry import (
    data_home,
    install_desktop_entry,
    quote_exec,
    uninstall_desktop_entry,
)
from app.window.icons import (
    ACTION_ICONS,
    APP_ICON_NAME,
    action_icon,
    app_icon,
    icon_dir,
    icon_path,
    svg_supported,
)

pytestmark = pytest.mark.timeout(30)

ROOT = Path(__file__).resolve().parents[3]
DESKTOP_FILE = ROOT / "resources" / "motionpanel.desktop"


def _opaque_pixels(image: QImage) -> int:
    """How many pixels of `image` are not fully transparent (sampled every other pixel)."""
    return sum(
        1
        for y in range(0, image.height(), 2)
        for x in range(0, image.width(), 2)
        if image.pixelColor(x, y).alpha() > 0
    )


def test_svg_plugin_is_there(qapp) -> None:
    assert svg_supported()


def test_icon_folder_is_resources_icons() -> None:
    assert icon_dir() == ROOT / "resources" / "icons"
    assert icon_path(APP_ICON_NAME).is_file()


@pytest.mark.parametrize("size", [16, 32, 256])
def test_app_icon_renders_at(qapp, size: int) -> None:
    icon = app_icon()
    assert isinstance(icon, QIcon)
    assert not icon.isNull()
    pixmap = icon.pixmap(size, size)
    assert not pixmap.isNull()
    assert (pixmap.width(), pixmap.height()) == (size, size)
    image = pixmap.toImage()
    assert _opaque_pixels(image) > (size // 2) ** 2 // 2  # drawn, not an empty square


@pytest.mark.parametrize("name", ACTION_ICONS)
def test_action_icons_render(qapp, name: str) -> None:
    icon = action_icon(name, "#123456")
    assert not icon.isNull()
    assert _opaque_pixels(icon.pixmap(24, 24).toImage()) > 0


def test_action_icon_takes_the_colour(qapp) -> None:
    image = action_icon("jog-right", QColor("#00ff00")).pixmap(32, 32).toImage()
    colours = {
        image.pixelColor(x, y).name()
        for y in range(32)
        for x in range(32)
        if image.pixelColor(x, y).alpha() == 255
    }
    assert colours == {"#00ff00"}


def test_missing_action_icon_is_null_with_a_warning(qapp, caplog) -> None:
    assert action_icon("no-such-icon").isNull()
    assert "no-such-icon" in caplog.text


def _desktop_entry() -> configparser.SectionProxy:
    parser = configparser.ConfigParser(interpolation=None, delimiters=("=",))
    parser.optionxform = str  # keys are case-sensitive
    parser.read(DESKTOP_FILE, encoding="utf-8")
    return parser["Desktop Entry"]


def test_desktop_file_keys() -> None:
    entry = _desktop_entry()
    assert entry["Type"] == "Application"
    assert entry["Name"] == "Motion Panel"
    assert entry["GenericName"]
    assert entry["Comment"]
    assert entry["Exec"] == "motionpanel"
    assert entry["Icon"] == APP_ICON_NAME
    assert entry["Terminal"] == "false"
    assert entry["Categories"] == "Development;Engineering;"
    keywords = entry["Keywords"]
    assert keywords.endswith(";")
    assert {"stepper", "motor", "serial"} <= set(keywords.split(";"))


def test_desktop_file_runs_a_declared_script() -> None:
    with (ROOT / "pyproject.toml").open("rb") as file:
        project = tomllib.load(file)
    scripts = project["project"]["scripts"]
    assert {"motionpanel", "motionctl", "motionsim"} <= set(scripts)
    assert _desktop_entry()["Exec"].split()[0] in scripts


def test_icons_and_desktop_file_are_package_data() -> None:
    with (ROOT / "pyproject.toml").open("rb") as file:
        tool = tomllib.load(file)["tool"]["setuptools"]
    assert "resources" in tool["packages"]["find"]["include"]
    data = tool["package-data"]["resources"]
    assert "icons/*.svg" in data
    assert "*.desktop" in data


@pytest.mark.skipif(shutil.which("desktop-file-validate") is None, reason="no desktop-file-utils")
def test_desktop_file_validates() -> None:
    result = subprocess.run(
        ["desktop-file-validate", str(DESKTOP_FILE)], capture_output=True, text=True, timeout=20
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.strip() == ""  # no hints or warnings either


def test_install_and_uninstall_desktop_entry(tmp_path: Path) -> None:
    desktop, icon = install_desktop_entry(tmp_path)
    assert desktop == tmp_path / "applications" / "motionpanel.desktop"
    assert icon == tmp_path / "icons" / "hicolor" / "scalable" / "apps" / "motionpanel.svg"
    assert desktop.read_text(encoding="utf-8") == DESKTOP_FILE.read_text(encoding="utf-8")
    assert icon.read_bytes() == icon_path(APP_ICON_NAME).read_bytes()
    assert uninstall_desktop_entry(tmp_path) == [desktop, icon]
    assert not desktop.exists()
    assert not icon.exists()
    assert uninstall_desktop_entry(tmp_path) == []


def test_install_with_an_absolute_program(tmp_path: Path) -> None:
    program = "/home/a user/.local/bin/motionpanel"
    desktop, _ = install_desktop_entry(tmp_path / "share", exec_path=program)
    text = desktop.read_text(encoding="utf-8")
    assert f'\nExec="{program}"\n' in text
    assert f"\nTryExec={program}\n" in text
    if shutil.which("desktop-file-validate"):
        result = subprocess.run(
            ["desktop-file-validate", str(desktop)], capture_output=True, text=True, timeout=20
        )
        assert result.returncode == 0, result.stdout + result.stderr


def test_data_home_follows_xdg(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    assert data_home() == tmp_path
    monkeypatch.setenv("XDG_DATA_HOME", "relative/ignored")
    assert data_home() == Path.home() / ".local" / "share"


@pytest.mark.parametrize(
    ("program", "value"),
    [
        ("/usr/bin/motionpanel", "/usr/bin/motionpanel"),
        ("/opt/a b/motionpanel", '"/opt/a b/motionpanel"'),
        ("/opt/50%/motionpanel", "/opt/50%%/motionpanel"),
        ('/opt/a"b$/mp', '"/opt/a\\\\"b\\\\$/mp"'),
    ],
)
def test_quote_exec(program: str, value: str) -> None:
    assert quote_exec(program) == value
