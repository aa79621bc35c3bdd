"""The whole trail is kept, and drawn decimated: newest point, ends and extremes always there."""

from __future__ import annotations

import itertools
import os

import numpy as np
import pytest

from widgets.position_buffer import RECENT_ROWS, PositionBuffer, TrailLOD

pytestmark = pytest.mark.timeout(60)

NO_DISPLAY = "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen"
needs_display = pytest.mark.skipif(
    NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)"
)


def _walk(points: int, seed: int = 0) -> np.ndarray:
    """(points, 4) rows: time in 0.1 s steps, a 3D random walk in mm."""
    rng = np.random.default_rng(seed)
    rows = np.cumsum(rng.normal(0.0, 0.1, (points, 4)), axis=0)
    rows[:, 0] = np.arange(points) * 0.1
    return rows


def _is_subsequence(drawn: np.ndarray, rows: np.ndarray) -> bool:
    """Whether every drawn row is a row of `rows`, in the same order."""
    index = {tuple(row): i for i, row in enumerate(rows)}
    positions = [index.get(tuple(row), -1) for row in drawn]
    return min(positions) >= 0 and all(b > a for a, b in itertools.pairwise(positions))


def _check_extremes(lod: TrailLOD, rows: np.ndarray) -> None:
    """The drawn rows keep the first, the newest and each axis' lowest and highest row."""
    drawn = lod.update()
    np.testing.assert_array_equal(drawn[0], rows[0])
    np.testing.assert_array_equal(drawn[-1], rows[-1])
    for axis in (1, 2, 3):
        for pick in (np.argmin, np.argmax):
            extreme = rows[pick(rows[:, axis])]
            assert (drawn == extreme).all(axis=1).any(), (axis, pick.__name__)
    low, high = lod.bounds()
    np.testing.assert_array_equal(low, rows[:, 1:4].min(axis=0))
    np.testing.assert_array_equal(high, rows[:, 1:4].max(axis=0))


def test_the_trail_keeps_every_point() -> None:
    buffer = PositionBuffer(capacity=None)
    assert buffer.capacity is None
    rows = _walk(100_000)
    for row in rows[:5000]:  # one at a time, as positions come
        buffer.append(*row)
    buffer.extend(rows[5000:])
    assert len(buffer) == 100_000
    assert buffer.row(0) == tuple(rows[0])  # the first point is still there
    assert buffer.last() == tuple(rows[-1])
    np.testing.assert_array_equal(buffer.view(), rows)
    buffer.append(1e4, 1.0, 2.0, 3.0)
    assert len(buffer) == 100_001 and buffer.row(0) == tuple(rows[0])


def test_shift_and_clear_of_an_unbounded_buffer() -> None:
    buffer = PositionBuffer(capacity=None)
    buffer.extend(_walk(3000))
    before = buffer.view().copy()
    generation = buffer.generation
    buffer.shift(1.0, -2.0, 0.5)
    assert buffer.generation != generation
    shifted = before + np.array([0.0, 1.0, -2.0, 0.5])
    np.testing.assert_array_equal(buffer.view(), shifted)
    buffer.clear(keep_last=True)
    assert len(buffer) == 1 and buffer.last() == pytest.approx(tuple(shifted[-1]))


def test_decimation_keeps_the_newest_point_the_ends_and_the_extremes() -> None:
    rows = _walk(200_000, seed=3)
    buffer = PositionBuffer(capacity=None)
    lod = buffer.lod
    for chunk in np.array_split(rows, 150):  # as frames come: a few hundred points each
        buffer.extend(chunk)
        seen = len(buffer)
        _check_extremes(lod, rows[:seen])
    drawn = lod.update()
    assert len(drawn) <= lod.max_rows + lod.recent + lod.block_rows
    assert len(drawn) < len(rows) / 20
    np.testing.assert_array_equal(drawn[-RECENT_ROWS:], rows[-RECENT_ROWS:])  # recent: all
    assert _is_subsequence(drawn, rows)


def test_a_long_trail_at_once_is_decimated_as_well() -> None:
    rows = _walk(300_000, seed=5)
    buffer = PositionBuffer(capacity=None)
    buffer.extend(rows)
    _check_extremes(buffer.lod, rows)
    assert len(buffer.lod.update()) <= buffer.lod.max_rows + buffer.lod.recent + buffer.lod.block


def test_a_constant_axis_and_nan_keep_the_decimation_bounded() -> None:
    rows = _walk(60_000, seed=7)
    rows[:, 3] = np.nan  # a device without Z
    buffer = PositionBuffer(capacity=None)
    for chunk in np.array_split(rows, 40):
        buffer.extend(chunk)
        buffer.lod.update()
    drawn = buffer.lod.update()
    assert len(drawn) <= buffer.lod.max_rows + buffer.lod.recent + buffer.lod.block
    np.testing.assert_array_equal(drawn[-1, :3], rows[-1, :3])
    low, high = buffer.lod.bounds()
    assert low[0] == rows[:, 1].min() and high[1] == rows[:, 2].max()


def test_unchanged_prefix_tells_what_the_gpu_already_has() -> None:
    buffer = PositionBuffer(capacity=None)
    lod = TrailLOD(buffer, max_rows=64, recent=32, first_block=4)
    rows = _walk(5000, seed=11)
    previous, token = np.zeros((0, 4)), None
    for start in range(0, len(rows), 37):
        buffer.extend(rows[start : start + 37])
        drawn = lod.update().copy()
        same = lod.unchanged_prefix(token)
        np.testing.assert_array_equal(drawn[:same], previous[:same])
        previous, token = drawn, lod.token()
    assert lod.unchanged_prefix(token) == len(previous)
    buffer.shift(1.0, 0.0, 0.0)  # every row changed
    lod.update()
    assert lod.unchanged_prefix(token) == 0


def test_rows_since_gives_every_row_from_there() -> None:
    rows = _walk(50_000, seed=13)
    buffer = PositionBuffer(capacity=None)
    buffer.extend(rows)
    lod = buffer.lod
    since = lod.rows_since(40_000)
    np.testing.assert_array_equal(since[-10_000:], rows[40_000:])
    assert _is_subsequence(since, rows)
    assert len(lod.rows_since(len(rows))) == len(lod.update())


def test_a_ring_buffer_is_decimated_over_what_it_keeps() -> None:
    rows = _walk(30_000, seed=17)
    buffer = PositionBuffer(capacity=10_000)
    for row in rows:
        buffer.append(*row)
    _check_extremes(buffer.lod, rows[-10_000:])


def test_the_2d_view_draws_a_long_trail_whole(qtbot) -> None:
    from widgets.position_view_2d import PositionView2D

    rows = _walk(100_000, seed=19)
    buffer = PositionBuffer(capacity=None)
    buffer.extend(rows)
    view = PositionView2D(buffer)
    qtbot.addWidget(view)
    view.resize(900, 400)
    view.show()
    qtbot.waitExposed(view)
    view.refresh()
    x, y = view.trail.getData()
    assert len(x) < 20_000
    assert (x[0], y[0]) == (rows[0, 1], rows[0, 2]) and (x[-1], y[-1]) == (rows[-1, 1], rows[-1, 2])
    assert x.min() == rows[:, 1].min() and y.max() == rows[:, 2].max()
    (x0, x1), (y0, y1) = view.xy_plot.getPlotItem().viewRange()
    assert x0 < rows[:, 1].min() and x1 > rows[:, 1].max()  # the whole trail is in view
    assert y0 < rows[:, 2].min() and y1 > rows[:, 2].max()
    _, values = view.curves["x"].getOriginalDataset()
    recent = rows[rows[:, 0] >= rows[-1, 0] - 60.0]  # the last minute: every point
    np.testing.assert_array_equal(values[-len(recent) :], recent[:, 1])
    assert not view.grab().isNull()


@pytest.fixture
def gl_pair(qtbot):
    """A real 3D view on a long trail (the view the window shows), and its buffer."""
    from widgets.position_view_3d import PositionView3D, make_position_view_3d

    buffer = PositionBuffer(capacity=None)
    buffer.extend(_walk(200_000, seed=23))
    view = make_position_view_3d(buffer)
    qtbot.addWidget(view)
    assert isinstance(view, PositionView3D), getattr(view, "reason", "")
    view.resize(400, 300)
    view.show()
    qtbot.waitExposed(view)
    return view, buffer


@pytest.mark.gl
@needs_display
def test_the_3d_view_renders_a_long_trail(gl_pair) -> None:
    view, buffer = gl_pair
    view.refresh()
    assert view.trail.visible() and view.trail_history.visible()
    assert len(view.trail.pos) + len(view.trail_history.pos) < 20_000
    np.testing.assert_allclose(view.trail.pos[-1], buffer.last()[1:], rtol=1e-6)
    np.testing.assert_allclose(view.trail_history.pos[0], buffer.row(0)[1:], rtol=1e-6)
    image = view.grabFramebuffer()
    assert not image.isNull()
    colours = {image.pixel(x, y) for x in range(0, 400, 4) for y in range(0, 300, 4)}
    assert len(colours) > 3


@pytest.mark.gl
@needs_display
def test_appending_uploads_only_the_new_vertices_and_draws_as_a_fresh_view(gl_pair, qtbot) -> None:
    from widgets.position_view_3d import make_position_view_3d

    view, buffer = gl_pair
    view.set_view_preset("top")
    view.refresh()
    view.grabFramebuffer()
    rows = _walk(60_000, seed=29)
    low, high = buffer.lod.bounds()
    rows[:, 1:4] = np.clip(rows[:, 1:4], low, high)  # inside the trail's box: the same camera
    rows[:, 0] += buffer.last()[0] + 0.1
    for chunk in np.array_split(rows, 120):  # blocks finish and merge on the way
        buffer.extend(chunk)
        view.refresh()
        view.grabFramebuffer()
    assert view.trail._upload_from == len(view.trail.pos)  # everything on the GPU
    fresh = make_position_view_3d(buffer)
    qtbot.addWidget(fresh)
    fresh.resize(400, 300)
    fresh.show()
    qtbot.waitExposed(fresh)
    fresh.set_view_preset("top")
    fresh.refresh()
    assert fresh.grabFramebuffer() == view.grabFramebuffer()  # same pixels: no stale vertex
