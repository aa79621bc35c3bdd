"""3D position view (pyqtgraph.opengl), with a placeholder when OpenGL is unavailable."""

from __future__ import annotations

import logging
import sys
from collections.abc import Callable
from functools import cache, partial
from types import ModuleType

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QSize, Qt, QTimer, Signal
from PySide6.QtGui import (
    QColor,
    QFont,
    QFontMetrics,
    QImage,
    QMouseEvent,
    QPainter,
    QPaintEvent,
    QPen,
    QResizeEvent,
    QVector3D,
    QWheelEvent,
)
from PySide6.QtWidgets import QLabel, QToolButton, QWidget

from widgets._axes import Box, target_point
from widgets._buttons import overlay_button_style
from widgets._gl_scene import (
    FIELD_OF_VIEW,
    MARGINS_PX,
    NO_CONTEXT,
    VIEW_ANGLES,
    VIEW_PRESETS,
    axis_ends,
    box_corners,
    box_edges,
    camera_rotation,
    fit_camera,
    grid_colour,
    grid_for,
    label_colour,
    opengl_problem,
    overlay_buttons,
    preview_array,
    preview_tuples,
    segment_vertices,
    spacing_text,
)
from widgets._gl_scene import (  # here for its callers of before; it imports no OpenGL
    share_opengl_contexts as share_opengl_contexts,
)
from widgets._i18n import fill
from widgets._pacer import run_paced
from widgets._program_path import ProgramPath, program_arrays
from widgets._units import INCH, MM, check_units, unit_text
from widgets._view_common import REFRESH_INTERVAL_MS, BufferedViewMixin
from widgets.position_buffer import PositionBuffer

log = logging.getLogger(__name__)

# pyqtgraph.opengl, imported by `load_gl()` when a view is first made: importing it takes a
# fifth of a second, and PyOpenGL may be missing or broken (this module must still import).
gl: ModuleType | None = None
_IMPORT_ERROR: str | None = None
TRAIL_CHUNK = 16_384  # the trail's vertex buffer grows by at least this many vertices
RENDER_DELAY_MS = 2 * REFRESH_INTERVAL_MS // 3  # a change is rendered this long after (below)

TRAIL_COLOUR = (0.36, 0.42, 0.75, 1.0)
CURRENT_COLOUR = (1.0, 0.70, 0.0, 1.0)
TARGET_COLOUR = (0.85, 0.11, 0.38, 1.0)
ESTIMATED_COLOUR = (*CURRENT_COLOUR[:3], 0.5)  # a position estimated, not measured
AXIS_COLOURS = ((0.90, 0.22, 0.21, 1.0), (0.26, 0.63, 0.28, 1.0), (0.12, 0.53, 0.90, 1.0))
WORKSPACE_COLOUR = (0.30, 0.80, 0.78, 0.9)
PREVIEW_COLOUR = (1.0, 0.80, 0.50, 1.0)  # light orange (#ffcc80): a planned path, not yet run
THEME_ROLE = "theme_role"  # an item's colour role in app.window.theme.PlotColors: recoloured
BACKGROUND = (24, 24, 28, 255)
NOTICE_COLOUR = (97, 97, 97)
NOTICE_STYLE = "color: #616161; border: 1px dashed #9e9e9e;"
NOTICE_TOOLTIP = QT_TRANSLATE_NOOP(
    "PositionView3D", "Needs OpenGL 2.1 or newer (e.g. Mesa) on a display; see the README."
)


def notice_text(reason: str) -> str:
    """The words shown where the 3D view would be, for `reason`."""
    template = QCoreApplication.translate(
        "PositionView3D",
        "3D view unavailable: OpenGL could not be initialised.\n(%1)\n"
        "The 2D view shows the same positions.",
    )
    return fill(template, reason)


def load_gl() -> ModuleType | None:
    """pyqtgraph.opengl, imported at the first call; None when it cannot be (see the log)."""
    global gl, _IMPORT_ERROR
    if gl is None and _IMPORT_ERROR is None:
        try:
            import pyqtgraph.opengl as module
        except Exception as exc:  # any failure means "no 3D view"
            _IMPORT_ERROR = f"{type(exc).__name__}: {exc}"
        else:
            gl = module
    return gl


def opengl_unavailable_reason() -> str | None:
    """Why the 3D view cannot be drawn here (no pyqtgraph.opengl, platform, context), or None."""
    if load_gl() is None:
        return f"pyqtgraph.opengl is unavailable ({_IMPORT_ERROR})"
    return opengl_problem()


def opengl_available() -> bool:
    """Whether pyqtgraph.opengl imports and a usable OpenGL context can be made current here."""
    return opengl_unavailable_reason() is None


def _failure(exc: BaseException) -> str:
    """An exception in words, for the notice and the log."""
    return f"{type(exc).__name__}: {exc}"


@cache
def _scene_class() -> type:
    """pyqtgraph's GLViewWidget, with GL callbacks that never let an exception reach Qt.

    An exception thrown out of initializeGL or paintGL crosses Qt's C++ frames (in issue 11:
    paintEvent -> sendEvent -> a Python event filter -> initializeGL) and left a corrupted
    reference that crashed the interpreter's last garbage collection. The failure is kept in
    `failure` for the view to show instead.
    """

    class GuardedScene(gl.GLViewWidget):
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
                self.failure = _failure(exc)

        def paintGL(self) -> None:
            """pyqtgraph's painting, unless something failed; a failure is recorded."""
            if self.failure is not None:
                return
            try:
                super().paintGL()
            except Exception as exc:  # any failure: no 3D view
                self.failure = _failure(exc)

    return GuardedScene


@cache
def _trail_class() -> type:
    """A GLLinePlotItem whose vertex buffer grows in chunks and takes only what changed.

    pyqtgraph sends every vertex to the GPU whenever the data is set; the trail only grows at
    its end, so `set_vertices` says how many leading vertices are as before, and only the rest
    is written (glBufferSubData). With a pyqtgraph that draws without vertex buffers, all the
    vertices are set each time.
    """
    base = gl.GLLinePlotItem
    dirty = getattr(sys.modules[base.__module__], "DirtyFlag", None)
    partial_upload = dirty is not None and hasattr(base, "upload_vbo")

    class TrailLine(base):
        """The trail's line strip; see `set_vertices`."""

        _vertices = np.zeros((0, 3), dtype=np.float32)  # a chunk-grown store; `pos` views it
        _allocated = 0  # bytes of the vertex buffer on the GPU
        _upload_from = 0  # vertices before this one are on the GPU already

        def set_vertices(self, xyz: np.ndarray, unchanged: int = 0) -> None:
            """Draw the (n, 3) vertices `xyz`, the first `unchanged` being the same as before."""
            if not partial_upload:
                base.setData(self, pos=xyz)
                return
            n = len(xyz)
            unchanged = max(0, min(unchanged, n, 0 if self.pos is None else len(self.pos)))
            if n > len(self._vertices):
                grown = np.empty((max(n, 2 * len(self._vertices), TRAIL_CHUNK), 3), np.float32)
                grown[:unchanged] = self._vertices[:unchanged]
                self._vertices = grown
            self._vertices[unchanged:n] = xyz[unchanged:]
            self._upload_from = min(self._upload_from, unchanged)
            self.pos = self._vertices[:n]
            self.dirty_bits |= dirty.POSITION
            self.update()

        def setData(self, **kwds: object) -> None:
            """As GLLinePlotItem's; new positions go through `set_vertices`."""
            pos = kwds.pop("pos", None)
            if pos is not None and partial_upload:
                self.set_vertices(np.asarray(pos, dtype=np.float32).reshape(-1, 3))
            elif pos is not None:
                kwds["pos"] = pos
            super().setData(**kwds)

        def upload_vbo(self, vbo: object, arr: np.ndarray | None) -> None:
            """Write the vertices not on the GPU yet; grow the buffer when the store grew."""
            if vbo is not self.m_vbo_position or arr is None:
                super().upload_vbo(vbo, arr)
                return
            if not vbo.isCreated():
                vbo.create()
                self._allocated = 0
            vbo.bind()
            start = self._upload_from
            if self._allocated != self._vertices.nbytes:
                vbo.allocate(self._vertices.nbytes)
                self._allocated = self._vertices.nbytes
                start = 0
            part = self._vertices[start : len(arr)]
            if len(part):
                vbo.write(start * part.itemsize * 3, part, part.nbytes)
            vbo.release()
            self._upload_from = len(arr)

    return TrailLine


class PositionView3D(BufferedViewMixin, QWidget):
    """Grid, axes, trail, current and target markers in 3D, refreshed from a buffer.

    The scene is drawn with OpenGL by `self.scene`, a pyqtgraph GLViewWidget that is never
    shown, into an image this plain widget paints. A QOpenGLWidget inside the window would make
    Qt compose the whole window through OpenGL on every repaint of any widget: with software
    OpenGL (Mesa llvmpipe) that took 75-90 ms a frame, while rendering the scene alone into an
    image takes about 1.5 ms.

    If OpenGL fails while rendering (an exception in pyqtgraph's initialisation or painting, or
    an invalid context), the view stops rendering and paints a notice in its place, saying why
    (`failure`); its methods keep working and draw nothing.

    The grid covers the origin, the trail, the target and the workspace box, with a 1-2-5 mm
    spacing (0.1, 0.25, 0.5, 1 in... in inches: `set_units`); it grows when the data leaves
    it. A view preset ("top", "front", "side", "iso", "fit") stays in force, refitted on
    resizes and grid changes, until the mouse moves the camera.
    """

    def __init__(self, buffer: PositionBuffer, parent: QWidget | None = None) -> None:
        if load_gl() is None:
            raise RuntimeError(f"pyqtgraph.opengl is unavailable ({_IMPORT_ERROR})")
        super().__init__(parent)
        self.setObjectName("positionView3d")
        self.setToolTip(self.tr("Drag to rotate, wheel to zoom, middle-drag to pan"))
        self.setMinimumSize(160, 120)
        self.buffer = buffer
        self._target: tuple[float, float, float] | None = None
        self._workspace: Box | None = None
        self._preview = np.zeros((0, 3))
        self._program: ProgramPath | None = None
        self._program_done = 0
        self._current: np.ndarray | None = None
        self._follow = False
        self._estimated = False
        self._preset: str | None = "iso"
        self._units = MM  # what the grid, its scale and the axis labels are in (data: mm)
        self._fitted_size = QSize()
        self._framebuffer_key: tuple[int, int, float] | None = None
        self._image = QImage()
        self._stale = True
        # The scene is rendered in a turn of the event loop of its own, 2/3 of a refresh after
        # the change, not in the window's repaint: Qt paints every dirty widget in one go (a
        # 2D plot's repaint paints this view too), and a render (3-12 ms with software OpenGL)
        # on top of the 2D view's refresh and painting, which come at the same moment (the
        # same buffer, the same refresh rate), made the window's longest stalls.
        self._render_timer = QTimer(self)
        self._render_timer.setObjectName("view3dRenderTimer")
        self._render_timer.setSingleShot(True)
        self._render_timer.setInterval(RENDER_DELAY_MS)
        self._render_timer.timeout.connect(self._render_pending)
        self.failure: str | None = None
        self.scene = _scene_class()()  # no parent: it must stay out of this window
        self._scale_colour = QColor()
        self.scene.setBackgroundColor(BACKGROUND)
        self.scene.opts["fov"] = FIELD_OF_VIEW
        self.destroyed.connect(self.scene.deleteLater)
        self.addItem = self.scene.addItem
        self._label_font = QFont()
        self._label_font.setPointSize(10)

        self.grid_item = _lines(grid_colour(QColor(*BACKGROUND)), 1.0, glOptions="translucent")
        self.axes_item = _lines(np.repeat(np.array(AXIS_COLOURS), 2, axis=0), 2.0)
        self.workspace_item = _lines(WORKSPACE_COLOUR, 1.5)
        self.workspace_item.setVisible(False)
        self.labels = [
            gl.GLTextItem(
                text=_axis_label(name, MM),
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
        self.trail_history = _lines(
            TRAIL_COLOUR,
            1.0,
            mode="lines",
            kind=_trail_class(),
            antialias=False,
            glOptions=_blended_without_depth(),
        )
        self.trail = _lines(TRAIL_COLOUR, 1.5, mode="lines", kind=_trail_class())
        self._trail_token: tuple[int, int, int] | None = None
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
            _lines(
                PREVIEW_COLOUR,
                1.0,
                mode="lines",
                kind=_trail_class(),
                antialias=False,
                glOptions=_blended_without_depth(),
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
        self.preview_item = _lines(PREVIEW_COLOUR, 1.5, mode="line_strip")
        self.preview_item.setVisible(False)
        setattr(self.preview_item, THEME_ROLE, "preview")
        self.addItem(self.preview_item)

        self._make_buttons()
        self._follow_background()
        self.scene.background_changed.connect(self._follow_background)
        self.start_refresh_timer()
        self._fit_grid()

    # -- public API ----------------------------------------------------------------------------
    def refresh(self) -> None:
        """Redraw from the buffer if it changed since the last refresh."""
        if self.changed_rows() is None:
            return
        lod = self.buffer.lod
        rows = lod.update()  # the whole trail, decimated where old: its shape and extremes
        unchanged = lod.unchanged_prefix(self._trail_token)
        self._trail_token = lod.token()
        old = lod.decimated_count
        start = max(old - 1, 0)  # the recent line starts where the history ends
        history, same = segment_vertices(rows[:old, 1:4], min(unchanged, old))
        self.trail_history.set_vertices(history, same)
        self.trail_history.setVisible(len(history) >= 2)
        recent, same = segment_vertices(rows[start:, 1:4], max(0, unchanged - start))
        self.trail.set_vertices(recent, same)
        self.trail.setVisible(len(recent) >= 2)
        self.current_marker.setVisible(bool(len(rows)))
        if len(rows):
            current = rows[-1, 1:4].astype(np.float32)
            self.current_marker.setData(pos=current[None, :])
            moved = self._current is None or not np.array_equal(current, self._current)
            self._current = current
            if self._follow and moved:
                self.scene.opts["center"] = QVector3D(*map(float, current))
        else:
            self._current = None
        bounds = lod.bounds()
        if bounds is not None and not self._grid.contains(np.array(bounds)):
            self._fit_grid()
        self._redraw()

    def set_target(self, x: object, y: float | None = None, z: float | None = None) -> None:
        """Mark the target: `set_target(x, y, z)` or `set_target((x, y, z))` in mm; None hides it.

        z None (a device without Z) puts the marker at z = 0.
        """
        point = target_point(x, y, z)
        if point is None:
            self._target = None
            self.target_marker.setVisible(False)
        else:
            tx, ty, tz = point
            self._target = (tx, ty, tz or 0.0)
            self.target_marker.setData(pos=np.array([self._target], dtype=np.float32))
            self.target_marker.setVisible(True)
            if not self._grid.contains(np.array([self._target])):
                self._fit_grid()
        self._redraw()

    def set_workspace(self, box: Box | None) -> None:
        """Draw the travel box (mm) as a wireframe and fit the grid to it; None removes it."""
        self._workspace = box
        self.workspace_item.setVisible(box is not None)
        if box is not None:
            self.workspace_item.setData(pos=box_edges(box))
        self._fit_grid()
        self._redraw()

    def set_preview(self, points: object) -> None:
        """Draw a planned path (a list of (x, y, z) in mm) as a light orange line; None or []
        removes it. The grid grows to hold it."""
        self._preview = preview_array(points)
        shown = len(self._preview) >= 2
        self.preview_item.setVisible(shown)
        if shown:
            self.preview_item.setData(pos=self._preview.astype(np.float32))
        if not self._grid.contains(self._preview):
            self._fit_grid()
        self._redraw()

    def preview(self) -> list[tuple[float, float, float]]:
        """The planned path shown, as (x, y, z) points in mm; [] when none."""
        return preview_tuples(self._preview)

    def set_program(self, points: np.ndarray | None, rapid: np.ndarray | None = None) -> None:
        """Draw a whole program: `points` (n, 3) mm, row 0 its start and row i the end of
        segment i; `rapid` (n,) whether segment i is a travel move (dashed; the others solid).
        None or fewer than 2 points removes it. The grid grows to hold it."""
        array, moves = program_arrays(points, rapid)
        self._program = ProgramPath(array, moves) if len(array) >= 2 else None
        self._program_done = 0
        self._draw_program(fresh=True)
        if self._program is not None:
            corners = box_corners(tuple(zip(self._program.low, self._program.high, strict=True)))
            if not self._grid.contains(corners):
                self._fit_grid()
        self._redraw()

    def set_program_done(self, row: int) -> None:
        """The program has run up to `row` (the trail shows it): draw only rows >= `row`."""
        if self._program is None:
            return
        row = self._program.clamp(row)
        if row != self._program_done:
            self._program_done = row
            self._draw_program(fresh=False)
            self._redraw()

    def program(self) -> np.ndarray:
        """The program's points drawn, (n, 3) mm from the row it is done up to; (0, 3) when
        none."""
        if self._program is None:
            return np.zeros((0, 3))
        return self._program.points[self._program_done :]

    def _draw_program(self, fresh: bool) -> None:
        """Give the program's items what is left of it; `fresh`: a new program (uploaded
        whole), else the same one further on (a shorter prefix: nothing uploaded)."""
        program, row = self._program, self._program_done
        for item, part in (
            (self.program_cut, "cut_vertices"),
            (self.program_rapid, "dash_vertices"),
        ):
            vertices = getattr(program, part)(row) if program is not None else np.zeros((0, 3))
            item.set_vertices(vertices, 0 if fresh else len(vertices))
            item.setVisible(len(vertices) >= 2)

    def grid_spacing(self) -> float:
        """The distance between grid lines, in mm."""
        return self._grid.spacing

    def scale_text(self) -> str:
        """The grid's scale as written at the bottom, in the units shown ("grid 0.25 in")."""
        if self._units == INCH:
            return fill(self.tr("grid %1 in"), spacing_text(self._grid.spacing, INCH))
        return fill(self.tr("grid %1 mm"), spacing_text(self._grid.spacing))

    def set_units(self, units: str) -> None:
        """Grid, scale and axis labels in "mm" or "in" (0.1, 0.25, 0.5, 1... in apart); what
        is drawn stays where it is (the data are in mm)."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        for name, label in zip("XYZ", self.labels, strict=True):
            label.setData(text=_axis_label(name, units))
        self._fit_grid()
        self._redraw()

    def units(self) -> str:
        """The units the grid and the labels are in: "mm" or "in"."""
        return self._units

    def reset_view(self) -> None:
        """Look at the whole scene from above at an angle (the "iso" preset)."""
        self.set_view_preset("iso")

    def set_view_preset(self, name: str) -> None:
        """Look from "top", "front", "side" or "iso" at the whole scene, or "fit" the data."""
        if name not in VIEW_PRESETS:
            raise ValueError(f"unknown view preset {name!r}")
        self._preset = name
        self._fit_camera()
        self._redraw()

    def _fit_camera(self) -> None:
        """Point the camera as the active preset says, at the widget's present size."""
        opts = self.scene.opts
        name = self._preset
        elevation, azimuth = VIEW_ANGLES.get(name, (opts["elevation"], opts["azimuth"]))
        points, margins = self._fit_points(data_only=name == "fit")
        following = self._follow and self._current is not None
        centre, distance = fit_camera(
            points,
            self._current if following else (points.min(axis=0) + points.max(axis=0)) / 2,
            camera_rotation(elevation, azimuth),
            opts["fov"],
            (self.width(), self.height()),
            margins,
            move_centre=not following,
        )
        self.scene.setCameraPosition(
            pos=QVector3D(*map(float, centre)),
            distance=distance,
            elevation=elevation,
            azimuth=azimuth,
        )
        self._fitted_size = self.size()

    def set_follow(self, on: bool) -> None:
        """Keep the camera centred on the current position while `on`."""
        self._follow = bool(on)
        self.follow_button.setChecked(self._follow)
        if self._follow and self._current is not None:
            self.scene.opts["center"] = QVector3D(*map(float, self._current))
            self._redraw()

    def is_following(self) -> bool:
        """Whether the camera follows the current position."""
        return self._follow

    def set_estimated(self, estimated: bool) -> None:
        """Draw the current marker faded while its position is estimated, not measured."""
        self._estimated = bool(estimated)
        self.current_marker.setData(color=ESTIMATED_COLOUR if estimated else CURRENT_COLOUR)
        self._redraw()

    def is_estimated(self) -> bool:
        """Whether the current marker shows an estimated position."""
        return self._estimated

    # -- scene -------------------------------------------------------------------------------
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

    def _fit_points(self, data_only: bool) -> tuple[np.ndarray, np.ndarray]:
        """The points a camera preset must show, and their margins (left, right, bottom, top px)."""
        points = self._data_points()
        margins = np.tile(MARGINS_PX, (len(points), 1))
        if data_only and len(points):
            return points, margins
        grid = self._grid
        corners = np.array([(x, y, 0.0) for x in (grid.x0, grid.x1) for y in (grid.y0, grid.y1)])
        metrics = QFontMetrics(self._label_font)
        label_margins = [  # the text is drawn right of and above its position
            np.add(MARGINS_PX, (0, metrics.horizontalAdvance(lab.text), 0, metrics.height()))
            for lab in self.labels
        ]
        label_pos = np.array([lab.pos for lab in self.labels])
        points = np.vstack([points, corners, self._axis_ends, label_pos])
        margins = np.vstack([margins, np.tile(MARGINS_PX, (7, 1)), label_margins])
        return points, margins

    def _make_buttons(self) -> None:
        """The view-preset and follow buttons over the top-left corner."""
        for button in overlay_buttons(self):
            preset = button.objectName().removeprefix("view3d").lower()
            if preset in VIEW_PRESETS:
                button.clicked.connect(partial(self.set_view_preset, preset))
        self.follow_button = self.findChild(QToolButton, "view3dFollow")
        self.follow_button.toggled.connect(self.set_follow)
        self._buttons_light: bool | None = None
        self._style_buttons()

    def _style_buttons(self) -> None:
        """The buttons in the style for the scene's background (the theme's), on a change."""
        light = QColor.fromRgbF(*self.scene.opts["bgcolor"]).lightnessF() > 0.5
        if light is self._buttons_light:
            return
        self._buttons_light = light
        style = overlay_button_style(light)
        for button in self.findChildren(QToolButton):
            button.setStyleSheet(style)

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

    # -- drawing -----------------------------------------------------------------------------
    def _redraw(self) -> None:
        """Mark the image out of date; it is rendered RENDER_DELAY_MS later (or at the next
        paint, if that comes first with no render waiting: hidden, resized)."""
        self._stale = True
        if not self._render_timer.isActive():  # changes meanwhile go into the same render
            self._render_timer.start(RENDER_DELAY_MS)

    def _render_pending(self) -> None:
        """Render the out-of-date image, then have it painted (a copy of it, no rendering);
        paced: not in the same turn of the event loop as other heavy work."""
        if self._stale and self.failure is None and self.isVisible():
            if not run_paced(self._render_timer):
                return
            self.render_scene()
            self.update()

    def render_scene(self) -> QImage:
        """Render the scene at the widget's size now, and keep the image (null once failed)."""
        if self.failure is not None:
            return QImage()
        if self._preset is not None and self._fitted_size != self.size():
            self._fit_camera()  # the active preset, refitted to the new shape
        if self.scene.screen() is not self.screen():
            self.scene.setScreen(self.screen())  # the device pixel ratio of this widget's screen
        size = QSize(max(1, self.width()), max(1, self.height()))
        old = self.scene.size()
        self.scene.resize(size)
        ratio = self.scene.devicePixelRatioF()
        key = (size.width(), size.height(), ratio)
        if key != self._framebuffer_key:
            # A hidden widget's resize event is held back until it is shown, and this one never
            # is: without the event QOpenGLWidget keeps its first framebuffer size.
            QCoreApplication.sendEvent(self.scene, QResizeEvent(size, old))
            self._framebuffer_key = key
        image = self.scene.grabFramebuffer()
        problem = self.scene.failure
        if problem is None and not self.scene.isValid():
            problem = "the OpenGL context is invalid"
        if problem is None and image.isNull():
            problem = "OpenGL rendered no image"
        if problem is not None:
            self._fail(problem)
            return QImage()
        image.setDevicePixelRatio(ratio)
        self._image = image
        self._stale = False
        self._style_buttons()  # the background may have changed with the theme
        return image

    def _fail(self, reason: str) -> None:
        """Stop rendering for good and show a notice saying why; logged once."""
        self.failure = reason
        self._image = QImage()
        self._stale = False
        log.warning("3D view disabled: %s", reason)
        self.timer.stop()
        self._render_timer.stop()
        for button in self.findChildren(QToolButton):
            button.hide()
        self.setToolTip(QCoreApplication.translate("PositionView3D", NOTICE_TOOLTIP))
        self.update()

    def _paint_notice(self) -> None:
        """Paint the failure notice, as the placeholder shows it."""
        painter = QPainter(self)
        painter.setPen(QPen(QColor(*NOTICE_COLOUR), 1, Qt.PenStyle.DashLine))
        painter.drawRect(self.rect().adjusted(0, 0, -1, -1))
        painter.drawText(
            self.rect().adjusted(8, 8, -8, -8),
            Qt.AlignmentFlag.AlignCenter | Qt.TextFlag.TextWordWrap,
            notice_text(self.failure or ""),
        )

    def grabFramebuffer(self) -> QImage:
        """The scene as it is now, rendered with OpenGL."""
        return self.render_scene()

    def paintEvent(self, event: QPaintEvent) -> None:
        """Paint the rendered scene and the scale; the scene is rendered first when the image
        does not fit the widget, or is out of date with no render on its way."""
        if self.failure is None and (
            (self._stale and not self._render_timer.isActive())
            or self._image.deviceIndependentSize().toSize() != self.size()
        ):
            self.render_scene()
        if self.failure is not None:
            self._paint_notice()
            return
        painter = QPainter(self)
        painter.drawImage(0, 0, self._image)
        painter.setPen(self._scale_colour)
        painter.drawText(
            self.rect().adjusted(6, 0, 0, -4),
            Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignBottom,
            self.scale_text(),
        )

    # -- camera: the mouse handlers of pyqtgraph's view, then a new image ----------------------
    def mousePressEvent(self, event: QMouseEvent) -> None:
        """Start a rotation (left), pan (middle or Ctrl) or zoom drag."""
        self.scene.mousePressEvent(event)

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        """Rotate, pan or zoom while a button is held."""
        self.scene.mouseMoveEvent(event)
        self._preset = None
        self._redraw()

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        """End the drag."""
        self.scene.mouseReleaseEvent(event)

    def wheelEvent(self, event: QWheelEvent) -> None:
        """Zoom."""
        self.scene.wheelEvent(event)
        self._preset = None
        self._redraw()


def _axis_label(name: str, units: str) -> str:
    """An axis's label in the scene: "X (mm)", "X (in)"."""
    return f"{name} ({unit_text(units)})"


def _blended_without_depth() -> dict:
    """pyqtgraph's "translucent" blending without its depth test, as antialiased lines are drawn.

    The lines' default, "additive", adds overlapping lines up: a dense trail turned white.
    """
    from OpenGL import GL
    from pyqtgraph.opengl.GLGraphicsItem import GLOptions

    return {**GLOptions["translucent"], GL.GL_DEPTH_TEST: False}


def _lines(
    colour: object,
    width: float,
    mode: str = "lines",
    kind: type | None = None,
    antialias: bool = True,
    **kwargs: object,
) -> object:
    """A GLLinePlotItem (or a `kind` of one) with placeholder vertices."""
    return (kind or gl.GLLinePlotItem)(
        pos=np.zeros((2, 3), dtype=np.float32),
        color=colour,
        width=width,
        mode=mode,
        antialias=antialias,
        **kwargs,
    )


class PositionView3DPlaceholder(QLabel):
    """Stands in for the 3D view when OpenGL is unavailable; same API, does nothing."""

    def __init__(self, reason: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("positionView3d")
        self.reason = reason
        self.setText(notice_text(reason))
        self.setToolTip(QCoreApplication.translate("PositionView3D", NOTICE_TOOLTIP))
        self.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.setWordWrap(True)
        self.setStyleSheet(NOTICE_STYLE)

    def refresh(self) -> None:
        """Nothing to draw."""

    def set_target(self, x: object, y: float | None = None, z: float | None = None) -> None:
        """Nothing to draw."""

    def clear_trail(self) -> None:
        """Nothing to draw."""

    def reset_view(self) -> None:
        """Nothing to draw."""

    def set_workspace(self, box: Box | None) -> None:
        """Nothing to draw."""

    def set_preview(self, points: object) -> None:
        """Nothing to draw."""

    def preview(self) -> list[tuple[float, float, float]]:
        """Nothing drawn: []."""
        return []

    def set_program(self, points: np.ndarray | None, rapid: np.ndarray | None = None) -> None:
        """Nothing to draw."""

    def set_program_done(self, row: int) -> None:
        """Nothing to draw."""

    def program(self) -> np.ndarray:
        """Nothing drawn: (0, 3)."""
        return np.zeros((0, 3))

    def grid_spacing(self) -> float:
        """No grid: 0.0."""
        return 0.0

    def set_view_preset(self, name: str) -> None:
        """No camera."""

    def set_follow(self, on: bool) -> None:
        """No camera."""

    def is_following(self) -> bool:
        """Never following."""
        return False

    def set_estimated(self, estimated: bool) -> None:
        """Nothing to draw."""

    def set_units(self, units: str) -> None:
        """Nothing drawn in any units."""
        check_units(units)

    def is_estimated(self) -> bool:
        """Nothing drawn: False."""
        return False


def make_position_view_3d(
    buffer: PositionBuffer,
    parent: QWidget | None = None,
    *,
    probe: Callable[[], bool] | None = None,
) -> QWidget:
    """The 3D view, or a placeholder label (objectName "positionView3d") if GL is unavailable.

    Nothing that touches OpenGL runs before `opengl_unavailable_reason()` (or `probe`, which
    says only yes or no) has found a context that can be made current; then the view is built
    and rendered once, and any failure there gives the placeholder too. Logged once.
    """
    if not QCoreApplication.testAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts):
        log.info("AA_ShareOpenGLContexts is not set: see share_opengl_contexts()")
    view = None
    try:
        if probe is None:
            reason = opengl_unavailable_reason()
        else:
            reason = None if probe() else _IMPORT_ERROR or NO_CONTEXT
        if reason is None:
            view = PositionView3D(buffer)
            view.render_scene()  # initialises OpenGL: a failure shows here, and is logged
            if view.failure is None:
                if parent is not None:
                    view.setParent(parent)
                return view
            return _placeholder(view.failure, parent, view)
    except Exception as exc:  # any failure: the placeholder
        reason = _failure(exc)
    log.warning("3D view disabled: %s", reason)
    return _placeholder(reason, parent, view)


def _placeholder(
    reason: str, parent: QWidget | None, failed: QWidget | None
) -> PositionView3DPlaceholder:
    """The placeholder for `reason`; a view that failed is deleted."""
    if failed is not None:
        failed.deleteLater()
    return PositionView3DPlaceholder(reason, parent)
