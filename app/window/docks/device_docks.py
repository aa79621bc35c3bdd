"""Docks of one device kind: Firmata stepper setup, pi-frame ticks per mm, arcs and dwell; the
Program dock (app/window/docks/program_dock.py drives it); and the connected device's travel
limits."""

from __future__ import annotations

import dataclasses
import logging
from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, Qt
from PySide6.QtWidgets import QDockWidget, QMainWindow, QWidget

from app.common.settings import write_protocol_settings
from app.window.device import jobs
from app.window.device.connect_options import DeviceInfo
from app.window.docks.program_dock import ProgramDock
from app.window.layout.dock_layout import DEVICE_DOCKS
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.commands import Arc
from widgets._i18n import fill
from widgets.arc_entry import ArcEntry
from widgets.dwell_entry import DwellEntry
from widgets.firmata_panel import FirmataPanel
from widgets.panel_scroll_area import PanelScrollArea
from widgets.piframe_panel import PiFramePanel
from widgets.program_panel import ProgramPanel
from widgets.travel_limits_form import TravelLimitsPanel

if TYPE_CHECKING:
    from app.window.services import WindowServices

log = logging.getLogger(__name__)


class DeviceDocks(QObject):
    """Shows the panels the connected device calls for, and turns their requests into jobs."""

    def __init__(
        self,
        window: QMainWindow,
        services: WindowServices,
        place: Callable[[dict[str, bool]], None],
    ) -> None:
        """`place(wanted)`: shows the docks the device calls for (by object name, True) where
        the window's layout has them, and hides the others (app/window/layout/layouts.py)."""
        super().__init__(window)
        self.window = window  # the docks' parent
        self.services = services
        self.place = place
        self.info: DeviceInfo | None = None
        self.firmata = FirmataPanel(window)
        self.piframe = PiFramePanel(window)
        self.arc = ArcEntry(window)
        self.dwell = DwellEntry(window)
        self.program = ProgramPanel(window)
        self.travel = TravelLimitsPanel(window)
        self.firmata_dock = self._dock(self.firmata)
        self.piframe_dock = self._dock(self.piframe)
        self.arc_dock = self._dock(self.arc)
        self.dwell_dock = self._dock(self.dwell)
        self.program_dock = self._dock(self.program)
        self.travel_dock = self._dock(self.travel)
        made = (self.firmata_dock, self.piframe_dock, self.arc_dock, self.dwell_dock)
        by_name = {dock.objectName(): dock for dock in (*made, self.program_dock, self.travel_dock)}
        self.docks = tuple(by_name[name] for name in DEVICE_DOCKS)  # in tab order
        self.programs = ProgramDock(self.program, services, self)
        self._wire()

    def _dock(self, widget: QWidget) -> QDockWidget:
        """The panel's dock: the window's empty one of that name if it made one before its
        first paint (placed and restored already), else a new, hidden one."""
        name = f"{widget.objectName()}Dock"
        title, area = DEVICE_DOCKS[name]
        dock = self.window.findChild(QDockWidget, name, Qt.FindChildOption.FindDirectChildrenOnly)
        if dock is not None and dock.widget() is None:
            dock.setWidget(PanelScrollArea(widget, dock))
            return dock
        # The titles are marked in app/window/layout/dock_layout.py, context "DockLayout".
        dock = QDockWidget(QCoreApplication.translate("DockLayout", title), self.window)
        dock.setObjectName(name)
        dock.setWidget(PanelScrollArea(widget, dock))
        self.window.addDockWidget(area, dock)
        dock.hide()
        return dock

    def set_motion_allowed(self, allowed: bool, reason: str = "") -> None:
        """Arcs, dwells and a program's Run on or off (off while a program, a macro or a
        parameter write runs: `reason` says which); a program's Pause and Stop stay on."""
        for widget in (self.arc, self.dwell):
            widget.setEnabled(allowed)
            widget.setToolTip("" if allowed else fill(self.tr("Not now: %1"), reason))
        self.program.set_allowed(allowed, reason)

    def set_speed(self, speed: float) -> None:
        """The device's speed (mm/s), for the panels that show it."""
        self.firmata.set_speed_mm_s(speed)
        self.programs.set_speed(speed)

    def _wire(self) -> None:
        self.firmata.configure_requested.connect(self._configure_stepper)
        self.firmata.version_requested.connect(
            lambda: self.services.submit_job(jobs.StepperVersionJob())
        )
        self.firmata.steps_per_mm_changed.connect(lambda value: self._set({"steps_per_mm": value}))
        self.piframe.ticks_per_mm_changed.connect(lambda value: self._set({"ticks_per_mm": value}))
        self.arc.preview_changed.connect(self._preview)
        self.arc.arc_requested.connect(self._run_arc)
        self.dwell.dwell_requested.connect(lambda ms: self.services.submit_job(jobs.DwellJob(ms)))
        self.dwell.refused.connect(self.services.say)  # a typed dwell that cannot be sent
        self.services.worker.job_finished.connect(self._on_job_finished)
        self.travel.apply_requested.connect(self.services.set_travel_limits)

    # -- connection --------------------------------------------------------------------------
    def device_ready(self, info: DeviceInfo) -> None:
        """Show the panels this device calls for, filled with what the panel kept for it."""
        self.info = info
        names = {s.name for s in info.settings}
        values = info.values
        if "steps_per_rev" in names:
            pins = [int(values[f"pin{i}"]) for i in range(1, 5) if values.get(f"pin{i}", -1) >= 0]
            self.firmata.set_settings(
                int(values["steps_per_rev"]), pins if len(pins) in (2, 4) else [8, 9],
                values["steps_per_mm"],
            )  # fmt: skip
        if "ticks_per_mm" in names:
            self.piframe.set_ticks_per_mm(values["ticks_per_mm"])
        self.programs.set_speed(info.capabilities.default_speed)  # until the device tells
        self.adapt(info.capabilities)
        self.programs.set_device(info.capabilities)  # checks the program loaded again
        travel = self.services.travel
        self.travel.set_device(
            fill(self.tr("%1 on %2"), info.protocol, info.port),
            travel.box if travel is not None else None,
            travel.clamp if travel is not None else False,
        )
        self.place(
            {
                "parameterEditor": bool(info.parameters),
                self.firmata_dock.objectName(): "steps_per_rev" in names,
                self.piframe_dock.objectName(): "ticks_per_mm" in names,
            }
        )

    def adapt(self, caps: Capabilities) -> None:
        """Follow the capabilities (after a connection, or new settings)."""
        if self.info is not None:
            self.info = dataclasses.replace(self.info, capabilities=caps)
        self.place(
            {
                self.arc_dock.objectName(): caps.arcs,
                self.dwell_dock.objectName(): caps.dwell,
                self.program_dock.objectName(): caps.absolute_moves or caps.relative_moves,
            }
        )
        self.arc.set_resolution(caps.resolution)
        self.arc.set_box(
            self.services.travel.box if self.services.travel is not None else caps.travel
        )
        self.piframe.set_dtr(caps.dtr)
        if caps.travel is not None:
            (x0, x1), _, _ = caps.travel
            reach = self.tr("%1 to %2 mm on every axis (16-bit ticks)")
            self.piframe.set_range_text(fill(reach, f"{x0:g}", f"{x1:g}"))
        self._preview(self.arc.arc_points() if self.arc.preview_check.isChecked() else [])

    def disconnected(self) -> None:
        """No device: the arc preview goes away."""
        self.info = None
        self.programs.set_device(None)  # Run off, saying why
        self._preview([])
        self.travel.set_device("", None, False)

    def travel_changed(self) -> None:
        """New travel limits are in use (from the dock or the menu's dialog): show them."""
        travel = self.services.travel
        self.travel.show_limits(
            travel.box if travel is not None else None,
            travel.clamp if travel is not None else False,
        )
        if self.info is not None:
            self.adapt(self.info.capabilities)  # the arc entry's box
        self.programs.travel_changed()  # the program loaded is checked again

    # -- requests ----------------------------------------------------------------------------
    def _set(self, values: dict[str, float]) -> None:
        """New settings: used from the next command on, and remembered for this device."""
        if self.info is None:
            return
        write_protocol_settings(self.services.settings, self.info.protocol, self.info.port, values)
        self.services.submit_job(jobs.SettingsJob(values))

    def _configure_stepper(self, steps_per_rev: int, pins: list[int], steps_per_mm: float) -> None:
        if self.info is None:
            return
        self._set({"steps_per_mm": steps_per_mm})
        self.services.submit_job(jobs.StepperConfigJob(steps_per_rev, tuple(pins)))

    def _run_arc(self, values: dict[str, object]) -> None:
        arc = Arc(
            float(values["cx"]),  # type: ignore[arg-type]
            float(values["cy"]),  # type: ignore[arg-type]
            float(values["radius"]),  # type: ignore[arg-type]
            float(values["start"]),  # type: ignore[arg-type]
            float(values["end"]),  # type: ignore[arg-type]
            bool(values["ccw"]),
            float(values["z"]),  # type: ignore[arg-type]
        )
        self.services.submit_job(jobs.ArcJob(arc))

    def _preview(self, points: list[tuple[float, float, float]]) -> None:
        if self.info is None or not self.info.capabilities.arcs:
            points = []  # no arcs on this device: nothing to preview
        self.services.show_preview(points or None)

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        if isinstance(job, (jobs.StepperConfigJob, jobs.StepperVersionJob)):
            self.firmata.set_library_version(str(result))
        if isinstance(job, jobs.StepperConfigJob) and self.info is not None:
            pins = {
                f"pin{i}": float(job.pins[i - 1]) if i <= len(job.pins) else -1.0
                for i in range(1, 5)
            }
            write_protocol_settings(
                self.services.settings,
                self.info.protocol,
                self.info.port,
                {"steps_per_rev": float(job.steps_per_rev), **pins},
            )
