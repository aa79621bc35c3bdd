"""Rendering the 3D view: the scene drawn off screen into an image, a moment after a change."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QSize, Qt, QTimer
from PySide6.QtGui import QColor, QImage, QPainter, QPaintEvent, QPen, QResizeEvent

from widgets._pacer import run_paced
from widgets._view_common import REFRESH_INTERVAL_MS
from widgets.view3d.notice import NOTICE_COLOUR, notice_text

RENDER_DELAY_MS = 2 * REFRESH_INTERVAL_MS // 3  # a change is rendered this long after (below)


class RenderingMixin:
    """The drawing of PositionView3D: its `scene` rendered into `_image`, which it paints."""

    failure: str | None
    _image: QImage
    _stale: bool
    _preset: str | None
    _fitted_size: QSize
    _framebuffer_key: tuple[int, int, float] | None
    _scale_colour: QColor

    def _make_render_timer(self) -> None:
        """The single-shot timer that renders the scene RENDER_DELAY_MS after a change."""
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
