"""A new connection starts a new segment of the trail; another device starts a new trail.

No line may join the last point before a disconnection to the first after it (the stage was
not watched meanwhile: a line would be motion that never happened), in the buffer's decimated
trail, the 2D views, the time plot or the 3D view.
"""

from __future__ import annotations

import itertools
import os

import numpy as np
import pytest

from app.window.main_window import MainWindow
from widgets._gl_scene import segment_vertices
from widgets.position_buffer import PositionBuffer, TrailLOD

pytestmark = pytest.mark.timeout(60)

NO_DISPLAY = "DISPLAY" not in os.environ and "WAYLAND_DISPLAY" not in os.environ


def _sessions(buffer: PositionBuffer, counts: list[int], seed: int = 1) -> list[float]:
    """Append sessions of `counts` rows, a break before each but the first; times 0.1 s apart.
    Returns the time of each session's first row."""
    rng = np.random.default_rng(seed)
    last = buffer.last()
    starts, t = [], 0.0 if last is None else last[0] + 0.1
    for number, count in enumerate(counts):
        if number:
            buffer.break_trail()
        starts.append(t)
        for _ in range(count):
            x, y, z = rng.normal(0.0, 5.0, 3)
            buffer.append(t, x, y, z)
            t += 0.1
    return starts


def _session_of(t: float, starts: list[float]) -> int:
    return int(np.searchsorted(starts, t + 1e-9, side="right")) - 1


def _joined_across(drawn: np.ndarray, starts: list[float]) -> list[tuple[float, float]]:
    """The (t, t) of every drawn line whose two ends are in different sessions."""
    finite = np.isfinite(drawn[:, 1])
    return [
        (a[0], b[0])
        for (a, fa), (b, fb) in itertools.pairwise(zip(drawn, finite, strict=True))
        if fa and fb and _session_of(a[0], starts) != _session_of(b[0], starts)
    ]


def test_a_break_is_a_nan_row_before_the_next_point_only() -> None:
    buffer = PositionBuffer(capacity=None)
    buffer.break_trail()  # an empty trail: nothing to break
    buffer.append(0.0, 1.0, 2.0, 3.0)
    buffer.break_trail()
    assert len(buffer) == 1 and buffer.last() == (0.0, 1.0, 2.0, 3.0)  # the marker stays
    buffer.append(1.0, 0.0, 0.0, 0.0)
    rows = buffer.view()
    assert len(rows) == 3 and np.isnan(rows[1, 1:]).all() and rows[1, 0] == 1.0
    assert buffer.lod.bounds()[1].tolist() == [1.0, 2.0, 3.0]  # a break has no extent


@pytest.mark.parametrize("counts", [[3000, 5, 3, 2, 4000], [7] * 400, [2] * 3000])
def test_no_decimated_line_joins_two_sessions(counts: list[int]) -> None:
    """Short sessions put several breaks in one block, and merging folds many blocks: every
    break is kept, and the extremes of the whole trail with it."""
    buffer = PositionBuffer(capacity=None)
    lod = TrailLOD(buffer, max_rows=64, recent=32, first_block=4)
    half = len(counts) // 2
    _sessions(buffer, counts[:half])
    lod.update()  # decimated in two goes: blocks made, then merged
    buffer.break_trail()
    _sessions(buffer, counts[half:], seed=2)
    rows = buffer.view()
    starts = [rows[0, 0]] + [rows[i + 1, 0] for i in np.flatnonzero(np.isnan(rows[:, 1]))]
    assert len(starts) == len(counts)
    drawn = lod.update()
    assert lod.decimated_count > 0
    assert _joined_across(drawn, starts) == []
    rows = buffer.view()
    low, high = lod.bounds()
    np.testing.assert_array_equal(low, np.nanmin(rows[:, 1:4], axis=0))
    np.testing.assert_array_equal(high, np.nanmax(rows[:, 1:4], axis=0))


def test_segment_vertices_join_only_neighbours_on_one_side_of_a_break() -> None:
    xyz = np.array([[0, 0, 0], [1, 0, 0], [np.nan] * 3, [5, 5, 5], [6, 5, 5]], dtype=float)
    vertices, same = segment_vertices(xyz, unchanged=4)
    assert vertices.tolist() == [[0, 0, 0], [1, 0, 0], [5, 5, 5], [6, 5, 5]]
    assert same == 2  # the first segment; the one ending at point 4 is new


def test_an_estimate_taken_back_leaves_the_trail_as_it_was() -> None:
    for capacity in (None, 50):
        buffer = PositionBuffer(capacity=capacity)
        buffer.append(0.0, 1.0, 1.0, 0.0)
        buffer.break_trail()
        before = buffer.view().copy()
        buffer.begin_provisional()
        for i in range(10):
            buffer.append(1.0 + i, 1.0 + i, 1.0, 0.0)
        buffer.drop_provisional()
        np.testing.assert_array_equal(buffer.view(), before)
        buffer.append(20.0, 0.0, 0.0, 0.0)  # the break asked for before still applies
        assert np.isnan(buffer.view()[-2, 1])
        buffer.begin_provisional()
        buffer.append(21.0, 2.0, 0.0, 0.0)
        buffer.keep_provisional()
        buffer.drop_provisional()  # nothing provisional any more
        assert buffer.last() == (21.0, 2.0, 0.0, 0.0)


def _lines_of(path) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The straight lines a QPainterPath draws, as ((x0, y0), (x1, y1)); none of no length."""
    lines = []
    for i in range(1, path.elementCount()):
        element, before = path.elementAt(i), path.elementAt(i - 1)
        if element.isLineTo() and (element.x, element.y) != (before.x, before.y):
            lines.append(((before.x, before.y), (element.x, element.y)))
    return lines


def test_the_2d_views_draw_no_line_across_a_break(qtbot) -> None:
    from widgets.position_view_2d import PositionView2D

    buffer = PositionBuffer(capacity=None)
    for i in range(5):
        buffer.append(i * 0.5, 15.74 * i / 4, 0.0, 0.0)
    buffer.break_trail()
    for i in range(5):
        buffer.append(45.0 + i * 0.5, 0.0, i * 1.0, 0.0)
    view = PositionView2D(buffer)
    qtbot.addWidget(view)
    view.resize(800, 400)
    view.show()
    view.refresh()
    xy = _lines_of(view.trail.curve.getPath())
    assert ((15.74, 0.0), (0.0, 0.0)) not in [
        (tuple(round(v, 2) for v in a), tuple(round(v, 2) for v in b)) for a, b in xy
    ]
    assert len(xy) == 8  # four lines each side of the break
    t_lines = _lines_of(view.curves["x"].curve.getPath())
    assert len(t_lines) == 8
    assert all(abs(b[0] - a[0]) < 1.0 for a, b in t_lines)  # no 45 s ramp from 15.74 to 0


@pytest.mark.gl
@pytest.mark.skipif(NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)")
def test_the_3d_view_draws_no_line_across_a_break(qtbot) -> None:
    from widgets.position_view_3d import PositionView3D, make_position_view_3d

    buffer = PositionBuffer(capacity=None)
    starts = _sessions(buffer, [3000, 4, 2500])
    view = make_position_view_3d(buffer)
    qtbot.addWidget(view)
    assert isinstance(view, PositionView3D), getattr(view, "reason", "")
    view.resize(300, 200)
    view.show()
    view.refresh()
    rows = buffer.view()
    session = {tuple(np.float32(r[1:4])): _session_of(r[0], starts) for r in rows}
    for item in (view.trail_history, view.trail):
        pairs = np.asarray(item.pos).reshape(-1, 2, 3)
        assert len(pairs)
        for a, b in pairs:
            assert session[tuple(a)] == session[tuple(b)]
    assert view.trail_history.visible() and view.trail.visible()
    np.testing.assert_allclose(view.trail.pos[-1], rows[-1, 1:4], rtol=1e-6)


def _connect(qtbot, win: MainWindow, url: str, protocol: str, baud: int = 115200) -> None:
    with qtbot.waitSignal(win.settled, timeout=15000):
        win.connect_device(url, protocol, baud)


def test_a_reconnect_breaks_the_trail_and_another_device_clears_it(
    qtbot, window: MainWindow
) -> None:
    from app.window.device import jobs

    _connect(qtbot, window, "sim://coxiris?speed=100", "coxiris")
    finished: list[object] = []
    window.worker.job_finished.connect(lambda job, result: finished.append(job))
    window.submit_job(jobs.MoveToJob(15.74, 0.0, 0.0))
    qtbot.waitUntil(lambda: bool(finished), timeout=10000)  # confirmed by the device
    qtbot.waitUntil(lambda: window.readout.position() == (15.74, 0.0, 0.0), timeout=5000)
    assert window.view2d.target() == (15.74, 0.0, 0.0)
    window.disconnect_device()
    qtbot.waitUntil(lambda: window.connection_bar.state() == "disconnected", timeout=10000)
    assert window.view2d.target() is None
    assert window.view3d.target() is None  # type: ignore[attr-defined]

    _connect(qtbot, window, "sim://coxiris?speed=100", "coxiris")  # a fresh device, at 0
    qtbot.waitUntil(lambda: window.readout.position() == (0.0, 0.0, 0.0), timeout=10000)
    rows = window.buffer.view()
    gap = int(np.flatnonzero(np.isnan(rows[:, 1]))[-1])
    assert rows[gap - 1, 1] == pytest.approx(15.74) and rows[gap + 1, 1] == 0.0
    window.view2d.refresh()
    xy = _lines_of(window.view2d.trail.curve.getPath())
    assert all(not (a[0] > 15.7 and b[0] == 0.0) for a, b in xy)  # nothing back to 0
    assert window.view2d.target() is None

    _connect(qtbot, window, "sim://pi-frame?instant=1", "pi-frame")  # another device
    rows = window.buffer.view()
    assert not np.isnan(rows[:, 1]).any()
    assert np.abs(rows[:, 1:4]).max() < 15.0  # nothing of the COXIRIS trail is left
