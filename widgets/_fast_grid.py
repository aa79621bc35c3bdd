"""A plot's background grid, as pyqtgraph's GridItem draws it, at a fraction of the cost."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from pyqtgraph import functions as fn
from PySide6.QtCore import QLineF
from PySide6.QtGui import QPainter, QPicture


class FastGrid(pg.GridItem):
    """pyqtgraph's GridItem with the same lines drawn at a fraction of the cost.

    GridItem builds its picture line by line with a few numpy operations each, up to ~300
    lines in three levels, the finest often fully transparent: 12-14 ms each time the range
    changed (the time plot's step to a wider window, an XY refit), in one turn of the event
    loop. Here each level's positions come from one numpy expression and are drawn with one
    `drawLines`, and a level drawn fully transparent is left out.

    `set_value_scale` puts the lines where an axis scaled as much (`AxisItem.setScale`) has its
    ticks: at 0.1, 1, 10 inches of a plot in mm.
    """

    def __init__(self, colour: object) -> None:
        super().__init__()
        self.setPen(pg.mkPen(colour))
        self.setTextPen(None)
        self._per_unit = np.ones(2)  # the values shown per view unit, on x and y

    def set_value_scale(self, x: float = 1.0, y: float = 1.0) -> None:
        """Lines at round values of x * (view x) and y * (view y); redrawn."""
        scale = np.array([float(x), float(y)])
        if not np.array_equal(scale, self._per_unit):
            self._per_unit = scale
            self.picture = None
            self.update()

    def value_scale(self) -> tuple[float, float]:
        """The values shown per view unit, on x and y (1, 1 unless `set_value_scale`)."""
        return float(self._per_unit[0]), float(self._per_unit[1])

    def generatePicture(self) -> None:
        """Draw the grid's picture for the present view range (as GridItem, without text)."""
        if self.opts["textPen"] is not None:  # labels: pyqtgraph's own drawing (no scale)
            super().generatePicture()
            return
        rect = self.boundingRect()
        if rect.isNull() or self.deviceTransform_() is None:
            return
        self.picture = QPicture()
        painter = QPainter(self.picture)
        scale = self._per_unit
        ul = np.array([min(rect.left(), rect.right()), min(rect.top(), rect.bottom())])
        br = np.array([max(rect.left(), rect.right()), max(rect.top(), rect.bottom())])
        for ax, alpha, at in self.line_levels():
            pen = self.opts["pen"]
            colour = pen.color()
            colour.setAlpha(alpha)
            pen.setColor(colour)
            pen.setCosmetic(True)
            other = 1 - ax
            ends = (ul[other], br[other])
            at = at / scale[ax]  # drawn in view units
            if ax == 0:
                lines = [QLineF(v, ends[0], v, ends[1]) for v in at.tolist()]
            else:
                lines = [QLineF(ends[0], v, ends[1], v) for v in at.tolist()]
            painter.setPen(pen)
            painter.drawLines(lines)
        painter.end()

    def line_levels(self) -> list[tuple[int, int, np.ndarray]]:
        """The lines drawn, coarsest level last: (axis 0 x / 1 y, alpha, values shown)."""
        rect = self.boundingRect()
        widget = self.getViewWidget()
        if rect.isNull() or widget is None:
            return []
        view = widget.rect()
        dim = (view.width(), view.height())
        scale = self._per_unit  # positive: the grid's lines at round values shown
        ul = np.array([min(rect.left(), rect.right()), min(rect.top(), rect.bottom())]) * scale
        br = np.array([max(rect.left(), rect.right()), max(rect.top(), rect.bottom())]) * scale
        spacing = self.opts["tickSpacing"]
        levels = []
        for level in range(self.grid_depth - 1, -1, -1):
            with np.errstate(divide="ignore", invalid="ignore"):
                d = 10.0 ** np.floor(np.log10(np.abs((br - ul) / 10.0**level)) + 0.5)
            for ax in (0, 1):
                if level < len(spacing[ax]) and spacing[ax][level] is not None:
                    d[ax] = spacing[ax][level]
            first = np.floor(ul / d) * d
            count = (np.ceil(br / d) * d - first) / d + 0.5
            for ax in (0, 1):
                if level >= len(spacing[ax]) or not np.isfinite(count[ax]):
                    continue
                alpha = int(fn.clip_scalar(5 * (dim[ax] / count[ax] - 3), 0, 50))
                if alpha == 0:
                    continue  # drawn, these lines would not show
                at = first[ax] + np.arange(int(count[ax])) * d[ax]
                levels.append((ax, alpha, at[(at >= ul[ax]) & (at <= br[ax])]))
        return levels
