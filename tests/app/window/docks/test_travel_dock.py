"""The Set up layout's Travel limits dock: the same form as Motion → Travel limits…, applied the
same way (kept for the device, used at once), and in step with the dialog."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDialog, QDockWidget

from app.common.settings import read_travel
from app.window.layout.arrangements import SETUP
from app.window.main_window import MainWindow
from drivers.device.travel import TravelLimits
from widgets.travel_limits_dialog import TravelLimitsDialog
from widgets.travel_limits_form import TravelLimitsForm, TravelLimitsPanel

pytestmark = pytest.mark.timeout(60)

SIM = "sim://coxiris?speed=100"


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(SIM, "coxiris", 115200)


def _panel(win: MainWindow) -> TravelLimitsPanel:
    dock = win.findChild(QDockWidget, "travelLimitsDock")
    assert dock is not None
    panel = dock.findChild(TravelLimitsPanel, "travelLimits")
    assert panel is not None
    return panel


def test_set_up_edits_and_applies_the_travel_limits(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    window.layouts.switch(SETUP)
    dock = window.findChild(QDockWidget, "travelLimitsDock")
    assert dock is not None and not dock.isHidden()
    dock.raise_()
    panel = _panel(window)
    qtbot.waitUntil(panel.isVisible, timeout=3000)
    assert panel.form.isEnabled() and "coxiris" in panel.form.intro.text()
    assert not panel.apply_button.isEnabled()  # nothing changed yet
    form = panel.form
    form.enabled_check.setChecked(True)
    low, high = form.spins["x"]
    low.setValue(-20.0)
    high.setValue(30.0)
    form.clamp_radio.setChecked(True)
    assert panel.apply_button.isEnabled()
    qtbot.mouseClick(panel.apply_button, Qt.MouseButton.LeftButton)
    assert window.travel is not None
    assert window.travel.box[0] == (-20.0, 30.0) and window.travel.clamp
    kept = read_travel(window.settings, "coxiris", SIM)  # kept for the device, as OK does
    assert kept == window.travel
    assert not panel.apply_button.isEnabled() and not panel.revert_button.isEnabled()
    assert "travel limits: " in window.status_line.message()

    high.setValue(10.0)  # an edit, then Revert: the limits in use again
    assert panel.revert_button.isEnabled()
    qtbot.mouseClick(panel.revert_button, Qt.MouseButton.LeftButton)
    assert high.value() == 30.0 and window.travel.box[0] == (-20.0, 30.0)


def test_the_menu_dialog_and_the_dock_show_the_same_limits(
    qtbot, window: MainWindow, monkeypatch: pytest.MonkeyPatch
) -> None:
    _connect(qtbot, window)
    window.layouts.switch(SETUP)
    panel = _panel(window)

    def ok(dialog: TravelLimitsDialog) -> int:
        dialog.enabled_check.setChecked(True)
        dialog.spins["y"][1].setValue(42.0)
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(TravelLimitsDialog, "exec", ok)
    window.travel_action.trigger()
    assert window.travel is not None and window.travel.box[1][1] == 42.0
    assert panel.form.result_limits()[0] == window.travel.box  # the dock follows

    window.set_travel_limits(None, False)  # the dock's Apply with the box off
    assert window.travel is None and read_travel(window.settings, "coxiris", SIM) is None
    assert not panel.form.enabled_check.isChecked()


def test_without_a_device_the_dock_says_so(qtbot, window: MainWindow) -> None:
    window.layouts.switch(SETUP)
    panel = _panel(window)
    assert not panel.form.isEnabled() and not panel.apply_button.isEnabled()
    assert "Connect a device" in panel.form.intro.text()
    _connect(qtbot, window)
    assert panel.form.isEnabled()
    window.disconnect_device()
    qtbot.waitUntil(lambda: not panel.form.isEnabled(), timeout=3000)


def test_the_form_refuses_an_empty_box(qtbot) -> None:
    form = TravelLimitsForm("COXIRIS", TravelLimits(((0.0, 10.0),) * 3).box, False)
    qtbot.addWidget(form)
    assert form.problem() == "" and form.problem_label.isHidden()
    low = form.spins["z"][0]
    low.setValue(10.0)
    assert form.problem() == "Z: the minimum must be below the maximum"
    assert not form.problem_label.isHidden()
    form.enabled_check.setChecked(False)
    assert form.result_limits() == (None, False)
