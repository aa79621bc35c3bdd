"""What the docks, tools and controllers ask of the window: a small interface, not the window.

`MainWindow` provides both protocols; nothing in app/ but app/main.py imports it, so the docks
and the controllers of a device can be built against another host (a second device, a test).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from PySide6.QtCore import QSettings
    from PySide6.QtGui import QAction
    from PySide6.QtWidgets import QMenuBar

    from app.window.device.jobs import Job
    from app.window.device.worker import SerialWorker
    from app.window.device.worker_thread import WorkerThread
    from app.window.keyboard_jog import KeyboardJog
    from drivers.device.travel import TravelLimits
    from drivers.toolpath.geometry import FlatPath
    from widgets._axes import Box
    from widgets.connection_bar import ConnectionBar
    from widgets.coordinate_entry import CoordinateEntry
    from widgets.jog_panel import JogPanel
    from widgets.lazy_view import DeferredViews
    from widgets.position_readout import PositionReadout
    from widgets.speed_control import SpeedControl
    from widgets.status_line import StatusLine

Point = tuple[float, float, float]


class WindowServices(Protocol):
    """What a dock needs: the settings, a word to the operator, the device's jobs and worker."""

    settings: QSettings

    def say(self, text: str) -> None:
        """Tell the operator something (status line and console log)."""

    def submit_job(self, job: Job) -> bool:
        """Queue a job for the device; False (and a message) when refused."""

    def jobs_dropped(self, dropped: list[Job]) -> None:
        """Jobs taken off the worker's queue unrun: motion may be on again."""

    def to_worker(self, call: Callable[[WorkerThread], object]) -> None:
        """`call(worker_thread)` now, or once the worker is built."""

    @property
    def worker(self) -> SerialWorker:
        """The device's serial worker (its signals; built now if it is not yet)."""

    @property
    def worker_thread(self) -> WorkerThread:
        """The serial worker's thread (the GUI's calls to the worker)."""

    @property
    def travel(self) -> TravelLimits | None:
        """The travel box set for the device connected (None: none)."""

    def show_preview(self, points: list[Point] | None) -> None:
        """Draw `points` as the path to come in the 2D and 3D views (None: none)."""

    def show_program(self, flat: FlatPath | None) -> None:
        """Draw a program's whole path in the 2D and 3D views, travel moves dashed (None:
        none)."""

    def show_program_done(self, row: int) -> None:
        """The program has run up to `row` of its flat path: the views draw only the rest."""

    def set_travel_limits(self, box: Box | None, clamp: bool) -> None:
        """Use and keep this travel box for the device connected (None: none)."""


class WindowParts(WindowServices, Protocol):
    """What the window's tools and controllers use besides: its widgets and docks."""

    views: DeferredViews
    connection_bar: ConnectionBar
    readout: PositionReadout
    coordinates: CoordinateEntry
    jog_panel: JogPanel
    speed: SpeedControl
    status_line: StatusLine
    stop_action: QAction
    travel_action: QAction
    view2d: Any
    view3d: Any
    buffer: Any  # a PositionBuffer (built after the first paint)
    console: Any  # a RawConsole (built after the first paint)
    parameters: Any  # a ParameterDock (built after the first paint)
    devices: Any  # a DeviceDocks (built after the first paint)
    tools: Any  # the WindowTools
    keyboard_jog: KeyboardJog

    def tell(self, text: str, kind: str = "info", note: bool = True) -> None:
        """Tell the operator: the status line (as `kind`), and the console's log if `note`."""

    def restart_session_log(self) -> None:
        """Follow the session-log settings now."""

    def menuBar(self) -> QMenuBar:
        """The window's menu bar."""

    def addDockWidget(self, *args: Any) -> None:
        """Add a dock to the window."""

    def findChildren(self, *args: Any) -> list[Any]:
        """The window's children of a type."""
