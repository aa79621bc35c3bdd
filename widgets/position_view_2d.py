"""2D position plots: the XY trail seen from above, and X/Y/Z against time."""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtGui import QResizeEvent
from PySide6.QtWidgets import QHBoxLayout, QPushButton, QSplitter, QVBoxLayout, QWidget

from widgets._axes import Box
from widgets._program_path import ProgramPath
from widgets._units import INCH, MM, MM_PER_INCH, check_units
from widgets._view_common import BufferedViewMixin
from widgets.position_buffer import PositionBuffer
from widgets.view2d.following import (
    FOLLOW_PADDING,
    MIN_MARGIN_MM,
    TIME_WINDOWS_S,
    XY_FIT_MIN_MARGIN_MM,
    XY_MARGIN,
    FollowingMixin,
)
from widgets.view2d.markers import MarkersMixin
from widgets.view2d.plans import PlansMixin
from widgets.view2d.style import (
    AXIS_COLOURS,
    CURRENT_COLOUR,
    GRID_COLOUR,
    PREVIEW_COLOUR,
    TARGET_COLOUR,
    THEME_ROLE,
    TRAIL_COLOUR,
    WORKSPACE_COLOUR,
    grid,
    steady_axes,
)
from widgets.view2d.time_plot import TIME_PLOT_DELAY_MS, TIME_TICK_SAMPLE, TimePlotMixin
from widgets.view2d.xy_plot import XYPlotMixin

__all__ = [  # what other modules take from here; the parts are in widgets.view2d
    "AXIS_COLOURS",
    "CURRENT_COLOUR",
    "FOLLOW_PADDING",
    "GRID_COLOUR",
    "MIN_MARGIN_MM",
    "PREVIEW_COLOUR",
    "TARGET_COLOUR",
    "THEME_ROLE",
    "TIME_PLOT_DELAY_MS",
    "TIME_TICK_SAMPLE",
    "TIME_WINDOWS_S",
    "TRAIL_COLOUR",
    "WORKSPACE_COLOUR",
    "XY_FIT_MIN_MARGIN_MM",
    "XY_MARGIN",
    "PositionView2D",
]


class PositionView2D(
    XYPlotMixin,
    TimePlotMixin,
    PlansMixin,
    MarkersMixin,
    FollowingMixin,
    BufferedViewMixin,
    QWidget,
):
    """XY trail with current and target markers, and a position-time chart, from a buffer.

    The parts are in widgets.view2d: the XY plot and its trail (XYPlotMixin), the time plot and
    the refresh's turns (TimePlotMixin), the travel box, preview and program (PlansMixin), the
    current and target markers (MarkersMixin), the ranges followed (FollowingMixin).
    """

    def __init__(self, buffer: PositionBuffer, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("positionView2d")
        self.buffer = buffer
        self._target: tuple[float, float, float] | None = None
        self._workspace: Box | None = None
        self._estimated = False
        self._preview = np.zeros((0, 3))
        self._program: ProgramPath | None = None
        self._program_done = 0
        self._units = MM  # what the axes are written in (the data, the items: mm)
        self.xy_grid, self.time_grid = grid(), grid()
        self._make_xy_plot()
        self._make_time_plot()

        clear_button = QPushButton(self.tr("Clear trail"))
        clear_button.setObjectName("clearTrailButton")
        clear_button.setToolTip(self.tr("Forget the path so far (the current position stays)"))
        clear_button.clicked.connect(self.clear_trail)
        reset_button = QPushButton(self.tr("Reset view"))
        reset_button.setObjectName("resetViewButton")
        reset_button.setToolTip(self.tr("Zoom both plots to fit the data again"))
        reset_button.clicked.connect(self.reset_view)
        buttons = QHBoxLayout()
        buttons.addStretch(1)
        buttons.addWidget(clear_button)
        buttons.addWidget(reset_button)

        for plot in (self.xy_plot, self.time_plot):
            steady_axes(plot.getPlotItem())
        self.splitter = QSplitter(Qt.Orientation.Horizontal)
        self.splitter.addWidget(self.xy_plot)
        self.splitter.addWidget(self.time_plot)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.splitter, 1)
        layout.addLayout(buttons)

        for plot in (self.xy_plot, self.time_plot):
            plot.getPlotItem().getViewBox().sigRangeChangedManually.connect(self._stop_following)
        self._following = True
        self.start_refresh_timer()
        self._make_time_timers()
        self.reset_view()

    # -- units ---------------------------------------------------------------------------------
    def set_units(self, units: str) -> None:
        """Write the lengths on the axes in "mm" or "in": labels, ticks and grid lines (round
        inches); what is drawn stays where it is (the data and the view ranges are in mm)."""
        check_units(units)
        if units == self._units:
            return
        self._units = units
        per_unit = 1.0 / MM_PER_INCH if units == INCH else 1.0  # values shown per mm
        for side in ("bottom", "left"):
            self.xy_plot.getPlotItem().getAxis(side).setScale(per_unit)
        self.time_plot.getPlotItem().getAxis("left").setScale(per_unit)
        self.xy_grid.set_value_scale(per_unit, per_unit)
        self.time_grid.set_value_scale(1.0, per_unit)
        self.xy_fit.set_labels(self._xy_labels())
        self.time_fit.set_labels(self._time_labels())

    def units(self) -> str:
        """The units the axes are written in: "mm" or "in"."""
        return self._units

    def _xy_labels(self) -> dict[str, list[str]]:
        """The XY plot's axis labels (long, short) in the units shown."""
        if self._units == INCH:
            return {
                "bottom": [self.tr("X (in)"), self.tr("X")],
                "left": [self.tr("Y (in)"), self.tr("Y")],
            }
        return {
            "bottom": [self.tr("X (mm)"), self.tr("X")],
            "left": [self.tr("Y (mm)"), self.tr("Y")],
        }

    def _time_labels(self) -> dict[str, list[str]]:
        """The time plot's axis labels (long, short) in the units shown."""
        time = [self.tr("time (s, 0 = latest sample)"), self.tr("t (s)")]
        if self._units == INCH:
            return {"bottom": time, "left": [self.tr("position (in)"), self.tr("in")]}
        return {"bottom": time, "left": [self.tr("position (mm)"), self.tr("mm")]}

    def refresh(self) -> None:
        """Redraw both plots from the buffer if it changed since the last refresh.

        What is drawn is the buffer's decimated trail (`buffer.lod`): every recent point, and
        the first, last and extreme points of each block of older ones, so a long trail keeps its
        shape and extent at the cost of a few thousand points.
        """
        if self._refresh_xy() or self._time_timer.isActive():  # a time plot due, drawn now
            self._time_timer.stop()
            self._refresh_time_plot()

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Plots side by side when there is width for it, else one above the other."""
        super().resizeEvent(event)
        wide = event.size().width() >= 1.3 * event.size().height()
        orientation = Qt.Orientation.Horizontal if wide else Qt.Orientation.Vertical
        if self.splitter.orientation() != orientation:
            self.splitter.setOrientation(orientation)
