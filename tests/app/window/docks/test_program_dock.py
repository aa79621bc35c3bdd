"""The Program dock on every device: a file read off the GUI thread, drawn in both views with its
figures and lines, checked against the travel box, run line by line, stopped; a bad file refused."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget

from app.window.docks.program_dock import ProgramDock
from app.window.main_window import MainWindow
from drivers.sim.piframe_device import CIRCULAR, DWELL
from drivers.toolpath.geometry import flatten
from drivers.toolpath.loader import load_toolpath
from tests.support.relay import wait_in_gui
from widgets.program_panel import ERROR_STYLE, ProgramPanel

pytestmark = pytest.mark.timeout(60)

# A square with a rounded corner: a rapid, feeds, a counter-clockwise arc (I/J), a dwell, an M-code.
GCODE = """\
(a rounded square)
G21 G90
M3 S1000
G0 X1 Y1
G1 X6 Y1 F600
G3 X8 Y3 I0 J2
G1 X8 Y8
G4 P0.05
G1 X1 Y8
G1 X1 Y1
"""
LAST = (1.0, 1.0, 0.0)


def _connect(qtbot, win: MainWindow, url: str, protocol: str) -> None:
    with qtbot.waitSignal(win.settled, timeout=10000):
        win.connect_device(url, protocol, 115200)


def _parts(win: MainWindow) -> tuple[ProgramPanel, ProgramDock]:
    return win.devices.program, win.devices.programs


def _load(qtbot, win: MainWindow, path: Path) -> None:
    panel, dock = _parts(win)
    panel._choose_path = lambda: str(path)  # type: ignore[method-assign]
    qtbot.mouseClick(panel.load_button, Qt.MouseButton.LeftButton)
    assert dock.reading  # read in the background: the click returns at once
    qtbot.waitUntil(lambda: not dock.reading, timeout=10000)


def _gcode(tmp_path: Path, text: str = GCODE, name: str = "square.nc") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def _rows(panel: ProgramPanel) -> list[str]:
    model = panel.line_model
    return [model.index(row, 0).data() for row in range(model.rowCount())]


def _run_to_end(qtbot, win: MainWindow) -> None:
    panel, _ = _parts(win)
    assert panel.run_button.isEnabled(), panel.run_button.toolTip()
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: panel.stop_button.isEnabled(), timeout=5000)
    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=30000)


def test_a_csv_program_is_drawn_summed_up_and_listed(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window, "sim://coxiris?instant=1", "coxiris")
    dock = window.findChild(QDockWidget, "programPanelDock")
    assert dock is not None and dock.isVisible()  # not only on laser-frame now
    panel, _ = _parts(window)
    path = tmp_path / "zigzag.csv"
    points = [(2.0, 0.0), (2.0, 3.0), (5.0, 3.0), (5.0, 7.0)]
    path.write_text("x,y,z,speed\n" + "".join(f"{x},{y},0,20\n" for x, y in points))
    _load(qtbot, window, path)
    assert "zigzag.csv (4 points)" in panel.file_label.text()
    assert _rows(panel) == [
        "point 1  2, 0, 0 @ 20 mm/s",
        "point 2  2, 3, 0 @ 20 mm/s",
        "point 3  5, 3, 0 @ 20 mm/s",
        "point 4  5, 7, 0 @ 20 mm/s",
    ]
    summary = panel.summary.text()
    assert "length 12.0 mm (travel moves 0.0 mm), 4 segments" in summary  # from (0, 0, 0)
    assert "box X 0 to 5, Y 0 to 7, Z 0 to 0 mm" in summary
    assert "0:00:01" in summary  # 12 mm at 20 mm/s
    expected = np.array([(0.0, 0.0, 0.0)] + [(x, y, 0.0) for x, y in points])
    for view in (window.view2d, window.view3d):
        assert np.allclose(view.program(), expected)  # drawn before anything is sent
    assert panel.run_button.isEnabled() and panel.save_button.isEnabled()
    assert window.readout.position() == (0.0, 0.0, 0.0)  # nothing was sent


def test_a_gcode_program_shows_its_figures_notices_and_lines(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window, "sim://coxiris?instant=1", "coxiris")
    panel, dock = _parts(window)
    path = _gcode(tmp_path)
    _load(qtbot, window, path)
    rows = _rows(panel)
    assert len(rows) == len(GCODE.splitlines())
    assert rows[5] == "line 6  G3 X8 Y3 I0 J2"
    assert "square.nc (10 lines)" in panel.file_label.text()
    assert panel.notices.isVisibleTo(panel) and "M3" in panel.notices.text()
    assert "travel moves 1.4 mm" in panel.summary.text()  # the G0 from (0, 0) to (1, 1)
    assert "box X 0 to 8, Y 0 to 8" in panel.summary.text()
    assert not panel.save_button.isEnabled()
    assert "CSV, JSON" in panel.save_button.toolTip()
    drawn = window.view2d.program()
    fine = flatten(load_toolpath(path), 0.01).points
    assert np.allclose(drawn, fine) and len(drawn) > 12  # the arc cut into chords
    # A coarser chord tolerance: the path is made again, with fewer chords.
    panel.tolerance.setValue(0.5)
    qtbot.waitUntil(lambda: len(window.view2d.program()) < len(fine), timeout=5000)
    qtbot.waitUntil(lambda: not dock.reading, timeout=5000)
    assert np.allclose(window.view3d.program(), flatten(load_toolpath(path), 0.5).points)
    assert dock.flat is not None and len(dock.flat) == len(window.view2d.program())


def test_a_program_outside_the_box_is_refused_naming_its_line(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window, "sim://coxiris?instant=1", "coxiris")
    panel, dock = _parts(window)
    window.set_travel_limits(((0.0, 7.0), (0.0, 20.0), (-1.0, 1.0)), False)
    _load(qtbot, window, _gcode(tmp_path))
    refusal = panel.figures.text()
    assert "square.nc line 6" in refusal and "(8, 3, 0)" in refusal  # the arc's widest point
    assert panel.figures.styleSheet() == ERROR_STYLE
    assert not panel.run_button.isEnabled()
    assert "square.nc line 6" in panel.run_button.toolTip()
    assert "square.nc line 6" in window.status_line.message()
    assert len(window.view2d.program()) > 0  # still drawn, to see where it goes out
    # Wider limits: checked again, and it may run.
    window.set_travel_limits(((0.0, 10.0), (0.0, 20.0), (-1.0, 1.0)), False)
    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=5000)
    assert panel.refused() == "" and "line 6" not in panel.run_button.toolTip()
    window.set_travel_limits(((0.0, 10.0), (0.0, 5.0), (-1.0, 1.0)), False)
    qtbot.waitUntil(lambda: not panel.run_button.isEnabled(), timeout=5000)
    assert "line 7" in panel.refused() and "(8, 8, 0)" in panel.refused()
    assert dock.toolpath is not None


@pytest.mark.parametrize(
    ("url", "protocol"),
    [("sim://coxiris?instant=1", "coxiris"), ("sim://pi-frame?instant=1", "pi-frame")],
)
def test_a_program_runs_to_its_last_point_with_its_last_line_highlighted(
    qtbot, window: MainWindow, tmp_path: Path, url: str, protocol: str
) -> None:
    _connect(qtbot, window, url, protocol)
    if protocol == "pi-frame":  # absolute targets: its program needs a known place first
        with wait_in_gui(qtbot, window.worker.job_finished, timeout=5000):
            window.coordinates.go_requested.emit("absolute", (0.0, 0.0, 0.0))
    panel, dock = _parts(window)
    _load(qtbot, window, _gcode(tmp_path))
    seen_lines: list[int | None] = []
    window.worker.stream_progress.connect(lambda state: seen_lines.append(state.source))
    _run_to_end(qtbot, window)
    assert window.readout.position() == pytest.approx(LAST, abs=0.01)
    assert panel.current_line() == len(GCODE.splitlines()) - 1  # the last line, highlighted
    selected = panel.lines.selectionModel().selectedRows()
    assert [index.row() for index in selected] == [panel.current_line()]
    assert panel.progress.value() == panel.progress.maximum()
    assert "done" in window.status_line.message()
    assert seen_lines and seen_lines[-1] == len(GCODE.splitlines()) - 1
    assert len(window.view2d.program()) == len(dock.flat)  # type: ignore[arg-type]
    if protocol == "pi-frame":  # the arc went as the device's own arc, the dwell too
        device = window.worker.session.simulator  # type: ignore[union-attr]
        assert device.position() == pytest.approx((100.0, 100.0, 0.0))  # ticks: 100 a mm
        actions = [action for action, _ in device.history]
        assert actions.count(CIRCULAR) == 1 and actions.count(DWELL) == 1


def test_stop_ends_a_program_midway_on_coxiris(qtbot, window: MainWindow, tmp_path: Path) -> None:
    _connect(qtbot, window, "sim://coxiris?speed=20", "coxiris")  # 4 mm a move: 0.2 s each
    panel, dock = _parts(window)
    lines = ["G21 G90 F1200"] + [f"G1 X{4 * (i % 2)} Y{i}" for i in range(1, 41)]
    _load(qtbot, window, _gcode(tmp_path, "\n".join(lines) + "\n", "zigzag.gcode"))
    qtbot.mouseClick(panel.run_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: (panel.current_line() or 0) >= 3, timeout=10000)
    shown = window.view2d.program()
    assert 0 < len(shown) < len(dock.flat)  # type: ignore[arg-type]  # only what is left
    qtbot.mouseClick(panel.stop_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: panel.run_button.isEnabled(), timeout=10000)
    assert "stopped" in window.status_line.message()
    stopped_at = panel.current_line()
    assert stopped_at is not None and stopped_at < len(lines) - 1
    position = window.readout.position()
    assert position is not None and position[1] < 40 - 5


def test_a_file_with_an_error_is_refused_and_nothing_is_loaded(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    _connect(qtbot, window, "sim://coxiris?instant=1", "coxiris")
    panel, dock = _parts(window)
    _load(qtbot, window, _gcode(tmp_path))
    assert panel.run_button.isEnabled()
    bad = _gcode(tmp_path, "G21\nG1 X1 Y1 F100\nG1 X2 Q7\n", "bad.nc")
    _load(qtbot, window, bad)
    text = panel.figures.text()
    assert "bad.nc line 3" in text and "Q" in text
    assert panel.figures.styleSheet() == ERROR_STYLE
    assert "bad.nc line 3" in window.status_line.message()
    assert dock.toolpath is None and panel.line_model.rowCount() == 0
    assert len(window.view2d.program()) == 0 and len(window.view3d.program()) == 0
    assert not panel.run_button.isEnabled() and "no program" in panel.file_label.text()


def test_dxf_layers_are_chosen_in_the_dock(qtbot, window: MainWindow, tmp_path: Path) -> None:
    import ezdxf

    _connect(qtbot, window, "sim://coxiris?instant=1", "coxiris")
    panel, dock = _parts(window)
    drawing = ezdxf.new()
    drawing.header["$INSUNITS"] = 4  # mm
    space = drawing.modelspace()
    space.add_line((0, 0), (10, 0), dxfattribs={"layer": "cut"})
    space.add_circle((5, 5), 2, dxfattribs={"layer": "cut"})
    space.add_line((20, 20), (30, 20), dxfattribs={"layer": "mark"})
    path = tmp_path / "plate.dxf"
    drawing.saveas(path)
    _load(qtbot, window, path)
    assert panel.layers.isVisibleTo(panel)
    assert sorted(panel.checked_layers()) == ["cut", "mark"]
    assert window.view2d.program()[:, 0].max() == pytest.approx(30.0)
    assert not panel.save_button.isEnabled()

    mark = panel.layer_model.findItems("mark")[0]
    mark.setCheckState(Qt.CheckState.Unchecked)  # the file is read again with "cut" only
    qtbot.waitUntil(lambda: dock.layers == ["cut"] and not dock.reading, timeout=5000)
    assert window.view2d.program()[:, 0].max() == pytest.approx(10.0)
    assert panel.run_button.isEnabled()

    cut = panel.layer_model.findItems("cut")[0]
    cut.setCheckState(Qt.CheckState.Unchecked)  # nothing left to run: refused, list kept
    qtbot.waitUntil(lambda: dock.layers == [] and not dock.reading, timeout=5000)
    assert dock.toolpath is None and not panel.run_button.isEnabled()
    assert panel.figures.styleSheet() == ERROR_STYLE and "plate.dxf" in panel.figures.text()
    assert panel.layers.isVisibleTo(panel) and panel.layer_model.rowCount() == 2
    cut = panel.layer_model.findItems("cut")[0]
    cut.setCheckState(Qt.CheckState.Checked)
    qtbot.waitUntil(lambda: dock.toolpath is not None and not dock.reading, timeout=5000)
    assert panel.run_button.isEnabled() and dock.layers == ["cut"]


def test_a_program_moving_an_axis_the_device_lacks_is_refused_when_read(
    qtbot, window: MainWindow, tmp_path: Path
) -> None:
    with qtbot.waitSignal(window.settled, timeout=10000):
        window.connect_device("sim://firmata?reset_delay=0.2&instant=1", "firmata", 57600)
    panel, _ = _parts(window)
    _load(qtbot, window, _gcode(tmp_path))  # a square in X and Y: Firmata turns X only
    assert "square.nc line 4: the program moves Y to 1 mm" in panel.refused()
    assert "it has X" in panel.refused()
    assert not panel.run_button.isEnabled()
    assert len(window.view2d.program()) > 2  # drawn all the same, to see why
