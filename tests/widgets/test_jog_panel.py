"""JogPanel: buttons, steps, Shift, keyboard map, disabled axes."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from widgets.jog_panel import KEY_HINT, JogPanel

BUTTONS = [
    ("jogXPlus", "X+", "x", 1.0),
    ("jogXMinus", "X-", "x", -1.0),
    ("jogYPlus", "Y+", "y", 1.0),
    ("jogYMinus", "Y-", "y", -1.0),
    ("jogZPlus", "Z+", "z", 1.0),
    ("jogZMinus", "Z-", "z", -1.0),
]
KEYS = [
    (Qt.Key.Key_Left, "x", -1.0),
    (Qt.Key.Key_Right, "x", 1.0),
    (Qt.Key.Key_Up, "y", 1.0),
    (Qt.Key.Key_Down, "y", -1.0),
    (Qt.Key.Key_PageUp, "z", 1.0),
    (Qt.Key.Key_PageDown, "z", -1.0),
]


@pytest.fixture
def panel(qtbot) -> JogPanel:
    widget = JogPanel()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def _button(panel: JogPanel, name: str) -> QPushButton:
    button = panel.findChild(QPushButton, name)
    assert button is not None, name
    return button


def test_object_name_hint_and_tooltips(panel: JogPanel) -> None:
    assert panel.objectName() == "jogPanel"
    assert panel.hint_label.text().startswith(KEY_HINT)
    assert "Shift ×10" in panel.hint_label.text()
    assert panel.step_spin.suffix() == " mm"
    for button in panel.findChildren(QPushButton):
        assert button.toolTip(), button.text()


@pytest.mark.parametrize(("name", "text", "axis", "sign"), BUTTONS)
def test_buttons_emit_axis_and_distance(panel, qtbot, record, name, text, axis, sign) -> None:
    calls = record(panel.jog_requested)
    button = _button(panel, name)
    assert button.text() == text
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    assert calls == [(axis, sign * 1.0)]


def test_shift_click_jogs_ten_times_the_step(panel, qtbot, record) -> None:
    calls = record(panel.jog_requested)
    panel.set_step(0.1)
    qtbot.mouseClick(
        _button(panel, "jogYMinus"), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.ShiftModifier
    )
    assert calls == [("y", pytest.approx(-1.0))]


def test_presets_and_free_step(panel, qtbot, record) -> None:
    calls = record(panel.jog_requested)
    qtbot.mouseClick(panel.preset_buttons[10.0], Qt.MouseButton.LeftButton)
    assert panel.step() == 10.0
    assert panel.preset_buttons[10.0].isChecked()
    panel.step_spin.setValue(2.5)  # a free value: no preset is checked
    assert panel.step() == 2.5
    assert not any(b.isChecked() for b in panel.preset_buttons.values())
    panel.set_step(0.01)
    assert panel.preset_buttons[0.01].isChecked()
    assert calls == []  # changing the step jogs nothing
    qtbot.mouseClick(_button(panel, "jogXPlus"), Qt.MouseButton.LeftButton)
    assert calls == [("x", pytest.approx(0.01))]
    assert "+0.01 mm" in _button(panel, "jogXPlus").toolTip()


@pytest.mark.parametrize(("key", "axis", "sign"), KEYS)
def test_handle_key_maps_keys(panel, record, key, axis, sign) -> None:
    calls = record(panel.jog_requested)
    panel.set_step(1.0)
    assert panel.handle_key(key, Qt.KeyboardModifier.NoModifier) is True
    assert panel.handle_key(int(key), Qt.KeyboardModifier.ShiftModifier) is True
    assert calls == [(axis, sign * 1.0), (axis, sign * 10.0)]


def test_handle_key_ignores_other_keys_and_combinations(panel, record) -> None:
    calls = record(panel.jog_requested)
    assert panel.handle_key(Qt.Key.Key_A, Qt.KeyboardModifier.NoModifier) is False
    assert panel.handle_key(Qt.Key.Key_Left, Qt.KeyboardModifier.ControlModifier) is False
    assert panel.handle_key(Qt.Key.Key_Left, Qt.KeyboardModifier.AltModifier) is False
    assert panel.handle_key(Qt.Key.Key_Left, None, auto_repeat=True) is True  # consumed
    assert calls == []


def test_keypad_arrows_jog(panel, record) -> None:
    calls = record(panel.jog_requested)
    assert panel.handle_key(Qt.Key.Key_Up, Qt.KeyboardModifier.KeypadModifier)
    assert calls == [("y", 1.0)]


def test_key_press_on_focused_panel(panel, qtbot, record) -> None:
    calls = record(panel.jog_requested)
    qtbot.keyClick(panel, Qt.Key.Key_Right)
    qtbot.keyClick(panel, Qt.Key.Key_PageDown, Qt.KeyboardModifier.ShiftModifier)
    assert calls == [("x", 1.0), ("z", -10.0)]


def test_disabled_axes(panel, qtbot, record) -> None:
    calls = record(panel.jog_requested)
    panel.set_axes_enabled(["X", "y"])  # case does not matter
    assert panel.axes_enabled() == {"x", "y"}
    assert not _button(panel, "jogZPlus").isEnabled()
    assert not _button(panel, "jogZMinus").isEnabled()
    assert _button(panel, "jogXPlus").isEnabled()
    qtbot.mouseClick(_button(panel, "jogZPlus"), Qt.MouseButton.LeftButton)
    assert panel.handle_key(Qt.Key.Key_PageUp, None) is False
    assert calls == []
    panel.set_axes_enabled("xyz")
    assert _button(panel, "jogZPlus").isEnabled()


def test_disabled_panel_jogs_nothing(panel, qtbot, record) -> None:
    calls = record(panel.jog_requested)
    panel.setEnabled(False)  # disconnected
    assert panel.handle_key(Qt.Key.Key_Left, None) is False
    qtbot.mouseClick(_button(panel, "jogXPlus"), Qt.MouseButton.LeftButton)
    assert calls == []


def test_a_held_button_is_held_until_released(qtbot, panel: JogPanel, record) -> None:
    panel.set_step(1)
    steps, releases = record(panel.jog_requested), record(panel.jog_released)
    button = panel.buttons[("x", 1.0)]
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    assert steps == [("x", 1.0)] and panel.held() == ("x", 1.0)
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    assert panel.held() is None and len(releases) == 1
    assert steps == [("x", 1.0)]  # one press, one step: the window repeats while held


def test_a_held_key_ends_on_its_own_release_only(panel: JogPanel, record) -> None:
    panel.set_step(2)
    releases = record(panel.jog_released)
    assert panel.handle_key(Qt.Key.Key_Up)
    assert panel.held() == ("y", 2.0)
    assert panel.handle_key(Qt.Key.Key_Up, auto_repeat=True)  # the X server's repeat
    assert panel.handle_key_release(Qt.Key.Key_Up, auto_repeat=True)
    assert panel.held() == ("y", 2.0) and releases == []
    assert panel.handle_key_release(Qt.Key.Key_Down)  # another jog key: not the held one
    assert panel.held() == ("y", 2.0)
    assert panel.handle_key_release(Qt.Key.Key_Up)
    assert panel.held() is None and len(releases) == 1
    assert not panel.handle_key_release(Qt.Key.Key_A)


def test_keyboard_state_and_resolution(panel: JogPanel) -> None:
    panel.set_keyboard_state(False, "the focus is in a text field")
    assert panel.hint_label.text().endswith("keys off: the focus is in a text field")
    panel.set_resolution(0.01)
    assert panel.step_spin.decimals() == 2
    assert panel.preset_buttons[0.01].isEnabled()  # 0.01 mm is still possible
    panel.set_resolution(0.1)
    assert not panel.preset_buttons[0.01].isEnabled()
    panel.set_resolution(None)
    assert panel.step_spin.decimals() == 3
