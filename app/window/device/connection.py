"""One device's connection as the window drives it: connect, disconnect, the bridge, reconnecting
when the port comes back, and the protocol, variant and baud rate in the connection bar."""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.common.messages import localized
from app.common.settings import (
    DEFAULT_PORT,
    DEFAULT_PROTOCOL,
    read_counted_position,
    read_number,
    read_parameters,
    read_protocol_settings,
    read_str,
    read_travel,
    write_travel,
)
from app.window.layout.fit_controls import fit_controls
from drivers.errors import BadInput, MotionError
from drivers.protocols.registry import (
    create_protocol,
    get_protocol_class,
    has_variants,
    protocol_names,
)
from widgets import status_line as status
from widgets._i18n import fill
from widgets.connection_bar import sim_protocol

if TYPE_CHECKING:
    from app.window.device.bridge_session import BridgeSession
    from app.window.device.connect_options import DeviceInfo
    from app.window.device.job_desk import JobDesk
    from app.window.device.machine_state import MachineState
    from app.window.device.ports import PortWatcher
    from app.window.device.worker import SerialWorker
    from app.window.device.worker_link import WorkerLink
    from app.window.device.worker_thread import WorkerThread
    from app.window.services import WindowParts
    from drivers.link.records import Traffic
    from drivers.protocols.base import Protocol
    from drivers.protocols.capabilities import Capabilities
    from widgets._axes import Box

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"


def sim_ports() -> list[tuple[str, str]]:
    """Every built-in simulated device as a (port, description) pair."""
    from drivers.sim.registry import simulator_names  # (listed after the first paint)

    description = translate("MainWindow", "simulated %1 device")
    return [(f"sim://{name}", fill(description, name)) for name in simulator_names()]


class Connection(QObject):
    """Opens and closes one device for the window (through its worker, or as a bridge)."""

    settled = Signal()  # connected, state read, first position drawn
    device_shown = Signal()  # the window shows the device connected, its controls enabled

    def __init__(
        self,
        window: WindowParts,
        link: WorkerLink,
        machine: MachineState,
        desk: JobDesk,
        ports: PortWatcher,
    ) -> None:
        super().__init__(window)  # type: ignore[arg-type]
        self.window = window
        self.workers = link
        self.machine = machine
        self.desk = desk
        self.settings = window.settings
        self.bar = window.connection_bar
        self.last: tuple[str, str, int] | None = None  # port, protocol, baud asked for last
        self.bridge: BridgeSession | None = None
        self._waiting: DeviceInfo | None = None  # ready while the window's docks were built
        # A turn after: once the layout has fitted the docks built (as when the device answers
        # after them), so the device's docks come in as they would then.
        window.views.usable.connect(lambda: QTimer.singleShot(0, self, self._show_waiting))
        link.wirers.append(self._wire_worker)
        bar = self.bar
        bar.set_protocols(protocol_names())
        bar.connect_requested.connect(self._connect_from_bar)
        bar.disconnect_requested.connect(self._disconnect_from_bar)
        bar.protocol_changed.connect(self._on_protocol_changed)
        bar.variant_changed.connect(self._on_variant_changed)
        bar.refresh_requested.connect(ports.refresh)
        ports.ports_changed.connect(lambda found: bar.set_ports(sim_ports() + found))
        ports.port_added.connect(self._on_port_added)
        ports.port_removed.connect(
            lambda port: self._tell(fill(translate("MainWindow", "port %1 disappeared"), port))
        )

    def _wire_worker(self, w: SerialWorker) -> None:
        w.state_changed.connect(self._on_state)
        w.device_ready.connect(self._on_device_ready)
        w.traffic.connect(self._on_traffic)
        w.capabilities_changed.connect(self._on_capabilities_changed)
        w.control_lines_changed.connect(self.window.tools.show_lines)
        w.control_note.connect(self._on_control_note)

    def _tell(self, text: str, kind: str = status.INFO, note: bool = True) -> None:
        self.window.tell(text, kind, note)

    def restore(self) -> None:
        """The port, protocol, variant and baud rate last used, in the bar."""
        s, bar = self.settings, self.bar
        protocol = read_str(s, "protocol", DEFAULT_PROTOCOL)
        bar.set_protocol(protocol)
        self._show_variants(protocol, read_str(s, f"variant/{protocol}", ""))
        bar.set_port(read_str(s, "port", DEFAULT_PORT))
        bar.set_baud(int(read_number(s, "baud", 115200)))

    # -- connecting --------------------------------------------------------------------------
    def connect_device(
        self, port: str, protocol: str, baud: int, variant: str | None = None
    ) -> None:
        """Ask the worker to open `port`; the result arrives as signals.

        `variant`: the protocol's wire variant (None: the one chosen in the bar, else saved).
        A `sim://NAME` port names its protocol: NAME is used (at its default baud rate).
        """
        named = sim_protocol(port)
        if named != protocol and named in protocol_names():
            text = translate("MainWindow", "%1 names its protocol: connecting as %2")
            self._tell(fill(text, port, named))
            protocol, variant = named, None
            baud = get_protocol_class(named).default_baud()
        self.settings.setValue("port", port)
        self.settings.setValue("protocol", protocol)
        self.settings.setValue("baud", baud)
        self.last = (port, protocol, baud)
        bar = self.bar
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
        text = translate("MainWindow", "connecting to %1 (%2, %3 baud)")
        self.window.console.append_note(fill(text, port, shown, baud))
        parameters = read_parameters(self.settings, protocol, port)
        protocol_settings = read_protocol_settings(self.settings, protocol, port)
        window = self.window

        def open_port(thread: WorkerThread) -> None:
            """What needs the protocol's module and the worker: done once the worker is (just
            after the first paint when asked for before it)."""
            from app.window.device.connect_options import ConnectOptions

            try:
                window.console.set_protocol(create_protocol(protocol, variant or None))
            except (LookupError, BadInput):
                window.console.set_protocol(None)  # the worker reports it; shown undecoded
            clamp = window.tools.prefs.clamp_to_limits
            travel = read_travel(self.settings, protocol, port, clamp_default=clamp)
            self.machine.apply_travel(travel)
            dtr, rts = window.tools.saved_lines(protocol, port)
            # A device that cannot be asked goes on from where it was left (by this panel, another
            # one or motionctl); not after a lost link, when where it stands is not known.
            kept = None if self.machine.link_failed else read_counted_position(
                self.settings, protocol, port
            )  # fmt: skip
            self.machine.resumed_from = kept
            options = ConnectOptions(
                variant=variant,
                settings=protocol_settings,
                parameters=parameters,
                dtr=dtr,
                rts=rts,
                position=kept,
                after_loss=self.machine.link_failed and self.machine.was_on(port, protocol),
            )
            thread.open(port, protocol, baud, options)  # a sim:// device speaks the variant

        self.workers.to_worker(open_port)

    def disconnect_device(self) -> None:
        """Ask the worker to close the port (and do not reconnect by itself)."""
        self.last = None
        if self.workers.thread is not None:  # (before the worker is built, nothing is queued)
            self.desk.report_dropped(self.workers.thread.worker.cancel_pending())
        self.workers.to_worker(lambda thread: thread.close())

    def _connect_from_bar(self, port: str, protocol: str, baud: int) -> None:
        if self.bar.bridge_mode():
            self.start_bridge(port, protocol, baud)
        else:
            self.connect_device(port, protocol, baud)

    def _disconnect_from_bar(self) -> None:
        if self.bridge is not None:
            self.stop_bridge()
        else:
            self.disconnect_device()

    # -- the bridge --------------------------------------------------------------------------
    def start_bridge(self, port: str, protocol: str, baud: int) -> str | None:
        """Bridge mode: forward `port` to a new pty for another program, showing every frame
        decoded; motion controls are off meanwhile. Returns the pty's path (None: refused)."""
        if self.bridge is not None:
            return self.bridge.bridge.path
        self.disconnect_device()
        console, bar = self.window.console, self.bar
        variant = bar.variant() if bar.protocol() == protocol else ""
        speaks: Protocol | None
        try:
            speaks = create_protocol(protocol, variant or None)
        except (LookupError, BadInput):
            speaks = None
        console.set_protocol(speaks)
        from app.window.device.bridge_readout import BridgeReadout
        from app.window.device.bridge_session import BridgeSession

        session = BridgeSession(
            port,
            baud,
            self.workers.session_log_path,
            self.workers.log_start,
            self,
            protocol=speaks,  # a sim:// device speaks its variant, DTR as the device needs
        )
        try:
            path = session.start()
        except MotionError as exc:
            session.deleteLater()
            bar.set_state("error", localized(exc))
            text = translate("MainWindow", "bridge refused: %1")
            self._tell(fill(text, localized(exc)), status.FAILURE)
            return None
        self.bridge = session
        session.traffic.connect(self._on_traffic)
        BridgeReadout(self.machine, session)  # the readout follows the traffic, marked observed
        session.ended.connect(self._on_bridge_ended)
        bar.set_state("connected", fill(translate("MainWindow", "bridge: %1"), path))
        self.desk.set_controls_enabled(False)
        console.set_send_enabled(False)
        text = translate("MainWindow", "bridging %1 to %2")
        self.window.status_line.set_state(status.BUSY, fill(text, port, path))
        text = translate("MainWindow", "bridge: another program can open %1; every byte goes to %2")
        self._tell(fill(text, path, port))
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
            self.bar.set_state("error", error)
            self._tell(fill(translate("MainWindow", "bridge ended: %1"), error), status.FAILURE)
        else:
            self.bar.set_state("disconnected")
            self._tell(translate("MainWindow", "bridge closed"))
        self.machine.show_status()

    # -- the worker's reports ----------------------------------------------------------------
    def _on_traffic(self, records: list[Traffic]) -> None:
        self.window.console.append_records(records)  # unchanged, as the tap made them

    def _on_control_note(self, text: str) -> None:
        """A control line changed, or a break was sent: in the console, among the traffic."""
        self.window.console.append_note(text)

    def _on_state(self, state: str, detail: str) -> None:
        window, machine = self.window, self.machine
        self.bar.set_state(state)
        was_connected, machine.connected = machine.connected, state == "connected"
        window.tools.connection_state(machine.connected)
        if state == "error":
            machine.failed = machine.link_failed = True
            text = translate("MainWindow", "connection error: %1")
            self._tell(fill(text, detail), status.FAILURE)
        elif state == "disconnected":
            window.console.append_note(translate("MainWindow", "disconnected"))
            info = machine.info  # the status line no longer says "connected to ..."
            gone = (
                fill(
                    translate("MainWindow", "disconnected from %1 on %2"),
                    localized(info.identity),
                    info.port,
                )
                if info is not None and was_connected
                else translate("MainWindow", "disconnected")
            )
            self._tell(gone, note=False)
        elif state == "connected" and detail.startswith("device: "):
            machine.failed = True
            text = translate("MainWindow", "device: %1")
            self._tell(fill(text, detail.removeprefix("device: ")), status.FAILURE, note=False)
        if not machine.connected:
            machine.link_lost()
            self.desk.disconnected()
            window.parameters.disconnected()
            window.devices.disconnected()
        elif not was_connected:
            machine.failed = False
        machine.show_status(state, detail)

    def _on_device_ready(self, info: DeviceInfo) -> None:
        if self.window.views.building():  # the docks, console and menus first (a few 10 ms)
            self._waiting = info
            self.machine.held_back = True
            self.machine.show_status()
            return
        self._show_device(info)

    def _show_waiting(self) -> None:
        info, self._waiting = self._waiting, None
        self.machine.held_back = False
        if info is not None and self.machine.connected:  # (not if the link went meanwhile)
            self._show_device(info)
        else:
            self.machine.show_status()

    def _show_device(self, info: DeviceInfo) -> None:
        window = self.window
        text = translate("MainWindow", "connected to %1 on %2")
        connected = fill(text, localized(info.identity), info.port)
        window.console.append_note(connected)
        self._tell(connected, note=False)
        self.machine.device_ready(info)
        fit_controls(window, info.capabilities, info.protocol)
        window.parameters.device_ready(info)
        window.devices.device_ready(info)
        self.machine.show_unknown_to_program()
        window.tools.device_ready(info.protocol, info.variant, info.port)
        known = self.machine.known_position()
        if known is not None:
            window.tools.position(known)
        self.desk.set_controls_enabled(True)
        window.travel_action.setEnabled(True)
        self.machine.show_status()
        self.device_shown.emit()
        QTimer.singleShot(100, self, self.settled.emit)  # cancelled if the window goes first

    def _on_capabilities_changed(self, caps: Capabilities) -> None:
        info = self.machine.info
        if info is not None:
            self.machine.info = info = dataclasses.replace(info, capabilities=caps)
        fit_controls(self.window, caps, info.protocol if info is not None else None)
        self.window.devices.adapt(caps)

    # -- the connection bar ------------------------------------------------------------------
    def _on_protocol_changed(self, name: str) -> None:
        try:
            cls = get_protocol_class(name)
        except LookupError as exc:
            self._tell(localized(exc), status.WARNING, note=False)
            return
        self.window.tools.protocol_chosen(name)
        self._show_variants(name, read_str(self.settings, f"variant/{name}", ""))
        self.bar.set_baud(cls.default_baud(self.bar.variant() or None))

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
        self.bar.set_variants(variants, current)

    def _on_variant_changed(self, variant: str) -> None:
        try:
            cls = get_protocol_class(self.bar.protocol())
            self.bar.set_baud(cls.default_baud(variant))
        except LookupError as exc:
            self._tell(localized(exc), status.WARNING, note=False)

    def _on_port_added(self, port: str) -> None:
        """A port appeared; if it is the one that was lost, connect again (position re-read)."""
        self._tell(fill(translate("MainWindow", "port %1 appeared"), port))
        last = self.last
        if self.bar.state() == "error" and last is not None and last[0] == port:
            self._tell(fill(translate("MainWindow", "reconnecting to %1"), port))
            self.connect_device(*last)

    # -- travel limits -----------------------------------------------------------------------
    def edit_travel_limits(self) -> None:
        """Let the operator set this device's travel box (saved per device)."""
        if self.last is None:
            return
        port, protocol, _ = self.last
        from widgets.travel_limits_dialog import TravelLimitsDialog

        current = self.machine.travel
        dialog = TravelLimitsDialog(
            fill(translate("MainWindow", "%1 on %2"), protocol, port),
            current.box if current is not None else None,
            current.clamp if current is not None else False,
            self.window,  # type: ignore[arg-type]
        )
        if dialog.exec() != TravelLimitsDialog.DialogCode.Accepted:
            return
        self.set_travel_limits(*dialog.result_limits())

    def set_travel_limits(self, box: Box | None, clamp: bool) -> None:
        """Use and keep this travel box for the device connected (None: none), as the Travel
        limits dialog's OK and the Set up layout's Travel limits dock do."""
        if self.last is None:
            return
        port, protocol, _ = self.last
        from drivers.device.travel import TravelLimits

        limits = TravelLimits(box, clamp) if box is not None else None
        write_travel(self.settings, protocol, port, limits)
        self.machine.apply_travel(limits)
        self.window.devices.travel_changed()  # the dock shows what is in use
        described = limits.describe() if limits else translate("MainWindow", "none")
        self._tell(fill(translate("MainWindow", "travel limits: %1"), described))
