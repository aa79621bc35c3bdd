"""app/window/layout/screen_fit.py: a first window and a remembered one fit the screen they open
on."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QMargins, QRect, QSize
from PySide6.QtWidgets import QMainWindow

from app.window.layout import screen_fit
from app.window.layout.screen_fit import FRAME_GUESS, ScreenFit, fit_new_window, fitted

pytestmark = pytest.mark.timeout(60)

FRAME = QMargins(2, 20, 2, 2)


@pytest.mark.parametrize(
    ("content", "available", "expected"),
    [
        # room enough: unchanged
        (QRect(10, 30, 800, 600), QRect(0, 0, 1600, 1000), QRect(10, 30, 800, 600)),
        # 1400x900 on 1280x720: as large as the room inside the frame, at its top left
        (QRect(2, 20, 1400, 900), QRect(0, 0, 1280, 720), QRect(2, 20, 1276, 698)),
        # a screen with a panel on top (available geometry starts at y 32)
        (QRect(2, 20, 1400, 900), QRect(0, 32, 1024, 608), QRect(2, 52, 1020, 586)),
        # small enough but off the right and bottom edges: moved in
        (QRect(900, 500, 400, 300), QRect(0, 0, 1024, 640), QRect(622, 338, 400, 300)),
        # off the left and top: moved in
        (QRect(-300, -50, 400, 300), QRect(0, 0, 1024, 640), QRect(2, 20, 400, 300)),
    ],
)
def test_fitted_puts_content_and_frame_inside_the_available_geometry(
    content: QRect, available: QRect, expected: QRect
) -> None:
    result = fitted(content, FRAME, available)
    assert result == expected
    assert available.contains(result.marginsAdded(FRAME))


@pytest.fixture
def small_screen(monkeypatch: pytest.MonkeyPatch) -> QRect:
    """A 1024x640 screen's available geometry, as the windows see it."""
    available = QRect(0, 0, 1024, 640)
    monkeypatch.setattr(screen_fit, "available_geometry", lambda window: QRect(available))
    return available


def _frame_rect(window: QMainWindow) -> QRect:
    """Where the window and its frame go once shown (before: pos() is the frame's top left)."""
    return QRect(window.pos(), window.size().grownBy(FRAME_GUESS))


def test_a_new_window_is_no_larger_than_the_screen(qtbot, small_screen: QRect) -> None:
    window = QMainWindow()
    qtbot.addWidget(window)
    fit_new_window(window, 1200, 800)
    room = small_screen.marginsRemoved(FRAME_GUESS)
    assert window.size() == room.size()
    fit_new_window(window, 640, 400)  # room enough: the size asked for
    assert window.size() == QSize(640, 400)


def test_a_remembered_geometry_larger_than_the_screen_is_fitted(qtbot, small_screen: QRect) -> None:
    window = QMainWindow()
    qtbot.addWidget(window)
    window.setGeometry(200, 100, 1400, 900)  # as restored from a 1600x1000 screen
    ScreenFit(window).keep_inside()
    assert small_screen.contains(_frame_rect(window)), _frame_rect(window)
    assert window.size() == small_screen.marginsRemoved(FRAME_GUESS).size()


def test_the_main_window_first_opens_within_the_screen(
    qtbot, small_screen: QRect, settings_file: object
) -> None:
    from app.window.main_window import MainWindow

    window = MainWindow()
    qtbot.addWidget(window)
    assert small_screen.contains(_frame_rect(window)), _frame_rect(window)
    window.close()
