"""A top-level window kept on the screen it opens on: its first size, and a remembered one.

A first start asks for the window's preferred size, made smaller where the screen's available
geometry (without the desktop's panels) has less room, title bar and borders included; a
geometry remembered from a larger screen is fitted the same way. The window manager's frame is
known only once the window is shown, so until then `FRAME_GUESS` stands for it, and the fit is
checked again once the real frame is known (once: after that the operator sizes the window).
"""

from __future__ import annotations

import logging

from PySide6.QtCore import QEvent, QMargins, QObject, QPoint, QRect, QSize, QTimer
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QWidget

log = logging.getLogger(__name__)

FRAME_GUESS = QMargins(4, 32, 4, 4)  # a title bar and borders, until the real ones are known


def fitted(content: QRect, frame: QMargins, available: QRect) -> QRect:
    """`content` (the window without its frame) made as small and moved as far as needed for it
    and its `frame` to lie inside `available`; unchanged when it does already."""
    room = available.marginsRemoved(frame)
    width = min(content.width(), room.width())
    height = min(content.height(), room.height())
    left = min(max(content.left(), room.left()), room.left() + room.width() - width)
    top = min(max(content.top(), room.top()), room.top() + room.height() - height)
    return QRect(left, top, width, height)


def frame_margins(window: QWidget) -> QMargins | None:
    """The window manager's frame around `window`, None while it is not known."""
    frame, inner = window.frameGeometry(), window.geometry()
    if frame == inner:
        return None
    return QMargins(
        inner.left() - frame.left(),
        inner.top() - frame.top(),
        frame.right() - inner.right(),
        frame.bottom() - inner.bottom(),
    )


def available_geometry(window: QWidget) -> QRect:
    """The available geometry of the screen `window` is on (else the primary screen's)."""
    screen = window.screen() or QGuiApplication.primaryScreen()
    return screen.availableGeometry()


class ScreenFit(QObject):
    """Keeps `window` inside its screen's available geometry: `first_size`, `keep_inside`."""

    def __init__(self, window: QWidget) -> None:
        super().__init__(window)
        self.window = window
        self._checked = False  # whether the fit was checked with the real frame
        window.installEventFilter(self)

    def first_size(self, preferred: QSize) -> None:
        """The window's size on a first start: `preferred`, or the room the screen has, placed
        at the top left of the available geometry."""
        available = available_geometry(self.window)
        origin = available.topLeft()
        content = QRect(origin.x() + FRAME_GUESS.left(), origin.y() + FRAME_GUESS.top(), 0, 0)
        content.setSize(preferred)
        self._apply(fitted(content, FRAME_GUESS, available))

    def keep_inside(self) -> None:
        """Fit the window (a geometry restored from a larger screen) inside its screen."""
        window = self.window
        if window.isMaximized() or window.isFullScreen():
            return
        margins = self._margins()
        # pos() is the frame's top left (before the window is shown: where it will be)
        content = QRect(window.pos() + QPoint(margins.left(), margins.top()), window.size())
        rect = fitted(content, margins, available_geometry(window))
        if rect != content:
            log.info("window %s fitted to the screen: %s", content, rect)
            self._apply(rect)

    def _margins(self) -> QMargins:
        """The frame around the window: the window manager's once known, else the guess."""
        frame = frame_margins(self.window) if self.window.isVisible() else None
        return frame or FRAME_GUESS

    def _apply(self, rect: QRect) -> None:
        """Give the window's content `rect` (move places the frame's top left)."""
        margins = self._margins()
        self.window.resize(rect.size())
        self.window.move(QPoint(rect.left() - margins.left(), rect.top() - margins.top()))

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Once the window manager's frame is known, check the fit once with it."""
        # (getattr: while Qt tears the window down, this object's Python side may be gone)
        if (
            not getattr(self, "_checked", True)
            and watched is self.window
            and event.type() in (QEvent.Type.Move, QEvent.Type.Resize, QEvent.Type.Show)
            and frame_margins(self.window) is not None
        ):
            self._checked = True
            self.window.removeEventFilter(self)
            QTimer.singleShot(0, self.keep_inside)  # not from inside the window's own event
        return False


def fit_new_window(window: QWidget, width: int, height: int) -> ScreenFit:
    """Give a new top-level `window` the size `width` x `height`, or what its screen has room
    for; kept inside the screen once the window manager's frame is known."""
    fit = ScreenFit(window)
    fit.first_size(QSize(width, height))
    return fit
