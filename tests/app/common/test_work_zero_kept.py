"""The work zero kept per device: set from the Zero buttons, saved, read back, moved with Set
Home, and used by the coordinate entry."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt

from app.window.docks.work_frame import WorkFrame
from widgets.coordinate_entry import WORK, CoordinateEntry
from widgets.position_readout import PositionReadout

pytestmark = pytest.mark.timeout(30)
LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def parts(qtbot, tmp_path: Path):
    readout, entry = PositionReadout(), CoordinateEntry()
    for widget in (readout, entry):
        qtbot.addWidget(widget)
        widget.show()
    said: list[str] = []
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    return WorkFrame(settings, readout, entry, said.append), readout, entry, said, settings


def test_zero_buttons_set_and_keep_the_work_zero(qtbot, parts, tmp_path: Path) -> None:
    frame, readout, entry, said, _settings = parts
    frame.device_ready("coxiris", "/dev/ttyUSB0")
    assert not readout.zero_buttons["x"].isEnabled()  # no position yet
    readout.set_position(12.0, 5.0, -1.0)
    frame.set_position((12.0, 5.0, -1.0))
    qtbot.mouseClick(readout.zero_buttons["x"], LEFT)
    qtbot.mouseClick(readout.zero_buttons["z"], LEFT)
    assert readout.work_text("x") == "0.00 mm" and readout.work_text("y") == "5.00 mm"
    assert said[-1] == "work zero set at Z -1.00 mm (machine)"
    sent: list[object] = []
    entry.go_requested.connect(lambda mode, target: sent.append(target))
    entry.set_frame(WORK)
    entry.set_values(1.0, 1.0, 1.0)
    qtbot.mouseClick(entry.go_button, LEFT)
    assert sent == [(13.0, 1.0, 0.0)]
    # Another panel, later, on the same device: the same zero.
    again = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    other = PositionReadout()
    qtbot.addWidget(other)
    later = WorkFrame(again, other, CoordinateEntry(), said.append)
    later.device_ready("coxiris", "/dev/ttyUSB0")
    assert other.work_zero() == (12.0, 0.0, -1.0)
    assert said[-1] == "work coordinates: work zero at (12, 0, -1) mm machine"
    later.device_ready("coxiris", "/dev/ttyUSB1")  # another device: its own (none)
    assert other.work_zero() == (0.0, 0.0, 0.0)


def test_set_home_keeps_the_zero_in_place_and_clear_resets(parts) -> None:
    frame, readout, _entry, said, _settings = parts
    frame.device_ready("visiomex", "sim://visiomex")
    frame.set_position((10.0, 10.0, 0.0))
    frame.zero_axes("xy")
    frame.home_moved((4.0, 0.0, 0.0))
    assert readout.work_zero() == (6.0, 10.0, 0.0)
    frame.clear()
    assert readout.work_zero() == (0.0, 0.0, 0.0)
    assert said[-1] == "work zero cleared: work coordinates are machine coordinates"


def test_no_position_no_zero_and_a_bad_kept_value_is_ignored(parts) -> None:
    frame, readout, _entry, said, settings = parts
    settings.setValue("devices/coxiris/x/work_zero", "1,2")
    frame.device_ready("coxiris", "x")
    assert readout.work_zero() == (0.0, 0.0, 0.0)
    frame.zero_axes("x")
    assert said[-1] == "work zero not set: the position is unknown"
    frame.set_position((1.0, 2.0, 3.0))
    frame.disconnected()
    assert not readout.zero_all_button.isEnabled()
