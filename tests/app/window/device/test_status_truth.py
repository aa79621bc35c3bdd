"""The status says what is: a notice goes when what it was about ends, Disconnected is not
beside "connected to", a paused program is Paused and says what the device still holds, and an
estimate is not shown beside "commanded" (issue 28, items 12 and 22)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import Qt

from app.window.main_window import MainWindow
from drivers.sim.laser_device import LaserDevice
from widgets import status_line as status
from widgets.position_readout import PositionReadout

pytestmark = pytest.mark.timeout(60)

_HOLDS = re.compile(r"still holds (\d+) move\(s\).* in about (\d+) s")


def pause_a_laser_zigzag(qtbot, window: MainWindow, tmp_path: Path) -> LaserDevice:
    """A laser-frame device (a queue of 8) running a 16 s zigzag, paused once 6 moves are
    queued on it; its simulated device."""
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device("sim://laser-frame?queue=8", "laser-frame", 115200)
    path = tmp_path / "zigzag.csv"
    rows = [f"{i * 0.5:g},{(i % 2) * 2:g},0,5" for i in range(1, 41)]  # 16 s at 5 mm/s
    path.write_text("x,y,z,speed\n" + "\n".join(rows) + "\n")
    panel = window.devices.program
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not window.devices.programs.reading, timeout=5000)
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    device = window.worker.session.simulator  # type: ignore[union-attr]
    qtbot.waitUntil(lambda: device.queue_length() >= 6, timeout=10000)
    qtbot.mouseClick(panel.pause_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.status_line.state() == status.PAUSED, timeout=5000)
    return device


def test_the_off_notice_goes_when_the_parameter_write_ends(qtbot, window: MainWindow) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device("sim://visiomex", "visiomex", 9600, "seed")
    window.layouts.switch("setup")
    editor = window.parameters.editor
    editor.table.selectRow(0)  # one packet (about a second), not the whole table's 25
    qtbot.mouseClick(editor.write_selected_button, Qt.MouseButton.LeftButton)
    assert "motion controls are off until" in window.status_line.message()
    assert editor.writing()
    qtbot.waitUntil(lambda: not editor.writing(), timeout=10000)
    qtbot.waitUntil(lambda: window.jog_panel.isEnabled(), timeout=5000)
    assert "motion controls are off" not in window.status_line.message()


def test_disconnect_replaces_connected_to(qtbot, window: MainWindow) -> None:
    with qtbot.waitSignal(window.settled, timeout=8000):
        window.connect_device("sim://coxiris", "coxiris", 115200)
    assert window.status_line.message().startswith("connected to")
    window.disconnect_device()
    qtbot.waitUntil(lambda: window.status_line.state() == status.DISCONNECTED, timeout=5000)
    assert "connected to" not in window.status_line.message().removeprefix("disconnected from")
    assert window.status_line.message().startswith("disconnected from")


def test_a_paused_laser_program_says_what_the_device_still_holds(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    device = pause_a_laser_zigzag(qtbot, window, tmp_path)
    seen: list[re.Match[str]] = []

    def said_held() -> bool:
        found = _HOLDS.search(window.status_line.message())
        if found is not None:
            seen.append(found)
        return found is not None

    qtbot.waitUntil(said_held, timeout=5000)
    held = seen[0]
    count, seconds = int(held.group(1)), int(held.group(2))
    assert 1 <= count <= 9, held.string
    assert 1 <= seconds <= 9 * 2.1 / 5 + 1, held.string  # moves of about 2 mm
    qtbot.waitUntil(lambda: "has run what it held" in window.status_line.message(), timeout=15000)
    assert device.queue_length() == 0
    assert window.status_line.state() == status.PAUSED  # not Moving
    window.stop_action.trigger()
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=10000)


def test_an_estimate_is_not_shown_beside_commanded_and_the_badges_keep_their_place(
    qtbot,
) -> None:
    readout = PositionReadout()
    qtbot.addWidget(readout)
    readout.show()
    readout.set_measured(False, True)
    assert readout.measured_label.isVisible()
    readout.set_status("estimated")
    assert not readout.measured_label.isVisible() and readout.status_label.isVisible()
    tallest = readout.badges.minimumHeight()
    assert tallest >= readout.status_label.sizeHint().height()
    readout.set_status("live")
    assert readout.measured_label.isVisible() and not readout.status_label.isVisible()
    assert readout.badges.minimumHeight() == tallest  # no jump back
    assert not readout.is_measured()
