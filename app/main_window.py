"""The operator's main window: connection bar, jog, coordinates, speed, position views, console."""

from __future__ import annotations

import logging
import time

from PySide6.QtCore import QEvent, QObject, Qt, QTimer, Signal
from PySide6.QtGui import QCloseEvent, QKeyEvent, QKeySequence
from PySide6.QtWidgets import (
    QAbstractSpinBox,
    QApplication,
    QComboBox,
    QDockWidget,
    QLabel,
    QLineEdit,
    QMainWindow,
    QPlainTextEdit,
    QSplitter,
    QTextEdit,
    QToolBar,
    QWidget,
)

from app import jobs
from app.ports import PortWatcher
from app.settings import DEFAULT_PORT, DEFAULT_PROTOCOL, open_settings, read_number, read_str
from app.worker import DeviceInfo, SerialWorker
from app.worker_thread import WorkerThread
from drivers.events import PositionReport
from drivers.registry import get_protocol_class, protocol_names
from drivers.sim.registry import simulator_names
from drivers.traffic import Traffic
from widgets.connection_bar import ConnectionBar
from widgets.coordinate_entry import CoordinateEntry
from widgets.jog_panel import JogPanel
from widgets.position_buffer import PositionBuffer
from widgets.position_readout import PositionReadout
from widgets.position_view_2d import PositionView2D
from widgets.position_view_3d import make_position_view_3d
from widgets.raw_console import RawConsole
from widgets.speed_control import SpeedControl

log = logging.getLogger(__name__)

TEXT_INPUTS = (QLineEdit, QAbstractSpinBox, QPlainTextEdit, QTextEdit, QComboBox)
KEYBOARD_JOG_KEYS = {
    Qt.Key.Key_Left,
    Qt.Key.Key_Right,
    Qt.Key.Key_Up,
    Qt.Key.Key_Down,
    Qt.Key.Key_PageUp,
    Qt.Key.Key_PageDown,
}


def sim_ports() -> list[tuple[str, str]]:
    """Every built-in simulated device as a (port, description) pair."""
    return [(f"sim://{name}", f"simulated {name} device") for name in simulator_names()]


class MainWindow(QMainWindow):
    """Wires the widgets to the serial worker; never touches the port itself."""

    settled = Signal()  # connected, state read, first position drawn

    def __init__(self, worker_thread: WorkerThread | None = None) -> None:
        super().__init__()
        self.setObjectName("mainWindow")
        self.setWindowTitle("Motion Panel")
        self.settings = open_settings()
        self.worker_thread = worker_thread or WorkerThread(self._make_worker())
        self.worker = self.worker_thread.worker
        self.buffer = PositionBuffer()
        self.t0 = time.monotonic()
        self.connected = False
        self.info: DeviceInfo | None = None
        self._last_connection: tuple[str, str, int] | None = None
        self._build()
        self._wire()
        self._restore()
        self._set_controls_enabled(False)
        QApplication.instance().installEventFilter(self)  # type: ignore[union-attr]

    def _make_worker(self) -> SerialWorker:
        """A worker with the saved polling rates (5-10 Hz while a move is confirmed, 1 s idle)."""
        moving_hz = min(max(read_number(self.settings, "poll_moving_hz", 10.0), 5.0), 10.0)
        idle_s = min(max(read_number(self.settings, "poll_idle_s", 1.0), 0.2), 10.0)
        return SerialWorker(poll_moving_hz=moving_hz, poll_idle_s=idle_s)

    # -- layout ------------------------------------------------------------------------------
    def _build(self) -> None:
        self.connection_bar = ConnectionBar(self)
        self.connection_bar.set_protocols(protocol_names())
        toolbar = QToolBar("Connection", self)
        toolbar.setObjectName("connectionToolBar")
        toolbar.setMovable(False)
        toolbar.addWidget(self.connection_bar)
        self.addToolBar(toolbar)

        self.view3d = make_position_view_3d(self.buffer, self)
        self.view2d = PositionView2D(self.buffer, self)
        splitter = QSplitter(Qt.Orientation.Horizontal, self)
        splitter.addWidget(self.view3d)
        splitter.addWidget(self.view2d)
        splitter.setSizes([600, 600])
        self.setCentralWidget(splitter)

        self.readout = PositionReadout(self)
        self.jog_panel = JogPanel(self)
        self.coordinates = CoordinateEntry(self)
        self.speed = SpeedControl(self)
        self.console = RawConsole(self)
        left, bottom = Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.BottomDockWidgetArea
        docks = [
            self._dock("Position", self.readout, left),
            self._dock("Jog", self.jog_panel, left),
            self._dock("Go to", self.coordinates, left),
            self._dock("Speed", self.speed, left),
            self._dock("Console", self.console, bottom),
        ]
        self._build_menus(docks)

        self.state_label = QLabel("disconnected", self)
        self.state_label.setObjectName("statusConnection")
        self.error_label = QLabel("", self)
        self.error_label.setObjectName("statusError")
        self.statusBar().addWidget(self.state_label)
        self.statusBar().addPermanentWidget(self.error_label)
        self.resize(1400, 900)

    def _build_menus(self, docks: list[QDockWidget]) -> None:
        file_menu = self.menuBar().addMenu("&File")
        export = file_menu.addAction("&Export traffic log…", self.console.export_interactively)
        export.setShortcut(QKeySequence("Ctrl+E"))
        export.setToolTip("Save every byte sent and received, with timestamps, to a text file")
        file_menu.addSeparator()
        file_menu.addAction("&Quit", QKeySequence.StandardKey.Quit, self.close)
        motion_menu = self.menuBar().addMenu("&Motion")
        stop = motion_menu.addAction("&Stop (drop queued commands)", self.stop)
        stop.setShortcut(QKeySequence(Qt.Key.Key_Escape))
        stop.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
        view_menu = self.menuBar().addMenu("&View")
        reset = view_menu.addAction("&Reset views", self.reset_views)
        reset.setShortcut(QKeySequence("Ctrl+R"))
        view_menu.addAction("&Clear trail", self.view2d.clear_trail)
        view_menu.addSeparator()
        for dock in docks:
            view_menu.addAction(dock.toggleViewAction())

    def reset_views(self) -> None:
        """Fit the 2D and 3D views to the trail again."""
        self.view2d.reset_view()
        self.view3d.reset_view()  # type: ignore[attr-defined]

    def _dock(self, title: str, widget: QWidget, area: Qt.DockWidgetArea) -> QDockWidget:
        dock = QDockWidget(title, self)
        dock.setObjectName(f"{widget.objectName()}Dock")
        dock.setWidget(widget)
        dock.setFeatures(
            QDockWidget.DockWidgetFeature.DockWidgetMovable
            | QDockWidget.DockWidgetFeature.DockWidgetFloatable
            | QDockWidget.DockWidgetFeature.DockWidgetClosable  # View menu brings it back
        )
        self.addDockWidget(area, dock)
        return dock

    def _wire(self) -> None:
        w = self.worker
        w.state_changed.connect(self._on_state)
        w.device_ready.connect(self._on_device_ready)
        w.traffic.connect(self._on_traffic)
        w.position_changed.connect(self._on_position)
        w.target_changed.connect(self._on_target)
        w.speed_changed.connect(self._on_speed)
        w.speed_limits_changed.connect(self.speed.set_range)
        w.job_failed.connect(self._on_job_failed)
        w.job_finished.connect(self._on_job_finished)
        w.device_text.connect(lambda text: self.console.append_note(f"device: {text}"))

        bar = self.connection_bar
        bar.connect_requested.connect(self.connect_device)
        bar.disconnect_requested.connect(self.disconnect_device)
        bar.protocol_changed.connect(self._on_protocol_changed)
        self.port_watcher = PortWatcher(self)
        self.port_watcher.ports_changed.connect(self._on_ports)
        self.port_watcher.port_added.connect(self._on_port_added)
        self.port_watcher.port_removed.connect(lambda p: self._notice(f"port {p} disappeared"))
        bar.refresh_requested.connect(self.port_watcher.refresh)

        self.jog_panel.jog_requested.connect(self._on_jog)
        self.coordinates.go_requested.connect(self._on_go)
        self.coordinates.home_requested.connect(lambda: self._submit(jobs.HomeJob()))
        self.coordinates.set_home_requested.connect(lambda: self._submit(jobs.SetHomeJob()))
        self.coordinates.stop_requested.connect(self.stop)
        self.speed.speed_requested.connect(lambda v: self._submit(jobs.SetSpeedJob(v)))
        self.console.send_requested.connect(lambda data: self._submit(jobs.RawJob(data)))

    # -- connection --------------------------------------------------------------------------
    def connect_device(self, port: str, protocol: str, baud: int) -> None:
        """Ask the worker to open `port`; the result arrives as signals."""
        self.settings.setValue("port", port)
        self.settings.setValue("protocol", protocol)
        self.settings.setValue("baud", baud)
        self._last_connection = (port, protocol, baud)
        self.console.append_note(f"connecting to {port} ({protocol}, {baud} baud)")
        self.worker_thread.open(port, protocol, baud)

    def disconnect_device(self) -> None:
        """Ask the worker to close the port (and do not reconnect by itself)."""
        self._last_connection = None
        dropped = self.worker.cancel_pending()
        self._report_dropped(dropped)
        self.worker_thread.close()

    def _on_state(self, state: str, detail: str) -> None:
        self.connection_bar.set_state(state)
        self.connected = state == "connected"
        text = state if not detail else f"{state}: {detail}"
        self.state_label.setText(text)
        if state == "error":
            self.error_label.setText(detail)
            self.console.append_note(f"error: {detail}")
            self.statusBar().showMessage(detail, 10000)
        elif state == "disconnected":
            self.console.append_note("disconnected")
        if not self.connected:
            self._set_controls_enabled(False)

    def _on_device_ready(self, info: DeviceInfo) -> None:
        self.info = info
        caps = info.capabilities
        self.console.append_note(f"connected to {info.identity} on {info.port}")
        for widget in (self.jog_panel, self.coordinates, self.readout):
            widget.set_axes_enabled(caps.axes)
        self.readout.set_measured(caps.position_feedback)
        self._set_controls_enabled(True)
        self.speed.setEnabled(caps.speed)
        if caps.speed_range is not None:
            self.speed.set_range(*caps.speed_range)
        QTimer.singleShot(100, self, self.settled.emit)  # cancelled if the window goes first

    def _on_protocol_changed(self, name: str) -> None:
        try:
            self.connection_bar.set_baud(get_protocol_class(name).capabilities.default_baud)
        except LookupError as exc:
            self.statusBar().showMessage(str(exc), 5000)

    def _on_port_added(self, port: str) -> None:
        """A port appeared; if it is the one that was lost, connect again (position re-read)."""
        self._notice(f"port {port} appeared")
        last = self._last_connection
        if self.connection_bar.state() == "error" and last is not None and last[0] == port:
            self._notice(f"reconnecting to {port}")
            self.connect_device(*last)

    def _notice(self, text: str) -> None:
        self.statusBar().showMessage(text, 8000)
        self.console.append_note(text)

    def _on_ports(self, ports: list[tuple[str, str]]) -> None:
        self.connection_bar.set_ports(sim_ports() + ports)

    # -- operator actions --------------------------------------------------------------------
    def _submit(self, job: jobs.Job) -> None:
        if not self.connected:
            self.statusBar().showMessage(f"not connected: {job.describe()} not sent", 5000)
            return
        self.worker.submit(job)

    def _on_jog(self, axis: str, distance: float) -> None:
        deltas = {"x": 0.0, "y": 0.0, "z": 0.0}
        deltas[axis] = distance
        self.settings.setValue("jog_step", self.jog_panel.step())
        self._submit(jobs.MoveByJob(deltas["x"], deltas["y"], deltas["z"]))

    def _on_go(self, mode: str, values: tuple[float, float, float]) -> None:
        if mode == "relative":
            self._submit(jobs.MoveByJob(*values))
        else:
            self._submit(jobs.MoveToJob(*values))

    def stop(self) -> None:
        """Cancel what is queued and say what was not sent."""
        dropped = self.worker.cancel_pending()
        self._report_dropped(dropped)
        if not dropped:
            self.statusBar().showMessage("nothing queued; the move under way finishes", 5000)

    def _report_dropped(self, dropped: list[jobs.Job]) -> None:
        if not dropped:
            return
        names = ", ".join(job.describe() for job in dropped)
        message = f"stopped: {len(dropped)} command(s) not sent: {names}"
        self.statusBar().showMessage(message, 10000)
        self.console.append_note(message)

    def _set_controls_enabled(self, enabled: bool) -> None:
        for widget in (self.jog_panel, self.coordinates, self.speed):
            widget.setEnabled(enabled)

    # -- worker results ----------------------------------------------------------------------
    def _on_traffic(self, records: list[Traffic]) -> None:
        for record in records:
            self.console.append_traffic(record.direction, record.data, record.time)

    def _on_position(self, report: PositionReport) -> None:
        self.readout.set_position(report.x, report.y, report.z)
        self.coordinates.set_known_position(report.x, report.y, report.z)
        self.buffer.append(time.monotonic() - self.t0, report.x, report.y, report.z)

    def _on_target(self, target: tuple[float, float, float] | None) -> None:
        self.view2d.set_target(target)
        self.view3d.set_target(target)  # type: ignore[attr-defined]

    def _on_speed(self, speed: float) -> None:
        self.speed.set_reported(speed)
        self.speed.set_value(speed)

    def _on_job_failed(self, job: jobs.Job, message: str) -> None:
        text = f"{job.describe()} failed: {message}"
        self.error_label.setText(text)
        self.statusBar().showMessage(text, 10000)
        self.console.append_note(text)

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        self.error_label.setText("")
        if isinstance(job, jobs.SetSpeedJob) and isinstance(result, float) and result != job.speed:
            self.statusBar().showMessage(
                f"speed {job.speed:g} mm/s reads back as {result:g} mm/s (the device rounds)", 5000
            )

    # -- keyboard jog ------------------------------------------------------------------------
    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Arrow keys and Page Up/Down jog wherever the focus is, except in text fields."""
        if (
            event.type() == QEvent.Type.KeyPress
            and isinstance(event, QKeyEvent)
            and event.key() in KEYBOARD_JOG_KEYS
            and self.isActiveWindow()
            and self.jog_panel.isEnabled()
            and not isinstance(QApplication.focusWidget(), TEXT_INPUTS)
        ):
            return self.jog_panel.handle_key(
                event.key(), event.modifiers(), auto_repeat=event.isAutoRepeat()
            )
        return super().eventFilter(watched, event)

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
        self.connection_bar.set_port(read_str(s, "port", DEFAULT_PORT))
        self.connection_bar.set_baud(int(read_number(s, "baud", 115200)))

    def closeEvent(self, event: QCloseEvent) -> None:
        """Save the layout and stop the worker thread before closing."""
        self.settings.setValue("geometry", self.saveGeometry())
        self.settings.setValue("windowState", self.saveState())
        self.settings.setValue("jog_step", self.jog_panel.step())
        self.settings.sync()
        QApplication.instance().removeEventFilter(self)  # type: ignore[union-attr]
        self.port_watcher.stop()
        if not self.worker_thread.stop():
            log.error("the serial worker did not stop in time")
        super().closeEvent(event)
