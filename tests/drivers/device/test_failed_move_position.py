"""A move that failed never moves the readout, the views or a commanded-only device's count.

Firmata's board refuses a move until its stepper is configured ("STEPPER Error: not
configured"): the jog fails, and the window goes on showing where the stage really is.
"""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.window.main_window import MainWindow
from tests.support.relay import wait_in_gui
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.timeout(60)


def _connect(qtbot, win: MainWindow, port: str) -> None:
    with qtbot.waitSignal(win.settled, timeout=15000):
        win.connect_device(port, "firmata", 57600)


def _jog_x_plus_fails(qtbot, win: MainWindow) -> list[str]:
    """Click X+ (10 mm) and wait until the window has been told the jog failed (received in the
    GUI thread after the window's own slot); the failure's message."""
    win.jog_panel.set_step(10)
    with wait_in_gui(qtbot, win.worker.job_failed, timeout=10000) as failed:
        qtbot.mouseClick(win.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
    return [str(failed.args[1])]


def _assert_at_origin(win: MainWindow) -> None:
    """The readout, the trail, the 2D views and the Go-to fields: all still at 0."""
    assert win.readout.position() == (0.0, 0.0, 0.0)
    assert win.readout.status() != "estimated"
    rows = win.buffer.view()
    assert np.nanmax(np.abs(rows[:, 1:4])) == 0.0  # no estimated point is left in the trail
    win.view2d.refresh()
    x, y = win.view2d.trail.getData()
    assert (x[-1], y[-1]) == (0.0, 0.0)
    for curve in win.view2d.curves.values():
        assert curve.getData()[1][-1] == 0.0
    assert win.view2d.target() is None
    assert win.view3d.target() is None  # type: ignore[attr-defined]
    assert not win.view2d.is_estimated()


def test_an_unconfigured_firmata_jog_leaves_the_position_where_it_was(
    qtbot, window: MainWindow
) -> None:
    _connect(qtbot, window, "sim://firmata?reset_delay=0.2")
    failures = _jog_x_plus_fails(qtbot, window)
    assert "not configured" in failures[0]
    _assert_at_origin(window)
    motion = window.worker.session
    assert motion is not None and motion.last_position is not None
    assert (motion.last_position.x, motion.last_position.y) == (0.0, 0.0)  # count not advanced


def test_a_late_error_takes_the_estimated_motion_back(qtbot, window: MainWindow) -> None:
    """The board's error comes 0.6 s late (a slow line): the estimate has moved the readout
    meanwhile; the failure puts it, and the views, back where the stage is; the count is not
    advanced, so after Configure a 1 mm jog ends at 1 mm."""
    sim = SimProcess("firmata", "--reset-delay", "0.2", control=True)
    try:
        _connect(qtbot, window, sim.path)
        estimates: list[float] = []
        assert window.machine.estimate is not None
        window.machine.estimate.estimated.connect(lambda x, y, z: estimates.append(x))
        sim.fault("slow 0.6")
        failures = _jog_x_plus_fails(qtbot, window)
        assert "not configured" in failures[0]
        assert max(estimates) > 1.0  # the readout had moved with the estimate
        _assert_at_origin(window)

        sim.fault("slow 0")
        panel = window.devices.firmata
        qtbot.mouseClick(
            window.findChild(QPushButton, "firmataConfigure"), Qt.MouseButton.LeftButton
        )
        qtbot.waitUntil(
            lambda: panel.findChild(object, "firmataVersionLabel").text() == "5", timeout=10000
        )
        window.jog_panel.set_step(1)
        qtbot.mouseClick(window.findChild(QPushButton, "jogXPlus"), Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: window.readout.position() == (1.0, 0.0, 0.0), timeout=10000)
    finally:
        if sim.proc.poll() is None:
            sim.stop()
