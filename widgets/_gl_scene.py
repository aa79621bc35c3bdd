"""The 3D view's helpers under their name of before; each is now in its module of widgets.view3d."""

from __future__ import annotations

from widgets.gl_share import share_opengl_contexts
from widgets.view3d.camera import (
    FIELD_OF_VIEW,
    MARGINS_PX,
    VIEW_ANGLES,
    VIEW_PRESETS,
    camera_rotation,
    fit_camera,
)
from widgets.view3d.colours import (
    GRID_CONTRAST,
    LABEL_CONTRAST,
    contrast_ratio,
    grey_at_contrast,
    grid_colour,
    label_colour,
    relative_luminance,
)
from widgets.view3d.geometry import (
    GRID_CELLS,
    INCH_STEPS,
    MIN_SPAN_MM,
    MM_STEPS,
    Grid,
    axis_ends,
    box_corners,
    box_edges,
    grid_for,
    nice_spacing,
    spacing_text,
)
from widgets.view3d.navigation import BUTTON_STYLE, BUTTONS, overlay_buttons
from widgets.view3d.opengl import (
    GL_VERSION,
    MIN_GL_VERSION,
    NO_CONTEXT,
    NO_GL_WIDGET_PLATFORMS,
    _version_problem,
    opengl_problem,
)
from widgets.view3d.program_overlay import preview_array, preview_tuples
from widgets.view3d.trail import segment_vertices

__all__ = [
    "BUTTONS",
    "BUTTON_STYLE",
    "FIELD_OF_VIEW",
    "GL_VERSION",
    "GRID_CELLS",
    "GRID_CONTRAST",
    "INCH_STEPS",
    "LABEL_CONTRAST",
    "MARGINS_PX",
    "MIN_GL_VERSION",
    "MIN_SPAN_MM",
    "MM_STEPS",
    "NO_CONTEXT",
    "NO_GL_WIDGET_PLATFORMS",
    "VIEW_ANGLES",
    "VIEW_PRESETS",
    "Grid",
    "_version_problem",
    "axis_ends",
    "box_corners",
    "box_edges",
    "camera_rotation",
    "contrast_ratio",
    "fit_camera",
    "grey_at_contrast",
    "grid_colour",
    "grid_for",
    "label_colour",
    "nice_spacing",
    "opengl_problem",
    "overlay_buttons",
    "preview_array",
    "preview_tuples",
    "relative_luminance",
    "segment_vertices",
    "share_opengl_contexts",
    "spacing_text",
]
