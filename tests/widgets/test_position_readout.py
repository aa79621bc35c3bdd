"""PositionReadout: formatting, measured/commanded label, disabled axes."""

from __future__ import annotations

import pytest

from widgets.position_readout import NOT_MEASURED_TEXT, PositionReadout


def test_object_name_and_unknown_position(readout: PositionReadout) -> None:
    assert readout.objectName() == "positionReadout"
    assert readout.text("x") == "— mm"
    assert readout.position() is None


def test_set_position_formats_with_units(readout: PositionReadout) -> None:
    readout.set_position(12.344, -3.2, 0)
    assert [readout.text(a) for a in "xyz"] == ["12.34 mm", "-3.20 mm", "0.00 mm"]
    assert readout.text("X") == "12.34 mm"
    readout.clear()
    assert readout.text("y") == "— mm"


def test_decimals(qtbot) -> None:
    widget = PositionReadout(decimals=3)
    qtbot.addWidget(widget)
    widget.set_position(1.23456, 0, 0)
    assert widget.text("x") == "1.235 mm"


def test_measured_label(readout: PositionReadout) -> None:
    assert not readout.measured_label.isVisible()
    readout.set_measured(False)
    assert readout.measured_label.isVisible()
    assert readout.measured_label.text() == NOT_MEASURED_TEXT
    assert not readout.is_measured()
    readout.set_measured(True)
    assert not readout.measured_label.isVisible()
    assert readout.is_measured()


def test_disabled_axes(readout: PositionReadout) -> None:
    readout.set_position(1, 2, 3)
    readout.set_axes_enabled(["x", "y"])
    assert not readout.labels["z"].isEnabled()
    assert readout.text("z") == "— mm"
    assert readout.text("y") == "2.00 mm"
    readout.set_axes_enabled(["x", "y", "z"])
    assert readout.text("z") == "3.00 mm"


def test_estimated_and_stale_are_visible(qtbot) -> None:
    readout = PositionReadout()
    qtbot.addWidget(readout)
    readout.set_position(1, 2, 3)
    assert readout.status() == "live" and readout.status_label.isHidden()
    readout.set_status("estimated")
    assert not readout.status_label.isHidden()
    assert "estimated" in readout.status_label.text()
    assert readout.value_style("x") == ("#1565c0", True)  # blue italic
    readout.set_status("stale")
    assert "last known" in readout.status_label.text()
    assert readout.text("x") == "1.00 mm"  # kept, but greyed
    assert readout.value_style("x") == ("#9e9e9e", False)
    readout.set_status("live")
    assert readout.status_label.isHidden()
    assert readout.value_style("x") == (
        readout.palette().color(readout.palette().ColorRole.WindowText).name(),
        False,
    )
    with pytest.raises(ValueError):
        readout.set_status("bold")
