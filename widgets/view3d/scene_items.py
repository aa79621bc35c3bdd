"""The 3D view's OpenGL items: its guarded GL widget, and the grid, axes, trail and markers."""

from __future__ import annotations

from functools import cache

import numpy as np
from PySide6.QtCore import Signal
from PySide6.QtGui import QColor, QFont

from widgets._axes import Box
from widgets._program_path import ProgramPath
from widgets._units import MM, unit_text
from widgets.position_buffer import PositionBuffer
from widgets.view3d.colours import (
    AXIS_COLOURS,
    BACKGROUND,
    CURRENT_COLOUR,
    PREVIEW_COLOUR,
    TARGET_COLOUR,
    THEME_ROLE,
    TRAIL_COLOUR,
    WORKSPACE_COLOUR,
    grid_colour,
    label_colour,
)
from widgets.view3d.geometry import axis_ends, box_corners, grid_for
from widgets.view3d.opengl import failure_text, load_gl
from widgets.view3d.trail import trail_class


@cache
def scene_class() -> type:
    """pyqtgraph's GLViewWidget, with GL callbacks that never let an exception reach Qt.

    An exception thrown out of initializeGL or paintGL crosses Qt's C++ frames (in issue 11:
    paintEvent -> sendEvent -> a Python event filter -> initializeGL) and left a corrupted
    reference that crashed the interpreter's last garbage collection. The failure is kept in
    `failure` for the view to show instead.
    """

    class GuardedScene(load_gl().GLViewWidget):
        """A GLViewWidget that records, rather than raises, a failure to initialise or paint,
        and says when its background changes (the theme's: the view follows it)."""

        failure: str | None = None
        background_changed = Signal()

        def setBackgroundColor(self, *args: object, **kwds: object) -> None:
            """pyqtgraph's, then `background_changed`."""
            super().setBackgroundColor(*args, **kwds)
            self.background_changed.emit()

        def initializeGL(self) -> None:
            """pyqtgraph's initialisation; a failure is recorded."""
            try:
                super().initializeGL()
            except Exception as exc:  # any failure: no 3D view
                self.failure = failure_text(exc)

        def paintGL(self) -> None:
            """pyqtgraph's painting, unless something failed; a failure is recorded."""
            if self.failure is not None:
                return
            try:
                super().paintGL()
            except Exception as exc:  # any failure: no 3D view
                self.failure = failure_text(exc)

    return GuardedScene


def axis_label(name: str, units: str) -> str:
    """An axis's label in the scene: "X (mm)", "X (in)"."""
    return f"{name} ({unit_text(units)})"


def blended_without_depth() -> dict:
    """pyqtgraph's "translucent" blending without its depth test, as antialiased lines are drawn.

    The lines' default, "additive", adds overlapping lines up: a dense trail turned white.
    """
    from OpenGL import GL
    from pyqtgraph.opengl.GLGraphicsItem import GLOptions

    return {**GLOptions["translucent"], GL.GL_DEPTH_TEST: False}


def line_item(
    colour: object,
    width: float,
    mode: str = "lines",
    kind: type | None = None,
    antialias: bool = True,
    **kwargs: object,
) -> object:
    """A GLLinePlotItem (or a `kind` of one) with placeholder vertices."""
    return (kind or load_gl().GLLinePlotItem)(
        pos=np.zeros((2, 3), dtype=np.float32),
        color=colour,
        width=width,
        mode=mode,
        antialias=antialias,
        **kwargs,
    )


class SceneItemsMixin:
    """The items of PositionView3D's scene, the grid fitted to its data, and their colours."""

    buffer: PositionBuffer
    _target: tuple[float, float, float] | None
    _workspace: Box | None
    _preview: np.ndarray
    _program: ProgramPath | None
    _preset: str | None
    _units: str
    _scale_colour: QColor

    def _make_items(self) -> None:
        """Make the scene's items and add them, those drawn first first."""
        gl = load_gl()
        self._label_font = QFont()
        self._label_font.setPointSize(10)

        self.grid_item = line_item(grid_colour(QColor(*BACKGROUND)), 1.0, glOptions="translucent")
        self.axes_item = line_item(np.repeat(np.array(AXIS_COLOURS), 2, axis=0), 2.0)
        self.workspace_item = line_item(WORKSPACE_COLOUR, 1.5)
        self.workspace_item.setVisible(False)
        self.labels = [
            gl.GLTextItem(
                text=axis_label(name, MM),
                color=[int(255 * c) for c in colour],
                font=self._label_font,
            )
            for name, colour in zip("XYZ", AXIS_COLOURS, strict=True)
        ]
        # The trail: the older part decimated (buffer.lod), drawn 1 px wide without antialiasing
        # (with software OpenGL antialiasing cost 12 ms a frame for a million-point raster that
        # covers the view, and 1.5 px 1.5 ms more); the recent part, every point, antialiased.
        # Both as separate segments ("lines"), so that a break in the trail (a NaN row: a new
        # connection) joins nothing: OpenGL leaves a NaN vertex undefined.
        self.trail_history = line_item(
            TRAIL_COLOUR,
            1.0,
            mode="lines",
            kind=trail_class(),
            antialias=False,
            glOptions=blended_without_depth(),
        )
        self.trail = line_item(TRAIL_COLOUR, 1.5, mode="lines", kind=trail_class())
        self.current_marker = gl.GLScatterPlotItem(
            pos=np.zeros((1, 3), dtype=np.float32), color=CURRENT_COLOUR, size=12.0
        )
        self.target_marker = gl.GLScatterPlotItem(
            pos=np.zeros((1, 3), dtype=np.float32), color=TARGET_COLOUR, size=14.0
        )
        for item in (self.current_marker, self.target_marker):
            item.setGLOptions("translucent")
        for item in (self.grid_item, self.axes_item, self.workspace_item, *self.labels):
            self.addItem(item)
        # A program's path, under the trail: its cut segments as lines, its travel (rapid) moves
        # as dashes (GL has no dashed lines: each is cut into pieces), drawn as the trail's
        # history is (1 px, no antialiasing: cheap in software OpenGL) from vertex buffers
        # that hold the whole program in reverse order, so what is left to run is a prefix
        # and the run's progress uploads nothing.
        self.program_cut, self.program_rapid = (
            line_item(
                PREVIEW_COLOUR,
                1.0,
                mode="lines",
                kind=trail_class(),
                antialias=False,
                glOptions=blended_without_depth(),
            )
            for _ in range(2)
        )
        for item in (self.program_cut, self.program_rapid):
            item.setVisible(False)
            setattr(item, THEME_ROLE, "preview")
            self.addItem(item)
        for item in (self.trail_history, self.trail, self.current_marker, self.target_marker):
            item.setVisible(False)
            self.addItem(item)
        self.preview_item = line_item(PREVIEW_COLOUR, 1.5, mode="line_strip")
        self.preview_item.setVisible(False)
        setattr(self.preview_item, THEME_ROLE, "preview")
        self.addItem(self.preview_item)

    def _fit_grid(self) -> None:
        """Size the grid, axes and labels to the data and workspace; refit an active preset."""
        points = self._data_points()
        pad = 0.0 if self._workspace else 0.05
        self._grid = grid = grid_for(points, pad=pad, units=self._units)
        self.grid_item.setData(pos=grid.lines())
        self._axis_ends = axis_ends(grid, float(points[:, 2].max()) if len(points) else 0.0)
        vertices = np.zeros((6, 3), dtype=np.float32)
        vertices[1::2] = self._axis_ends
        self.axes_item.setData(pos=vertices)
        span = max(grid.x1 - grid.x0, grid.y1 - grid.y0)
        for label, end in zip(self.labels, self._axis_ends, strict=True):
            label.setData(pos=end + np.sign(end) * 0.03 * span)
        if self._preset is not None:
            self._fit_camera()

    def _data_points(self) -> np.ndarray:
        """The corners of the trail's bounding box, the target and the workspace corners."""
        parts = [np.zeros((0, 3), dtype=np.float32)]
        bounds = self.buffer.lod.bounds()  # of every point, from the decimated trail
        if bounds is not None:
            parts.append(box_corners(tuple(zip(*bounds, strict=True))))
        if self._target is not None:
            parts.append(np.array([self._target], dtype=np.float32))
        if self._workspace is not None:
            parts.append(box_corners(self._workspace))
        if len(self._preview):
            low, high = self._preview.min(axis=0), self._preview.max(axis=0)
            parts.append(box_corners(tuple(zip(low, high, strict=True))))
        if self._program is not None:  # the whole program's, done part included: no jumps
            parts.append(
                box_corners(tuple(zip(self._program.low, self._program.high, strict=True)))
            )
        return np.vstack(parts)

    def background(self) -> QColor:
        """The scene's background colour (the theme's, once the window applied it)."""
        return QColor.fromRgbF(*self.scene.opts["bgcolor"])

    def grid_colour(self) -> QColor:
        """The colour the grid's lines are drawn in."""
        return QColor.fromRgbF(*self.grid_item.color)

    def scale_colour(self) -> QColor:
        """The colour of the "grid N mm" text."""
        return QColor(self._scale_colour)

    def _follow_background(self) -> None:
        """The grid and its scale text in greys that contrast with the new background."""
        background = self.background()
        self.grid_item.setData(color=grid_colour(background))
        self._scale_colour = label_colour(background)
        self._redraw()  # painted once rendered: the scale with the image it belongs to
