"""app/common/i18n.py: the language from --lang, $MOTIONPANEL_LANG, Settings or the locale; .qm."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

import pytest
from PySide6.QtCore import QCoreApplication, QLocale
from PySide6.QtWidgets import QApplication, QDialogButtonBox

from app.common import i18n

pytestmark = pytest.mark.timeout(60)

QT_CANCEL = {"en": "Cancel", "es": "Cancelar", "fr": "Annuler", "zh_CN": "取消"}


@pytest.fixture
def app(qapp: QApplication, monkeypatch: pytest.MonkeyPatch) -> Iterator[QApplication]:
    """The application, with no $MOTIONPANEL_LANG; every translator removed afterwards."""
    monkeypatch.delenv(i18n.ENV_VAR, raising=False)
    yield qapp
    i18n.remove_translations(qapp)
    assert QLocale().name() == QLocale.system().name()


def cancel_text() -> str:
    """What QDialogButtonBox's Cancel button says (Qt's own translation)."""
    box = QDialogButtonBox(QDialogButtonBox.StandardButton.Cancel)
    text = box.button(QDialogButtonBox.StandardButton.Cancel).text().replace("&", "")
    box.deleteLater()
    return text


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        ("es", "es"),
        ("es_MX", "es"),
        ("fr-CA", "fr"),
        ("FR", "fr"),
        ("zh", "zh_CN"),
        ("zh-CN", "zh_CN"),
        ("zh_CN", "zh_CN"),
        ("zh_Hans", "zh_CN"),
        ("zh-Hans-CN", "zh_CN"),
        ("zh_TW", None),
        ("zh-Hant", None),
        ("en_GB.UTF-8", "en"),
        ("de", None),
        ("C", None),
        ("", None),
        (None, None),
    ],
)
def test_language_codes_are_normalized(code: str | None, expected: str | None) -> None:
    assert i18n.normalize_language(code) == expected


@pytest.mark.parametrize("language", ["es", "fr", "zh_CN"])
def test_lang_installs_ours_and_qts_translations(app: QApplication, language: str) -> None:
    assert i18n.install_translations(app, language) == language
    assert cancel_text() == QT_CANCEL[language]  # qtbase_<lang>.qm is loaded
    names = [t.filePath() for t in i18n._installed]
    assert any(name.endswith(f"motionpanel_{language}.qm") for name in names)
    assert any(name.endswith(f"qtbase_{language}.qm") for name in names)
    assert QLocale().name().startswith(language.split("_")[0])


@pytest.mark.parametrize(
    ("system", "expected"),
    [("es_ES", "es"), ("fr_FR", "fr"), ("zh_CN", "zh_CN"), ("de_DE", "en"), ("C", "en")],
)
def test_the_locale_chooses_when_nothing_else_does(
    app: QApplication, system: str, expected: str
) -> None:
    assert i18n.install_translations(app, None, locale=QLocale(system)) == expected
    assert cancel_text() == QT_CANCEL[expected]


def test_the_environment_comes_before_the_locale_and_lang_before_both(
    app: QApplication, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(i18n.ENV_VAR, "es")
    assert i18n.install_translations(app, None, locale=QLocale("fr_FR")) == "es"
    assert i18n.install_translations(app, "zh-CN", locale=QLocale("fr_FR")) == "zh_CN"
    assert cancel_text() == QT_CANCEL["zh_CN"]  # the earlier translators are gone
    monkeypatch.setenv(i18n.ENV_VAR, "klingon")  # unknown: the locale decides
    assert i18n.install_translations(app, None, locale=QLocale("fr_FR")) == "fr"


def test_english_installs_nothing(app: QApplication) -> None:
    i18n.install_translations(app, "fr")
    assert i18n.install_translations(app, "en", locale=QLocale("fr_FR")) == "en"
    assert i18n._installed == []
    assert cancel_text() == "Cancel"
    assert QCoreApplication.translate("SpeedControl", "Apply") == "Apply"


def test_fallback_to_english_without_any_catalog(
    app: QApplication, monkeypatch: pytest.MonkeyPatch, tmp_path
) -> None:
    monkeypatch.setattr(i18n, "SOURCE_DIR", tmp_path)
    monkeypatch.setattr(i18n, "qt_translations_dir", lambda: str(tmp_path))
    assert i18n.install_translations(app, "es") == "en"
    assert i18n.available_languages() == ["en"]
    assert cancel_text() == "Cancel"


def test_available_languages_are_found_in_the_source_tree() -> None:
    assert i18n.available_languages() == ["en", "es", "fr", "zh_CN"]
    assert i18n.catalog_path("fr") == i18n.SOURCE_DIR / "motionpanel_fr.qm"
    assert i18n.catalog_path("de") is None


def test_numbers_follow_the_locale_without_grouping() -> None:
    assert i18n.format_number(1234.5, 2, QLocale("fr_FR")) == "1234,50"
    assert i18n.format_number(1234.5, 2, QLocale("en_US")) == "1234.50"
    assert i18n.format_number(-0.125, 1, QLocale("es_ES")) == "-0,1"
    assert i18n.format_quantity(12.5, 2, "mm", QLocale("de_DE")) == "12,50 mm"
    assert i18n.format_quantity(3, 0, "", QLocale("zh_CN")) == "3"
    assert i18n.parse_number("12,5", QLocale("fr_FR")) == 12.5
    assert i18n.parse_number("12.5", QLocale("fr_FR")) == 12.5
    assert i18n.parse_number("abc", QLocale("fr_FR")) is None


def test_lang_option() -> None:
    from app.main import build_parser

    parser = build_parser()
    assert parser.parse_args(["--lang", "zh-Hans"]).lang == "zh_CN"
    assert parser.parse_args([]).lang is None
    assert "--lang CODE" in parser.format_help()
    with pytest.raises(SystemExit):
        parser.parse_args(["--lang", "de"])


def test_the_language_saved_in_settings_comes_after_the_environment_and_before_the_locale(
    app: QApplication, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert i18n.choose_language(None, QLocale("fr_FR"), saved="es") == ("es", "Settings")
    assert i18n.install_translations(app, None, locale=QLocale("fr_FR"), saved="es") == "es"
    assert cancel_text() == QT_CANCEL["es"]
    assert i18n.install_translations(app, None, locale=QLocale("fr_FR"), saved="system") == "fr"
    assert i18n.install_translations(app, "zh_CN", locale=QLocale("fr_FR"), saved="es") == "zh_CN"
    monkeypatch.setenv(i18n.ENV_VAR, "fr")
    assert i18n.install_translations(app, None, locale=QLocale("C"), saved="es") == "fr"


def test_motionpanel_reads_the_language_saved_in_settings(settings_file: object) -> None:
    from app.common.settings import open_settings
    from app.main import saved_language
    from app.window.preferences import read_preferences, write_preferences

    assert saved_language() == "system"
    settings = open_settings()
    prefs = read_preferences(settings)
    write_preferences(settings, dataclasses.replace(prefs, language="fr"))
    assert saved_language() == "fr"
