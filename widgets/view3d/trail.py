"""The 3D view's trail: segment vertices broken at NaN rows, in a chunk-grown vertex buffer."""

from __future__ import annotations

import sys
from functools import cache

import numpy as np

from widgets.view3d.opengl import load_gl

TRAIL_CHUNK = 16_384  # the trail's vertex buffer grows by at least this many vertices


def segment_vertices(xyz: np.ndarray, unchanged: int = 0) -> tuple[np.ndarray, int]:
    """The line through the (n, 3) points in order, as segment end pairs (GL "lines" mode),
    with no segment to or from a NaN point (a break in the trail); and how many of these
    vertices depend only on the first `unchanged` points (so are the same as before)."""
    finite = np.isfinite(xyz).all(axis=1)
    joined = finite[:-1] & finite[1:]
    starts = np.flatnonzero(joined)
    vertices = np.empty((2 * len(starts), 3), dtype=np.float32)
    vertices[0::2] = xyz[starts]
    vertices[1::2] = xyz[starts + 1]
    same = 2 * int(np.count_nonzero(joined[: max(unchanged - 1, 0)]))
    return vertices, same


@cache
def trail_class() -> type:
    """A GLLinePlotItem whose vertex buffer grows in chunks and takes only what changed.

    pyqtgraph sends every vertex to the GPU whenever the data is set; the trail only grows at
    its end, so `set_vertices` says how many leading vertices are as before, and only the rest
    is written (glBufferSubData). With a pyqtgraph that draws without vertex buffers, all the
    vertices are set each time.
    """
    base = load_gl().GLLinePlotItem
    dirty = getattr(sys.modules[base.__module__], "DirtyFlag", None)
    partial_upload = dirty is not None and hasattr(base, "upload_vbo")

    class TrailLine(base):
        """The trail's line strip; see `set_vertices`."""

        _vertices = np.zeros((0, 3), dtype=np.float32)  # a chunk-grown store; `pos` views it
        _allocated = 0  # bytes of the vertex buffer on the GPU
        _upload_from = 0  # vertices before this one are on the GPU already

        def set_vertices(self, xyz: np.ndarray, unchanged: int = 0) -> None:
            """Draw the (n, 3) vertices `xyz`, the first `unchanged` being the same as before."""
            if not partial_upload:
                base.setData(self, pos=xyz)
                return
            n = len(xyz)
            unchanged = max(0, min(unchanged, n, 0 if self.pos is None else len(self.pos)))
            if n > len(self._vertices):
                grown = np.empty((max(n, 2 * len(self._vertices), TRAIL_CHUNK), 3), np.float32)
                grown[:unchanged] = self._vertices[:unchanged]
                self._vertices = grown
            self._vertices[unchanged:n] = xyz[unchanged:]
            self._upload_from = min(self._upload_from, unchanged)
            self.pos = self._vertices[:n]
            self.dirty_bits |= dirty.POSITION
            self.update()

        def setData(self, **kwds: object) -> None:
            """As GLLinePlotItem's; new positions go through `set_vertices`."""
            pos = kwds.pop("pos", None)
            if pos is not None and partial_upload:
                self.set_vertices(np.asarray(pos, dtype=np.float32).reshape(-1, 3))
            elif pos is not None:
                kwds["pos"] = pos
            super().setData(**kwds)

        def upload_vbo(self, vbo: object, arr: np.ndarray | None) -> None:
            """Write the vertices not on the GPU yet; grow the buffer when the store grew."""
            if vbo is not self.m_vbo_position or arr is None:
                super().upload_vbo(vbo, arr)
                return
            if not vbo.isCreated():
                vbo.create()
                self._allocated = 0
            vbo.bind()
            start = self._upload_from
            if self._allocated != self._vertices.nbytes:
                vbo.allocate(self._vertices.nbytes)
                self._allocated = self._vertices.nbytes
                start = 0
            part = self._vertices[start : len(arr)]
            if len(part):
                vbo.write(start * part.itemsize * 3, part, part.nbytes)
            vbo.release()
            self._upload_from = len(arr)

    return TrailLine
