"""Toolpaths: one program model for G-code, DXF, SVG and the panel's own CSV/JSON points.

`load_toolpath(path)` reads any of them (model.py holds the model, geometry.py flattens, measures
and checks it, runner.py runs it on a device); nothing here sends anything by itself.
"""

from drivers.toolpath.model import (
    ArcTo,
    Dwell,
    Line,
    Source,
    Step,
    Toolpath,
    ToolpathError,
)

__all__ = ["ArcTo", "Dwell", "Line", "Source", "Step", "Toolpath", "ToolpathError"]
