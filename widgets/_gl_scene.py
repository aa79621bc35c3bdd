"""Helpers of the 3D position view: OpenGL probe, grid sizing, box edges, camera, buttons."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Qt
from PySide6.QtGui import QColor, QGuiApplication, QOffscreenSurface, QOpenGLContext
from PySide6.QtWidgets import QToolButton, QWidget

from widgets._axes import Box
from widgets._i18n import number_text
from widgets._units import INCH, MM, MM_PER_INCH, check_units
from widgets.gl_share import share_opengl_contexts as share_opengl_contexts

# Qt platforms whose integration cannot draw a QOpenGLWidget (no RasterGLSurface capability).
# Under a running X server "offscreen" still creates GLX contexts, but reports them as OpenGL 2.0
# whatever the driver gives: pyqtgraph's initializeGL then raises, and that exception, thrown
# through Qt's C++ frames (paintEvent -> sendEvent -> a Python eventFilter -> initializeGL),
# left a corrupted reference that crashed the interpreter's last garbage collection (issue 11).
NO_GL_WIDGET_PLATFORMS = frozenset({"offscreen", "minimal", "vnc", "linuxfb"})
MIN_GL_VERSION = (2, 1)  # what pyqtgraph.opengl requires of a desktop (not ES) context
GL_VERSION = 0x1F02
NO_CONTEXT = "no OpenGL context can be created on this display"

MIN_SPAN_MM = 10.0
GRID_CELLS = 10
MM_STEPS = (1.0, 2.0, 5.0, 10.0)  # grid spacings in mm: 1-2-5 x 10^n
INCH_STEPS = (1.0, 2.5, 5.0, 10.0)  # in inches: 0.1, 0.25, 0.5, 1, 2.5 ...
FIELD_OF_VIEW = 35.0  # degrees across; pyqtgraph's 60 distorts the flat presets
MARGINS_PX = np.array((8, 8, 20, 30))  # left, right, bottom (scale text), top (buttons)
GRID_CONTRAST = 2.3  # the grid's grey against the background: visible, below the data
LABEL_CONTRAST = 9.0  # the scale text's grey against the background (WCAG asks 4.5 at least)

# (elevation, azimuth) in degrees, as pyqtgraph's GLViewWidget camera uses them
VIEW_ANGLES: dict[str, tuple[float, float]] = {
    "top": (90.0, -90.0),  # X right, Y up
    "front": (0.0, -90.0),  # from -Y: X right, Z up
    "side": (0.0, 0.0),  # from +X: Y right, Z up
    "iso": (30.0, -60.0),
}
VIEW_PRESETS = (*VIEW_ANGLES, "fit")

BUTTONS = (
    (
        "view3dTop",
        QT_TRANSLATE_NOOP("PositionView3D", "Top"),
        QT_TRANSLATE_NOOP("PositionView3D", "View from above (X right, Y up)"),
    ),
    (
        "view3dFront",
        QT_TRANSLATE_NOOP("PositionView3D", "Front"),
        QT_TRANSLATE_NOOP("PositionView3D", "View from the front (X right, Z up)"),
    ),
    (
        "view3dSide",
        QT_TRANSLATE_NOOP("PositionView3D", "Side"),
        QT_TRANSLATE_NOOP("PositionView3D", "View from the side (Y right, Z up)"),
    ),
    (
        "view3dIso",
        QT_TRANSLATE_NOOP("PositionView3D", "Iso"),
        QT_TRANSLATE_NOOP("PositionView3D", "View from above at an angle"),
    ),
    (
        "view3dFit",
        QT_TRANSLATE_NOOP("PositionView3D", "Fit"),
        QT_TRANSLATE_NOOP("PositionView3D", "Zoom to the trail, the target and the workspace"),
    ),
    (
        "view3dFollow",
        QT_TRANSLATE_NOOP("PositionView3D", "Follow"),
        QT_TRANSLATE_NOOP("PositionView3D", "Keep the camera on the current position"),
    ),
)
BUTTON_STYLE = (
    "QToolButton { color: #ddd; background: rgba(255, 255, 255, 24); border: none;"
    " border-radius: 3px; padding: 2px 6px; }"
    " QToolButton:hover { background: rgba(255, 255, 255, 60); }"
    " QToolButton:checked { background: rgba(255, 179, 0, 110); color: white; }"
)


class Grid(NamedTuple):
    """An XY grid in mm: x0..x1, y0..y1 with lines every `spacing`."""

    x0: float
    x1: float
    y0: float
    y1: float
    spacing: float

    def contains(self, points: np.ndarray) -> bool:
        """Whether every (x, y, ...) row lies on the grid."""
        if not len(points):
            return True
        tol = self.spacing * 1e-6
        lo, hi = points[:, :2].min(axis=0), points[:, :2].max(axis=0)
        return bool(
            lo[0] >= self.x0 - tol
            and hi[0] <= self.x1 + tol
            and lo[1] >= self.y0 - tol
            and hi[1] <= self.y1 + tol
        )

    def lines(self) -> np.ndarray:
        """The grid's line segments as (2n, 3) float32 vertices at z = 0."""
        xs = np.arange(self.x0, self.x1 + self.spacing / 2, self.spacing)
        ys = np.arange(self.y0, self.y1 + self.spacing / 2, self.spacing)
        vertical = [((x, self.y0, 0.0), (x, self.y1, 0.0)) for x in xs]
        horizontal = [((self.x0, y, 0.0), (self.x1, y, 0.0)) for y in ys]
        return np.array(vertical + horizontal, dtype=np.float32).reshape(-1, 3)


def nice_spacing(
    span: float, cells: int = GRID_CELLS, steps: tuple[float, ...] = MM_STEPS
) -> float:
    """The spacing of `steps` x 10^n (1-2-5 by default) that divides `span` into about `cells`
    cells."""
    raw = max(float(span), 1e-9) / cells
    decade = 10.0 ** math.floor(math.log10(raw))
    candidates = [m * decade for m in steps]
    return min(candidates, key=lambda c: abs(math.log(raw / c)))


def grid_for(points: np.ndarray, pad: float = 0.05, units: str = MM) -> Grid:
    """A grid covering the origin and the XY of `points` ((n, 3) mm), with `pad` headroom.

    Each side is at least half the longest one; the edges fall on grid lines. The grid is in
    mm; with `units` "in" its lines are 0.1, 0.25, 0.5, 1... inch apart, from the origin.
    """
    check_units(units)
    unit = MM_PER_INCH if units == INCH else 1.0
    xy = np.vstack([np.zeros((1, 2)), np.asarray(points, dtype=float).reshape(-1, 3)[:, :2]])
    xy = xy / unit
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    span = max(float(np.max(hi - lo)), MIN_SPAN_MM / unit)
    spacing = nice_spacing(span, steps=INCH_STEPS if units == INCH else MM_STEPS)
    lo = np.where(lo < 0, lo - pad * span, lo)
    hi = np.where(hi > 0, hi + pad * span, hi)
    for axis in range(2):
        short = span / 2 - (hi[axis] - lo[axis])
        if short > 0:
            if hi[axis] > 0 or lo[axis] >= 0:
                hi[axis] += short
            else:
                lo[axis] -= short
    lo = np.floor(lo / spacing + 1e-9) * spacing * unit + 0.0  # + 0.0: no -0.0
    hi = np.ceil(hi / spacing - 1e-9) * spacing * unit + 0.0
    return Grid(float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1]), spacing * unit)


def spacing_text(spacing_mm: float, units: str = MM) -> str:
    """A grid spacing in `units` as the scale writes it ("0.25", "0,25" in French)."""
    check_units(units)
    return number_text(spacing_mm / (MM_PER_INCH if units == INCH else 1.0), 6)


def axis_ends(grid: Grid, top: float) -> np.ndarray:
    """The ends of the X, Y and Z axes (rows of a diagonal 3x3), scaled to the grid.

    X and Y reach the grid's far edge; Z reaches `top` (the highest data), at least a quarter
    of the grid.
    """
    span = max(grid.x1 - grid.x0, grid.y1 - grid.y0)
    lengths = (
        grid.x1 if grid.x1 > 0 else span / 2,
        grid.y1 if grid.y1 > 0 else span / 2,
        max(span / 4, top),
    )
    return np.diag(lengths).astype(np.float32)


def box_corners(box: Box) -> np.ndarray:
    """The 8 corners of a travel box as (8, 3) float32."""
    (x0, x1), (y0, y1), (z0, z1) = box
    return np.array(
        [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)], dtype=np.float32
    )


def box_edges(box: Box) -> np.ndarray:
    """The 12 edges of a travel box as (24, 3) float32 vertices for a "lines" plot."""
    corners = box_corners(box)
    pairs = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]
    return np.array([corners[i] for pair in pairs for i in pair], dtype=np.float32)


def camera_rotation(elevation: float, azimuth: float) -> np.ndarray:
    """The 3x3 world-to-camera rotation of pyqtgraph's GLViewWidget (euler mode)."""
    a = math.radians(elevation - 90.0)
    b = math.radians(azimuth + 90.0)
    about_x = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    about_minus_z = np.array(
        [[math.cos(b), math.sin(b), 0], [-math.sin(b), math.cos(b), 0], [0, 0, 1]]
    )
    return about_x @ about_minus_z


def _limits(margins: np.ndarray, size: tuple[int, int]) -> np.ndarray:
    """Margins in pixels (left, right, bottom, top) as normalised device coordinate limits."""
    width, height = size
    m = np.asarray(margins, dtype=float)
    return np.stack(
        [
            np.minimum(-1 + 2 * m[:, 0] / width, -0.05),
            np.maximum(1 - 2 * m[:, 1] / width, 0.05),
            np.minimum(-1 + 2 * m[:, 2] / height, -0.05),
            np.maximum(1 - 2 * m[:, 3] / height, 0.05),
        ],
        axis=1,
    )


def fit_camera(
    points: np.ndarray,
    centre: np.ndarray,
    rotation: np.ndarray,
    fov: float,
    size: tuple[int, int],
    margins: np.ndarray,
    move_centre: bool = True,
) -> tuple[np.ndarray, float]:
    """The camera centre and distance that put every point in view, as large as they fit.

    `margins` is (n, 4): the pixels each point keeps from the left, right, bottom and top edges
    of a `size` (width, height) image; `fov` is pyqtgraph's horizontal field of view in degrees.
    With `move_centre` the centre moves across the view to balance the free space.
    """
    size = (max(1, size[0]), max(1, size[1]))
    tan = np.array([1.0, size[1] / size[0]]) * math.tan(math.radians(fov) / 2)
    limits = _limits(margins, size)
    centre = np.asarray(centre, dtype=float)
    points = np.asarray(points, dtype=float)
    rounds = 4 if move_centre else 1
    for round_ in range(rounds):
        view = (points - centre) @ rotation.T
        needed = [view[:, 2] + 1e-3]
        for side in range(4):
            coord = view[:, side // 2]
            limit = limits[:, side]
            same = np.sign(coord) == np.sign(limit)
            needed.append(np.where(same, view[:, 2] + coord / (limit * tan[side // 2]), -np.inf))
        distance = max(float(np.max(np.concatenate(needed))), 1.0)
        if round_ == rounds - 1:
            break
        ndc = view[:, :2] / (distance - view[:, 2:3]) / tan
        low = np.min(ndc - limits[:, [0, 2]], axis=0)  # free space left and below
        high = np.min(limits[:, [1, 3]] - ndc, axis=0)  # right and above
        shift = (low - high) / 2 * distance * tan  # in mm at the centre's depth
        centre = centre + rotation[:2].T @ shift
    return centre, distance


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


def overlay_buttons(parent: QWidget) -> list[QToolButton]:
    """Flat buttons in a row over the top-left corner of `parent`; they never take focus.

    The arrow keys jog the stage elsewhere in the window, so the buttons must not keep them.
    """
    buttons, x = [], 4
    for name, text, tip in BUTTONS:
        button = QToolButton(parent)
        button.setObjectName(name)
        button.setText(QCoreApplication.translate("PositionView3D", text))
        button.setToolTip(QCoreApplication.translate("PositionView3D", tip))
        button.setAutoRaise(True)
        button.setCheckable(name == "view3dFollow")
        button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        button.setStyleSheet(BUTTON_STYLE)
        button.resize(button.sizeHint())
        button.move(x, 4)
        x += button.width() + 2
        buttons.append(button)
    return buttons


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


def preview_array(points: object) -> np.ndarray:
    """A planned path's points as (n, 3) float64 mm; None or [] give (0, 3).

    Each point is (x, y, z); x and y must be finite, a missing (NaN) z counts as 0.
    """
    if points is None:
        return np.zeros((0, 3))
    array = np.asarray(points, dtype=float)
    if array.size == 0:
        return np.zeros((0, 3))
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"a preview is a list of (x, y, z) points, not shape {array.shape}")
    if not np.isfinite(array[:, :2]).all():
        raise ValueError("a preview's X and Y must be finite")
    array = array.copy()
    array[~np.isfinite(array[:, 2]), 2] = 0.0
    return array


def preview_tuples(array: np.ndarray) -> list[tuple[float, float, float]]:
    """The rows of a preview array as (x, y, z) tuples."""
    return [(float(x), float(y), float(z)) for x, y, z in array]


def opengl_problem() -> str | None:
    """Why OpenGL cannot draw the 3D scene here, or None when it can; needs a QGuiApplication.

    Makes no call that can crash the process: it looks at the Qt platform, then creates a
    context and an offscreen surface, makes the context current and reads the version it
    reports, the one pyqtgraph checks in its initializeGL.
    """
    if QGuiApplication.instance() is None:
        return "no QGuiApplication yet"
    platform = QGuiApplication.platformName()
    if platform in NO_GL_WIDGET_PLATFORMS:
        return f"the Qt platform {platform!r} cannot draw OpenGL widgets"
    shared = QOpenGLContext.globalShareContext()
    if QCoreApplication.testAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts) and (
        shared is None or not shared.isValid()
    ):
        return NO_CONTEXT
    context = QOpenGLContext()
    if shared is not None:
        context.setShareContext(shared)
    if not context.create() or not context.isValid():
        return NO_CONTEXT
    surface = QOffscreenSurface()
    surface.setFormat(context.format())
    surface.create()
    try:
        if not surface.isValid():
            return "no OpenGL surface can be created on this display"
        if not context.makeCurrent(surface):
            return "an OpenGL context was created but cannot be made current"
        try:
            return _version_problem(context)
        finally:
            context.doneCurrent()
    finally:
        surface.destroy()


def _version_problem(context: QOpenGLContext) -> str | None:
    """Why the current `context` is too old for pyqtgraph.opengl, or None."""
    if context.isOpenGLES():
        return None  # pyqtgraph only warns
    version = context.format().version()
    if tuple(version) >= MIN_GL_VERSION:
        return None
    driver = context.functions().glGetString(GL_VERSION) or "unknown"
    return (
        f"the OpenGL context reports version {version[0]}.{version[1]} (driver: {driver}),"
        f" {MIN_GL_VERSION[0]}.{MIN_GL_VERSION[1]} is needed"
    )
