"""The traffic logs the operator opens from the main window, each in a viewer window of its own."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, QUrl
from PySide6.QtGui import QDesktopServices
from PySide6.QtWidgets import QWidget

from app.common.session_log import log_folder

if TYPE_CHECKING:
    from app.window.console.log_viewer import LogViewer


class LogViewers(QObject):
    """Opens logs in viewers (decoded as `protocol()` says until the log's notes say better),
    and closes those still open with the window."""

    def __init__(self, parent: QWidget, protocol: Callable[[], str]) -> None:
        super().__init__(parent)
        self._parent = parent
        self._protocol = protocol
        self.viewers: list[LogViewer] = []
        self.ask_path: Callable[[], str] = self._ask_path

    def _ask_path(self) -> str:
        from app.window.console.log_viewer import ask_open_path

        return ask_open_path(self._parent)

    def open(self, path: str | None = None) -> LogViewer | None:
        """Open a traffic log in a viewer window (asks for the file when `path` is None)."""
        from app.window.console.log_viewer import LogViewer

        viewer = LogViewer(None, self._protocol())
        viewer.ask_path = self.ask_path
        chosen = path if path is not None else self.ask_path()
        if not chosen:
            viewer.deleteLater()
            return None
        self.viewers = [v for v in self.viewers if v.isVisible()]  # closed ones go
        self.viewers.append(viewer)
        viewer.show()
        viewer.open(chosen)
        return viewer

    @staticmethod
    def open_folder() -> None:
        """Show the session logs' folder in the desktop's file manager."""
        QDesktopServices.openUrl(QUrl.fromLocalFile(str(log_folder())))

    def close_all(self) -> None:
        """The window closes: so do the viewers."""
        for viewer in self.viewers:
            viewer.close()
