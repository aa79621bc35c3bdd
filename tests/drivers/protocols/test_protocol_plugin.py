"""The example protocol plugin (resources/examples/protocol_plugin) installed into a new virtual
environment beside the project: its `echo-stage` protocol is in motionctl's and motionsim's help
and in the window's protocol list, its simulator answers motionctl over a pty, and the
conformance and fuzz suites pass over it there. Without the entry point none of it would show."""

from __future__ import annotations

import os
import selectors
import subprocess
import time
from pathlib import Path

import pytest

from tests.support.fresh_venv import ROOT, make_venv

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(120)]

PLUGIN = ROOT / "resources" / "examples" / "protocol_plugin"
NAME = "echo-stage"
WINDOW_PROTOCOLS = """
from PySide6.QtWidgets import QApplication
app = QApplication([])
from app.window.main_window import MainWindow
window = MainWindow()
combo = window.connection_bar.protocol_combo
print("\\n".join(combo.itemText(i) for i in range(combo.count())))
"""


@pytest.fixture(scope="session")
def venv(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, str]]:
    """The new venv's bin folder and an environment to run its programs in (made once)."""
    folder = tmp_path_factory.mktemp("plugin_venv")
    started = time.monotonic()
    python, how = make_venv(folder, PLUGIN)
    print(f"venv made in {time.monotonic() - started:.1f} s ({how})")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env |= {
        "MOTIONPANEL_SETTINGS": str(folder / "settings.ini"),
        "MOTIONPANEL_LOG_DIR": str(folder / "logs"),
        "QT_QPA_PLATFORM": "offscreen",
    }
    return python.parent, env


def _run(venv, *command: str, timeout: float = 60) -> str:
    bin_dir, env = venv
    program = [str(bin_dir / command[0]), *command[1:]]
    done = subprocess.run(
        program, capture_output=True, text=True, env=env, timeout=timeout, cwd=bin_dir
    )
    assert done.returncode == 0, done.stderr[-3000:] + done.stdout[-3000:]
    return done.stdout


def test_the_plugin_protocol_is_in_motionctl_and_motionsim_help(venv) -> None:
    assert NAME in _run(venv, "motionctl", "--help")
    simulated = " ".join(_run(venv, "motionsim", "--help").split())
    assert f"{NAME} (example plugin: ASCII lines" in simulated


def test_the_plugin_protocol_is_in_the_window_protocol_list(venv) -> None:
    listed = _run(venv, "python", "-c", WINDOW_PROTOCOLS).split()
    assert listed[-1] == NAME and "coxiris" in listed


def test_the_plugin_simulator_answers_motionctl_over_a_pty(venv) -> None:
    bin_dir, env = venv
    sim = subprocess.Popen(
        [str(bin_dir / "motionsim"), NAME],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
    )
    try:
        assert sim.stdout is not None
        with selectors.DefaultSelector() as selector:
            selector.register(sim.stdout, selectors.EVENT_READ)
            assert selector.select(20), "motionsim printed no device path"
        port = sim.stdout.readline().strip()
        assert port.startswith("/dev/"), port
        ask = ("motionctl", "--protocol", NAME, "--port", port, "--travel", "none")
        assert _run(venv, *ask, "position").split() == ["0.00", "0.00", "0.00"]
        _run(venv, *ask, "move", "3", "4")
        assert _run(venv, *ask, "position").split() == ["3.00", "4.00", "0.00"]
    finally:
        sim.terminate()
        sim.wait(10)


def test_the_conformance_and_fuzz_suites_pass_over_the_plugin(venv) -> None:
    bin_dir, env = venv
    command = [
        str(bin_dir / "python"),
        *("-m", "pytest", "-q", "-p", "no:randomly", "-p", "no:cacheprovider"),
        *(
            "tests/drivers/protocols/test_protocol_registry.py",
            "tests/drivers/protocols/test_fuzz_all.py",
            "-k",
            "echo and stage",
        ),
    ]
    done = subprocess.run(command, capture_output=True, text=True, env=env, cwd=ROOT, timeout=100)
    assert done.returncode == 0, done.stdout[-4000:]
    passed = int(done.stdout.split(" passed")[0].split()[-1])
    assert passed >= 8, done.stdout[-2000:]  # conformance + every fuzz test of the protocol
