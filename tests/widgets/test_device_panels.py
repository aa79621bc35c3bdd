"""FirmataPanel and PiFramePanel: signals, the rpm label, pin count switching, save/restore."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractSpinBox, QWidget

from widgets.firmata_panel import FirmataPanel
from widgets.piframe_panel import PiFramePanel

LEFT = Qt.MouseButton.LeftButton


def _controls_have_tooltips(panel: QWidget) -> None:
    """Every control the panel made (named; Qt's own parts are "qt_..." or unnamed) has a tip."""
    controls = [
        widget
        for widget in panel.findChildren(QWidget)
        if widget.focusPolicy() != Qt.FocusPolicy.NoFocus
        and widget.objectName()
        and not widget.objectName().startswith("qt_")
    ]
    assert len(controls) >= 2
    for widget in controls:
        assert widget.toolTip(), widget.objectName()


@pytest.fixture
def firmata(qtbot) -> FirmataPanel:
    widget = FirmataPanel()
    qtbot.addWidget(widget)
    widget.show()
    return widget


@pytest.fixture
def piframe(qtbot) -> PiFramePanel:
    widget = PiFramePanel()
    qtbot.addWidget(widget)
    widget.show()
    return widget


# -- FirmataPanel ----------------------------------------------------------------------------
def test_firmata_names_units_and_ranges(firmata: FirmataPanel) -> None:
    assert firmata.objectName() == "firmataPanel"
    assert firmata.configure_button.objectName() == "firmataConfigure"
    assert firmata.version_button.objectName() == "firmataVersion"
    assert firmata.version_label.objectName() == "firmataVersionLabel"
    assert (firmata.steps_per_rev_spin.minimum(), firmata.steps_per_rev_spin.maximum()) == (
        1,
        16383,
    )
    assert "steps/rev" in firmata.steps_per_rev_spin.suffix()
    assert firmata.steps_per_mm_spin.suffix() == " steps/mm"
    assert firmata.steps_per_mm_spin.minimum() > 0
    for spin in firmata.pin_spins:
        assert (spin.minimum(), spin.maximum()) == (0, 127)
    _controls_have_tooltips(firmata)
    assert firmata.minimumSizeHint().width() <= 1024 // 2


def test_pin_count_switching_hides_the_unused_pins(firmata: FirmataPanel) -> None:
    assert firmata.pin_count() == 4
    assert not any(spin.isHidden() for spin in firmata.pin_spins)
    firmata.pin_count_combo.setCurrentIndex(firmata.pin_count_combo.findData(2))
    assert firmata.pin_count() == 2
    assert [spin.isHidden() for spin in firmata.pin_spins] == [False, False, True, True]
    assert [label.isHidden() for label in firmata.pin_labels] == [False, False, True, True]
    assert len(firmata.pins()) == 2
    firmata.pin_count_combo.setCurrentIndex(firmata.pin_count_combo.findData(4))
    assert not any(spin.isHidden() for spin in firmata.pin_spins)
    assert len(firmata.pins()) == 4


def test_configure_and_version_signals(firmata: FirmataPanel, qtbot, record) -> None:
    configure = record(firmata.configure_requested)
    version = record(firmata.version_requested)
    firmata.set_settings(400, [2, 3], 80.0)
    qtbot.mouseClick(firmata.configure_button, LEFT)
    assert configure == [(400, [2, 3], 80.0)]
    firmata.set_settings(200, [4, 5, 6, 7], 12.5)
    qtbot.mouseClick(firmata.configure_button, LEFT)
    assert configure[-1] == (200, [4, 5, 6, 7], 12.5)
    qtbot.mouseClick(firmata.version_button, LEFT)
    assert version == [()]
    firmata.set_library_version("2.3")
    assert firmata.version_label.text() == "2.3"


def test_steps_per_mm_edits_emit(firmata: FirmataPanel, qtbot, record) -> None:
    calls = record(firmata.steps_per_mm_changed)
    spin = firmata.steps_per_mm_spin
    spin.lineEdit().selectAll()
    qtbot.keyClicks(spin, "25")
    assert calls == []  # nothing while typing
    qtbot.keyClick(spin, Qt.Key.Key_Return)
    assert calls == [(25.0,)]


def test_rpm_label(firmata: FirmataPanel, record) -> None:
    calls = record(firmata.steps_per_mm_changed)
    firmata.set_settings(200, [8, 9, 10, 11], 100.0)
    assert "—" in firmata.rpm_label.text()
    firmata.set_speed_mm_s(10.0)
    # 10 mm/s x 100 steps/mm x 60 / 200 steps/rev = 300 rpm
    assert firmata.rpm() == pytest.approx(300.0)
    assert "10 mm/s" in firmata.rpm_label.text() and "300 rpm" in firmata.rpm_label.text()
    firmata.steps_per_mm_spin.setValue(50.0)  # the label follows the settings
    assert "150 rpm" in firmata.rpm_label.text()
    firmata.steps_per_rev_spin.setValue(400)
    assert "75 rpm" in firmata.rpm_label.text()
    assert calls == [(50.0,)]


def test_settings_round_trip_emit_nothing(firmata: FirmataPanel, record) -> None:
    signals = (firmata.configure_requested, firmata.version_requested, firmata.steps_per_mm_changed)
    calls = [record(signal) for signal in signals]
    firmata.set_settings(1000, [20, 21], 33.5)
    assert firmata.settings() == {"steps_per_rev": 1000, "pins": [20, 21], "steps_per_mm": 33.5}
    assert firmata.pin_spins[2].isHidden()
    other = FirmataPanel()
    other.set_settings(**firmata.settings())
    assert other.settings() == firmata.settings()
    other.deleteLater()
    assert calls == [[], [], []]
    with pytest.raises(ValueError):
        firmata.set_settings(200, [1, 2, 3], 10.0)
    with pytest.raises(ValueError):
        firmata.set_settings(200, [1, 2], 0.0)


# -- PiFramePanel ----------------------------------------------------------------------------
def test_piframe_names_and_units(piframe: PiFramePanel) -> None:
    assert piframe.objectName() == "piFramePanel"
    assert piframe.dtr_label.objectName() == "piFrameDtr"
    assert piframe.ticks_spin.suffix() == " ticks/mm"
    assert piframe.ticks_spin.minimum() > 0
    assert piframe.range_line.isReadOnly()
    _controls_have_tooltips(piframe)
    assert piframe.dtr_label.toolTip()


def test_piframe_ticks_per_mm(piframe: PiFramePanel, qtbot, record) -> None:
    calls = record(piframe.ticks_per_mm_changed)
    piframe.set_ticks_per_mm(40.0)
    assert piframe.ticks_per_mm() == 40.0
    assert calls == []
    piframe.ticks_spin.lineEdit().selectAll()
    qtbot.keyClicks(piframe.ticks_spin, "12.5")
    qtbot.keyClick(piframe.ticks_spin, Qt.Key.Key_Return)
    assert calls == [(12.5,)]
    piframe.ticks_spin.stepBy(1)
    assert calls[-1] == (13.5,)
    with pytest.raises(ValueError):
        piframe.set_ticks_per_mm(0.0)
    assert piframe.ticks_spin.buttonSymbols() != QAbstractSpinBox.ButtonSymbols.NoButtons


def test_piframe_dtr_and_range(piframe: PiFramePanel) -> None:
    assert piframe.dtr_label.text() == "DTR unknown"
    piframe.set_dtr(True)
    assert piframe.dtr_label.text() == "DTR on" and piframe.dtr() is True
    piframe.set_dtr(False)
    assert piframe.dtr_label.text() == "DTR off"
    piframe.set_dtr(None)
    assert piframe.dtr_label.text() == "DTR unknown" and piframe.dtr() is None
    piframe.set_range_text("X 0 to 120 mm, Y 0 to 80 mm")
    assert piframe.range_line.text() == "X 0 to 120 mm, Y 0 to 80 mm"
    assert piframe.range_text() == piframe.range_line.text()
