"""A motionctl whose reader has gone (`motionctl … | head`) ends quietly, whatever it printed."""

from __future__ import annotations

import io

import pytest

from app.cli.main import EXIT_BROKEN_PIPE, main

pytestmark = [pytest.mark.timeout(30), pytest.mark.usefixtures("settings_file")]


class GoneReader(io.StringIO):
    """A stdout whose reader has gone: every write fails as a closed pipe's does."""

    def write(self, text: str) -> int:
        raise BrokenPipeError(32, "Broken pipe")


@pytest.mark.parametrize(
    "args",
    [
        ["--port", "sim://coxiris?instant=1", "--protocol", "coxiris", "position"],
        ["--port", "sim://coxiris?instant=1", "--protocol", "coxiris", "--json", "id"],
        ["macro", "list"],
    ],
)
def test_a_reader_gone_ends_the_command_quietly(
    args: list[str], monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setattr("sys.stdout", GoneReader())
    assert main(args) == EXIT_BROKEN_PIPE
    assert "Traceback" not in capsys.readouterr().err
