"""A whole program drawn in the 2D and 3D views before it runs: cut segments solid, travel
(rapid) moves dashed, what is done left out, the views widened to hold it, the theme followed
(the 3D parts need Xvfb with OpenGL)."""

from __future__ import annotations

import os
import time

import numpy as np
import pytest

from app.window.theme import DARK_PLOT_COLORS, LIGHT_PLOT_COLORS, apply_gl_colors, apply_plot_colors
from widgets import position_view_3d
from widgets._program_path import MAX_GL_SEGMENTS, ProgramPath, program_arrays
from widgets.position_buffer import PositionBuffer
from widgets.position_view_2d import PositionView2D
from widgets.position_view_3d import PositionView3DPlaceholder, make_position_view_3d

NO_DISPLAY = "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen"
needs_display = pytest.mark.skipif(
    NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)"
)

# start, cut, cut, travel, cut, travel, travel, cut: row i ends segment i
POINTS = np.array(
    [
        (0, 0, 0),
        (10, 0, 0),
        (10, 10, 0),
        (40, 50, 5),
        (45, 50, 5),
        (-20, -30, 0),
        (-20, 60, 0),
        (0, 60, 1),
    ],
    dtype=float,
)
RAPID = np.array([False, False, False, True, False, True, True, False])


def big_program(segments: int = 100_000, share: float = 0.2) -> tuple[np.ndarray, np.ndarray]:
    """A dense spiral of `segments` short chords, a `share` of them travel moves, and some
    long travel moves across it."""
    rng = np.random.default_rng(7)
    t = np.linspace(0.0, 40 * np.pi, segments + 1)
    points = np.column_stack(
        (100 + 80 * np.cos(t), 50 + 40 * np.sin(t), np.linspace(0.0, 5.0, segments + 1))
    )
    rapid = rng.random(segments + 1) < share
    rapid[0] = False
    jumps = rng.choice(segments, 50, replace=False) + 1
    points[jumps, :2] = rng.uniform((20, 10), (180, 90), (50, 2))
    rapid[jumps] = True
    return points, rapid


def segments(x: np.ndarray, y: np.ndarray) -> set[tuple[float, float, float, float]]:
    """(start, end) pairs of "pairs" data as a set of (x0, y0, x1, y1)."""
    assert len(x) % 2 == 0
    return {(x[i], y[i], x[i + 1], y[i + 1]) for i in range(0, len(x), 2)}


def expected(from_row: int, travel: bool) -> set[tuple[float, float, float, float]]:
    """The XY segments of POINTS from `from_row` on that are (not) travel moves."""
    return {
        (*POINTS[j, :2], *POINTS[j + 1, :2])
        for j in range(from_row, len(POINTS) - 1)
        if RAPID[j + 1] == travel
    }


@pytest.fixture
def buffer() -> PositionBuffer:
    buffer = PositionBuffer(capacity=50)
    for i in range(5):
        buffer.append(float(i), float(i), 2.0 * i, 0.0)
    return buffer


@pytest.fixture
def view2d(qtbot, buffer) -> PositionView2D:
    view = PositionView2D(buffer)
    qtbot.addWidget(view)
    view.resize(900, 400)
    view.show()
    qtbot.waitExposed(view)
    return view


@pytest.fixture
def gl_view(qtbot, buffer):
    widget = make_position_view_3d(buffer)
    qtbot.addWidget(widget)
    assert isinstance(widget, position_view_3d.PositionView3D), getattr(widget, "reason", "")
    widget.resize(320, 240)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


def test_program_arrays_check_their_input() -> None:
    points, rapid = program_arrays([(0, 0, np.nan), (1, 2, 3)], [True, True])
    assert points.tolist() == [[0, 0, 0], [1, 2, 3]]
    assert rapid.tolist() == [False, True]  # row 0 ends no segment
    assert program_arrays(None)[0].shape == (0, 3)
    assert not program_arrays(POINTS)[1].any()
    with pytest.raises(ValueError):
        program_arrays([(0, 0), (1, 1)])
    with pytest.raises(ValueError):
        program_arrays([(0, np.nan, 0), (1, 1, 1)])
    with pytest.raises(ValueError):
        program_arrays(POINTS, RAPID[:3])


def test_3d_vertices_hold_what_is_left_as_a_prefix() -> None:
    path = ProgramPath(*program_arrays(POINTS, RAPID))
    for row in range(len(POINTS)):
        cut = path.cut_vertices(row).reshape(-1, 2, 3)
        left = {(tuple(a), tuple(b)) for a, b in cut.astype(float)}
        want = {
            (tuple(POINTS[j]), tuple(POINTS[j + 1]))
            for j in range(row, len(POINTS) - 1)
            if not RAPID[j + 1]
        }
        assert left == want, row  # no chords to simplify here: exact
        assert np.shares_memory(path.cut_vertices(row), path.cut_vertices(0)) or not len(cut)
        dashes = path.dash_vertices(row).reshape(-1, 2, 3)
        # each dash lies on a travel move still to come, and each such move has dashes
        moves = [j for j in range(row, len(POINTS) - 1) if RAPID[j + 1]]
        owners = set()
        for a, b in dashes.astype(float):
            for j in moves:
                p, q = POINTS[j], POINTS[j + 1]
                ta = np.dot(a - p, q - p) / np.dot(q - p, q - p)
                tb = np.dot(b - p, q - p) / np.dot(q - p, q - p)
                on = np.allclose(p + ta * (q - p), a, atol=1e-3) and np.allclose(
                    p + tb * (q - p), b, atol=1e-3
                )
                if on and -1e-6 <= ta < tb <= 1 + 1e-6:
                    owners.add(j)
                    break
            else:
                pytest.fail(f"a dash {a}-{b} off every travel move from row {row}")
        assert owners == set(moves), row
    long_move = ProgramPath(*program_arrays(POINTS[:4], RAPID[:4])).dash_vertices(0)
    assert len(long_move) > 20  # a move across the whole extent: many dashes, with gaps
    gaps = np.linalg.norm(long_move[2::2] - long_move[1:-1:2], axis=1)
    assert (gaps > 0.1).all()


def test_2d_draws_cut_and_travel_apart(view2d) -> None:
    view2d.set_program(POINTS, RAPID)
    cut, rapid = view2d.program_cut, view2d.program_rapid
    assert cut.isVisible() and rapid.isVisible()
    assert segments(*cut.getData()) == expected(0, travel=False)
    assert segments(*rapid.getData()) == expected(0, travel=True)
    assert rapid.opts["pen"].style() == position_view_3d.Qt.PenStyle.DashLine
    assert cut.opts["pen"].style() == position_view_3d.Qt.PenStyle.SolidLine
    assert np.array_equal(view2d.program(), POINTS)
    view2d.set_preview([(0, 0, 0), (1, 1, 0)])  # the preview is independent of it
    assert view2d.preview_curve.isVisible() and cut.isVisible()
    assert view2d.preview() == [(0.0, 0.0, 0.0), (1.0, 1.0, 0.0)]


def test_2d_done_leaves_the_rows_from_there_on(view2d) -> None:
    view2d.set_program(POINTS, RAPID)
    for row in (1, 3, 4, 6, 5, 0):
        view2d.set_program_done(row)
        assert np.array_equal(view2d.program(), POINTS[row:]), row
        assert segments(*view2d.program_cut.getData()) == expected(row, travel=False)
        assert segments(*view2d.program_rapid.getData()) == expected(row, travel=True)
    view2d.set_program_done(len(POINTS) + 10)  # beyond the end: nothing left to draw
    assert len(view2d.program()) == 1
    assert not view2d.program_cut.isVisible() and not view2d.program_rapid.isVisible()


def test_2d_none_or_one_point_removes_it(view2d) -> None:
    view2d.set_program(POINTS, RAPID)
    view2d.set_program(None)
    assert view2d.program().shape == (0, 3)
    assert not view2d.program_cut.isVisible() and not view2d.program_rapid.isVisible()
    view2d.set_program(POINTS[:1])
    assert view2d.program().shape == (0, 3)
    view2d.set_program_done(3)  # no program: nothing happens
    assert view2d.program().shape == (0, 3)


def test_2d_view_widens_to_hold_the_program(view2d) -> None:
    (x0, x1), (y0, y1) = view2d.xy_plot.getPlotItem().viewRange()
    assert x0 > -20 or y1 < 60  # the program is not in view before
    view2d.set_program(POINTS, RAPID)
    (x0, x1), (y0, y1) = view2d.xy_plot.getPlotItem().viewRange()
    low, high = POINTS[:, :2].min(axis=0), POINTS[:, :2].max(axis=0)
    assert x0 < low[0] and x1 > high[0] and y0 < low[1] and y1 > high[1]
    view2d.set_program_done(6)  # what is done stays in view: no jump
    assert view2d.xy_plot.getPlotItem().viewRange() == [[x0, x1], [y0, y1]]
    view2d.reset_view()
    (x0, x1), (y0, y1) = view2d.xy_plot.getPlotItem().viewRange()
    assert x0 < low[0] and x1 > high[0] and y0 < low[1] and y1 > high[1]


def test_2d_program_follows_the_theme(view2d) -> None:
    view2d.set_program(POINTS, RAPID)
    for colors in (LIGHT_PLOT_COLORS, DARK_PLOT_COLORS):
        apply_plot_colors(view2d.xy_plot, colors)
        for item in (view2d.program_cut, view2d.program_rapid, view2d.preview_curve):
            assert item.opts["pen"].color().name() == colors.preview
        assert view2d.program_rapid.opts["pen"].style() == position_view_3d.Qt.PenStyle.DashLine


def test_2d_big_program_is_drawn_fast(view2d, qtbot) -> None:
    # Budgets in this thread's CPU time: in wall time they failed beside other test workers.
    points, rapid = big_program()
    start = time.thread_time()
    view2d.set_program(points, rapid)
    elapsed = time.thread_time() - start
    assert elapsed < 1.0, elapsed
    assert len(view2d.program_rapid.getData()[0]) == 2 * np.count_nonzero(rapid)
    view2d.xy_plot.grab()  # drawn once
    steps = []
    for row in range(1000, 100_000, 9000):
        start = time.thread_time()
        view2d.set_program_done(row)
        steps.append(time.thread_time() - start)
        assert len(view2d.program()) == len(points) - row
    assert max(steps) < 0.05, steps


def test_placeholder_takes_the_program_calls(qtbot) -> None:
    widget = PositionView3DPlaceholder("no GL")
    qtbot.addWidget(widget)
    widget.set_program(POINTS, RAPID)
    widget.set_program_done(3)
    assert widget.program().shape == (0, 3)
    widget.set_program(None)
    assert widget.program().shape == (0, 3)


@pytest.mark.gl
@needs_display
def test_3d_draws_cut_and_dashed_travel(gl_view) -> None:
    assert not gl_view.program_cut.visible() and not gl_view.program_rapid.visible()
    gl_view.set_program(POINTS, RAPID)
    assert gl_view.program_cut.visible() and gl_view.program_rapid.visible()
    assert gl_view.program_cut.mode == gl_view.program_rapid.mode == "lines"
    assert gl_view.program_cut.pos.dtype == np.float32
    pairs = {(tuple(a), tuple(b)) for a, b in gl_view.program_cut.pos.reshape(-1, 2, 3)}
    assert pairs == {(tuple(POINTS[j]), tuple(POINTS[j + 1])) for j in range(7) if not RAPID[j + 1]}
    assert len(gl_view.program_rapid.pos) > 2 * np.count_nonzero(RAPID)  # cut into dashes
    assert np.array_equal(gl_view.program(), POINTS)
    gl_view.set_preview([(0, 0, 0), (1, 1, 1)])  # independent of each other
    assert gl_view.preview_item.visible() and gl_view.program_cut.visible()
    assert not gl_view.render_scene().isNull()


@pytest.mark.gl
@needs_display
def test_3d_done_and_removal(gl_view) -> None:
    gl_view.set_program(POINTS, RAPID)
    whole_cut = gl_view.program_cut.pos.copy()
    gl_view.render_scene()
    gl_view.set_program_done(4)
    assert np.array_equal(gl_view.program(), POINTS[4:])
    left = {(tuple(a), tuple(b)) for a, b in gl_view.program_cut.pos.reshape(-1, 2, 3)}
    assert left == {(tuple(POINTS[6]), tuple(POINTS[7]))}  # 4-5 and 5-6 are travel moves
    assert len(gl_view.program_rapid.pos) >= 4  # their dashes
    assert np.array_equal(gl_view.program_cut.pos, whole_cut[: len(gl_view.program_cut.pos)])
    assert not gl_view.render_scene().isNull()
    gl_view.set_program_done(7)
    assert not gl_view.program_cut.visible() and not gl_view.program_rapid.visible()
    gl_view.set_program(None)
    assert gl_view.program().shape == (0, 3)
    assert not gl_view.program_cut.visible() and not gl_view.program_rapid.visible()


@pytest.mark.gl
@needs_display
def test_3d_grid_widens_to_hold_the_program(gl_view) -> None:
    far = POINTS * 10
    assert not gl_view._grid.contains(far)
    gl_view.set_program(far, RAPID)
    assert gl_view._grid.contains(far)
    assert gl_view.grid_spacing() >= 50


@pytest.mark.gl
@needs_display
def test_3d_program_follows_the_theme(gl_view) -> None:
    gl_view.set_program(POINTS, RAPID)
    for colors in (LIGHT_PLOT_COLORS, DARK_PLOT_COLORS):
        apply_gl_colors(gl_view.scene, colors)
        for item in (gl_view.program_cut, gl_view.program_rapid, gl_view.preview_item):
            assert tuple(item.color) == pytest.approx(colors.gl("preview"))


@pytest.mark.gl
@needs_display
def test_3d_big_program_is_drawn_fast(gl_view) -> None:
    # Budgets in this thread's CPU time, as in the 2D test.
    points, rapid = big_program()
    start = time.thread_time()
    gl_view.set_program(points, rapid)
    elapsed = time.thread_time() - start
    assert elapsed < 1.0, elapsed
    assert not gl_view.render_scene().isNull()
    steps = []
    for row in range(1000, 100_000, 9000):
        start = time.thread_time()
        gl_view.set_program_done(row)
        steps.append(time.thread_time() - start)
        assert len(gl_view.program()) == len(points) - row
    assert max(steps) < 0.05, steps
    assert not gl_view.render_scene().isNull()


def test_a_dense_program_is_simplified_within_the_3d_budget() -> None:
    """200,000 short cuts in a 50 mm field: the 3D view draws at most MAX_GL_SEGMENTS of them
    (a coarser grid), each vertex still on the program's path."""
    count = 200_000
    t = np.arange(count + 1)
    points = np.column_stack(((t % 500) * 0.1, (t // 500) * 0.125, np.zeros(count + 1)))
    path = ProgramPath(points, np.zeros(count + 1, dtype=bool))
    vertices = path.cut_vertices(0)
    assert 0 < len(vertices) <= 2 * MAX_GL_SEGMENTS
    on_path = {tuple(p) for p in points.astype(np.float32)}
    assert all(tuple(v) in on_path for v in vertices[:: max(1, len(vertices) // 500)])
