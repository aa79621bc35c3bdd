"""A new virtual environment with the project and a plugin pip-installed into it, offline.

The project's dependencies are not installed again: a .pth file makes the project venv's
site-packages visible. Each package is built by pip (`--no-build-isolation`) where the new
venv's setuptools can: 77 and later for the project (its PEP 639 licence), 70.1 and later for
the plugin (bdist_wheel built in). With an older one (3.11's ensurepip brings 65.5, without the
`wheel` package) it is pip-installed from a wheel made here from its pyproject.toml: its name,
version and entry points, and a .pth to its source tree, as an editable install has them.
"""

from __future__ import annotations

import base64
import hashlib
import logging
import shutil
import subprocess
import sys
import sysconfig
import tomllib
import zipfile
from pathlib import Path

log = logging.getLogger(__name__)

ROOT = Path(__file__).resolve().parents[2]
PROJECT_SITE = Path(sysconfig.get_paths()["purelib"])  # the project venv's site-packages


def pip(python: Path, *args: str | Path, timeout: float = 60) -> None:
    """`python -m pip install --no-deps --no-index ARGS`, offline."""
    command = [python, "-m", "pip", "install", "-q", "--no-deps", "--no-index", *args]
    subprocess.run(command, check=True, timeout=timeout, capture_output=True)


def _setuptools_version(python: Path) -> tuple[int, ...]:
    out = subprocess.run(
        [python, "-c", "import setuptools; print(setuptools.__version__)"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return tuple(int(p) for p in out.strip().split(".")[:2] if p.isdigit())


def _record_line(name: str, data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def source_wheel(source: Path, folder: Path) -> Path:
    """A wheel of the project in `source` that points at that tree, with its entry points."""
    project = tomllib.loads((source / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    name, version = project["name"], project["version"]
    stem = f"{name.replace('-', '_')}-{version}"
    groups = {"console_scripts": project.get("scripts", {}), **project.get("entry-points", {})}
    entry_points = "".join(
        f"[{group}]\n" + "".join(f"{k} = {v}\n" for k, v in points.items()) + "\n"
        for group, points in groups.items()
        if points
    )
    files = {
        f"{stem}_source.pth": f"{source}\n",
        f"{stem}.dist-info/METADATA": f"Metadata-Version: 2.1\nName: {name}\nVersion: {version}\n",
        f"{stem}.dist-info/WHEEL": "Wheel-Version: 1.0\nGenerator: tests\n"
        "Root-Is-Purelib: true\nTag: py3-none-any\n",
        f"{stem}.dist-info/entry_points.txt": entry_points,
    }
    wheel = folder / f"{stem}-py3-none-any.whl"
    record = []
    with zipfile.ZipFile(wheel, "w") as archive:
        for path, text in files.items():
            archive.writestr(path, text.encode())
            record.append(_record_line(path, text.encode()))
        record.append(f"{stem}.dist-info/RECORD,,")
        archive.writestr(f"{stem}.dist-info/RECORD", "\n".join(record) + "\n")
    return wheel


def _install(python: Path, source: Path, folder: Path, builds: bool) -> str:
    if builds:
        pip(python, "--no-build-isolation", source, timeout=120)
        return "built by pip"
    pip(python, source_wheel(source, folder))
    return "a wheel of its source tree"


def make_venv(folder: Path, *plugins: Path) -> tuple[Path, str]:
    """A venv in `folder` with the project and `plugins` installed; its python, and how each
    went in (built by pip, or a wheel of its source tree)."""
    base = Path(getattr(sys, "_base_executable", sys.executable))
    venv = folder / "venv"
    subprocess.run([base, "-m", "venv", venv], check=True, timeout=120, capture_output=True)
    python = venv / "bin" / "python"
    site = Path(
        subprocess.run(
            [python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
    )
    (site / "zz_project_dependencies.pth").write_text(f"{PROJECT_SITE}\n", encoding="utf-8")
    setuptools = _setuptools_version(python)
    how = [f"project: {_install(python, ROOT, folder, setuptools >= (77,))}"]
    for plugin in plugins:  # from a copy: pip builds in the tree it is given
        copy = folder / plugin.name
        shutil.copytree(plugin, copy, ignore=shutil.ignore_patterns("build", "*.egg-info"))
        how.append(f"{plugin.name}: {_install(python, copy, folder, setuptools >= (70, 1))}")
    log.info("venv %s, setuptools %s: %s", venv, setuptools, "; ".join(how))
    return python, "; ".join(how)
