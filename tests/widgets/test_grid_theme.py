"""The 3D view's grid and its "grid N mm" scale follow the theme, in contrast."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QRect
from PySide6.QtGui import QAction, QColor, QImage
from PySide6.QtWidgets import QApplication

from app.window.theme import (
    DARK_PLOT_COLORS,
    LIGHT_PLOT_COLORS,
    PlotColors,
    apply_gl_colors,
    apply_theme,
    dark_palette,
    light_palette,
)
from widgets._gl_scene import contrast_ratio, grid_colour, label_colour
from widgets.position_buffer import PositionBuffer

pytestmark = pytest.mark.timeout(60)

NO_DISPLAY = "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen"
SHOTS = Path(os.environ.get("GRID_THEME_SHOTS", "/tmp/issue22_grid_theme"))
THEMES = pytest.mark.parametrize(
    "colors", [LIGHT_PLOT_COLORS, DARK_PLOT_COLORS], ids=["light", "dark"]
)
GRID_RANGE = (1.8, 4.5)  # visible, yet fainter than the data and the text
READABLE = 4.5  # WCAG AA for text


def _grid_contrast(background: QColor) -> float:
    return contrast_ratio(QColor.fromRgbF(*grid_colour(background)), background)


@pytest.mark.parametrize(
    "background",
    [
        LIGHT_PLOT_COLORS.background,
        DARK_PLOT_COLORS.background,
        light_palette().window().color().name(),
        dark_palette().window().color().name(),
        "#000000",
        "#808080",
        "#c0c0c0",
        "#3c3c44",
    ],
)
def test_grid_and_label_greys_contrast_with_any_background(background: str) -> None:
    colour = QColor(background)
    grid = _grid_contrast(colour)
    assert GRID_RANGE[0] <= grid < GRID_RANGE[1], (background, grid)
    assert contrast_ratio(label_colour(colour), colour) >= READABLE, background
    grey = QColor.fromRgbF(*grid_colour(colour))
    assert grey.red() == grey.green() == grey.blue()


def test_grid_is_darker_on_light_and_lighter_on_dark() -> None:
    light, dark = QColor(LIGHT_PLOT_COLORS.background), QColor(DARK_PLOT_COLORS.background)
    assert QColor.fromRgbF(*grid_colour(light)).lightness() < light.lightness()
    assert QColor.fromRgbF(*grid_colour(dark)).lightness() > dark.lightness()
    assert label_colour(light).lightness() < 100 < label_colour(dark).lightness()


def test_contrast_ratio_matches_wcag() -> None:
    assert contrast_ratio(QColor("black"), QColor("white")) == pytest.approx(21.0)
    assert contrast_ratio(QColor("#777777"), QColor("white")) == pytest.approx(4.48, abs=0.01)
    assert contrast_ratio(QColor("#123456"), QColor("#123456")) == pytest.approx(1.0)


# -- the real view, rendered with OpenGL -------------------------------------------------------


@pytest.fixture
def view(qtbot):
    """A shown 3D view over a short trail, looking from above."""
    from widgets.position_view_3d import PositionView3D, make_position_view_3d

    buffer = PositionBuffer(capacity=10)
    for i in range(3):
        buffer.append(float(i), 20.0 * i, 10.0 * i, 0.0)
    view = make_position_view_3d(buffer)
    qtbot.addWidget(view)
    assert isinstance(view, PositionView3D), getattr(view, "reason", "")
    view.resize(480, 320)
    view.show()
    qtbot.waitExposed(view)
    view.set_view_preset("top")
    return view


def _rendered(qtbot, view, colors: PlotColors) -> QImage:
    """The view's image once rendered over the theme's background, as the widget paints it."""
    background = QColor(colors.background)

    def shows_background() -> bool:
        image = view._image
        return not view._stale and image.pixelColor(image.width() - 3, 40) == background

    qtbot.waitUntil(shows_background, timeout=3000)  # re-rendered by itself, no new data
    return view.grab().toImage().convertToFormat(QImage.Format.Format_RGB32)


def _grey_line_pixels(image: QImage, background: QColor) -> int:
    """Pixels of a neutral grey that stands out from the background (the grid; the axes, the
    trail and the axis names are coloured)."""
    count = 0
    for y in range(40, image.height() - 30, 2):  # below the buttons, above the scale
        for x in range(0, image.width(), 2):
            pixel = image.pixelColor(x, y)
            grey = max(pixel.red(), pixel.green(), pixel.blue()) - min(
                pixel.red(), pixel.green(), pixel.blue()
            )
            if grey <= 6 and contrast_ratio(pixel, background) >= 1.4:
                count += 1
    return count


def _scale_contrast(image: QImage, background: QColor) -> float:
    """The strongest contrast with the background in the bottom-left corner (the scale text)."""
    ratio = image.devicePixelRatio()
    box = QRect(0, int(image.height() - 22 * ratio), int(130 * ratio), int(20 * ratio))
    return max(
        contrast_ratio(image.pixelColor(x, y), background)
        for x in range(box.left(), box.right())
        for y in range(box.top(), box.bottom())
    )


@pytest.mark.gl
@pytest.mark.skipif(NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)")
@THEMES
def test_the_grid_and_scale_are_drawn_to_contrast(qtbot, view, colors) -> None:
    apply_gl_colors(view.scene, colors)
    background = QColor(colors.background)
    assert view.background() == background
    grid = contrast_ratio(view.grid_colour(), background)
    assert GRID_RANGE[0] <= grid < GRID_RANGE[1]
    assert contrast_ratio(view.scale_colour(), background) >= READABLE
    image = _rendered(qtbot, view, colors)
    SHOTS.mkdir(parents=True, exist_ok=True)
    image.save(str(SHOTS / f"view3d_grid_{'dark' if colors.dark else 'light'}.png"))
    pixels = image.width() * image.height() // 4  # sampled every other row and column
    assert _grey_line_pixels(image, background) >= pixels // 100  # the grid's lines show
    assert _scale_contrast(image, background) >= READABLE


@pytest.mark.gl
@pytest.mark.skipif(NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)")
def test_a_theme_switch_recolours_the_grid_and_scale(qtbot, view) -> None:
    seen = []
    for colors in (LIGHT_PLOT_COLORS, DARK_PLOT_COLORS, LIGHT_PLOT_COLORS):
        apply_gl_colors(view.scene, colors)  # what the window does on a theme change
        background = QColor(colors.background)
        _rendered(qtbot, view, colors)
        seen.append((view.grid_colour().name(), view.scale_colour().name()))
        assert contrast_ratio(view.grid_colour(), background) >= GRID_RANGE[0]
        assert contrast_ratio(view.scale_colour(), background) >= READABLE
    assert seen[0] != seen[1]
    assert seen[0] == seen[2]


@pytest.fixture
def app_theme(qapp: QApplication) -> Iterator[QApplication]:
    """The application, given back with the system theme."""
    yield qapp
    apply_theme(qapp, "system")


@pytest.mark.gl
@pytest.mark.skipif(NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)")
def test_the_windows_theme_menu_recolours_the_3d_grid(qtbot, window, app_theme) -> None:
    from widgets.position_view_3d import PositionView3D

    view = window.view3d
    assert isinstance(view, PositionView3D), getattr(view, "reason", "")
    qtbot.waitUntil(lambda: window.findChild(QAction, "themeLight") is not None, timeout=5000)
    for name, colors in (("themeLight", LIGHT_PLOT_COLORS), ("themeDark", DARK_PLOT_COLORS)):
        window.findChild(QAction, name).trigger()
        background = QColor(colors.background)
        qtbot.waitUntil(lambda bg=background: view.background() == bg, timeout=3000)
        grid = contrast_ratio(view.grid_colour(), background)
        assert GRID_RANGE[0] <= grid < GRID_RANGE[1], name
        assert contrast_ratio(view.scale_colour(), background) >= READABLE, name
        qtbot.waitUntil(lambda: not view._stale, timeout=3000)  # rendered without new data
