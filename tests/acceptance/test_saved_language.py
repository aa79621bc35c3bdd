"""Issue 28 item 18: the language chosen in Settings is the one the panel starts in next time.

The real panel, started with no --lang and no $MOTIONPANEL_LANG in an English (C) locale: File →
Settings (Ctrl+,), its last tab (Appearance and language), the Language list set to Français
from the keyboard, OK (Return); Quit (Ctrl+Q); started again, its Settings dialog's window title
is the French one ("Réglages"), as the window manager sees it.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, XServer, wait_for

pytestmark = pytest.mark.timeout(120)

ENGLISH_LOCALE = {"LC_ALL": "C.UTF-8", "LANG": "C.UTF-8", "LANGUAGE": ""}


def _start(rig: Rig, x: XServer, settings: Path) -> Panel:
    """The panel on the simulated stage, with no --lang (rig.panel would add --lang en)."""
    env = dict(ENGLISH_LOCALE)
    panel = Panel(x, rig.tmp, "--port", "sim://coxiris", settings=settings, env_extra=env)
    rig.started.append(panel)
    return panel


def _settings_dialog_title(panel: Panel) -> str:
    """Open File → Settings with its shortcut; the title the dialog's window has."""
    panel.key("ctrl+comma")
    window = panel.dialog(".")  # the panel's one other window
    return panel.x.xdotool("getwindowname", window).strip()


def test_the_language_chosen_in_settings_is_used_at_the_next_start(
    x_server: XServer, rig: Rig, tmp_path: Path, shots: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("MOTIONPANEL_LANG", raising=False)
    settings = tmp_path / "settings.ini"
    panel = _start(rig, x_server, settings)
    panel.wait_ready(b"DONE GET_SPEED")
    assert _settings_dialog_title(panel) == "Settings"  # English at first
    x_server.xdotool("windowactivate", "--sync", panel.dialog("^Settings$"))
    x_server.xdotool("key", "--delay", "60", "ctrl+shift+Tab")  # the last tab: language
    x_server.xdotool("key", "--delay", "60", "Tab", "Tab", "Tab")  # past Theme to Language
    x_server.xdotool("type", "--delay", "60", "Fr")  # a list's keyboard search: Français
    x_server.screenshot(shots / "settings-french-chosen.png")
    x_server.xdotool("key", "Return")  # OK: use and save
    wait_for(
        lambda: "language=fr" in settings.read_text(encoding="utf-8"),
        10.0,
        "the language saved in the settings file",
    )
    panel.key("ctrl+q")
    wait_for(lambda: panel.proc.poll() is not None, 15.0, "the panel to quit")

    again = _start(rig, x_server, settings)
    again.wait_ready(b"DONE GET_SPEED")
    again.screenshot(shots / "started-again.png")
    title = _settings_dialog_title(again)
    x_server.screenshot(shots / "settings-in-french.png")
    assert title == "Réglages", f"the Settings dialog at the next start is titled {title!r}"
