"""Every motionctl command has its own help (`motionctl macro --help`), exit 0, as argparse
prints a sub-command's; the commands themselves are unchanged."""

from __future__ import annotations

import subprocess
import sys

import pytest

from app.cli.command_line import COMMANDS, usage_of
from app.cli.main import main
from tests.support.simproc import ROOT

pytestmark = [pytest.mark.usefixtures("settings_file"), pytest.mark.timeout(60)]


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("flag", ["--help", "-h"])
def test_each_command_prints_its_help_and_exits_0(command: str, flag: str, capsys) -> None:
    assert main([command, flag]) == 0
    out, err = capsys.readouterr()
    assert out.startswith(f"usage: motionctl [OPTIONS] {usage_of(command)}\n")
    assert "Exit status" in out and err == ""


def test_help_after_the_options_and_the_arguments(capsys) -> None:
    assert main(["--port", "sim://firmata", "--protocol", "firmata", "config", "--help"]) == 0
    out = capsys.readouterr().out
    assert "config --steps-per-rev N --pins P1 P2 [P3 P4]" in out
    assert main(["macro", "run", "square", "--help"]) == 0
    assert "macro list | macro run NAME" in capsys.readouterr().out


@pytest.mark.parametrize("command", ["macro", "log", "param", "run", "config"])
def test_the_installed_command_exits_0_on_a_command_help(command: str) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "app.cli", command, "--help"],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout.startswith(f"usage: motionctl [OPTIONS] {usage_of(command)}")


def test_a_wrong_command_line_still_exits_2(capsys) -> None:
    assert main(["macro"]) == 2
    assert main(["param", "set"]) == 2
    assert main(["--help"]) == 0
