"""Work coordinates in the widgets: the readout's work column and Zero buttons, and the
coordinate entry typing in either frame while the device is sent machine coordinates."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from drivers.device.work_zero import WorkZero, format_work_zero, parse_work_zero
from drivers.errors import BadInput
from widgets.coordinate_entry import MACHINE, WORK, CoordinateEntry
from widgets.position_readout import PositionReadout

pytestmark = pytest.mark.timeout(30)
LEFT = Qt.MouseButton.LeftButton


def test_work_zero_arithmetic() -> None:
    zero = WorkZero().zeroed("x", (10.0, 5.0, 1.0)).zeroed("z", (0.0, 0.0, -2.0))
    assert zero == WorkZero(10.0, 0.0, -2.0)
    assert zero.to_work((12.0, 5.0, 0.0)) == (2.0, 5.0, 2.0)
    assert zero.to_machine((2.0, 5.0, 2.0)) == (12.0, 5.0, 0.0)
    # Set Home at machine (4, 0, 0): the same physical zero is 4 mm nearer the new home.
    assert zero.after_set_home((4.0, 0.0, 0.0)) == WorkZero(6.0, 0.0, -2.0)
    assert WorkZero().is_machine() and not zero.is_machine()
    with pytest.raises(BadInput, match="no axis 'a'"):
        zero.zeroed("a", (0.0, 0.0, 0.0))


@pytest.mark.parametrize("text", ["1,2", "a,b,c", "1,2,nan", "1,2,inf", ""])
def test_a_malformed_saved_zero_is_refused(text: str) -> None:
    with pytest.raises(BadInput):
        parse_work_zero(text)


def test_a_saved_zero_round_trips() -> None:
    zero = WorkZero(1.5, -2.25, 0.1)
    assert parse_work_zero(format_work_zero(zero)) == zero


def test_the_readout_shows_both_frames_and_says_which(readout: PositionReadout) -> None:
    readout.set_position(12.0, 5.0, 0.0)
    assert readout.text("x") == "12.00 mm"
    assert readout.work_text("x") == "12.00 mm"
    assert readout.zero_label.text() == "work zero: home"
    assert not readout.clear_zero_button.isEnabled()
    readout.set_work_zero((10.0, 0.0, -2.0))
    assert readout.text("x") == "12.00 mm"  # machine, as before
    assert readout.work_text("x") == "2.00 mm"
    assert readout.work_text("z") == "2.00 mm"
    assert readout.zero_label.text() == "work zero at (10.00, 0.00, -2.00) mm (machine)"
    assert readout.machine_header.text() == "Machine" and readout.work_header.text() == "Work"
    assert readout.clear_zero_button.isEnabled()


def test_zero_buttons_ask_for_their_axis(qtbot, readout: PositionReadout) -> None:
    asked: list[str] = []
    cleared: list[bool] = []
    readout.zero_requested.connect(asked.append)
    readout.clear_zero_requested.connect(lambda: cleared.append(True))
    assert not readout.zero_buttons["x"].isEnabled()  # no position yet
    readout.set_zero_enabled(True)
    qtbot.mouseClick(readout.zero_buttons["y"], LEFT)
    qtbot.mouseClick(readout.zero_all_button, LEFT)
    readout.set_axes_enabled("xy")
    readout.set_zero_enabled(True)
    qtbot.mouseClick(readout.zero_all_button, LEFT)
    assert not readout.zero_buttons["z"].isEnabled()
    readout.set_work_zero((1.0, 0.0, 0.0))
    qtbot.mouseClick(readout.clear_zero_button, LEFT)
    assert asked == ["y", "xyz", "xy"]
    assert cleared == [True]
    for axis in "xyz":
        assert readout.zero_buttons[axis].objectName() == f"zero{axis.upper()}"
        assert "work zero" in readout.zero_buttons[axis].toolTip()


def test_work_coordinates_are_sent_as_machine_ones(qtbot, entry: CoordinateEntry) -> None:
    sent: list[tuple[str, tuple[float, float, float]]] = []
    entry.go_requested.connect(lambda mode, target: sent.append((mode, target)))
    entry.set_work_zero((10.0, 5.0, -2.0))
    entry.set_values(1.0, 2.0, 3.0)
    qtbot.mouseClick(entry.go_button, LEFT)  # machine frame: as typed
    entry.set_frame(WORK)
    entry.set_values(1.0, 2.0, 3.0)
    qtbot.mouseClick(entry.go_button, LEFT)
    entry.set_mode("relative")
    entry.set_values(1.0, 0.0, 0.0)
    qtbot.mouseClick(entry.go_button, LEFT)  # a distance is the same in both frames
    assert sent == [
        ("absolute", (1.0, 2.0, 3.0)),
        ("absolute", (11.0, 7.0, 1.0)),
        ("relative", (1.0, 0.0, 0.0)),
    ]


def test_use_current_and_ranges_follow_the_frame(entry: CoordinateEntry) -> None:
    entry.set_box(((0.0, 100.0), (0.0, 50.0), (-10.0, 0.0)))
    entry.set_work_zero((10.0, 5.0, -2.0))
    entry.set_current(12.0, 5.0, -2.0)
    assert entry.values() == (12.0, 5.0, -2.0)
    entry.set_frame(WORK)
    assert entry.values() == (2.0, 0.0, 0.0)
    assert entry.fields["x"].minimum() == -10.0 and entry.fields["x"].maximum() == 90.0
    assert "work frame" in entry.fields["x"].toolTip()
    entry.set_frame(MACHINE)
    assert entry.fields["x"].minimum() == 0.0
    assert entry.values() == (12.0, 5.0, -2.0)
    with pytest.raises(ValueError, match="frame must be"):
        entry.set_frame("tool")


def test_numbers_follow_the_interface_locale(readout: PositionReadout) -> None:
    from PySide6.QtCore import QLocale

    before = QLocale()
    QLocale.setDefault(QLocale(QLocale.Language.French, QLocale.Country.France))
    try:
        readout.set_position(1234.5, -0.004, 0.0)
        readout.set_work_zero((1.0, 0.0, 0.0))
        assert readout.text("x") == "1234,50 mm"  # no thousands separator
        assert readout.text("y") == "0,00 mm"  # no "-0,00"
        assert readout.work_text("x") == "1233,50 mm"
        assert readout.zero_label.text() == "work zero at (1,00; 0,00; 0,00) mm (machine)"
    finally:
        QLocale.setDefault(before)


def test_inches_shown_with_the_device_resolution_or_fixed_decimals(
    readout: PositionReadout,
) -> None:
    readout.set_resolution(0.01)
    readout.set_position(25.4, -12.7, 0.0)
    readout.set_work_zero((25.4, 0.0, 0.0))
    assert readout.text("x") == "25.40 mm"
    readout.set_display("in")
    assert readout.units() == "in"
    assert readout.text("x") == "1.0000 in"  # 0.01 mm is 0.0004 in: four decimals
    assert readout.work_text("x") == "0.0000 in"
    assert readout.text("y") == "-0.5000 in"
    assert readout.zero_label.text() == "work zero at (1.0000, 0.0000, 0.0000) in (machine)"
    readout.set_display("in", 2)
    assert readout.text("y") == "-0.50 in"
    readout.set_display("mm", -1)
    assert readout.text("y") == "-12.70 mm"
    with pytest.raises(ValueError, match="units must be"):
        readout.set_display("furlong")
