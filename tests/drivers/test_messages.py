"""Messages the driver layer and the app compose reach the operator in the interface's language:
a Message is the English text and keeps its template and values; app/common/messages.py translates
both; every error the code raises for people carries one; the catalogs translate every template,
keeping its fields."""

from __future__ import annotations

import ast
import importlib
import pickle
import pkgutil
import re
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QCoreApplication, QTranslator

import drivers
from app.common.messages import localized
from drivers.errors import BadInput, DeviceTimeout, MotionError, PortError
from drivers.messages import CONTEXT, Message, message_of

pytestmark = pytest.mark.timeout(60)

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "resources" / "i18n"))
import update  # noqa: E402

LANGUAGES = ("es", "fr", "zh_CN")
FIELD = re.compile(r"\{[^{}]*\}")
# Where an operator never reads what is raised: the simulated devices' own code, and the
# command-line tools (which print English).
NOT_FOR_THE_WINDOW = ("drivers/sim/", "app/cli", "app/simcli.py")


def test_a_message_is_its_english_text_and_keeps_template_and_values() -> None:
    said = Message("cannot open {url}: {error}", url="/dev/ttyUSB0", error="busy")
    assert said == "cannot open /dev/ttyUSB0: busy"
    assert isinstance(said, str)
    assert said.template == "cannot open {url}: {error}"
    assert dict(said.values) == {"url": "/dev/ttyUSB0", "error": "busy"}
    copy = pickle.loads(pickle.dumps(said))
    assert copy == said and copy.template == said.template
    assert message_of(PortError(said)) is said
    assert message_of(PortError("plain")) is None
    assert message_of(said) is said


def test_without_a_translator_the_english_text_is_shown(qapp) -> None:
    said = Message("{what} refused: {why}", what="speed 3", why=Message("too slow"))
    assert localized(said) == "speed 3 refused: too slow"
    assert localized(BadInput(said)) == "speed 3 refused: too slow"
    assert localized(ValueError("plain words")) == "plain words"


def test_translated_with_its_values_translated_too(upper) -> None:
    inner = DeviceTimeout(Message("no answer within {seconds:g} s", seconds=2.5))
    said = Message("GET_POSITION failed: {error} ({url})", error=inner, url="sim://coxiris")
    assert localized(said) == "GET_POSITION FAILED: NO ANSWER WITHIN 2.5 S (sim://coxiris)"
    assert str(said) == "GET_POSITION failed: no answer within 2.5 s (sim://coxiris)"
    assert localized(PortError(said)) == localized(said)
    assert localized(Message("no port given")) == "NO PORT GIVEN"


def test_a_translation_that_does_not_fit_its_values_falls_back_to_english(qapp) -> None:
    class Broken(QTranslator):
        def translate(self, context, source, disambiguation=None, n=-1):
            return "{missing} field" if context == CONTEXT else None

    broken = Broken()
    QCoreApplication.installTranslator(broken)
    try:
        assert localized(Message("took {seconds:g} s", seconds=3)) == "took 3 s"
    finally:
        QCoreApplication.removeTranslator(broken)


def _errors_for_people() -> set[str]:
    """The names of every MotionError class (and the app's) once every module is loaded."""
    for module in pkgutil.walk_packages(drivers.__path__, "drivers."):
        importlib.import_module(module.name)
    for name in (
        "app.common.macros",
        "app.cli.command_line",
        "app.window.device.worker",
        "app.window.device.jobs",
    ):
        importlib.import_module(name)
    names: set[str] = set()
    stack: list[type] = [MotionError]
    while stack:
        kind = stack.pop()
        names.add(kind.__name__)
        stack += kind.__subclasses__()
    return names


def _python_files() -> Iterator[tuple[str, ast.AST]]:
    for folder in ("drivers", "app"):
        for path in sorted((ROOT / folder).rglob("*.py")):
            where = path.relative_to(ROOT).as_posix()
            if not where.startswith(NOT_FOR_THE_WINDOW):
                yield where, ast.parse(path.read_text(encoding="utf-8"), where)


def test_errors_for_people_carry_a_message_not_bare_text() -> None:
    """`raise BadInput(f"…")` would reach a translated window in English."""
    names = _errors_for_people()
    bare = []
    for where, tree in _python_files():
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call)):
                continue
            func = node.exc.func
            name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            first = node.exc.args[0] if node.exc.args else None
            if name in names and isinstance(first, (ast.Constant, ast.JoinedStr)):
                bare.append(f"{where}:{node.lineno}")
    assert bare == []


def test_the_templates_file_is_current() -> None:
    """resources/i18n/update.py was run after a Message template last changed."""
    shipped = update.TEMPLATES.read_text(encoding="utf-8")
    assert shipped == update.templates_text(), "run resources/i18n/update.py"


def _catalog(language: str) -> dict[str, tuple[str, bool]]:
    """A .ts file's messages context: source -> (translation, finished)."""
    text = update.ts_path(language).read_text(encoding="utf-8")
    match = re.search(rf"<name>{CONTEXT}</name>(.*?)</context>", text, re.DOTALL)
    assert match, f"no {CONTEXT} context in the {language} catalog"
    found = {}
    for body in re.findall(r"<message>(.*?)</message>", match.group(1), re.DOTALL):
        source = _unescape(re.search(r"<source>(.*?)</source>", body, re.DOTALL).group(1))
        translation = re.search(r"<translation( type=\"\w+\")?>(.*?)</translation>", body, re.S)
        finished = translation.group(1) is None
        found[source] = (_unescape(translation.group(2)), finished)
    return found


def _unescape(text: str) -> str:
    for escaped, plain in (("&lt;", "<"), ("&gt;", ">"), ("&apos;", "'"), ("&quot;", '"')):
        text = text.replace(escaped, plain)
    return text.replace("&amp;", "&")


@pytest.mark.parametrize("language", LANGUAGES)
def test_every_template_is_translated_with_its_fields(language: str) -> None:
    catalog = _catalog(language)
    problems = []
    for template, where in update.message_templates():
        translation, finished = catalog.get(template, ("", False))
        if not finished or not translation:
            problems.append(f"{where}: not translated: {template!r}")
        elif sorted(FIELD.findall(translation)) != sorted(FIELD.findall(template)):
            problems.append(f"{where}: fields differ: {template!r} -> {translation!r}")
    assert problems == []
