"""The interface's language: Qt translators for our strings and Qt's own, and locale formats.

English is the source language. Spanish, French and Simplified Chinese come from
resources/i18n/motionpanel_<lang>.qm (made by resources/i18n/update.py), found beside app/ both
in the source tree and installed (package data of `resources`); Qt's own strings (standard
buttons, dialogs) from qtbase_<lang>.qm in Qt's translations directory.

Numbers shown to the operator may follow the locale (`format_number`); what is sent to a device,
written to a file or printed by the command-line tools never does.
"""

from __future__ import annotations

import argparse
import logging
import os
from collections.abc import Iterable
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QLibraryInfo, QLocale, QTranslator

from widgets._i18n import number_text

log = logging.getLogger(__name__)

SOURCE_LANGUAGE = "en"
LANGUAGES = ("en", "es", "fr", "zh_CN")
LANGUAGE_NAMES = {"en": "English", "es": "Español", "fr": "Français", "zh_CN": "简体中文"}
ENV_VAR = "MOTIONPANEL_LANG"
SYSTEM_CHOICE = "system"  # the Settings choice that leaves the language to the locale
CATALOG = "motionpanel"
QT_CATALOGS = ("qtbase",)
SOURCE_DIR = Path(__file__).resolve().parents[2] / "resources" / "i18n"
_TRADITIONAL = ("tw", "hk", "mo", "hant")

_installed: list[QTranslator] = []  # kept alive while installed
_default_set = False  # whether install_translations changed QLocale's default


def normalize_language(code: str | None) -> str | None:
    """Our language code for `code` ("es_ES", "fr-CA", "zh", "zh-Hans", "C" …), or None."""
    if not code:
        return None
    parts = code.strip().replace("-", "_").split(".")[0].split("@")[0].split("_")
    language = parts[0].lower()
    rest = [p.lower() for p in parts[1:]]
    if language == "zh":
        return None if any(p in _TRADITIONAL for p in rest) else "zh_CN"
    return language if language in LANGUAGES else None


def language_arg(code: str) -> str:
    """argparse type for --lang: our code for `code`, or an error naming the choices."""
    language = normalize_language(code)
    if language is None:
        raise argparse.ArgumentTypeError(
            f"unknown language {code!r}: one of {', '.join(LANGUAGES)}"
        )
    return language


def translations_dirs() -> list[Path]:
    """Where our .qm files are looked for: resources/i18n beside app/ (source tree or installed)."""
    return [SOURCE_DIR]


def catalog_path(language: str) -> Path | None:
    """Our .qm file for `language`, or None when there is none."""
    for folder in translations_dirs():
        path = folder / f"{CATALOG}_{language}.qm"
        if path.is_file():
            return path
    return None


def qt_translations_dir() -> str:
    """Qt's own translations directory (qtbase_*.qm)."""
    return QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)


def available_languages() -> list[str]:
    """The languages the interface can be shown in: English and those with a .qm file."""
    return [SOURCE_LANGUAGE, *(code for code in LANGUAGES[1:] if catalog_path(code))]


def _locale_language(locale: QLocale) -> str | None:
    """The first of the locale's UI languages we have, else its name's."""
    for name in (*locale.uiLanguages(), locale.name()):
        language = normalize_language(name)
        if language is not None:
            return language
    return None


def choose_language(
    lang: str | None, locale: QLocale | None = None, saved: str | None = None
) -> tuple[str, str]:
    """(language, where it came from): --lang, else $MOTIONPANEL_LANG, else the language saved
    in Settings (`saved`; "system" or None: none), else the locale."""
    candidates: Iterable[tuple[str | None, str]] = (
        (lang, "--lang"),
        (os.environ.get(ENV_VAR), f"${ENV_VAR}"),
        (None if saved == SYSTEM_CHOICE else saved, "Settings"),
    )
    for code, source in candidates:
        if code:
            language = normalize_language(code)
            if language is not None:
                return language, source
            log.warning("unknown language %r from %s: one of %s", code, source, LANGUAGES)
    system = locale if locale is not None else QLocale.system()
    language = _locale_language(system)
    if language is not None:
        return language, f"locale {system.name()}"
    return SOURCE_LANGUAGE, f"locale {system.name()} (no translation: English)"


def remove_translations(app: QCoreApplication | None = None) -> None:
    """Uninstall the translators installed by `install_translations`; the system's locale again."""
    global _default_set
    app = app or QCoreApplication.instance()
    if _default_set:
        QLocale.setDefault(QLocale.system())
        _default_set = False
    while _installed:
        translator = _installed.pop()
        if app is not None:
            app.removeTranslator(translator)
        translator.deleteLater()


def _load(app: QCoreApplication, name: str, folder: str | Path) -> bool:
    translator = QTranslator(app)
    if not translator.load(name, str(folder)):
        translator.deleteLater()
        return False
    app.installTranslator(translator)
    _installed.append(translator)
    log.info("loaded translation %s", translator.filePath())
    return True


def install_translations(
    app: QCoreApplication,
    lang: str | None = None,
    locale: QLocale | None = None,
    saved: str | None = None,
) -> str:
    """Install our and Qt's translations for --lang, $MOTIONPANEL_LANG, the language saved in
    Settings (`saved`) or the system locale.

    Returns the language in effect ("en" when nothing matched or no catalog was found). Called
    again, it replaces the translators it installed before. `locale` stands for the system's.
    """
    global _default_set
    remove_translations(app)
    language, source = choose_language(lang, locale, saved)
    system = locale if locale is not None else QLocale.system()
    if language != SOURCE_LANGUAGE:
        path = catalog_path(language)
        ours = path is not None and _load(app, path.stem, path.parent)
        if not ours:
            log.warning("no %s_%s.qm in %s", CATALOG, language, translations_dirs())
        theirs = [_load(app, f"{name}_{language}", qt_translations_dir()) for name in QT_CATALOGS]
        if not ours and not any(theirs):
            log.warning("no translation for %s (%s): English", language, source)
            language = SOURCE_LANGUAGE
    # Numbers in the chosen language's format, unless the system locale speaks it already
    # (es_MX stays es_MX) or is C and the language English (C's numbers are English ones).
    plain_english = system.language() == QLocale.Language.C and language == SOURCE_LANGUAGE
    if _locale_language(system) != language and not plain_english:
        QLocale.setDefault(QLocale(language))
        _default_set = True
    log.info("interface language: %s (%s)", language, source)
    return language


def format_number(value: float, decimals: int, locale: QLocale | None = None) -> str:
    """`value` with `decimals` decimals in the locale's digits and decimal point, no grouping."""
    return number_text(value, decimals, trim=False, locale=locale)


def format_quantity(value: float, decimals: int, unit: str, locale: QLocale | None = None) -> str:
    """`format_number` and a unit: "12,50 mm" in French, "12.50 mm" in English."""
    number = format_number(value, decimals, locale)
    return f"{number} {unit}" if unit else number


def parse_number(text: str, locale: QLocale | None = None) -> float | None:
    """A number typed in the locale's format (or with a point), or None."""
    shown = locale if locale is not None else QLocale()
    value, ok = shown.toDouble(text.strip())
    if ok:
        return float(value)
    try:
        return float(text.strip())
    except ValueError:
        return None
