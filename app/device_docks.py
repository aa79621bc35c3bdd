"""Docks of one device kind: Firmata stepper setup, pi-frame ticks per mm, arcs and dwell."""

from __future__ import annotations

import dataclasses
import logging
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Qt
from PySide6.QtWidgets import QDockWidget, QWidget

from app import jobs
from app.settings import write_protocol_settings
from app.worker import DeviceInfo
from drivers.capabilities import Capabilities
from drivers.commands import Arc
from widgets.arc_entry import ArcEntry
from widgets.dwell_entry import DwellEntry
from widgets.firmata_panel import FirmataPanel
from widgets.panel_scroll_area import PanelScrollArea
from widgets.piframe_panel import PiFramePanel

if TYPE_CHECKING:
    from app.main_window import MainWindow

log = logging.getLogger(__name__)


class DeviceDocks(QObject):
    """Shows the panels the connected device calls for, and turns their requests into jobs."""

    def __init__(self, window: MainWindow) -> None:
        super().__init__(window)
        self.window = window
        self.info: DeviceInfo | None = None
        self.firmata = FirmataPanel(window)
        self.piframe = PiFramePanel(window)
        self.arc = ArcEntry(window)
        self.dwell = DwellEntry(window)
        left, bottom = Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.BottomDockWidgetArea
        self.firmata_dock = self._dock("Stepper setup", self.firmata, bottom)
        self.piframe_dock = self._dock("Frame setup", self.piframe, bottom)
        self.arc_dock = self._dock("Arc", self.arc, left)
        self.dwell_dock = self._dock("Dwell", self.dwell, left)
        self.docks = (self.firmata_dock, self.piframe_dock, self.arc_dock, self.dwell_dock)
        self._wire()

    def _dock(self, title: str, widget: QWidget, area: Qt.DockWidgetArea) -> QDockWidget:
        dock = QDockWidget(title, self.window)
        dock.setObjectName(f"{widget.objectName()}Dock")
        dock.setWidget(PanelScrollArea(widget, dock))
        self.window.addDockWidget(area, dock)
        dock.hide()
        return dock

    def _wire(self) -> None:
        self.firmata.configure_requested.connect(self._configure_stepper)
        self.firmata.version_requested.connect(
            lambda: self.window.submit_job(jobs.StepperVersionJob())
        )
        self.firmata.steps_per_mm_changed.connect(lambda value: self._set({"steps_per_mm": value}))
        self.piframe.ticks_per_mm_changed.connect(lambda value: self._set({"ticks_per_mm": value}))
        self.arc.preview_changed.connect(self._preview)
        self.arc.arc_requested.connect(self._run_arc)
        self.dwell.dwell_requested.connect(lambda ms: self.window.submit_job(jobs.DwellJob(ms)))
        self.window.worker.job_finished.connect(self._on_job_finished)

    # -- connection --------------------------------------------------------------------------
    def device_ready(self, info: DeviceInfo) -> None:
        """Show the panels this device calls for, filled with what the panel kept for it."""
        self.info = info
        names = {s.name for s in info.settings}
        values = info.values
        self.firmata_dock.setVisible("steps_per_rev" in names)
        self.piframe_dock.setVisible("ticks_per_mm" in names)
        if "steps_per_rev" in names:
            pins = [int(values[f"pin{i}"]) for i in range(1, 5) if values.get(f"pin{i}", -1) >= 0]
            self.firmata.set_settings(
                int(values["steps_per_rev"]), pins if len(pins) in (2, 4) else [8, 9],
                values["steps_per_mm"],
            )  # fmt: skip
        if "ticks_per_mm" in names:
            self.piframe.set_ticks_per_mm(values["ticks_per_mm"])
        self.adapt(info.capabilities)
        for dock in (self.arc_dock, self.dwell_dock):  # one place for moves: Go to, Arc, Dwell
            if dock.isVisible():
                self.window.tabifyDockWidget(self.window.coordinates_dock, dock)
        self.window.coordinates_dock.raise_()

    def adapt(self, caps: Capabilities) -> None:
        """Follow the capabilities (after a connection, or new settings)."""
        if self.info is not None:
            self.info = dataclasses.replace(self.info, capabilities=caps)
        self.arc_dock.setVisible(caps.arcs)
        self.dwell_dock.setVisible(caps.dwell)
        self.arc.set_resolution(caps.resolution)
        self.arc.set_box(self.window.travel.box if self.window.travel is not None else caps.travel)
        self.piframe.set_dtr(caps.dtr)
        if caps.travel is not None:
            (x0, x1), _, _ = caps.travel
            self.piframe.set_range_text(f"{x0:g} to {x1:g} mm on every axis (16-bit ticks)")
        self._preview(self.arc.arc_points() if self.arc.preview_check.isChecked() else [])

    def disconnected(self) -> None:
        """No device: the arc preview goes away."""
        self.info = None
        self._preview([])

    # -- requests ----------------------------------------------------------------------------
    def _set(self, values: dict[str, float]) -> None:
        """New settings: used from the next command on, and remembered for this device."""
        if self.info is None:
            return
        write_protocol_settings(self.window.settings, self.info.protocol, self.info.port, values)
        self.window.submit_job(jobs.SettingsJob(values))

    def _configure_stepper(self, steps_per_rev: int, pins: list[int], steps_per_mm: float) -> None:
        if self.info is None:
            return
        self._set({"steps_per_mm": steps_per_mm})
        self.window.submit_job(jobs.StepperConfigJob(steps_per_rev, tuple(pins)))

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
        self.window.submit_job(jobs.ArcJob(arc))

    def _preview(self, points: list[tuple[float, float, float]]) -> None:
        if self.info is None or not self.info.capabilities.arcs:
            points = []  # no arcs on this device: nothing to preview
        self.window.view2d.set_preview(points or None)
        self.window.view3d.set_preview(points or None)  # type: ignore[attr-defined]

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        if isinstance(job, (jobs.StepperConfigJob, jobs.StepperVersionJob)):
            self.firmata.set_library_version(str(result))
        if isinstance(job, jobs.StepperConfigJob) and self.info is not None:
            pins = {
                f"pin{i}": float(job.pins[i - 1]) if i <= len(job.pins) else -1.0
                for i in range(1, 5)
            }
            write_protocol_settings(
                self.window.settings,
                self.info.protocol,
                self.info.port,
                {"steps_per_rev": float(job.steps_per_rev), **pins},
            )
