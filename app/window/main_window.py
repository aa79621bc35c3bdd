"""The operator's main window: connection bar, jog, coordinates, speed, position views, console."""

from __future__ import annotations

import dataclasses
import logging
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Qt, QTimer, QUrl, Signal
from PySide6.QtGui import QCloseEvent, QDesktopServices, QKeySequence
from PySide6.QtWidgets import (
    QDockWidget,
    QMainWindow,
    QSplitter,
    QToolBar,
    QWidget,
)

from app.common.messages import localized
from app.common.session_log import log_folder, open_session_log
from app.common.settings import (
    DEFAULT_PORT,
    DEFAULT_PROTOCOL,
    open_settings,
    read_number,
    read_parameters,
    read_protocol_settings,
    read_str,
    read_travel,
    settings_problem,
    write_counted_position,
    write_travel,
)
from app.window.dock_balance import DockBalance
from app.window.dock_layout import BOTTOM, DEVICE_DOCKS, LEFT
from app.window.keyboard_jog import KeyboardJog
from app.window.ports import PortWatcher
from app.window.preferences import session_log_folder
from app.window.window_tools import WindowTools, poll_rates
from drivers.errors import BadInput, MotionError
from drivers.registry import create_protocol, get_protocol_class, has_variants, protocol_names
from widgets import status_line as status
from widgets._i18n import fill
from widgets.connection_bar import ConnectionBar, sim_protocol
from widgets.coordinate_entry import CoordinateEntry
from widgets.jog_panel import JogPanel
from widgets.lazy_view import DeferredViews, LazyPart, built
from widgets.panel_scroll_area import PanelScrollArea
from widgets.position_readout import PositionReadout
from widgets.speed_control import SpeedControl
from widgets.status_line import StatusLine

if TYPE_CHECKING:
    from typing import TextIO

    from app.window import jobs
    from app.window.bridge_session import BridgeSession
    from app.window.device_docks import DeviceDocks
    from app.window.log_viewer import LogViewer
    from app.window.move_estimate import MoveEstimate
    from app.window.parameter_dock import ParameterDock
    from app.window.traffic_console import RawConsole
    from app.window.worker import DeviceInfo, SerialWorker
    from app.window.worker_thread import WorkerThread
    from drivers.capabilities import Capabilities
    from drivers.events import PositionReport
    from drivers.motion import MoveStart
    from drivers.traffic import Traffic
    from drivers.travel import TravelLimits
    from widgets.position_buffer import PositionBuffer
    from widgets.traffic_timeline import TrafficTimeline

log = logging.getLogger(__name__)

# Built just after the window's first paint (they import numpy and build many widgets): the
# calls the window makes on them before that are kept and replayed, in order.
CONSOLE_CALLS = frozenset(
    {
        "append_note",
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
JOG_TAP_S = 0.3
"""A jog press released sooner is a tap: its step is not stopped (as QAbstractButton's
default auto-repeat delay)."""
PARAMETER_CALLS = frozenset({"device_ready", "disconnected", "forget"})
DEVICE_CALLS = frozenset({"device_ready", "disconnected", "adapt", "set_speed"})


def _stamp_note(name: str, args: tuple, kwargs: dict) -> tuple[tuple, dict]:
    """A console note kept for later: stamped with the time it was made (the console's clock,
    time.monotonic), not the time it is replayed."""
    if name == "append_note" and len(args) < 2 and kwargs.get("timestamp") is None:
        kwargs = {**kwargs, "timestamp": time.monotonic()}
    return args, kwargs


# Marked here, translated at use (context "MainWindow"); %1: the device's protocol.
NO_STOP_TIP = QT_TRANSLATE_NOOP(
    "MainWindow",
    "%1 has no stop command: this drops the commands not yet sent; "
    "a move already under way on the device finishes (Esc)",
)
STOP_TIP = QT_TRANSLATE_NOOP(
    "MainWindow", "Stop the stage now: halts the move under way and drops what is queued (Esc)"
)


def _is_macro(job: object) -> bool:
    """Whether `job` is a macro (the worker is built: app.window.jobs is imported)."""
    from app.window import jobs

    return isinstance(job, jobs.MacroJob)


def _runs_alone(job: object) -> bool:
    """Whether `job` turns motion off until it ends: a program, a macro, a parameter write."""
    from app.window import jobs

    return isinstance(job, (jobs.StreamJob, jobs.MacroJob, jobs.SetParameterJob))


def _may_run_beside(job: object, running: list[jobs.Job]) -> bool:
    """Whether `job` may be queued while the jobs that run alone in `running` are under way:
    reading the device, or more parameter writes beside parameter writes; nothing that moves."""
    from app.window import jobs

    if isinstance(job, (jobs.RefreshJob, jobs.StepperVersionJob)):
        return True
    return isinstance(job, jobs.SetParameterJob) and all(
        isinstance(other, jobs.SetParameterJob) for other in running
    )


def _counts_its_position(caps: Capabilities) -> bool:
    """A device that confirms its moves but cannot be asked where it is (Visiomex): on a fresh
    connection the panel has counted nothing yet, so the position is unknown until Home or
    Set Home."""
    from drivers.capabilities import Completion

    return not caps.position_feedback and caps.completion is Completion.FEEDBACK


def sim_ports() -> list[tuple[str, str]]:
    """Every built-in simulated device as a (port, description) pair."""
    from drivers.sim.registry import simulator_names  # (listed after the first paint)

    description = QCoreApplication.translate("MainWindow", "simulated %1 device")
    return [(f"sim://{name}", fill(description, name)) for name in simulator_names()]


class MainWindow(QMainWindow):
    """Wires the widgets to the serial worker; never touches the port itself.

    The serial worker, its thread and the move estimate are built just after the window's first
    paint (they import the jobs, the motion engine, the client and pyserial), or as soon as
    `worker` or `worker_thread` is asked for; what the window asks of the worker's thread before
    that (connect, disconnect, travel limits, the session log) is kept and done then, in order.
    """

    settled = Signal()  # connected, state read, first position drawn

    def __init__(self, worker_thread: WorkerThread | None = None) -> None:
        super().__init__()
        self.setObjectName("mainWindow")
        self.setWindowTitle(self.tr("Motion Panel"))
        self.settings = open_settings()
        self._serial: WorkerThread | None = None  # built by `_build_serial`
        self._given_serial = worker_thread
        self._serial_calls: list[Callable[[WorkerThread], object]] = []  # until it is built
        self._pending_log: TextIO | None = None  # the session log, until the worker has it
        self._closed = False
        # The whole trail, drawn decimated; built with the views (it imports numpy).
        self.buffer: PositionBuffer = LazyPart(self._build_buffer, BUFFER_CALLS)  # type: ignore[assignment]
        self.t0 = time.monotonic()
        self.connected = False
        self.info: DeviceInfo | None = None
        self.travel: TravelLimits | None = None
        self._last_connection: tuple[str, str, int] | None = None
        self._viewers: list[LogViewer] = []
        self.bridge: BridgeSession | None = None
        self._log_start: float | None = None
        self.ask_log_path: Callable[[], str] = self._ask_log_path
        self._last_position: tuple[float, float, float] | None = None
        self._true_position: tuple[float, float, float] | None = None  # reported, not estimated
        self._count_kept: tuple[float, float, float] | None = None  # (Visiomex: _keep_count)
        self._unconfirmed_move = False  # a move started whose end no position has confirmed
        self._trail_device: tuple[str, str, str] | None = None  # port, protocol, identity
        self._busy_job: jobs.Job | None = None
        self._moving = False
        self._failed = False
        self._link_failed = False  # the connection failed since the device was last ready
        self._position_lost = False  # a device with no position feedback lost track of it
        self._lost_status = "lost"  # or "uncounted": a fresh connection, nothing counted yet
        self._jog_job: jobs.MoveByJob | None = None
        self._jog_repeat = False  # the step under way was sent because the jog was held
        self._jog_pressed_at = 0.0  # time.monotonic() of the last jog press
        self._jog_ended: jobs.Job | None = None  # a step whose end awaits the next decision
        self._running_alone: list[jobs.Job] = []  # programs, macros, parameter writes queued
        self._controls_on = False  # connected to a device (not a bridge)
        self._home_from: tuple[float, float, float] | None = None
        self._saved_step: float | None = None  # the jog step as last saved
        self.estimate: MoveEstimate | None = None  # built with the worker
        self._build()
        self.keyboard_jog = KeyboardJog(self, self.jog_panel)
        self._wire()
        self._restore()
        problem = settings_problem(self.settings)
        if problem:  # the panel runs on defaults; the file is left as it was
            self._say(problem, status.WARNING)
        self._set_controls_enabled(False)
        # Just after the first paint, before the views: the worker (a connection asked for
        # meanwhile starts), then the jog keys (an application event filter: see KeyboardJog).
        self.views.add(self.keyboard_jog.attach, first=True)
        self.views.add(self._start_serial, first=True)
        self.session_log_path = self._start_session_log()
        if worker_thread is not None:
            self._build_serial()

    # -- the serial worker -------------------------------------------------------------------
    @property
    def worker_thread(self) -> WorkerThread:
        """The serial worker's thread (built now if it is not yet)."""
        return self._serial or self._build_serial()

    @property
    def worker(self) -> SerialWorker:
        """The serial worker (built now if it is not yet)."""
        return self.worker_thread.worker

    def _build_serial(self) -> WorkerThread:
        """The worker, wired to the window, on its running thread; then what was asked of it
        before, in order. Harmless to call again."""
        if self._serial is not None:
            return self._serial
        from app.window.move_estimate import MoveEstimate
        from app.window.worker_thread import WorkerThread

        self.estimate = MoveEstimate(self)
        self.estimate.estimated.connect(self._on_estimate)
        thread = self._given_serial
        if thread is None:
            worker = self._make_worker()
            self._wire_worker(worker)  # before its thread starts: it says nothing unheard
            thread = WorkerThread(worker)
        else:
            self._wire_worker(thread.worker)
        self._serial, self._given_serial = thread, None
        if self._closed:  # asked for after the window closed: one that has stopped
            thread.stop()
            return thread
        calls, self._serial_calls = self._serial_calls, []
        self._pending_log = None  # handed over by the calls
        for call in calls:
            call(thread)
        return thread

    def _start_serial(self) -> None:
        """Just after the first paint: the worker, unless the window has closed meanwhile."""
        if not self._closed:
            self._build_serial()

    def _to_worker(self, call: Callable[[WorkerThread], object]) -> None:
        """`call(worker_thread)` now, or once the worker is built (in the order asked)."""
        if self._serial is not None:
            call(self._serial)
        else:
            self._serial_calls.append(call)

    def to_worker(self, call: Callable[[WorkerThread], object]) -> None:
        """`call(worker_thread)` now, or once the worker is built (for the window's tools)."""
        self._to_worker(call)

    def _start_session_log(self) -> Path | None:
        """Every byte of this session to a file in the log folder (on unless turned off)."""
        prefs = self.tools.prefs  # read once, by the tools; kept current by Settings
        if not prefs.session_log:
            return None
        try:
            path, stream = open_session_log(session_log_folder(prefs))
        except OSError as exc:
            self._say(fill(self.tr("no session log: %1"), exc), status.WARNING)
            return None
        self._log_start = time.monotonic()
        self._pending_log = stream  # closed here should the window close before the worker is

        def hand_over(thread: WorkerThread) -> None:
            self._log_start = time.monotonic()  # the worker's log counts from about now
            thread.set_session_log(stream)

        self._to_worker(hand_over)
        self.console.append_note(fill(self.tr("session log: %1"), path))
        return path

    def restart_session_log(self) -> None:
        """Follow the session-log settings now: a new file in the folder chosen (the worker
        goes on in it, and each file names the other), or no log at all."""
        self.session_log_path = self._start_session_log()
        if self.session_log_path is None:
            self._to_worker(lambda thread: thread.set_session_log(None))
            self.console.append_note(self.tr("no session log from now on"))

    def _ask_log_path(self) -> str:
        from app.window.log_viewer import ask_open_path

        return ask_open_path(self)

    def open_log(self, path: str | None = None) -> LogViewer | None:
        """Open a traffic log in a viewer window (asks for the file when `path` is None)."""
        from app.window.log_viewer import LogViewer

        viewer = LogViewer(None, self.connection_bar.protocol())
        viewer.ask_path = self.ask_log_path
        chosen = path if path is not None else self.ask_log_path()
        if not chosen:
            viewer.deleteLater()
            return None
        self._viewers = [v for v in self._viewers if v.isVisible()]  # closed ones go
        self._viewers.append(viewer)
        viewer.show()
        viewer.open(chosen)
        return viewer

    def _show_console(self) -> None:
        """A point on the timeline was clicked: show its line in the console's tab."""
        self.console_dock.show()
        self.console_dock.raise_()

    def open_log_folder(self) -> None:
        """Show the session logs' folder in the desktop's file manager."""
        QDesktopServices.openUrl(QUrl.fromLocalFile(str(log_folder())))

    def _make_worker(self) -> SerialWorker:
        """A worker with the saved polling rates (5-10 Hz while a move is confirmed, 1 s idle)."""
        moving_hz, idle_s = poll_rates(self.settings)
        from app.window.worker import SerialWorker

        return SerialWorker(poll_moving_hz=moving_hz, poll_idle_s=idle_s)

    # -- layout ------------------------------------------------------------------------------
    def _build(self) -> None:
        self.connection_bar = ConnectionBar(self)
        self.connection_bar.set_protocols(protocol_names())
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
        splitter = QSplitter(Qt.Orientation.Horizontal, self)
        splitter.addWidget(self.view3d)
        splitter.addWidget(self.view2d)
        splitter.setSizes([600, 600])
        self.setCentralWidget(splitter)

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
        self.tabifyDockWidget(docks[-1], parameter_dock)
        docks.append(parameter_dock)
        device_docks = [
            self._empty_dock(QCoreApplication.translate("DockLayout", title), name, area, True)
            for name, (title, area) in DEVICE_DOCKS.items()
        ]
        for dock in device_docks[:3]:
            self.tabifyDockWidget(docks[-2], dock)
        docks.extend(device_docks)
        self.timeline_dock = self._empty_dock(
            self.tr("Traffic timeline"), "trafficTimelineDock", bottom
        )
        self.tabifyDockWidget(docks[4], self.timeline_dock)
        docks.append(self.timeline_dock)
        docks[4].raise_()  # the console is the tab shown first
        self.console_dock = docks[4]
        for part in (self.buffer, self.console, self.parameters, self.devices):
            self.views.add(part.build)
        self.tools = WindowTools(self)  # macros, work coordinates, control lines, settings
        self.tabifyDockWidget(docks[3], self.tools.macro_dock)  # Macros beside Speed
        docks[3].raise_()
        docks.append(self.tools.macro_dock)
        self._build_menus(docks)
        # The left panels run the full height; the console sits under the views only.
        self.setCorner(Qt.Corner.BottomLeftCorner, Qt.DockWidgetArea.LeftDockWidgetArea)
        # Once the docks built after the first paint are in: no left panel scrolls while the
        # column has room for all of them.
        self.dock_balance = DockBalance(self, LEFT)
        self.views.ready.connect(self.dock_balance.start)

        self.status_line = StatusLine(self)
        self.statusBar().addWidget(self.status_line, 1)
        self.statusBar().setSizeGripEnabled(True)
        self.resize(1400, 900)

    def _build_menus(self, docks: list[QDockWidget]) -> None:
        file_menu = self.menuBar().addMenu(self.tr("&File"))
        export = file_menu.addAction(
            self.tr("&Export traffic log…"), lambda: self.console.export_interactively()
        )
        export.setShortcut(QKeySequence("Ctrl+E"))
        export.setToolTip(
            self.tr("Save every byte sent and received, with timestamps, to a text file")
        )
        opener = file_menu.addAction(self.tr("&Open log…"), self.open_log)
        opener.setShortcut(QKeySequence.StandardKey.Open)
        opener.setToolTip(
            self.tr("Browse a traffic log (ours or a pyserial spy:// capture) decoded")
        )
        folder = file_menu.addAction(self.tr("Open the session &log folder"), self.open_log_folder)
        folder.setToolTip(self.tr("Every byte of every session is kept there, one file a session"))
        file_menu.addSeparator()
        quit_action = file_menu.addAction(
            self.tr("&Quit"), QKeySequence.StandardKey.Quit, self.close
        )
        motion_menu = self.menuBar().addMenu(self.tr("&Motion"))
        self.stop_action = motion_menu.addAction(self.tr("&Stop"), self.stop)
        self.stop_action.setShortcut(QKeySequence(Qt.Key.Key_Escape))
        self.stop_action.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
        motion_menu.addSeparator()
        self.travel_action = motion_menu.addAction(
            self.tr("&Travel limits…"), self.edit_travel_limits
        )
        self.travel_action.setToolTip(self.tr("The box the stage may move in, for this device"))
        self.travel_action.setEnabled(False)
        view_menu = self.menuBar().addMenu(self.tr("&View"))
        reset = view_menu.addAction(self.tr("&Reset views"), self.reset_views)
        reset.setShortcut(QKeySequence("Ctrl+R"))
        view_menu.addAction(self.tr("&Clear trail"), self.view2d.clear_trail)
        view_menu.addSeparator()
        for dock in docks:
            view_menu.addAction(dock.toggleViewAction())
        view_menu.addSeparator()
        self.tools.add_menus(file_menu, quit_action, view_menu)

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
        from app.window.traffic_console import RawConsole
        from app.window.traffic_feed import TimelineFeed
        from widgets.traffic_timeline import TrafficTimeline

        self.console = console = RawConsole(self)
        self.console_dock.setWidget(console)
        console.send_requested.connect(self._send_raw)
        self.timeline = TrafficTimeline(self, deferred=True)
        self.timeline_dock.setWidget(self.timeline)
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
        from app.window.parameter_dock import ParameterDock

        self.parameters = ParameterDock(self)
        return self.parameters

    def _build_devices(self) -> DeviceDocks:
        """The device-specific panels, in their docks."""
        from app.window.device_docks import DeviceDocks

        self.devices = DeviceDocks(self)
        return self.devices

    def _wire_worker(self, w: SerialWorker) -> None:
        """The worker's signals to the window (queued: it lives in its own thread)."""
        w.state_changed.connect(self._on_state)
        w.device_ready.connect(self._on_device_ready)
        w.traffic.connect(self._on_traffic)
        w.position_changed.connect(self._on_position)
        w.target_changed.connect(self._on_target)
        w.speed_changed.connect(self._on_speed)
        w.speed_limits_changed.connect(self.speed.set_range)
        w.job_failed.connect(self._on_job_failed)
        w.job_finished.connect(self._on_job_finished)
        w.move_started.connect(self._on_move_started)
        w.notice.connect(self._on_notice)
        w.device_error.connect(self._on_device_error)
        w.device_note.connect(self._on_device_note)
        w.capabilities_changed.connect(self._on_capabilities_changed)
        w.control_lines_changed.connect(self.tools.show_lines)
        w.control_note.connect(self._on_control_note)

    def _wire(self) -> None:
        bar = self.connection_bar
        bar.connect_requested.connect(self._connect_from_bar)
        bar.disconnect_requested.connect(self._disconnect_from_bar)
        bar.protocol_changed.connect(self._on_protocol_changed)
        bar.variant_changed.connect(self._on_variant_changed)
        self.port_watcher = PortWatcher(self, list_now=False)
        self.views.add(self.port_watcher.refresh)  # listed once the window has painted
        self.port_watcher.ports_changed.connect(self._on_ports)
        self.port_watcher.port_added.connect(self._on_port_added)
        self.port_watcher.port_removed.connect(self._on_port_removed)
        bar.refresh_requested.connect(self.port_watcher.refresh)

        self.jog_panel.jog_requested.connect(self._on_jog)
        self.jog_panel.jog_released.connect(self._on_jog_released)
        self.keyboard_jog.refused.connect(self._on_jog_refused)
        self.coordinates.go_requested.connect(self._on_go)
        self.coordinates.home_requested.connect(self._go_home)
        self.coordinates.set_home_requested.connect(self._set_home)
        self.coordinates.stop_requested.connect(self.stop)
        self.speed.speed_requested.connect(self._set_speed)
        for part in (self.jog_panel, self.coordinates, self.speed):  # a typed number refused
            part.refused.connect(lambda why: self._say(why, status.WARNING))

    # -- connection --------------------------------------------------------------------------
    def connect_device(
        self, port: str, protocol: str, baud: int, variant: str | None = None
    ) -> None:
        """Ask the worker to open `port`; the result arrives as signals.

        `variant`: the protocol's wire variant (None: the one chosen in the bar, else saved).
        A `sim://NAME` port names its protocol: NAME is used (at its default baud rate).
        """
        named = sim_protocol(port)
        if named != protocol and named in protocol_names():
            self._say(fill(self.tr("%1 names its protocol: connecting as %2"), port, named))
            protocol, variant = named, None
            baud = get_protocol_class(named).default_baud()
        self.settings.setValue("port", port)
        self.settings.setValue("protocol", protocol)
        self.settings.setValue("baud", baud)
        self._last_connection = (port, protocol, baud)
        bar = self.connection_bar
        if variant is None and bar.protocol() == protocol:
            variant = bar.variant()
        bar.set_port(port)  # as typed, options included
        bar.set_protocol(protocol)
        self._show_variants(protocol, variant or read_str(self.settings, f"variant/{protocol}", ""))
        bar.set_baud(baud)
        variant = bar.variant()
        if variant:
            self.settings.setValue(f"variant/{protocol}", variant)
        shown = f"{protocol} {variant}" if variant else protocol
        self.console.append_note(fill(self.tr("connecting to %1 (%2, %3 baud)"), port, shown, baud))
        parameters = read_parameters(self.settings, protocol, port)
        protocol_settings = read_protocol_settings(self.settings, protocol, port)

        def open_port(thread: WorkerThread) -> None:
            """What needs the protocol's module and the worker: done once the worker is (just
            after the first paint when asked for before it)."""
            from app.window.worker import ConnectOptions
            from drivers.urlhandler.protocol_sim import with_sim_variant

            try:
                self.console.set_protocol(create_protocol(protocol, variant or None))
            except (LookupError, BadInput):
                self.console.set_protocol(None)  # the worker reports it; shown undecoded
            clamp = self.tools.prefs.clamp_to_limits
            self._apply_travel(read_travel(self.settings, protocol, port, clamp_default=clamp))
            # The built-in simulated device speaks the variant chosen for the protocol.
            try:
                default = next((v.name for v in get_protocol_class(protocol).variants), "")
            except LookupError:
                default = ""  # the worker reports the unknown protocol
            sim_variant = variant if variant != default else ""
            dtr, rts = self.tools.saved_lines(protocol, port)
            options = ConnectOptions(
                variant=variant,
                settings=protocol_settings,
                parameters=parameters,
                dtr=dtr,
                rts=rts,
            )
            thread.open(with_sim_variant(port, sim_variant), protocol, baud, options)

        self._to_worker(open_port)

    def _connect_from_bar(self, port: str, protocol: str, baud: int) -> None:
        if self.connection_bar.bridge_mode():
            self.start_bridge(port, protocol, baud)
        else:
            self.connect_device(port, protocol, baud)

    def _disconnect_from_bar(self) -> None:
        if self.bridge is not None:
            self.stop_bridge()
        else:
            self.disconnect_device()

    def start_bridge(self, port: str, protocol: str, baud: int) -> str | None:
        """Bridge mode: forward `port` to a new pty for another program, showing every frame
        decoded; motion controls are off meanwhile. Returns the pty's path (None: refused)."""
        if self.bridge is not None:
            return self.bridge.bridge.path
        self.disconnect_device()
        variant = (
            self.connection_bar.variant() if self.connection_bar.protocol() == protocol else ""
        )
        try:
            self.console.set_protocol(create_protocol(protocol, variant or None))
        except (LookupError, BadInput):
            self.console.set_protocol(None)
        from app.window.bridge_session import BridgeSession
        from drivers.urlhandler.protocol_sim import with_sim_variant

        session = BridgeSession(
            with_sim_variant(port, variant), baud, self.session_log_path, self._log_start, self
        )
        try:
            path = session.start()
        except MotionError as exc:
            session.deleteLater()
            self.connection_bar.set_state("error", localized(exc))
            self._say(fill(self.tr("bridge refused: %1"), localized(exc)), status.FAILURE)
            return None
        self.bridge = session
        session.traffic.connect(self._on_traffic)
        session.ended.connect(self._on_bridge_ended)
        self.connection_bar.set_state("connected", fill(self.tr("bridge: %1"), path))
        self._set_controls_enabled(False)
        self.console.set_send_enabled(False)
        self.status_line.set_state(status.BUSY, fill(self.tr("bridging %1 to %2"), port, path))
        self._say(
            fill(self.tr("bridge: another program can open %1; every byte goes to %2"), path, port)
        )
        return path

    def stop_bridge(self) -> None:
        """Leave bridge mode (the end is reported when the bridge's thread has closed)."""
        if self.bridge is not None:
            self.bridge.stop()

    def _on_bridge_ended(self, error: str) -> None:
        session, self.bridge = self.bridge, None
        if session is not None:
            session.deleteLater()
        if error:
            self.connection_bar.set_state("error", error)
            self._say(fill(self.tr("bridge ended: %1"), error), status.FAILURE)
        else:
            self.connection_bar.set_state("disconnected")
            self._say(self.tr("bridge closed"))
        self._show_machine_state()

    def disconnect_device(self) -> None:
        """Ask the worker to close the port (and do not reconnect by itself)."""
        self._last_connection = None
        if self._serial is not None:  # (before the worker is built, nothing is queued)
            self._report_dropped(self._serial.worker.cancel_pending())
        self._to_worker(lambda thread: thread.close())

    def _on_state(self, state: str, detail: str) -> None:
        self.connection_bar.set_state(state)
        was_connected, self.connected = self.connected, state == "connected"
        self.tools.connection_state(self.connected)
        if state == "error":
            self._failed = self._link_failed = True
            self._say(fill(self.tr("connection error: %1"), detail), status.FAILURE)
        elif state == "disconnected":
            self.console.append_note(self.tr("disconnected"))
        elif state == "connected" and detail.startswith("device: "):
            self._failed = True
            self._say(
                fill(self.tr("device: %1"), detail.removeprefix("device: ")),
                status.FAILURE,
                note=False,
            )
        if not self.connected:
            if self._unconfirmed_move:
                self._undo_move()
            self.buffer.break_trail()  # the next connection's positions: a new segment
            self._on_target(None)
            self._set_controls_enabled(False)
            self.parameters.disconnected()
            self.devices.disconnected()
            self._end_move()
            self.jog_panel.release()
            self._jog_job = None
            self._busy_job = None  # the worker dropped what was queued: nothing runs after this
            if self._running_alone:  # ended with the link (or dropped unreported)
                self._running_alone.clear()
                self._show_motion_allowed()
            if self._last_position is not None:
                self.readout.set_status("stale")
        elif not was_connected:
            self._failed = False
        self._show_machine_state(state, detail)

    def _show_machine_state(self, connection: str = "", detail: str = "") -> None:
        if not self.connected:
            name = connection or self.connection_bar.state()
            self.status_line.set_state(name if name != "connected" else status.IDLE, detail)
        elif self._moving:
            self.status_line.set_state(status.MOVING)
        elif self._busy_job is not None:
            self.status_line.set_state(status.BUSY, self._busy_job.describe())
        elif self._failed:
            self.status_line.set_state(status.ERROR, self.status_line.message())
        else:
            self.status_line.set_state(status.IDLE)

    def _on_device_ready(self, info: DeviceInfo) -> None:
        self.info = info
        device = (info.port, info.protocol, info.identity)
        if self._trail_device is not None and device != self._trail_device:
            self.buffer.clear(keep_last=True)  # another device: a trail of its own
        self._trail_device = device
        connected = fill(self.tr("connected to %1 on %2"), localized(info.identity), info.port)
        self.console.append_note(connected)
        self._say(connected, note=False)
        if self._link_failed:  # after a lost link or a restart: what is the position now?
            self._position_lost = not info.capabilities.position_feedback
            self._lost_status = "lost"
            self._say(
                self.tr(
                    "the position is unknown: this device cannot report it; home it or set home"
                )
                if self._position_lost
                else fill(
                    self.tr("connected again to %1: the position was read again"),
                    localized(info.identity),
                ),
                status.WARNING if self._position_lost else status.INFO,
            )
        elif _counts_its_position(info.capabilities):  # a fresh connection: nothing counted
            self._position_lost, self._lost_status = True, "uncounted"
            self._say(
                self.tr(
                    "position unknown: the device cannot be asked; Home or Set Home to start "
                    "counting"
                ),
                status.WARNING,
            )
        self._link_failed = False
        self.readout.set_status(self._settled_status())
        self._adapt(info.capabilities)
        self.parameters.device_ready(info)
        self.devices.device_ready(info)
        self.tools.device_ready(info.protocol, info.variant, info.port)
        if self._last_position is not None and not self._position_lost:
            self.tools.position(self._last_position)
        self._set_controls_enabled(True)
        self.travel_action.setEnabled(True)
        self._show_machine_state()
        QTimer.singleShot(100, self, self.settled.emit)  # cancelled if the window goes first

    def _adapt(self, caps: Capabilities) -> None:
        """Fit the controls to what the device can do (on connection, and after new settings)."""
        name = self.info.protocol.upper() if self.info is not None else self.tr("the device")
        for widget in (self.jog_panel, self.coordinates, self.readout):
            widget.set_axes_enabled(caps.axes)
        self.readout.set_measured(caps.position_feedback)
        self.speed.set_note(localized(caps.speed_note))
        self.speed.set_decimals(caps.speed_decimals)
        self.coordinates.set_home_tips(
            localized(caps.home_note)
            if caps.home_note
            else self.tr("Go to the home position (0, 0, 0)"),
            self.tr("Make the current position the origin (asks first)")
            if caps.set_home or caps.position_feedback
            else fill(
                self.tr(
                    "Restart the panel's count of the position here (asks first); %1 has no "
                    "set-home command, so nothing is sent"
                ),
                name,
            ),
        )
        self.console.set_line_ending(caps.raw_line_end.encode("ascii"))
        mode = "text" if caps.raw_text else "hex"  # a binary protocol's bytes read as hex
        self.console.set_display_mode(mode)
        self.console.set_send_mode(mode)
        for widget in (self.jog_panel, self.coordinates, self.readout):
            widget.set_resolution(caps.resolution)
        tip = self.tr(STOP_TIP) if caps.stop else fill(self.tr(NO_STOP_TIP), name)
        self.coordinates.set_stop_mode(caps.stop, tip)
        self.stop_action.setText(
            self.tr("&Stop") if caps.stop else self.tr("&Drop queued commands")
        )
        self.stop_action.setToolTip(tip)
        self.speed.setEnabled(caps.speed)
        if caps.speed_range is not None:
            self.speed.set_range(*caps.speed_range)

    def _on_capabilities_changed(self, caps: Capabilities) -> None:
        if self.info is not None:
            self.info = dataclasses.replace(self.info, capabilities=caps)
        self._adapt(caps)
        self.devices.adapt(caps)

    def _on_protocol_changed(self, name: str) -> None:
        try:
            cls = get_protocol_class(name)
        except LookupError as exc:
            self._say(localized(exc), status.WARNING, note=False)
            return
        self.tools.protocol_chosen(name)
        self._show_variants(name, read_str(self.settings, f"variant/{name}", ""))
        self.connection_bar.set_baud(cls.default_baud(self.connection_bar.variant() or None))

    def _show_variants(self, protocol: str, current: str) -> None:
        """List the protocol's wire variants in the bar (hidden when it has none); imports the
        protocol's module only when it has some."""
        try:
            cls = get_protocol_class(protocol) if has_variants(protocol) else None
        except LookupError:
            cls = None
        variants = (
            [(v.name, localized(v.description)) for v in cls.variants] if cls is not None else []
        )
        self.connection_bar.set_variants(variants, current)

    def _on_variant_changed(self, variant: str) -> None:
        try:
            cls = get_protocol_class(self.connection_bar.protocol())
            self.connection_bar.set_baud(cls.default_baud(variant))
        except LookupError as exc:
            self._say(localized(exc), status.WARNING, note=False)

    def _on_port_added(self, port: str) -> None:
        """A port appeared; if it is the one that was lost, connect again (position re-read)."""
        self._say(fill(self.tr("port %1 appeared"), port))
        last = self._last_connection
        if self.connection_bar.state() == "error" and last is not None and last[0] == port:
            self._say(fill(self.tr("reconnecting to %1"), port))
            self.connect_device(*last)

    def _on_port_removed(self, port: str) -> None:
        self._say(fill(self.tr("port %1 disappeared"), port))

    def say(self, text: str) -> None:
        """Tell the operator something (status line and console log)."""
        self._say(text)

    def submit_job(self, job: jobs.Job) -> bool:
        """Queue a job for the worker; False (and a message) when not connected."""
        return self._submit(job)

    def _say(self, text: str, kind: str = status.INFO, note: bool = True) -> None:
        """Tell the operator: the status line (once), and the console's log."""
        self.status_line.show_message(text, kind)
        if note:
            self.console.append_note(text)

    def _on_ports(self, ports: list[tuple[str, str]]) -> None:
        self.connection_bar.set_ports(sim_ports() + ports)

    # -- travel limits -----------------------------------------------------------------------
    def _apply_travel(self, limits: TravelLimits | None) -> None:
        self.travel = limits
        self._show_outside()
        box = limits.box if limits is not None else None
        self._to_worker(lambda thread: thread.set_travel(limits))
        self.coordinates.set_box(box)
        self.view2d.set_workspace(box)
        self.view3d.set_workspace(box)  # type: ignore[attr-defined]

    def edit_travel_limits(self) -> None:
        """Let the operator set this device's travel box (saved per device)."""
        if self._last_connection is None:
            return
        port, protocol, _ = self._last_connection
        from widgets.travel_limits_dialog import TravelLimitsDialog

        current = self.travel
        dialog = TravelLimitsDialog(
            fill(self.tr("%1 on %2"), protocol, port),
            current.box if current is not None else None,
            current.clamp if current is not None else False,
            self,
        )
        if dialog.exec() != TravelLimitsDialog.DialogCode.Accepted:
            return
        box, clamp = dialog.result_limits()
        from drivers.travel import TravelLimits

        limits = TravelLimits(box, clamp) if box is not None else None
        write_travel(self.settings, protocol, port, limits)
        self._apply_travel(limits)
        described = limits.describe() if limits else self.tr("none")
        self._say(fill(self.tr("travel limits: %1"), described))

    # -- operator actions --------------------------------------------------------------------
    def _submit(self, job: jobs.Job) -> bool:
        """Queue `job` for the worker; refused out loud (False) when not connected, or when a
        program, a macro or a parameter write is under way and `job` may not run beside it:
        the one check every control, key, macro and the console go through."""
        if not self.connected:
            self._say(
                fill(self.tr("not connected: %1 not sent"), job.describe()),
                status.WARNING,
                note=False,
            )
            return False
        running = list(self._running_alone)
        if running and not _may_run_beside(job, running):
            self._say(
                fill(
                    self.tr("%1 refused: %2 is under way; wait for its end or press Stop"),
                    job.describe(),
                    running[0].describe(),
                ),
                status.WARNING,
            )
            return False
        self._busy_job = job
        if _runs_alone(job):
            self._running_alone.append(job)
            if not running:
                self._show_motion_allowed()
                self._say(
                    fill(
                        self.tr("motion controls are off until %1 ends (Stop ends it now)"),
                        job.describe(),
                    ),
                    note=False,
                )
        self.worker.submit(job)
        self._show_machine_state()
        return True

    def jobs_dropped(self, dropped: list[jobs.Job]) -> None:
        """Jobs taken off the worker's queue unrun (by a dock's Cancel): motion may be on again."""
        kept = [job for job in self._running_alone if all(job is not d for d in dropped)]
        if len(kept) != len(self._running_alone):
            self._running_alone = kept
            self._show_motion_allowed()

    def _motion_blocker(self) -> str:
        """Why motion is off while connected ("" when it is on)."""
        if not self._running_alone:
            return ""
        return fill(self.tr("%1 is under way"), self._running_alone[0].describe())

    def _show_motion_allowed(self) -> None:
        """Motion controls on while connected and nothing runs alone; Stop always on."""
        reason = self._motion_blocker()
        allowed = self._controls_on and not reason
        if not allowed:
            self.jog_panel.release()
        for widget in (self.jog_panel, self.speed):
            widget.setEnabled(allowed)
        self.coordinates.setEnabled(self._controls_on)  # its Stop button too
        for button in (
            self.coordinates.go_button,
            self.coordinates.home_button,
            self.coordinates.set_home_button,
        ):
            button.setEnabled(not reason)
        self.keyboard_jog.set_motion_blocker(reason if self._controls_on else "")
        if self._controls_on:  # (when off, the tools turned the macros off themselves)
            self.tools.macros.set_runnable(allowed, reason)
        if built(self.devices):
            self.devices.set_motion_allowed(not reason, reason)

    def _on_jog_refused(self, reason: str) -> None:
        self._say(fill(self.tr("jog refused: %1"), reason), status.WARNING, note=False)

    def _on_jog(self, axis: str, distance: float) -> None:
        """A jog key or button was pressed: one step now, unless a step is under way (its end
        sends the next one only if the key or button is still held: a press never queues)."""
        step = self.jog_panel.step()
        if step != self._saved_step:  # written when it changes, not at every jog (a disk write)
            self._saved_step = step
            self.settings.setValue("jog_step", step)
        self._jog_pressed_at = time.monotonic()
        if self._jog_job is None:
            self._jog_repeat = False
            self._jog_step(axis, distance)

    def _jog_step(self, axis: str, distance: float) -> None:
        from app.window import jobs

        deltas = {"x": 0.0, "y": 0.0, "z": 0.0}
        deltas[axis] = distance
        job = jobs.MoveByJob(deltas["x"], deltas["y"], deltas["z"])
        self._jog_job = job if self._submit(job) else None
        if self._jog_job is None:
            self.jog_panel.release()  # refused: nothing to repeat

    def _jog_step_ended(self, job: jobs.Job) -> None:
        """A jog step ended: decide on the next one after the input events already received
        (a release waiting in the queue counts), one turn of the event loop later; a press
        meanwhile steps at once."""
        self._jog_job, self._jog_ended = None, job
        QTimer.singleShot(0, self, lambda: self._next_jog_step(job))

    def _next_jog_step(self, job: jobs.Job) -> None:
        """After the jog step `job`: the next one only if the jog is still held now."""
        if self._jog_job is not None or self._jog_ended is not job:
            return  # a press stepped meanwhile, or a later step ended
        self._jog_ended = None
        held = self.jog_panel.held()
        if held is not None and self.connected:
            self._jog_repeat = True
            self._jog_step(*held)

    def _on_jog_released(self) -> None:
        """A jog key or button was let go: where the device has a stop, the step under way
        halts now if the jog was held (a repeated step, or a press longer than a tap); a tap
        moves its whole step."""
        serial, caps = self._serial, self.info.capabilities if self.info is not None else None
        if self._jog_job is None or serial is None:
            return
        if not self._jog_repeat and time.monotonic() - self._jog_pressed_at < JOG_TAP_S:
            return
        if caps is not None and caps.stop:
            serial.worker.stop_now()

    def _on_go(self, mode: str, values: tuple[float, float, float]) -> None:
        from app.window import jobs

        if mode == "relative":
            self._submit(jobs.MoveByJob(*values))
        else:
            self._submit(jobs.MoveToJob(*values))

    def _set_home(self) -> None:
        from app.window import jobs

        if self._submit(jobs.SetHomeJob()):
            self._home_from = self._last_position

    def _go_home(self) -> None:
        from app.window import jobs

        self._submit(jobs.HomeJob())

    def _set_speed(self, speed: float) -> None:
        from app.window import jobs

        self._submit(jobs.SetSpeedJob(speed))

    def _send_raw(self, data: bytes) -> None:
        """The console's send line: bytes for the device as they are, through the motion guard
        (a move checked and followed like a typed one); bytes the protocol cannot read go,
        while a travel box is set, only once the operator confirms them."""
        from app.window import jobs
        from drivers.motion_guard import unreadable

        reason = unreadable(self.console.index.protocol, data) if self.travel else None
        if reason is not None:
            from PySide6.QtWidgets import QMessageBox

            answer = QMessageBox.question(
                self,
                self.tr("Send unchecked bytes?"),
                fill(
                    self.tr(
                        "These bytes cannot be read as a command (%1), so they cannot be checked "
                        "against the travel limits (%2): they might move the stage outside "
                        "them.\n\nSend them anyway?"
                    ),
                    localized(reason),
                    self.travel.describe() if self.travel else "",
                ),
                QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
                QMessageBox.StandardButton.No,
            )
            if answer != QMessageBox.StandardButton.Yes:
                self._say(
                    self.tr("not sent: the bytes could not be checked against the travel limits"),
                    status.WARNING,
                )
                return
        self._submit(jobs.RawJob(data, force=reason is not None))

    def stop(self) -> None:
        """Cancel what is queued and say what was not sent; where the device can stop, stop
        the move (or program) under way too."""
        self.jog_panel.release()
        serial = self._serial  # (before the worker is built, nothing is queued or moving)
        dropped = serial.worker.cancel_pending() if serial is not None else []
        self._report_dropped(dropped)
        can_stop = self.info is not None and self.info.capabilities.stop
        macro = serial is not None and _is_macro(self._busy_job)
        if serial is not None and macro:
            serial.worker.stop_now()  # every device: the macro ends between steps
            self._say(self.tr("stopping the macro under way"), status.WARNING, note=False)
        elif serial is not None and can_stop and (self._busy_job is not None or self._moving):
            serial.worker.stop_now()
            self._say(self.tr("stopping the move under way"), status.WARNING, note=False)
        elif not dropped:
            self._say(self.tr("nothing queued; the move under way finishes"), note=False)

    def _report_dropped(self, dropped: list[jobs.Job]) -> None:
        if not dropped:
            return
        self.parameters.forget(dropped)
        names = ", ".join(job.describe() for job in dropped)
        self._say(
            fill(self.tr("stopped: %1 command(s) not sent: %2"), len(dropped), names),
            status.WARNING,
        )
        if any(job is self._jog_job for job in dropped):
            self._jog_job = None
        self.jobs_dropped(dropped)

    def _set_controls_enabled(self, enabled: bool) -> None:
        self._controls_on = enabled
        self.console.set_send_enabled(enabled)
        self.tools.controls_enabled(enabled)
        self._show_motion_allowed()  # the jog hint follows: "keys off: not connected", or not

    # -- worker results ----------------------------------------------------------------------
    def _on_traffic(self, records: list[Traffic]) -> None:
        for record in records:
            self.console.append_traffic(record.direction, record.data, record.time, record.wall)

    def _on_position(self, report: PositionReport) -> None:
        self._true_position = (report.x, report.y, report.z)
        self._unconfirmed_move = False
        self.buffer.keep_provisional()  # the estimate so far was the stage's way
        if self._home_from is not None and (report.x, report.y, report.z) == (0.0, 0.0, 0.0):
            # Set Home: the trail moves into the new coordinates, with no false jump.
            x, y, z = self._home_from
            self._home_from = None
            self.buffer.shift(-x, -y, -z)
            self._on_target(None)
            self.console.append_note(
                fill(
                    self.tr("new home: the trail is shifted by (%1, %2, %3) mm"),
                    f"{-x:g}",
                    f"{-y:g}",
                    f"{-z:g}",
                )
            )
            self.tools.home_moved((x, y, z))
        if self.estimate is not None and self.estimate.active():
            self._end_move_estimate()
        devices = self.devices
        if built(devices) and devices.arc_dock.isVisible() and devices.arc.start_z() != report.z:
            devices.arc.set_start_z(report.z)  # the arc preview starts at the stage's Z
        if self.info is not None:  # measured, or where the last move's reply said it ended
            self.readout.set_measured(report.measured, report.confirmed or None)
        self._show_position(report.x, report.y, report.z)
        self._show_outside()
        self._keep_count()

    def _keep_count(self) -> None:
        """A device that cannot be asked where it is (Visiomex): the position counted since
        Home or Set Home is kept with the settings, for motionctl to go on from."""
        from drivers.position_count import COUNTED_PROTOCOLS

        info, here = self.info, self._true_position
        if info is None or info.protocol not in COUNTED_PROTOCOLS or here is None:
            return
        if info.capabilities.position_feedback or self._position_lost or here == self._count_kept:
            return
        self._count_kept = here
        write_counted_position(self.settings, info.protocol, info.port, here)

    def _show_outside(self) -> None:
        """The readout says so while the position reported is outside the travel limits."""
        here, travel = self._last_position, self.travel
        outside = travel.outside(here) if here is not None and travel is not None else []
        self.readout.show_outside(outside)

    def _show_position(self, x: float, y: float, z: float) -> None:
        self._last_position = (x, y, z)
        if self.connected and not self._position_lost:
            self.tools.position((x, y, z))
        self.readout.set_position(x, y, z)
        self.coordinates.set_known_position(x, y, z)
        self.buffer.append(time.monotonic() - self.t0, x, y, z)

    def _on_move_started(self, move: MoveStart) -> None:
        self._moving = True
        self._unconfirmed_move = True
        self._show_machine_state()
        if move.duration > 0 and self.estimate is not None:
            self.buffer.begin_provisional()  # taken back should the move fail
            self.estimate.start(move)

    def _undo_move(self) -> None:
        """A move failed (or its link went) before a position confirmed it: its estimate is
        taken back from the trail, its target mark goes, and the readout shows the last
        position reported again."""
        self._unconfirmed_move = False
        if self.estimate is not None:
            self.estimate.stop()
        self.buffer.drop_provisional()
        self._on_target(None)
        if self.readout.status() == "estimated":
            self._mark_estimated(False)
        true = self._true_position
        if true is not None and true != self._last_position:
            self._last_position = true
            if self.connected and not self._position_lost:
                self.tools.position(true)
            self.readout.set_position(*true)
            self.coordinates.set_known_position(*true)

    def _on_estimate(self, x: float, y: float, z: float) -> None:
        if self.readout.status() != "estimated":
            # Marked at the first estimate: a move over before it (a short jog step) restyles
            # nothing, which halved the GUI's event-loop gaps while jogging.
            self._mark_estimated(True)
        self._show_position(x, y, z)

    def _settled_status(self) -> str:
        """The readout's status when no move is being estimated."""
        return self._lost_status if self._position_lost else "live"

    def _mark_estimated(self, estimated: bool) -> None:
        self.readout.set_status("estimated" if estimated else self._settled_status())
        self.view2d.set_estimated(estimated)
        self.view3d.set_estimated(estimated)  # type: ignore[attr-defined]

    def _end_move_estimate(self) -> None:
        if self.estimate is not None:
            self.estimate.stop()
        if self.readout.status() == "estimated":
            self._mark_estimated(False)

    def _end_move(self) -> None:
        self._moving = False
        if self.estimate is not None and self.estimate.active():
            self._end_move_estimate()

    def _on_target(self, target: tuple[float, float, float] | None) -> None:
        self.view2d.set_target(target)
        self.view3d.set_target(target)  # type: ignore[attr-defined]

    def _on_speed(self, speed: float) -> None:
        self.speed.set_reported(speed)
        self.speed.set_value(speed)
        self.devices.set_speed(speed)

    def _on_notice(self, text: str) -> None:
        self._say(text, status.WARNING)

    def _on_control_note(self, text: str) -> None:
        """A control line changed, or a break was sent: in the console, among the traffic."""
        self.console.append_note(text)

    def _on_device_error(self, message: str) -> None:
        self._failed = True
        self._say(fill(self.tr("the device reported an error: %1"), message), status.FAILURE)
        self._show_machine_state()

    def _on_device_note(self, text: str) -> None:
        self.console.append_note(fill(self.tr("device: %1"), text))

    def _job_ended(self, job: jobs.Job) -> None:
        from app.window import jobs

        self._busy_job = None
        if self._moving:  # one job at a time: when it ends, nothing moves (arcs and jogs alike)
            self._end_move()
        if isinstance(job, jobs.SetHomeJob):
            self._home_from = None
        if any(job is other for other in self._running_alone):
            self._running_alone = [other for other in self._running_alone if other is not job]
            if not self._running_alone:
                self._show_motion_allowed()
        if job is self._jog_job:
            self._jog_step_ended(job)

    def _on_job_failed(self, job: jobs.Job, message: str) -> None:
        if self._unconfirmed_move:
            self._undo_move()
        if job is self._jog_job:
            self.jog_panel.release()  # e.g. refused at the travel limits: stop stepping
        self._failed = True
        self._say(fill(self.tr("%1 failed: %2"), job.describe(), message), status.FAILURE)
        self._job_ended(job)
        self._show_machine_state()

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        from app.window import jobs

        self._failed = False
        self.status_line.clear_error()
        caps = self.info.capabilities if self.info is not None else None
        if (
            isinstance(job, jobs.SetHomeJob)  # places that the device itself knows again
            or (caps is not None and caps.homing and isinstance(job, jobs.HomeJob))
            or (caps is not None and caps.absolute_moves and isinstance(job, jobs.MoveToJob))
        ):
            self._position_lost = False  # a known place again
            if self.readout.status() in ("lost", "uncounted"):
                self.readout.set_status("live")
        elif (
            self._position_lost
            and self._lost_status == "uncounted"
            and isinstance(job, jobs.HomeJob)
        ):  # the home move is confirmed: counting starts here
            self._position_lost = False
            self.readout.set_status("live")
            self._say(self.tr("home confirmed: the position is counted from here"))
        self._keep_count()  # Home, Set Home: counting starts
        if isinstance(job, jobs.SetSpeedJob) and isinstance(result, float) and result != job.speed:
            self._say(
                fill(
                    self.tr("speed %1 mm/s reads back as %2 mm/s (the device rounds)"),
                    f"{job.speed:g}",
                    f"{result:g}",
                ),
                note=False,
            )
        self._job_ended(job)
        self._show_machine_state()

    # -- settings ----------------------------------------------------------------------------
    def _restore(self) -> None:
        s = self.settings
        geometry = s.value("geometry")
        if geometry is not None:
            self.restoreGeometry(geometry)
        state = s.value("windowState")
        if state is not None:
            self.restoreState(state)
        self.jog_panel.set_step(read_number(s, "jog_step", 1.0))
        protocol = read_str(s, "protocol", DEFAULT_PROTOCOL)
        self.connection_bar.set_protocol(protocol)
        self._show_variants(protocol, read_str(s, f"variant/{protocol}", ""))
        self.connection_bar.set_port(read_str(s, "port", DEFAULT_PORT))
        self.connection_bar.set_baud(int(read_number(s, "baud", 115200)))

    def closeEvent(self, event: QCloseEvent) -> None:
        """Save the layout and stop the worker thread before closing."""
        self.settings.setValue("geometry", self.saveGeometry())
        self.settings.setValue("windowState", self.saveState())
        self.settings.setValue("jog_step", self.jog_panel.step())
        self.settings.sync()
        self._closed = True
        self.keyboard_jog.detach()
        self.port_watcher.stop()
        if self._serial is not None:
            if self.estimate is not None:
                self.estimate.stop()
            if not self._serial.stop():
                log.error("the serial worker did not stop in time")
        else:  # closed before the worker was built: nothing to stop, nothing asked of it is done
            self._serial_calls.clear()
            if self._pending_log is not None:
                self._pending_log.close()
                self._pending_log = None
        if self.bridge is not None:
            self.bridge.bridge.close()  # its thread returns within a moment
        for viewer in self._viewers:
            viewer.close()
        if built(self.console):
            self.console.index.close()
        super().closeEvent(event)
