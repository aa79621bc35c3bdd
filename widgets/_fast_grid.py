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
    """

    def __init__(self, colour: object) -> None:
        super().__init__()
        self.setPen(pg.mkPen(colour))
        self.setTextPen(None)

    def generatePicture(self) -> None:
        """Draw the grid's picture for the present view range (as GridItem, without text)."""
        if self.opts["textPen"] is not None:  # labels: pyqtgraph's own drawing
            super().generatePicture()
            return
        rect = self.boundingRect()
        device_transform = self.deviceTransform_()
        if rect.isNull() or device_transform is None:
            return
        self.picture = QPicture()
        painter = QPainter(self.picture)
        view = self.getViewWidget().rect()
        dim = (view.width(), view.height())
        ul = np.array([min(rect.left(), rect.right()), min(rect.top(), rect.bottom())])
        br = np.array([max(rect.left(), rect.right()), max(rect.top(), rect.bottom())])
        spacing = self.opts["tickSpacing"]
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
                pen = self.opts["pen"]
                colour = pen.color()
                colour.setAlpha(alpha)
                pen.setColor(colour)
                pen.setCosmetic(True)
                at = first[ax] + np.arange(int(count[ax])) * d[ax]
                at = at[(at >= ul[ax]) & (at <= br[ax])]
                other = 1 - ax
                ends = (ul[other], br[other])
                if ax == 0:
                    lines = [QLineF(v, ends[0], v, ends[1]) for v in at.tolist()]
                else:
                    lines = [QLineF(ends[0], v, ends[1], v) for v in at.tolist()]
                painter.setPen(pen)
                painter.drawLines(lines)
        painter.end()
