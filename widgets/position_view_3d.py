"""3D position view (pyqtgraph.opengl), with a placeholder when OpenGL is unavailable."""

from __future__ import annotations

import logging
from collections.abc import Callable

import numpy as np
from PySide6.QtCore import QCoreApplication, QSize, Qt
from PySide6.QtGui import QColor, QImage, QVector3D
from PySide6.QtWidgets import QToolButton, QWidget

from widgets._axes import Box, target_point
from widgets._i18n import fill
from widgets._program_path import ProgramPath
from widgets._units import INCH, MM, check_units
from widgets._view_common import BufferedViewMixin
from widgets.gl_share import share_opengl_contexts  # for its callers of before; no OpenGL
from widgets.position_buffer import PositionBuffer
from widgets.view3d.camera import FIELD_OF_VIEW
from widgets.view3d.colours import (
    AXIS_COLOURS,
    BACKGROUND,
    CURRENT_COLOUR,
    ESTIMATED_COLOUR,
    PREVIEW_COLOUR,
    TARGET_COLOUR,
    TRAIL_COLOUR,
    WORKSPACE_COLOUR,
)
from widgets.view3d.geometry import box_edges, spacing_text
from widgets.view3d.navigation import NavigationMixin
from widgets.view3d.notice import NOTICE_TOOLTIP, PositionView3DPlaceholder, notice_text
from widgets.view3d.opengl import NO_CONTEXT, failure_text, import_error, load_gl, opengl_problem
from widgets.view3d.program_overlay import ProgramOverlayMixin
from widgets.view3d.rendering import RenderingMixin
from widgets.view3d.scene_items import SceneItemsMixin, axis_label, scene_class
from widgets.view3d.trail import segment_vertices

__all__ = [  # what other modules take from here; the parts are in widgets.view3d
    "AXIS_COLOURS",
    "BACKGROUND",
    "CURRENT_COLOUR",
    "ESTIMATED_COLOUR",
    "PREVIEW_COLOUR",
    "TARGET_COLOUR",
    "TRAIL_COLOUR",
    "WORKSPACE_COLOUR",
    "PositionView3D",
    "PositionView3DPlaceholder",
    "load_gl",
    "make_position_view_3d",
    "notice_text",
    "opengl_available",
    "opengl_unavailable_reason",
    "share_opengl_contexts",
]

log = logging.getLogger(__name__)


def opengl_unavailable_reason() -> str | None:
    """Why the 3D view cannot be drawn here (no pyqtgraph.opengl, platform, context), or None."""
    if load_gl() is None:
        return f"pyqtgraph.opengl is unavailable ({import_error()})"
    return opengl_problem()


def opengl_available() -> bool:
    """Whether pyqtgraph.opengl imports and a usable OpenGL context can be made current here."""
    return opengl_unavailable_reason() is None


class PositionView3D(
    SceneItemsMixin,
    ProgramOverlayMixin,
    NavigationMixin,
    RenderingMixin,
    BufferedViewMixin,
    QWidget,
):
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

    The parts are in widgets.view3d: the scene's items and grid (SceneItemsMixin), the preview
    and program (ProgramOverlayMixin), the camera (NavigationMixin), the rendering
    (RenderingMixin).
    """

    def __init__(self, buffer: PositionBuffer, parent: QWidget | None = None) -> None:
        if load_gl() is None:
            raise RuntimeError(f"pyqtgraph.opengl is unavailable ({import_error()})")
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
        self._make_render_timer()
        self.failure: str | None = None
        self.scene = scene_class()()  # no parent: it must stay out of this window
        self._scale_colour = QColor()
        self.scene.setBackgroundColor(BACKGROUND)
        self.scene.opts["fov"] = FIELD_OF_VIEW
        self.destroyed.connect(self.scene.deleteLater)
        self.addItem = self.scene.addItem
        self._trail_token: tuple[int, int, int] | None = None
        self._make_items()

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
            label.setData(text=axis_label(name, units))
        self._fit_grid()
        self._redraw()

    def units(self) -> str:
        """The units the grid and the labels are in: "mm" or "in"."""
        return self._units

    def set_estimated(self, estimated: bool) -> None:
        """Draw the current marker faded while its position is estimated, not measured."""
        self._estimated = bool(estimated)
        self.current_marker.setData(color=ESTIMATED_COLOUR if estimated else CURRENT_COLOUR)
        self._redraw()

    def is_estimated(self) -> bool:
        """Whether the current marker shows an estimated position."""
        return self._estimated

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
            reason = None if probe() else import_error() or NO_CONTEXT
        if reason is None:
            view = PositionView3D(buffer)
            view.render_scene()  # initialises OpenGL: a failure shows here, and is logged
            if view.failure is None:
                if parent is not None:
                    view.setParent(parent)
                return view
            return _placeholder(view.failure, parent, view)
    except Exception as exc:  # any failure: the placeholder
        reason = failure_text(exc)
    log.warning("3D view disabled: %s", reason)
    return _placeholder(reason, parent, view)


def _placeholder(
    reason: str, parent: QWidget | None, failed: QWidget | None
) -> PositionView3DPlaceholder:
    """The placeholder for `reason`; a view that failed is deleted."""
    if failed is not None:
        failed.deleteLater()
    return PositionView3DPlaceholder(reason, parent)
