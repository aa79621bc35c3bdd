"""The 3D view's colours: its items' own, and greys that contrast with the theme's background."""

from __future__ import annotations

from PySide6.QtGui import QColor

TRAIL_COLOUR = (0.36, 0.42, 0.75, 1.0)
CURRENT_COLOUR = (1.0, 0.70, 0.0, 1.0)
TARGET_COLOUR = (0.85, 0.11, 0.38, 1.0)
ESTIMATED_COLOUR = (*CURRENT_COLOUR[:3], 0.5)  # a position estimated, not measured
AXIS_COLOURS = ((0.90, 0.22, 0.21, 1.0), (0.26, 0.63, 0.28, 1.0), (0.12, 0.53, 0.90, 1.0))
WORKSPACE_COLOUR = (0.30, 0.80, 0.78, 0.9)
PREVIEW_COLOUR = (1.0, 0.80, 0.50, 1.0)  # light orange (#ffcc80): a planned path, not yet run
THEME_ROLE = "theme_role"  # an item's colour role in app.window.theme.PlotColors: recoloured
BACKGROUND = (24, 24, 28, 255)
GRID_CONTRAST = 2.3  # the grid's grey against the background: visible, below the data
LABEL_CONTRAST = 9.0  # the scale text's grey against the background (WCAG asks 4.5 at least)


def relative_luminance(colour: QColor) -> float:
    """The WCAG 2 relative luminance of `colour` (0 black .. 1 white), alpha ignored."""

    def linear(channel: float) -> float:
        return channel / 12.92 if channel <= 0.04045 else ((channel + 0.055) / 1.055) ** 2.4

    return (
        0.2126 * linear(colour.redF())
        + 0.7152 * linear(colour.greenF())
        + 0.0722 * linear(colour.blueF())
    )


def contrast_ratio(first: QColor, second: QColor) -> float:
    """The WCAG 2 contrast ratio of two colours, 1 (the same) .. 21 (black on white)."""
    high, low = sorted((relative_luminance(first), relative_luminance(second)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def grey_at_contrast(background: QColor, ratio: float) -> QColor:
    """The grey with contrast `ratio` to `background`: darker than a light one, lighter than a
    dark one (as far as black or white allows)."""
    lum = relative_luminance(background) + 0.05
    if lum / 0.05 >= 1.05 / lum:  # more contrast to be had towards black
        target = max(lum / ratio - 0.05, 0.0)
    else:
        target = min(lum * ratio - 0.05, 1.0)
    channel = 12.92 * target if target <= 0.0031308 else 1.055 * target ** (1 / 2.4) - 0.055
    return QColor.fromRgbF(channel, channel, channel)


def grid_colour(background: QColor) -> tuple[float, float, float, float]:
    """The 3D grid's line colour over `background`, as pyqtgraph.opengl takes it."""
    grey = grey_at_contrast(background, GRID_CONTRAST)
    return (grey.redF(), grey.greenF(), grey.blueF(), 1.0)


def label_colour(background: QColor) -> QColor:
    """The colour of text drawn over `background` (the grid's scale), well readable."""
    return grey_at_contrast(background, LABEL_CONTRAST)
