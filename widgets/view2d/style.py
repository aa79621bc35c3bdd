"""The 2D view's colours, and its plots' background grid and steady axes."""

from __future__ import annotations

import pyqtgraph as pg

from widgets._fast_grid import FastGrid

GRID_COLOUR = (60, 60, 60)
AXIS_COLOURS = {"x": "#e53935", "y": "#43a047", "z": "#1e88e5"}
TRAIL_COLOUR = "#5c6bc0"
CURRENT_COLOUR = "#ffb300"
TARGET_COLOUR = "#d81b60"
WORKSPACE_COLOUR = "#26a69a"
PREVIEW_COLOUR = "#ffcc80"  # light orange: a planned path, not yet run
THEME_ROLE = "theme_role"  # an item's colour role in app.window.theme.PlotColors: recoloured


def grid() -> pg.GridItem:
    """A background grid; unlike the axes' own grid (showGrid), it does not repaint the axes'
    cached pictures on every frame, which cost 30 ms a frame under a software rasteriser."""
    return FastGrid(GRID_COLOUR)


def steady_axes(plot: pg.PlotItem) -> None:
    """Axes whose size and label change only when they must.

    No SI prefix ("(x0.001)"; on the hidden axes too, which else rebuilt their label's HTML on
    every range change). The tick labels' space only grows: with the XY view's aspect locked, a
    narrower Y label widened the view, which changed the ranges and the labels back, and the
    layout swung between the two every frame (the axes, the grid and the layout rebuilt ~30
    times a second with nothing moving).
    """
    for side in ("left", "bottom", "right", "top"):
        axis = plot.getAxis(side)
        axis.enableAutoSIPrefix(False)
        axis.setStyle(autoReduceTextSpace=False)
