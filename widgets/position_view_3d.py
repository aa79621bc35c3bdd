"""3D position view (pyqtgraph.opengl), with a placeholder when OpenGL is unavailable."""

from __future__ import annotations

import logging
from collections.abc import Callable

import numpy as np
from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import (
    QImage,
    QMouseEvent,
    QOpenGLContext,
    QPainter,
    QPaintEvent,
    QVector3D,
    QWheelEvent,
)
from PySide6.QtWidgets import QLabel, QWidget

from widgets._axes import target_point
from widgets._view_common import BufferedViewMixin
from widgets.position_buffer import PositionBuffer

log = logging.getLogger(__name__)

try:  # PyOpenGL may be missing or broken: the module must still import
    import pyqtgraph.opengl as gl

    _IMPORT_ERROR: str | None = None
except Exception as exc:  # any failure means "no 3D view"
    gl = None
    _IMPORT_ERROR = f"{type(exc).__name__}: {exc}"

TRAIL_COLOUR = (0.36, 0.42, 0.75, 1.0)
CURRENT_COLOUR = (1.0, 0.70, 0.0, 1.0)
TARGET_COLOUR = (0.85, 0.11, 0.38, 1.0)
AXIS_COLOURS = ((0.90, 0.22, 0.21, 1.0), (0.26, 0.63, 0.28, 1.0), (0.12, 0.53, 0.90, 1.0))


def share_opengl_contexts() -> None:
    """Call before the QApplication exists: lets the 3D view survive a new top-level window.

    pyqtgraph caches its shader programs globally, so without shared contexts a second
    GLViewWidget, or this one moved to another window (a floated dock), fails to draw
    (pyqtgraph issues #1822, #3455).
    """
    QCoreApplication.setAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts)


def opengl_available() -> bool:
    """Whether pyqtgraph.opengl imports and an OpenGL context can be created here."""
    if gl is None:
        return False
    context = QOpenGLContext()
    return bool(context.create())


class PositionView3D(BufferedViewMixin, QWidget):
    """Grid, axes, trail, current and target markers in 3D, refreshed from a buffer.

    The scene is drawn with OpenGL by `self.scene`, a pyqtgraph GLViewWidget that is never
    shown, into an image this plain widget paints. A QOpenGLWidget inside the window would make
    Qt compose the whole window through OpenGL on every repaint of any widget: with software
    OpenGL (Mesa llvmpipe) that took 75-90 ms a frame, while rendering the scene alone into an
    image takes about 1.5 ms.
    """

    def __init__(
        self, buffer: PositionBuffer, parent: QWidget | None = None, grid_mm: float = 200.0
    ) -> None:
        if gl is None:
            raise RuntimeError(f"pyqtgraph.opengl is unavailable ({_IMPORT_ERROR})")
        super().__init__(parent)
        self.setObjectName("positionView3d")
        self.setToolTip("Drag to rotate, wheel to zoom, middle-drag to pan")
        self.setMinimumSize(160, 120)
        self.buffer = buffer
        self.grid_mm = float(grid_mm)
        self._target: tuple[float, float, float] | None = None
        self._image = QImage()
        self._stale = True
        self.scene = gl.GLViewWidget()  # no parent: it must stay out of this window
        self.scene.setBackgroundColor((24, 24, 28, 255))
        self.destroyed.connect(self.scene.deleteLater)
        self.addItem = self.scene.addItem

        grid = gl.GLGridItem()
        grid.setSize(self.grid_mm, self.grid_mm)
        grid.setSpacing(self.grid_mm / 20, self.grid_mm / 20)
        self.addItem(grid)
        half = self.grid_mm / 2
        axis_pos = np.array(
            [[0, 0, 0], [half, 0, 0], [0, 0, 0], [0, half, 0], [0, 0, 0], [0, 0, half]],
            dtype=np.float32,
        )
        axis_colour = np.repeat(np.array(AXIS_COLOURS, dtype=np.float32), 2, axis=0)
        self.axes_item = gl.GLLinePlotItem(
            pos=axis_pos, color=axis_colour, width=2.0, mode="lines", antialias=True
        )
        self.addItem(self.axes_item)
        for index, name in enumerate("XYZ"):
            end = np.zeros(3)
            end[index] = half * 1.05
            colour = [int(255 * c) for c in AXIS_COLOURS[index]]
            self.addItem(gl.GLTextItem(pos=end, text=f"{name} (mm)", color=colour))

        self.trail = gl.GLLinePlotItem(
            pos=np.zeros((2, 3), dtype=np.float32),
            color=TRAIL_COLOUR,
            width=1.5,
            mode="line_strip",
            antialias=True,
        )
        self.current_marker = gl.GLScatterPlotItem(
            pos=np.zeros((1, 3), dtype=np.float32), color=CURRENT_COLOUR, size=12.0
        )
        self.target_marker = gl.GLScatterPlotItem(
            pos=np.zeros((1, 3), dtype=np.float32), color=TARGET_COLOUR, size=14.0
        )
        self.target_marker.setGLOptions("translucent")
        for item in (self.trail, self.current_marker, self.target_marker):
            item.setVisible(False)
            self.addItem(item)

        self.start_refresh_timer()
        self.reset_view()

    def refresh(self) -> None:
        """Redraw from the buffer if it changed since the last refresh."""
        rows = self.changed_rows()
        if rows is None:
            return
        if not len(rows):
            self.trail.setVisible(False)
            self.current_marker.setVisible(False)
            self._redraw()
            return
        points = np.ascontiguousarray(rows[:, 1:4], dtype=np.float32)
        self.trail.setVisible(len(points) >= 2)
        if len(points) >= 2:
            self.trail.setData(pos=points)
        self.current_marker.setData(pos=points[-1:])
        self.current_marker.setVisible(True)
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
        self._redraw()

    def reset_view(self) -> None:
        """Look at the data (or the whole grid) from above at an angle."""
        rows = self.buffer.view()
        if len(rows):
            lo, hi = rows[:, 1:4].min(axis=0), rows[:, 1:4].max(axis=0)
            centre = (lo + hi) / 2
            extent = float(max(np.max(hi - lo), self.grid_mm / 4))
        else:
            centre, extent = np.zeros(3), self.grid_mm * 0.7
        self.scene.setCameraPosition(
            pos=QVector3D(*map(float, centre)), distance=extent * 1.8, elevation=30, azimuth=-60
        )
        self._redraw()

    # -- drawing -----------------------------------------------------------------------------
    def _redraw(self) -> None:
        """Mark the image out of date; it is rendered at the next paint."""
        self._stale = True
        self.update()

    def render_scene(self) -> QImage:
        """Render the scene at the widget's size now, and keep the image."""
        ratio = self.devicePixelRatioF()
        self.scene.resize(max(1, self.width()), max(1, self.height()))
        image = self.scene.grabFramebuffer()
        image.setDevicePixelRatio(ratio)
        self._image = image
        self._stale = False
        return image

    def grabFramebuffer(self) -> QImage:
        """The scene as it is now, rendered with OpenGL."""
        return self.render_scene()

    def paintEvent(self, event: QPaintEvent) -> None:
        """Paint the rendered scene, rendering it first if it is out of date."""
        if self._stale or self._image.size() != self.size() * self.devicePixelRatioF():
            self.render_scene()
        QPainter(self).drawImage(0, 0, self._image)

    # -- camera: the mouse handlers of pyqtgraph's view, then a new image ----------------------
    def mousePressEvent(self, event: QMouseEvent) -> None:
        """Start a rotation (left), pan (middle or Ctrl) or zoom drag."""
        self.scene.mousePressEvent(event)

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        """Rotate, pan or zoom while a button is held."""
        self.scene.mouseMoveEvent(event)
        self._redraw()

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        """End the drag."""
        self.scene.mouseReleaseEvent(event)

    def wheelEvent(self, event: QWheelEvent) -> None:
        """Zoom."""
        self.scene.wheelEvent(event)
        self._redraw()


class PositionView3DPlaceholder(QLabel):
    """Stands in for the 3D view when OpenGL is unavailable; same API, does nothing."""

    def __init__(self, reason: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("positionView3d")
        self.reason = reason
        self.setText(
            "3D view unavailable: OpenGL could not be initialised.\n"
            f"({reason})\nThe 2D view shows the same positions."
        )
        self.setToolTip("Needs OpenGL 2.0 or newer (e.g. Mesa); see the README.")
        self.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.setWordWrap(True)
        self.setStyleSheet("color: #616161; border: 1px dashed #9e9e9e;")

    def refresh(self) -> None:
        """Nothing to draw."""

    def set_target(self, x: object, y: float | None = None, z: float | None = None) -> None:
        """Nothing to draw."""

    def clear_trail(self) -> None:
        """Nothing to draw."""

    def reset_view(self) -> None:
        """Nothing to draw."""


def make_position_view_3d(
    buffer: PositionBuffer,
    parent: QWidget | None = None,
    *,
    probe: Callable[[], bool] = opengl_available,
) -> QWidget:
    """The 3D view, or a placeholder label (objectName "positionView3d") if GL is unavailable."""
    if not QCoreApplication.testAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts):
        log.info("AA_ShareOpenGLContexts is not set: see share_opengl_contexts()")
    try:
        if probe():
            view = PositionView3D(buffer)
            if parent is not None:
                view.setParent(parent)
            return view
        reason = _IMPORT_ERROR or "no OpenGL context can be created on this display"
    except Exception as exc:  # any failure: the placeholder
        reason = f"{type(exc).__name__}: {exc}"
    log.warning("3D view disabled: %s", reason)
    return PositionView3DPlaceholder(reason, parent)
