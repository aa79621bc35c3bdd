"""The mouse wheel changes a number field only while it has the focus; over an unfocused
field it scrolls the dock that holds it (issue 28, item 9)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import QAbstractSlider, QAbstractSpinBox, QApplication, QScrollBar, QWidget

from app.window.main_window import MainWindow
from app.window.preferences import Preferences
from widgets._number_field import WHEEL_PROPERTY
from widgets.coordinate_entry import CoordinateEntry
from widgets.panel_scroll_area import PanelScrollArea
from widgets.settings_dialog import SettingsDialog
from widgets.travel_limits_dialog import TravelLimitsDialog

pytestmark = pytest.mark.timeout(60)


def _wheel(widget: QWidget, notches: int = 3) -> bool:
    """Wheel `notches` notches (up) over the middle of `widget`; whether it took the event
    (not taken, Qt offers a real wheel event to the parents: the scroll area scrolls)."""
    local = QPointF(widget.rect().center())
    event = QWheelEvent(
        local,
        QPointF(widget.mapToGlobal(local.toPoint())),
        QPoint(0, 0),
        QPoint(0, 120 * notches),
        Qt.MouseButton.NoButton,
        Qt.KeyboardModifier.NoModifier,
        Qt.ScrollPhase.NoScrollPhase,
        False,
    )
    QApplication.sendEvent(widget, event)
    return event.isAccepted()


def _value(widget: QWidget) -> object:
    if isinstance(widget, QAbstractSpinBox):
        return widget.text()
    assert isinstance(widget, QAbstractSlider)
    return widget.value()


def _number_fields(window: MainWindow) -> list[QWidget]:
    fields: list[QWidget] = list(window.findChildren(QAbstractSpinBox))
    fields += [s for s in window.findChildren(QAbstractSlider) if not isinstance(s, QScrollBar)]
    return fields


def test_no_number_field_of_the_window_changes_on_the_wheel_unless_focused(
    qtbot, window: MainWindow
) -> None:
    with qtbot.waitSignal(window.settled, timeout=5000):
        window.connect_device("sim://coxiris?speed=100", "coxiris", 115200)
    window.devices.arc  # noqa: B018  the device docks built (they are, once the views are)
    SettingsDialog(Preferences(), window)
    TravelLimitsDialog("COXIRIS", None, False, window)
    fields = _number_fields(window)
    names = {f.objectName() for f in fields}
    for expected in ("coordX", "jogStepSpin", "speedSpin", "speedSlider", "pollIdleS"):
        assert expected in names, (expected, sorted(names))
    assert len(fields) >= 25, sorted(names)
    for field in fields:  # the rule, on every one (a disabled one included)
        assert field.focusPolicy() == Qt.FocusPolicy.StrongFocus, field.objectName()
        assert field.property(WHEEL_PROPERTY) is True, field.objectName()
    enabled = [f for f in fields if f.isEnabled()]
    assert {"coordX", "coordY", "jogStepSpin", "speedSpin", "speedSlider"} <= {
        f.objectName() for f in enabled
    }
    changed = []
    for field in enabled:  # and what it does, on every one the operator can use now
        assert not field.hasFocus(), field.objectName()
        before = _value(field)
        taken = _wheel(field)
        if taken or _value(field) != before:
            changed.append((field.objectName(), before, _value(field)))
    assert changed == []


def test_the_focused_field_still_takes_the_wheel(qtbot) -> None:
    entry = CoordinateEntry()
    qtbot.addWidget(entry)
    entry.show()
    qtbot.waitExposed(entry)
    x = entry.fields["x"]
    x.set_mm_value(-40.0)
    _wheel(x, 1)
    assert x.value() == -40.0
    entry.activateWindow()
    x.setFocus()
    qtbot.waitUntil(x.hasFocus, timeout=2000)
    _wheel(x, 1)
    assert x.value() == pytest.approx(-40.0 + x.singleStep())


def test_the_wheel_over_an_unfocused_field_goes_on_to_the_dock(qtbot) -> None:
    entry = CoordinateEntry()
    area = PanelScrollArea(entry)
    qtbot.addWidget(area)
    area.show()
    qtbot.waitExposed(area)
    x = entry.fields["x"]
    x.set_mm_value(-40.0)
    assert _wheel(x, -3) is False  # ignored: Qt offers it to the scroll area, which scrolls
    assert x.value() == -40.0 and x.text() == "-40.000 mm"
