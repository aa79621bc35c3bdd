"""ArcEntry and DwellEntry: arc points, preview signal, Run payload, travel-box check; dwell."""

from __future__ import annotations

import itertools
import math

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDoubleSpinBox, QWidget

from widgets.arc_entry import ArcEntry, arc_extent, arc_path
from widgets.dwell_entry import DwellEntry

LEFT = Qt.MouseButton.LeftButton


def _angle(point: tuple[float, float, float], cx: float = 0.0, cy: float = 0.0) -> float:
    return math.degrees(math.atan2(point[1] - cy, point[0] - cx)) % 360.0


def test_object_names_units_tooltips(arc: ArcEntry) -> None:
    assert arc.objectName() == "arcEntry"
    assert arc.cw_radio.objectName() == "arcCw"
    assert arc.ccw_radio.objectName() == "arcCcw"
    assert arc.run_button.objectName() == "runArcButton"
    assert arc.problem_label.objectName() == "arcProblem"
    suffixes = {"cx": " mm", "cy": " mm", "radius": " mm", "start": " °", "end": " °", "z": " mm"}
    for key, suffix in suffixes.items():
        assert arc.fields[key].suffix() == suffix
    for widget in arc.findChildren(QWidget):
        focusable = widget.focusPolicy() != Qt.FocusPolicy.NoFocus
        if widget.isVisibleTo(arc) and focusable and widget.objectName() != "qt_spinbox_lineedit":
            assert widget.toolTip(), widget.objectName()
    assert arc.preview_check.isChecked()
    assert arc.ccw_radio.isChecked()
    assert arc.fields["start"].maximum() == 360.0 and arc.fields["start"].minimum() == 0.0
    assert arc.fields["radius"].minimum() > 0


def test_tab_order_follows_the_fields(arc: ArcEntry) -> None:
    order = [*arc.fields.values(), arc.cw_radio, arc.ccw_radio, arc.preview_check, arc.run_button]
    chain, widget = [], order[0]
    for _ in range(200):
        if widget in order and widget not in chain:
            chain.append(widget)
        widget = widget.nextInFocusChain()
    assert chain == order


def test_ccw_quarter_arc(arc: ArcEntry) -> None:
    arc.set_values(cx=10.0, cy=20.0, radius=5.0, start=0.0, end=90.0, ccw=True, z=0.0)
    points = arc.arc_points()
    assert len(points) >= 2 * 90
    assert points[0] == pytest.approx((15.0, 20.0, 0.0))
    assert points[-1] == pytest.approx((10.0, 25.0, 0.0))
    angles = [_angle(p, 10.0, 20.0) for p in points]
    assert all(b > a for a, b in itertools.pairwise(angles))  # counter-clockwise
    assert all(math.dist(p[:2], (10.0, 20.0)) == pytest.approx(5.0) for p in points)
    assert max(b - a for a, b in itertools.pairwise(angles)) <= 0.5 + 1e-9


def test_cw_goes_the_other_way_round(arc: ArcEntry) -> None:
    arc.set_values(cx=0.0, cy=0.0, radius=10.0, start=0.0, end=90.0, ccw=False)
    points = arc.arc_points()
    assert points[0] == pytest.approx((10.0, 0.0, 0.0))
    assert points[-1] == pytest.approx((0.0, 10.0, 0.0), abs=1e-9)
    assert len(points) >= 2 * 270  # 270° clockwise
    assert points[1][1] < 0  # first step goes below the X axis
    assert min(p[1] for p in points) == pytest.approx(-10.0, abs=1e-3)


def test_equal_angles_make_a_full_circle(arc: ArcEntry) -> None:
    arc.set_values(cx=1.0, cy=2.0, radius=3.0, start=45.0, end=45.0)
    points = arc.arc_points()
    assert len(points) == 720
    assert points[0] == pytest.approx(points[-1])
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    assert min(xs) == pytest.approx(-2.0, abs=1e-3) and max(xs) == pytest.approx(4.0, abs=1e-3)
    assert min(ys) == pytest.approx(-1.0, abs=1e-3) and max(ys) == pytest.approx(5.0, abs=1e-3)
    assert arc_path(0, 0, 1, 0, 360, False, 0, 0)[1][1] < 0  # 0 to 360 CW: full circle too


def test_few_points_for_a_small_arc_and_never_more_than_720() -> None:
    assert len(arc_path(0, 0, 1, 0, 1, True, 0, 0)) >= 3
    assert len(arc_path(0, 0, 1, 10, 10.5, True, 0, 0)) >= 2
    assert len(arc_path(0, 0, 1, 0, 359, True, 0, 0)) <= 720
    assert arc_path(0, 0, 0, 0, 90, True, 0, 0) == []


def test_z_is_interpolated_from_the_start_z(arc: ArcEntry, record) -> None:
    calls = record(arc.preview_changed)
    arc.set_start_z(2.0)
    assert calls  # the start Z changes the preview
    arc.set_values(start=0.0, end=180.0, z=6.0)
    points = arc.arc_points()
    assert points[0][2] == pytest.approx(2.0)
    assert points[-1][2] == pytest.approx(6.0)
    assert points[len(points) // 2][2] == pytest.approx(4.0, abs=0.05)
    zs = [p[2] for p in points]
    assert zs == sorted(zs)
    assert calls[-1][0] == points


def test_preview_emitted_on_edits(arc: ArcEntry, qtbot, record) -> None:
    calls = record(arc.preview_changed)
    field = arc.fields["radius"]
    field.lineEdit().selectAll()
    qtbot.keyClicks(field, "7")
    qtbot.keyClick(field, Qt.Key.Key_Return)
    assert len(calls) == 1
    assert calls[-1][0] == arc.arc_points()
    assert math.dist(calls[-1][0][0][:2], (0.0, 0.0)) == pytest.approx(7.0)
    qtbot.mouseClick(arc.cw_radio, LEFT)
    assert len(calls) == 2 and calls[-1][0][1][1] < 0
    arc.fields["end"].stepUp()
    assert len(calls) == 3
    arc.set_values(cx=1.0, cy=1.0)
    assert len(calls) == 4  # one emission for several values


def test_preview_off_emits_an_empty_list(arc: ArcEntry, qtbot, record) -> None:
    calls = record(arc.preview_changed)
    qtbot.mouseClick(arc.preview_check, LEFT)
    assert not arc.preview_check.isChecked()
    assert calls == [([],)]
    arc.set_values(radius=3.0)
    assert calls[-1] == ([],)
    assert arc.arc_points()  # the arc itself is still known
    qtbot.mouseClick(arc.preview_check, LEFT)
    assert calls[-1][0] == arc.arc_points()


def test_run_emits_the_arc(arc: ArcEntry, qtbot, record) -> None:
    calls = record(arc.arc_requested)
    arc.set_values(cx=1.5, cy=-2.0, radius=4.0, start=30.0, end=300.0, ccw=False, z=1.25)
    qtbot.mouseClick(arc.run_button, LEFT)
    assert calls == [
        (
            {
                "cx": 1.5,
                "cy": -2.0,
                "radius": 4.0,
                "start": 30.0,
                "end": 300.0,
                "ccw": False,
                "z": 1.25,
            },
        )
    ]
    assert arc.values() == calls[0][0]
    assert isinstance(calls[0][0]["ccw"], bool)


def test_set_values_rejects_unknown_keys(arc: ArcEntry) -> None:
    with pytest.raises(TypeError):
        arc.set_values(centre=1.0)


def test_an_arc_leaving_the_box_cannot_run(arc: ArcEntry, qtbot, record) -> None:
    calls = record(arc.arc_requested)
    arc.set_box(((0.0, 100.0), (0.0, 100.0), (0.0, 10.0)))
    arc.set_values(cx=50.0, cy=50.0, radius=20.0, start=0.0, end=0.0)
    assert arc.run_button.isEnabled()
    assert arc.problem() == "" and arc.problem_label.isHidden()
    arc.set_values(cx=90.0)  # the full circle reaches X 110
    assert not arc.run_button.isEnabled()
    assert "X" in arc.problem() and "110" in arc.problem()
    assert not arc.problem_label.isHidden()
    assert arc.problem() in arc.run_button.toolTip()
    qtbot.mouseClick(arc.run_button, LEFT)
    assert calls == []
    # a quarter arc that stays away from X 110 is fine
    arc.set_values(start=90.0, end=270.0, ccw=True)
    assert arc.run_button.isEnabled()
    arc.set_values(z=12.0)  # Z out of the box
    assert not arc.run_button.isEnabled() and "Z" in arc.problem()
    arc.set_values(z=5.0)
    arc.set_start_z(-1.0)  # Z starts below the box
    assert not arc.run_button.isEnabled()
    arc.set_box(None)
    assert arc.run_button.isEnabled() and arc.problem() == ""


def test_arc_extent_uses_the_swept_quadrants() -> None:
    (x0, x1), (y0, y1) = arc_extent(0, 0, 1, 0, 90, True)
    assert (x0, x1, y0, y1) == pytest.approx((0.0, 1.0, 0.0, 1.0))
    (x0, x1), (y0, y1) = arc_extent(0, 0, 1, 0, 90, False)
    assert (x0, x1, y0, y1) == pytest.approx((-1.0, 1.0, -1.0, 1.0))
    assert arc_extent(0, 0, 1, 80, 100, True)[1] == pytest.approx((math.sin(math.radians(80)), 1))


def test_resolution_sets_the_decimals(arc: ArcEntry, record) -> None:
    calls = record(arc.preview_changed)
    arc.set_resolution(0.1)
    for key in ("cx", "cy", "radius", "z"):
        assert arc.fields[key].decimals() == 1
    assert arc.fields["radius"].minimum() == pytest.approx(0.1)
    arc.set_resolution(None)
    assert arc.fields["cx"].decimals() == 3
    assert calls


def test_fit_at_narrow_dock_width(arc: ArcEntry) -> None:
    assert arc.minimumSizeHint().width() <= 1024 // 2
    for field in arc.findChildren(QDoubleSpinBox):
        assert field.keyboardTracking() is False


# -- DwellEntry ------------------------------------------------------------------------------
@pytest.fixture
def dwell(qtbot) -> DwellEntry:
    widget = DwellEntry()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def test_dwell_emits_milliseconds(dwell: DwellEntry, qtbot, record) -> None:
    assert dwell.objectName() == "dwellEntry"
    assert dwell.spin.suffix() == " ms"
    assert (dwell.spin.minimum(), dwell.spin.maximum()) == (0, 65535)
    assert dwell.spin.toolTip() and dwell.dwell_button.toolTip()
    calls = record(dwell.dwell_requested)
    dwell.set_value(250)
    qtbot.mouseClick(dwell.dwell_button, LEFT)
    dwell.spin.lineEdit().selectAll()
    qtbot.keyClicks(dwell.spin, "1500")
    qtbot.keyClick(dwell.spin, Qt.Key.Key_Return)  # Enter sends too
    assert calls == [(250,), (1500,)]
    dwell.set_value(70000)
    assert dwell.value() == 65535
    dwell.setEnabled(False)
    dwell._dwell()
    assert len(calls) == 2
