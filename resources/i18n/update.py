"""Refresh the translation sources (.ts) from the code, and compile them (.qm).

    .venv/bin/python resources/i18n/update.py            # lupdate, then lrelease
    .venv/bin/python resources/i18n/update.py --no-release   # lupdate only (.ts)
    .venv/bin/python resources/i18n/update.py --release-only # lrelease only (.qm)

lupdate reads every .py file under app/ and widgets/ (the strings in self.tr(),
QCoreApplication.translate() and QT_TRANSLATE_NOOP()) into resources/i18n/motionpanel_<lang>.ts
for es, fr and zh_CN, keeping what translators have done (new strings come in unfinished,
vanished ones are kept as obsolete). Translate the .ts files with pyside6-linguist or any XLIFF/TS
editor; lrelease then writes motionpanel_<lang>.qm beside them, which app/i18n.py loads (and
pyproject.toml installs as package data of `resources`, beside app/). lupdate's warnings (e.g. an
f-string inside tr(), which it cannot extract) are printed; --strict makes them fail the run.
For Python, lupdate says nothing about tr(f"…"), tr("a" + b) or tr("…".format(…)): it quietly
extracts the literal part. tests/widgets/test_translated.py checks the sources for those.
"""

from __future__ import annotations

import argparse
import logging
import shutil
import subprocess
import sys
from pathlib import Path

log = logging.getLogger("i18n-update")

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
SOURCES = ("app", "widgets")
LANGUAGES = ("es", "fr", "zh_CN")
CATALOG = "motionpanel"


def tool(name: str) -> str:
    """The path of a PySide6 tool: beside this Python first (a venv), else on PATH."""
    beside = Path(sys.executable).parent / name
    if beside.exists():
        return str(beside)
    found = shutil.which(name)
    if found is None:
        raise SystemExit(f"{name} not found: install PySide6 (pip install PySide6-Essentials)")
    return found


def source_files(root: Path = ROOT) -> list[Path]:
    """The Python files lupdate reads, relative to `root`, sorted."""
    files: list[Path] = []
    for folder in SOURCES:
        files += (p.relative_to(root) for p in (root / folder).rglob("*.py"))
    return sorted(files)


def ts_path(language: str, folder: Path = HERE) -> Path:
    """The .ts file of a language."""
    return folder / f"{CATALOG}_{language}.ts"


def lupdate(
    languages: tuple[str, ...] = LANGUAGES, folder: Path = HERE, root: Path = ROOT
) -> list[str]:
    """Run lupdate into each language's .ts; the warnings it printed, one per line."""
    warnings: list[str] = []
    files = [str(p) for p in source_files(root)]
    for language in languages:
        target = ts_path(language, folder)
        command = [
            tool("pyside6-lupdate"),
            "-locations",
            "relative",
            "-source-language",
            "en",
            "-target-language",
            language,
            *files,
            "-ts",
            str(target),
        ]
        done = subprocess.run(command, cwd=root, capture_output=True, text=True, check=False)
        output = (done.stdout + done.stderr).splitlines()
        for line in output:
            log.info("lupdate %s: %s", language, line)
        warnings += [line for line in output if "warning" in line.lower()]
        if done.returncode != 0:
            raise SystemExit(f"lupdate failed for {target}: {done.stderr.strip()}")
    return warnings


def lrelease(languages: tuple[str, ...] = LANGUAGES, folder: Path = HERE) -> None:
    """Compile each language's .ts into its .qm (unfinished strings stay English)."""
    for language in languages:
        source = ts_path(language, folder)
        target = source.with_suffix(".qm")
        command = [tool("pyside6-lrelease"), str(source), "-qm", str(target)]
        done = subprocess.run(command, capture_output=True, text=True, check=False)
        for line in (done.stdout + done.stderr).splitlines():
            log.info("lrelease %s: %s", language, line)
        if done.returncode != 0:
            raise SystemExit(f"lrelease failed for {source}: {done.stderr.strip()}")


def main(argv: list[str] | None = None) -> int:
    """Update the .ts files and compile the .qm files; 1 on lupdate warnings with --strict."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-release", action="store_true", help="only update the .ts files")
    parser.add_argument("--release-only", action="store_true", help="only compile the .qm files")
    parser.add_argument("--strict", action="store_true", help="fail on any lupdate warning")
    options = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    warnings: list[str] = []
    if not options.release_only:
        warnings = lupdate()
    if not options.no_release:
        lrelease()
    if warnings:
        log.warning("%d lupdate warning(s):\n%s", len(warnings), "\n".join(warnings))
    return 1 if warnings and options.strict else 0


if __name__ == "__main__":
    sys.exit(main())
