"""Moving the 3D view's camera: view presets, following, the mouse, and the overlay buttons."""

from __future__ import annotations

from functools import partial

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QSize, Qt
from PySide6.QtGui import QColor, QFontMetrics, QMouseEvent, QVector3D, QWheelEvent
from PySide6.QtWidgets import QToolButton, QWidget

from widgets._buttons import overlay_button_style
from widgets.view3d.camera import MARGINS_PX, VIEW_ANGLES, VIEW_PRESETS, camera_rotation, fit_camera
from widgets.view3d.geometry import Grid

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


class NavigationMixin:
    """The camera of PositionView3D: a preset in force until the mouse moves the camera."""

    _grid: Grid
    _axis_ends: np.ndarray
    _current: np.ndarray | None
    _follow: bool
    _preset: str | None
    _fitted_size: QSize

    def reset_view(self) -> None:
        """Look at the whole scene from above at an angle (the "iso" preset)."""
        self.set_view_preset("iso")

    def set_view_preset(self, name: str) -> None:
        """Look from "top", "front", "side" or "iso" at the whole scene, or "fit" the data."""
        if name not in VIEW_PRESETS:
            raise ValueError(f"unknown view preset {name!r}")
        self._preset = name
        self._fit_camera()
        self._redraw()

    def _fit_camera(self) -> None:
        """Point the camera as the active preset says, at the widget's present size."""
        opts = self.scene.opts
        name = self._preset
        elevation, azimuth = VIEW_ANGLES.get(name, (opts["elevation"], opts["azimuth"]))
        points, margins = self._fit_points(data_only=name == "fit")
        following = self._follow and self._current is not None
        centre, distance = fit_camera(
            points,
            self._current if following else (points.min(axis=0) + points.max(axis=0)) / 2,
            camera_rotation(elevation, azimuth),
            opts["fov"],
            (self.width(), self.height()),
            margins,
            move_centre=not following,
        )
        self.scene.setCameraPosition(
            pos=QVector3D(*map(float, centre)),
            distance=distance,
            elevation=elevation,
            azimuth=azimuth,
        )
        self._fitted_size = self.size()

    def _fit_points(self, data_only: bool) -> tuple[np.ndarray, np.ndarray]:
        """The points a camera preset must show, and their margins (left, right, bottom, top px)."""
        points = self._data_points()
        margins = np.tile(MARGINS_PX, (len(points), 1))
        if data_only and len(points):
            return points, margins
        grid = self._grid
        corners = np.array([(x, y, 0.0) for x in (grid.x0, grid.x1) for y in (grid.y0, grid.y1)])
        metrics = QFontMetrics(self._label_font)
        label_margins = [  # the text is drawn right of and above its position
            np.add(MARGINS_PX, (0, metrics.horizontalAdvance(lab.text), 0, metrics.height()))
            for lab in self.labels
        ]
        label_pos = np.array([lab.pos for lab in self.labels])
        points = np.vstack([points, corners, self._axis_ends, label_pos])
        margins = np.vstack([margins, np.tile(MARGINS_PX, (7, 1)), label_margins])
        return points, margins

    def set_follow(self, on: bool) -> None:
        """Keep the camera centred on the current position while `on`."""
        self._follow = bool(on)
        self.follow_button.setChecked(self._follow)
        if self._follow and self._current is not None:
            self.scene.opts["center"] = QVector3D(*map(float, self._current))
            self._redraw()

    def is_following(self) -> bool:
        """Whether the camera follows the current position."""
        return self._follow

    def _make_buttons(self) -> None:
        """The view-preset and follow buttons over the top-left corner."""
        for button in overlay_buttons(self):
            preset = button.objectName().removeprefix("view3d").lower()
            if preset in VIEW_PRESETS:
                button.clicked.connect(partial(self.set_view_preset, preset))
        self.follow_button = self.findChild(QToolButton, "view3dFollow")
        self.follow_button.toggled.connect(self.set_follow)
        self._buttons_light: bool | None = None
        self._style_buttons()

    def _style_buttons(self) -> None:
        """The buttons in the style for the scene's background (the theme's), on a change."""
        light = QColor.fromRgbF(*self.scene.opts["bgcolor"]).lightnessF() > 0.5
        if light is self._buttons_light:
            return
        self._buttons_light = light
        style = overlay_button_style(light)
        for button in self.findChildren(QToolButton):
            button.setStyleSheet(style)

    # -- the mouse handlers of pyqtgraph's view, then a new image ------------------------------
    def mousePressEvent(self, event: QMouseEvent) -> None:
        """Start a rotation (left), pan (middle or Ctrl) or zoom drag."""
        self.scene.mousePressEvent(event)

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        """Rotate, pan or zoom while a button is held."""
        self.scene.mouseMoveEvent(event)
        self._preset = None
        self._redraw()

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        """End the drag."""
        self.scene.mouseReleaseEvent(event)

    def wheelEvent(self, event: QWheelEvent) -> None:
        """Zoom."""
        self.scene.wheelEvent(event)
        self._preset = None
        self._redraw()
