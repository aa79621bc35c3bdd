"""SpeedControl: slider and field in sync; speed_requested only on release, Enter or Apply."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, Qt

from widgets.speed_control import SLIDER_STEPS, SpeedControl


def test_object_name_and_units(speed: SpeedControl) -> None:
    assert speed.objectName() == "speedControl"
    assert speed.spin.suffix() == " mm/s"
    assert "mm/s" in speed.slider.toolTip()
    assert speed.apply_button.toolTip()


def test_programmatic_changes_emit_nothing(speed, record) -> None:
    calls = record(speed.speed_requested)
    speed.set_value(25.0)
    assert speed.value() == 25.0
    assert speed.slider.value() == SLIDER_STEPS // 2
    speed.set_range(10.0, 20.0)  # clamps the value
    assert speed.value() == 20.0
    assert speed.slider.value() == SLIDER_STEPS
    speed.set_reported(13.0)
    assert calls == []


def test_dragging_sends_once_on_release(speed, record) -> None:
    calls = record(speed.speed_requested)
    speed.slider.setSliderDown(True)  # what a mouse press on the handle does
    for position in (100, 200, 300, 400):
        speed.slider.setSliderPosition(position)
    assert speed.value() == pytest.approx(20.0)  # the field follows the drag
    assert calls == []
    speed.slider.setSliderDown(False)  # release
    assert calls == [(pytest.approx(20.0),)]


def test_click_on_the_groove_sends_once(speed, qtbot, record) -> None:
    calls = record(speed.speed_requested)
    rect = speed.slider.rect()
    qtbot.mouseClick(
        speed.slider, Qt.MouseButton.LeftButton, pos=QPoint(rect.right() - 3, rect.center().y())
    )
    assert len(calls) == 1
    assert calls[0][0] == pytest.approx(speed.value())
    assert speed.value() > 0


def test_enter_in_field_sends(speed, qtbot, record) -> None:
    calls = record(speed.speed_requested)
    speed.spin.selectAll()
    qtbot.keyClicks(speed.spin, "12.5")
    assert calls == []  # typing alone sends nothing
    qtbot.keyClick(speed.spin, Qt.Key.Key_Return)
    assert calls == [(12.5,)]
    assert speed.slider.value() == round(12.5 / 50.0 * SLIDER_STEPS)


def test_stepping_the_field_moves_the_slider_only(speed, qtbot, record) -> None:
    calls = record(speed.speed_requested)
    speed.set_value(10.0)
    qtbot.keyClick(speed.spin, Qt.Key.Key_Up)
    assert speed.value() == pytest.approx(10.5)  # single step: 1/100 of the range
    assert speed.slider.value() == round(10.5 / 50.0 * SLIDER_STEPS)
    assert calls == []


def test_apply_sends_the_field(speed, qtbot, record) -> None:
    calls = record(speed.speed_requested)
    speed.set_value(7.0)
    qtbot.mouseClick(speed.apply_button, Qt.MouseButton.LeftButton)
    assert calls == [(7.0,)]


def test_reported_label(speed) -> None:
    speed.set_reported(13.0)
    assert speed.reported_label.text() == "device: 13 mm/s"
    speed.set_reported(12.5)
    assert speed.reported_label.text() == "device: 12.5 mm/s"
    speed.set_reported(None)
    assert speed.reported_label.text() == "device: — mm/s"


def test_range_checks(speed) -> None:
    with pytest.raises(ValueError):
        speed.set_range(5.0, 1.0)
    speed.set_range(3.0, 3.0)  # a fixed speed: nothing to slide
    assert not speed.slider.isEnabled()
    assert speed.speed_range() == (3.0, 3.0)
