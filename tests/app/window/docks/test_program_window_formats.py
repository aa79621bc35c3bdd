"""Issue 23's "done when", from the window: a DXF drawn in a CAD program, an SVG from an
illustration program and G-code from a CAM program (tests/support/program_files.py) each load in the
Program dock, are drawn before anything is sent, and run to their last point on every simulator
(in-process `sim://` devices; the same files through `motionctl run` and `motionsim` in another
process: tests/app/cli/test_cli_program_e2e.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QPushButton

from app.window.main_window import MainWindow
from tests.support.program_files import write_drawings
from widgets import status_line as status

pytestmark = pytest.mark.timeout(120)

TWO_AXES = ("part.nc", "drawing.dxf", "art.svg")
ONE_AXIS = ("line.nc", "line.dxf", "line.svg")
DEVICES = [
    # url, protocol, baud, variant, files, the panel's speed (mm/s) for moves without one
    ("sim://coxiris?instant=1", "coxiris", 115200, None, TWO_AXES, None),
    ("sim://laser-frame?instant=1", "laser-frame", 115200, None, TWO_AXES, None),
    # pi-frame's moves are waited for by estimate; its arcs hold at most 655.35 °/s
    ("sim://pi-frame?instant=1", "pi-frame", 115200, None, TWO_AXES, 25.0),
    # each Visiomex move is a packet and 1 s of silence: the short drawings along X
    ("sim://visiomex?instant=1", "visiomex", 9600, "seed", ("part.nc", *ONE_AXIS[1:]), None),
    ("sim://firmata?reset_delay=0.2&instant=1", "firmata", 57600, None, ONE_AXIS, None),
]


@pytest.mark.parametrize(
    ("url", "protocol", "baud", "variant", "files", "speed"),
    DEVICES,
    ids=[d[1] for d in DEVICES],
)
def test_each_kind_of_file_runs_to_its_last_point_from_the_window(
    qtbot,
    window: MainWindow,
    tmp_path: Path,
    url: str,
    protocol: str,
    baud: int,
    variant: str | None,
    files: tuple[str, ...],
    speed: float | None,
) -> None:
    drawings = write_drawings(tmp_path)
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device(url, protocol, baud, variant)
    if protocol == "firmata":  # its stepper configured first, as an operator does
        firmata = window.devices.firmata
        qtbot.mouseClick(
            firmata.findChild(QPushButton, "firmataConfigure"), Qt.MouseButton.LeftButton
        )
        version = firmata.findChild(QLabel, "firmataVersionLabel")
        qtbot.waitUntil(lambda: version.text() == "5", timeout=5000)
    panel, dock = window.devices.program, window.devices.programs
    if window.readout.status() == "uncounted":  # counting starts where the stage stands
        # Where the stage is cannot be asked: a program is refused until counting starts.
        panel._choose_path = lambda: str(drawings[files[0]][0])  # type: ignore[method-assign]
        qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: not dock.reading, timeout=10000)
        assert not panel.run_button.isEnabled()  # off, saying why (issue 28)
        assert "the position is unknown" in panel.run_button.toolTip()
        dock.run()  # past the button, as a shortcut could: the one guard refuses it too
        assert "the position is unknown" in window.status_line.message()
        assert not panel.stop_button.isEnabled()
        window.coordinates.confirm = lambda question: True
        qtbot.waitUntil(window.coordinates.set_home_button.isEnabled, timeout=5000)
        qtbot.mouseClick(window.coordinates.set_home_button, Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: window.readout.status() != "uncounted", timeout=5000)
    if speed is not None:
        window.speed.spin.setValue(speed)
        qtbot.mouseClick(window.speed.apply_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.status_line.state() == status.IDLE, timeout=10000)
    if protocol == "visiomex":
        panel.tolerance.setValue(1.0)
    for name in files:
        path, (x, y) = drawings[name]
        panel._choose_path = lambda p=path: str(p)  # type: ignore[method-assign]
        qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: not dock.reading, timeout=10000)
        if name.endswith(".dxf"):  # the CUT layer only, chosen in the dock's layer list
            assert sorted(panel.checked_layers()) == ["CUT", "ENGRAVE"]
            [engrave] = panel.layer_model.findItems("ENGRAVE")
            engrave.setCheckState(Qt.CheckState.Unchecked)  # what a click on its box does
            qtbot.waitUntil(lambda: dock.layers == ["CUT"] and not dock.reading, timeout=10000)
        drawn = window.view2d.program()
        assert len(drawn) > 2 and tuple(drawn[-1][:2]) == pytest.approx((x, y)), name
        assert panel.run_button.isEnabled(), (name, panel.run_button.toolTip())
        qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: panel.stop_button.isEnabled(), timeout=5000)
        qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=60000)
        assert "done" in window.status_line.message(), (name, window.status_line.message())
        position = window.readout.position()
        assert position is not None
        if protocol == "visiomex":  # its firmware's Y loop makes no step at power-on (issue 28)
            device = window.worker.session.simulator  # type: ignore[union-attr]
            assert position[:2] == pytest.approx(device.position(), abs=0.006), name
            assert position[0] == pytest.approx(x, abs=0.026), name
            continue
        assert position[:2] == pytest.approx((x, y), abs=0.011), name
