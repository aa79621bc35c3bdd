"""The 3D view's camera: view presets, and the distance and centre that fit points in view."""

from __future__ import annotations

import math

import numpy as np

FIELD_OF_VIEW = 35.0  # degrees across; pyqtgraph's 60 distorts the flat presets
MARGINS_PX = np.array((8, 8, 20, 30))  # left, right, bottom (scale text), top (buttons)

# (elevation, azimuth) in degrees, as pyqtgraph's GLViewWidget camera uses them
VIEW_ANGLES: dict[str, tuple[float, float]] = {
    "top": (90.0, -90.0),  # X right, Y up
    "front": (0.0, -90.0),  # from -Y: X right, Z up
    "side": (0.0, 0.0),  # from +X: Y right, Z up
    "iso": (30.0, -60.0),
}
VIEW_PRESETS = (*VIEW_ANGLES, "fit")


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
