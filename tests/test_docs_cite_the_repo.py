"""Docstrings, comments and docs cite the repository's own protocol page, never a file outside it,
and every section they cite exists there (issue 29)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PROTOCOL_PAGE = ROOT / "drivers" / "protocols" / "README.md"
# Spelled in pieces so that this file does not cite them itself.
OUTSIDE = (
    "PROTOCOLS" + ".md",  # the shared folder's protocol notes
    ".." + "/shared",
    "/work" + "/shared",
    "transcripts" + "/",  # the shared folder's recordings; ours are tests/data/
)
SECTION = r"§[0-9]+[a-z]?(?:\.[0-9]+)?"
CITATION = re.compile(
    r"drivers/protocols/README\.md((?:[\s#,]*(?:and\s+)?" + SECTION + r")+)", re.MULTILINE
)
HEADING = re.compile(r"^#{2,3} (" + SECTION + r") ", re.MULTILINE)

pytestmark = pytest.mark.timeout(60)


def _documents() -> list[Path]:
    """Every *.py and *.md of the repository, outside hidden folders (.venv, .git, caches)."""
    found = []
    for path in sorted(ROOT.rglob("*")):
        parts = path.relative_to(ROOT).parts
        if (
            path.suffix in (".py", ".md")
            and path.is_file()
            and not any(p.startswith(".") for p in parts)
        ):
            found.append(path)
    return found


def _outside_references(path: Path) -> list[str]:
    """`file:line: text` for each line of `path` that names a file outside the repository."""
    text = path.read_text(encoding="utf-8", errors="replace")
    return [
        f"{path.relative_to(ROOT)}:{number}: {line.strip()}"
        for number, line in enumerate(text.splitlines(), 1)
        if any(name in line for name in OUTSIDE)
    ]


def test_the_scan_sees_the_code_and_the_protocol_page() -> None:
    documents = set(_documents())
    assert PROTOCOL_PAGE in documents
    assert ROOT / "drivers" / "protocols" / "coxiris.py" in documents
    assert not any(".venv" in p.parts for p in documents)


def test_no_file_cites_a_document_outside_the_repository() -> None:
    offending = [hit for path in _documents() for hit in _outside_references(path)]
    assert not offending, "cite drivers/protocols/README.md instead:\n" + "\n".join(offending)


def test_every_cited_section_is_a_heading_of_the_protocol_page() -> None:
    headings = set(HEADING.findall(PROTOCOL_PAGE.read_text(encoding="utf-8")))
    assert {"§1", "§2", "§2b", "§3", "§4", "§5"} <= headings
    cited: dict[str, list[str]] = {}
    for path in _documents():
        for match in CITATION.finditer(path.read_text(encoding="utf-8", errors="replace")):
            for section in re.findall(SECTION, match.group(1)):
                cited.setdefault(section, []).append(str(path.relative_to(ROOT)))
    assert cited, "no citation of drivers/protocols/README.md found: is the pattern stale?"
    missing = {section: files for section, files in cited.items() if section not in headings}
    assert not missing, f"cited sections with no heading in {PROTOCOL_PAGE.name}: {missing}"
