"""The operator's main window: the layout of the connection bar, jog, coordinates, speed, position
views, console and docks; one device's connection, job desk and machine state do the work."""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QSize, Qt, Signal
from PySide6.QtGui import QCloseEvent
from PySide6.QtWidgets import QDockWidget, QMainWindow, QToolBar, QWidget

from app.common.settings import open_settings, read_number, settings_problem
from app.window.console.log_viewers import LogViewers
from app.window.device.connection import Connection
from app.window.device.job_desk import JobDesk
from app.window.device.machine_state import MachineState
from app.window.device.ports import PortWatcher
from app.window.device.worker_link import WorkerLink
from app.window.keyboard_jog import KeyboardJog
from app.window.layout.arrangements import DEVICE, OPERATE
from app.window.layout.dock_balance import DockBalance
from app.window.layout.dock_layout import BOTTOM, DEVICE_DOCKS, LEFT
from app.window.layout.layout_report import watch as watch_layout
from app.window.layout.layouts import Layouts
from app.window.layout.screen_fit import ScreenFit
from app.window.menus import build_menus
from app.window.window_tools import WindowTools
from widgets import status_line as status
from widgets.connection_bar import ConnectionBar
from widgets.coordinate_entry import CoordinateEntry
from widgets.jog_panel import JogPanel
from widgets.lazy_view import DeferredViews, LazyPart, built
from widgets.panel_scroll_area import PanelScrollArea
from widgets.position_readout import PositionReadout
from widgets.speed_control import SpeedControl
from widgets.status_line import StatusLine
from widgets.view_tabs import ViewTabs

if TYPE_CHECKING:
    from app.window.console.traffic_console import RawConsole
    from app.window.device import jobs
    from app.window.device.worker import SerialWorker
    from app.window.device.worker_thread import WorkerThread
    from app.window.docks.device_docks import DeviceDocks
    from app.window.docks.parameter_dock import ParameterDock
    from app.window.services import Point
    from drivers.device.travel import TravelLimits
    from drivers.toolpath.geometry import FlatPath
    from widgets._axes import Box
    from widgets.position_buffer import PositionBuffer
    from widgets.traffic_timeline import TrafficTimeline

log = logging.getLogger(__name__)

PREFERRED_SIZE = QSize(1400, 900)  # a first start's window, where the screen has the room

# Built just after the window's first paint (they import numpy and build many widgets): the
# calls the window makes on them before that are kept and replayed, in order.
CONSOLE_CALLS = frozenset(
    {
        "append_note",
        "append_records",
        "append_traffic",
        "set_protocol",
        "set_line_ending",
        "set_display_mode",
        "set_max_lines",
        "set_send_mode",
        "set_send_enabled",
    }
)
BUFFER_CALLS = frozenset(
    {"append", "shift", "break_trail", "begin_provisional", "keep_provisional", "drop_provisional"}
)
PARAMETER_CALLS = frozenset({"device_ready", "disconnected", "forget"})
DEVICE_CALLS = frozenset({"device_ready", "disconnected", "adapt", "set_speed"})


def _stamp_note(name: str, args: tuple, kwargs: dict) -> tuple[tuple, dict]:
    """A console note kept for later: stamped with the time it was made (the console's clock,
    time.monotonic), not the time it is replayed."""
    if name == "append_note" and len(args) < 2 and kwargs.get("timestamp") is None:
        kwargs = {**kwargs, "timestamp": time.monotonic()}
    return args, kwargs


class MainWindow(QMainWindow):
    """Lays out the widgets and docks; one device's controllers drive them: `link` (its serial
    worker, built just after the first paint), `connection`, `job_desk` and `machine` (its state).
    It offers the docks and tools what they need (app/window/services.py); never touches the port.
    """

    settled = Signal()  # connected, state read, first position drawn

    def __init__(self, worker_thread: WorkerThread | None = None) -> None:
        super().__init__()
        self.setObjectName("mainWindow")
        self.setWindowTitle(self.tr("Motion Panel"))
        self.settings = open_settings()
        self.link = WorkerLink(self, self.settings, worker_thread)
        # The whole trail, drawn decimated; built with the views (it imports numpy).
        self.buffer: PositionBuffer = LazyPart(self._build_buffer, BUFFER_CALLS)  # type: ignore[assignment]
        self.logs = LogViewers(self, lambda: self.connection_bar.protocol())
        self._build()
        self.keyboard_jog.refused.connect(self.job_desk.on_jog_refused)
        for part in (self.jog_panel, self.coordinates, self.speed):  # a typed number refused
            part.refused.connect(lambda why: self.tell(why, status.WARNING))
        self.views.add(self.port_watcher.refresh)  # listed once the window has painted
        self._restore()
        problem = settings_problem(self.settings)
        if problem:  # the panel runs on defaults; the file is left as it was
            self.tell(problem, status.WARNING)
        self.job_desk.set_controls_enabled(False)
        # Just after the first paint, before the views: the worker (a connection asked for
        # meanwhile starts), then the jog keys (an application event filter: see KeyboardJog).
        self.views.add(self.keyboard_jog.attach, first=True)
        self.views.add(self.link.start, first=True)
        self.link.start_session_log(self.tools.prefs, self._log_note)
        if worker_thread is not None:
            self.link.get()
        watch_layout(self)  # MOTIONPANEL_LAYOUT_REPORT: what Qt shows of the layout

    def _build_controllers(self) -> None:
        """The device's controllers (the widgets they drive are built)."""
        self.keyboard_jog = KeyboardJog(self, self.jog_panel)
        self.machine = MachineState(self, self.link)
        self.job_desk = JobDesk(self, self.link, self.machine)
        self.port_watcher = PortWatcher(self, list_now=False)
        self.connection = Connection(
            self, self.link, self.machine, self.job_desk, self.port_watcher
        )
        self.connection.settled.connect(self.settled)

    # -- what the docks, tools and app/main.py ask of the window (app/window/services.py) -----
    @property
    def worker_thread(self) -> WorkerThread:
        """The serial worker's thread (built now if it is not yet)."""
        return self.link.get()

    @property
    def worker(self) -> SerialWorker:
        """The serial worker (built now if it is not yet)."""
        return self.link.get().worker

    @property
    def connected(self) -> bool:
        """Whether a device is connected (not a bridge)."""
        return self.machine.connected

    @property
    def travel(self) -> TravelLimits | None:
        """The travel box set for the device connected (None: none)."""
        return self.machine.travel

    def connect_device(
        self, port: str, protocol: str, baud: int, variant: str | None = None
    ) -> None:
        """Ask the worker to open `port` (see Connection.connect_device)."""
        self.connection.connect_device(port, protocol, baud, variant)

    def disconnect_device(self) -> None:
        """Ask the worker to close the port (and do not reconnect by itself)."""
        self.connection.disconnect_device()

    def submit_job(self, job: jobs.Job) -> bool:
        """Queue a job for the worker; False (and a message) when refused."""
        return self.job_desk.submit(job)

    def jobs_dropped(self, dropped: list[jobs.Job]) -> None:
        """Jobs taken off the worker's queue unrun (by a dock's Cancel): motion may be on again."""
        self.job_desk.jobs_dropped(dropped)

    def to_worker(self, call: Callable[[WorkerThread], object]) -> None:
        """`call(worker_thread)` now, or once the worker is built (in the order asked)."""
        self.link.to_worker(call)

    def show_preview(self, points: list[Point] | None) -> None:
        """Draw `points` as the path to come in the 2D and 3D views (None: none)."""
        self.view2d.set_preview(points)
        self.view3d.set_preview(points)  # type: ignore[attr-defined]

    def show_program(self, flat: FlatPath | None) -> None:
        """Draw a program's whole path in the 2D and 3D views, travel moves dashed (None:
        none)."""
        points = None if flat is None else flat.points
        rapid = None if flat is None else flat.rapid
        self.view2d.set_program(points, rapid)
        self.view3d.set_program(points, rapid)  # type: ignore[attr-defined]

    def show_program_done(self, row: int) -> None:
        """The program has run up to `row` of its flat path: the views draw only the rest."""
        self.view2d.set_program_done(row)
        self.view3d.set_program_done(row)  # type: ignore[attr-defined]

    def set_travel_limits(self, box: Box | None, clamp: bool) -> None:
        """Use and keep this travel box for the device connected (None: none)."""
        self.connection.set_travel_limits(box, clamp)

    def say(self, text: str) -> None:
        """Tell the operator something (status line and console log)."""
        self.tell(text)

    def tell(self, text: str, kind: str = status.INFO, note: bool = True) -> None:
        """Tell the operator: the status line (once), and the console's log if `note`."""
        self.status_line.show_message(text, kind)
        if note:
            self.console.append_note(text)

    def _log_note(self, text: str, warning: bool) -> None:
        if warning:
            self.tell(text, status.WARNING)
        else:
            self.console.append_note(text)

    def restart_session_log(self) -> None:
        """Follow the session-log settings now: a new file in the folder chosen (the worker
        goes on in it, and each file names the other), or no log at all."""
        self.link.restart_session_log(self.tools.prefs, self._log_note)

    def _show_console(self) -> None:
        """A point on the timeline was clicked: show its line in the console's tab."""
        self.console_dock.show()
        self.console_dock.raise_()

    # -- layout ------------------------------------------------------------------------------
    def _build(self) -> None:
        self.connection_bar = ConnectionBar(self)
        toolbar = QToolBar(self.tr("Connection"), self)
        toolbar.setObjectName("connectionToolBar")
        toolbar.setMovable(False)
        toolbar.addWidget(self.connection_bar)
        self.addToolBar(toolbar)

        # Stand-ins until the window has painted: then the real views (pyqtgraph, OpenGL).
        self.views = DeferredViews(self, self.buffer)
        self.view3d, self.view2d = self.views.view3d, self.views.view2d
        for view in (self.view3d, self.view2d):
            view.setFocusPolicy(Qt.FocusPolicy.ClickFocus)  # a click gives the keys back to jog
        # One tab each, so that the view shown has the whole centre (issue 28 item 20).
        self.view_tabs = ViewTabs(self.view3d, self.view2d, self)
        self.setCentralWidget(self.view_tabs)

        self.readout = PositionReadout(self)
        self.jog_panel = JogPanel(self)
        self.coordinates = CoordinateEntry(self)
        self.speed = SpeedControl(self)
        # The console, its timeline and the parameter and device docks are built just after
        # the first paint (`_build_console`, ...): their docks are here already, empty.
        self.console: RawConsole = LazyPart(self._build_console, CONSOLE_CALLS, _stamp_note)  # type: ignore[assignment]
        self.parameters: ParameterDock = LazyPart(self._build_parameters, PARAMETER_CALLS)  # type: ignore[assignment]
        self.devices: DeviceDocks = LazyPart(self._build_devices, DEVICE_CALLS)  # type: ignore[assignment]
        self.timeline: TrafficTimeline | None = None
        left, bottom = LEFT, BOTTOM
        docks = [
            self._dock(self.tr("Position"), self.readout, left),
            self._dock(self.tr("Jog"), self.jog_panel, left),
            self._dock(self.tr("Go to"), self.coordinates, left),
            self._dock(self.tr("Speed"), self.speed, left),
            self._empty_dock(self.tr("Console"), "rawConsoleDock", bottom),
        ]
        self.coordinates_dock = docks[2]
        parameter_dock = self._empty_dock(
            self.tr("Parameters"), "parameterEditor", bottom, hidden=True
        )
        docks.append(parameter_dock)
        docks.extend(
            self._empty_dock(QCoreApplication.translate("DockLayout", title), name, area, True)
            for name, (title, area) in DEVICE_DOCKS.items()
        )
        self.timeline_dock = self._empty_dock(
            self.tr("Traffic timeline"), "trafficTimelineDock", bottom
        )
        docks.append(self.timeline_dock)
        self.console_dock = docks[4]
        for part in (self.buffer, self.console, self.parameters, self.devices):
            self.views.add(part.build)
        self.tools = WindowTools(self)  # macros, work coordinates, control lines, settings
        docks.append(self.tools.macro_dock)
        # Three layouts, one a job (Operate, Set up, Traffic): they place the docks.
        self.layouts = Layouts(self, self.settings, self.view_tabs, self.tell)
        for dock in docks:
            if dock.objectName() in DEVICE:
                dock.toggleViewAction().triggered.connect(
                    lambda shown, dock=dock: self.layouts.note_toggled(dock, shown)
                )
        self._build_controllers()
        self._build_menus(docks)
        # Once the docks built after the first paint are in: no left panel scrolls while the
        # column has room for all of them, and the panels under the views get their height.
        self.dock_balance = DockBalance(self, LEFT)
        self.bottom_balance = DockBalance(self, BOTTOM, grow=True)
        for balance in (self.dock_balance, self.bottom_balance):
            self.views.usable.connect(balance.start)
            self.views.ready.connect(balance.request)  # the views in place of their stand-ins
            self.layouts.after_apply.append(balance.request)
            self.layouts.after_device.append(balance.request)
        self.views.usable.connect(self.layouts.fit_device)

        self.status_line = StatusLine(self)
        self.statusBar().addWidget(self.status_line, 1)
        self.statusBar().addPermanentWidget(self.layouts.switcher)
        self.statusBar().setSizeGripEnabled(True)
        self.screen_fit = ScreenFit(self)  # the first size, a remembered one, on this screen

    def _build_menus(self, docks: list[QDockWidget]) -> None:
        file_menu, view_menu, actions = build_menus(
            self,
            docks,
            {
                "export": lambda: self.console.export_interactively(),
                "open_log": self.logs.open,
                "log_folder": self.logs.open_folder,
                "stop": self.job_desk.stop,
                "travel": self.connection.edit_travel_limits,
                "reset_views": self.reset_views,
                "clear_trail": self.view2d.clear_trail,
            },
        )
        self.stop_action, self.travel_action = actions["stop"], actions["travel"]
        self.layouts.add_to_menu(view_menu, view_menu.actions()[0])
        self.tools.add_menus(file_menu, actions["quit"], view_menu)

    def reset_views(self) -> None:
        """Fit the 2D and 3D views to the trail again."""
        self.view2d.reset_view()
        self.view3d.reset_view()  # type: ignore[attr-defined]

    def _dock(self, title: str, widget: QWidget, area: Qt.DockWidgetArea) -> QDockWidget:
        dock = self._empty_dock(title, f"{widget.objectName()}Dock", area)
        dock.setWidget(PanelScrollArea(widget, dock))  # a small screen scrolls the panel
        return dock

    def _empty_dock(
        self, title: str, name: str, area: Qt.DockWidgetArea, hidden: bool = False
    ) -> QDockWidget:
        """A dock named `name` in `area`; its widget comes later for the deferred parts."""
        dock = QDockWidget(title, self)
        dock.setObjectName(name)
        dock.setFeatures(
            QDockWidget.DockWidgetFeature.DockWidgetMovable
            | QDockWidget.DockWidgetFeature.DockWidgetFloatable
            | QDockWidget.DockWidgetFeature.DockWidgetClosable  # View menu brings it back
        )
        self.addDockWidget(area, dock)
        if hidden:
            dock.hide()
        return dock

    # -- the parts built after the first paint ------------------------------------------------
    def _build_console(self) -> RawConsole:
        """The traffic console and its timeline, in their docks (the calls made on the console
        until now are replayed on it next)."""
        from app.window.console.feed import TimelineFeed
        from app.window.console.traffic_console import RawConsole
        from widgets.traffic_timeline import TrafficTimeline

        self.console = console = RawConsole(self)
        self.console_dock.setWidget(console)
        console.send_requested.connect(self.job_desk.send_raw)
        self.timeline = TrafficTimeline(self, deferred=True)
        self.timeline_dock.setWidget(self.timeline)
        if self.views.building():  # pyqtgraph's import: with the views, after the docks
            self.views.add(self.timeline.build_plots, plots=True)
        else:
            self.timeline.build_plots()
        self.timeline_feed = TimelineFeed(console, self.timeline)
        self.timeline.line_clicked.connect(self._show_console)
        return console

    def _build_buffer(self) -> PositionBuffer:
        """The trail's buffer (the positions shown until now are replayed into it)."""
        from widgets.position_buffer import PositionBuffer

        self.buffer = PositionBuffer(capacity=None)
        return self.buffer

    def _build_parameters(self) -> ParameterDock:
        """The parameter editor, in its dock."""
        from app.window.docks.parameter_dock import ParameterDock

        self.parameters = ParameterDock(self, self)
        return self.parameters

    def _build_devices(self) -> DeviceDocks:
        """The device-specific panels, in their docks."""
        from app.window.docks.device_docks import DeviceDocks

        self.devices = DeviceDocks(self, self, self.layouts.device_docks)
        return self.devices

    # -- settings ------------------------------------------------------------------------------
    def _restore(self) -> None:
        s = self.settings
        geometry = s.value("geometry")
        if geometry is None or not self.restoreGeometry(geometry):
            self.screen_fit.first_size(PREFERRED_SIZE)
        else:
            self.screen_fit.keep_inside()  # remembered from a larger screen: fitted to this one
        self.layouts.current = OPERATE  # the panel opens in Operate, as last left
        self.layouts.apply()
        self.jog_panel.set_step(read_number(s, "jog_step", 1.0))
        self.connection.restore()

    def closeEvent(self, event: QCloseEvent) -> None:
        """Save the layout and stop the worker thread before closing."""
        self.settings.setValue("geometry", self.saveGeometry())
        self.layouts.save()
        self.settings.setValue("jog_step", self.jog_panel.step())
        self.settings.sync()
        self.keyboard_jog.detach()
        self.port_watcher.stop()
        if self.machine.estimate is not None:
            self.machine.estimate.stop()
        self.link.close()
        if self.connection.bridge is not None:
            self.connection.bridge.bridge.close()  # its thread returns within a moment
        self.logs.close_all()
        if built(self.console):
            self.console.index.close()
        super().closeEvent(event)
