"""OpenGL for the 3D view: pyqtgraph.opengl imported late, and a probe of the context."""

from __future__ import annotations

from types import ModuleType

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QGuiApplication, QOffscreenSurface, QOpenGLContext

# Qt platforms whose integration cannot draw a QOpenGLWidget (no RasterGLSurface capability).
# Under a running X server "offscreen" still creates GLX contexts, but reports them as OpenGL 2.0
# whatever the driver gives: pyqtgraph's initializeGL then raises, and that exception, thrown
# through Qt's C++ frames (paintEvent -> sendEvent -> a Python eventFilter -> initializeGL),
# left a corrupted reference that crashed the interpreter's last garbage collection (issue 11).
NO_GL_WIDGET_PLATFORMS = frozenset({"offscreen", "minimal", "vnc", "linuxfb"})
MIN_GL_VERSION = (2, 1)  # what pyqtgraph.opengl requires of a desktop (not ES) context
GL_VERSION = 0x1F02
NO_CONTEXT = "no OpenGL context can be created on this display"

# pyqtgraph.opengl, imported by `load_gl()` when a view is first made: importing it takes a
# fifth of a second, and PyOpenGL may be missing or broken (this module must still import).
gl: ModuleType | None = None
_IMPORT_ERROR: str | None = None


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


def import_error() -> str | None:
    """Why `load_gl()` could not import pyqtgraph.opengl, or None."""
    return _IMPORT_ERROR


def failure_text(exc: BaseException) -> str:
    """An exception in words, for the notice and the log."""
    return f"{type(exc).__name__}: {exc}"


def opengl_problem() -> str | None:
    """Why OpenGL cannot draw the 3D scene here, or None when it can; needs a QGuiApplication.

    Makes no call that can crash the process: it looks at the Qt platform, then creates a
    context and an offscreen surface, makes the context current and reads the version it
    reports, the one pyqtgraph checks in its initializeGL.
    """
    if QGuiApplication.instance() is None:
        return "no QGuiApplication yet"
    platform = QGuiApplication.platformName()
    if platform in NO_GL_WIDGET_PLATFORMS:
        return f"the Qt platform {platform!r} cannot draw OpenGL widgets"
    shared = QOpenGLContext.globalShareContext()
    if QCoreApplication.testAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts) and (
        shared is None or not shared.isValid()
    ):
        return NO_CONTEXT
    context = QOpenGLContext()
    if shared is not None:
        context.setShareContext(shared)
    if not context.create() or not context.isValid():
        return NO_CONTEXT
    surface = QOffscreenSurface()
    surface.setFormat(context.format())
    surface.create()
    try:
        if not surface.isValid():
            return "no OpenGL surface can be created on this display"
        if not context.makeCurrent(surface):
            return "an OpenGL context was created but cannot be made current"
        try:
            return _version_problem(context)
        finally:
            context.doneCurrent()
    finally:
        surface.destroy()


def _version_problem(context: QOpenGLContext) -> str | None:
    """Why the current `context` is too old for pyqtgraph.opengl, or None."""
    if context.isOpenGLES():
        return None  # pyqtgraph only warns
    version = context.format().version()
    if tuple(version) >= MIN_GL_VERSION:
        return None
    driver = context.functions().glGetString(GL_VERSION) or "unknown"
    return (
        f"the OpenGL context reports version {version[0]}.{version[1]} (driver: {driver}),"
        f" {MIN_GL_VERSION[0]}.{MIN_GL_VERSION[1]} is needed"
    )
