"""Shared OpenGL contexts for the application, set before the QApplication exists; imports no
OpenGL and no numpy (the panel's start-up waits for neither)."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt


def share_opengl_contexts() -> None:
    """Call before the QApplication exists: lets the 3D view survive a new top-level window.

    pyqtgraph caches its shader programs globally, so without shared contexts a second
    GLViewWidget, or this one moved to another window (a floated dock), fails to draw
    (pyqtgraph issues #1822, #3455). Here, not in position_view_3d, so that setting it imports
    no OpenGL.
    """
    QCoreApplication.setAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts)
