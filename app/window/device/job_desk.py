"""One device's job desk: every job the window sends goes through it (refused out loud while a
program, a macro or a parameter write runs), held jogs step here, Stop drops what is queued."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, QTimer

from app.common.messages import localized
from widgets import status_line as status
from widgets._i18n import fill
from widgets.lazy_view import built

if TYPE_CHECKING:
    from app.window.device import jobs
    from app.window.device.machine_state import MachineState
    from app.window.device.worker import SerialWorker
    from app.window.device.worker_link import WorkerLink
    from app.window.services import WindowParts

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"
JOG_TAP_S = 0.3
"""A jog press released sooner is a tap: its step is not stopped (as QAbstractButton's
default auto-repeat delay)."""


def _is_macro(job: object) -> bool:
    """Whether `job` is a macro (the worker is built: app.window.device.jobs is imported)."""
    from app.window.device import jobs

    return isinstance(job, jobs.MacroJob)


def _runs_alone(job: object) -> bool:
    """Whether `job` turns motion off until it ends: a program, a macro, a parameter write."""
    from app.window.device import jobs

    return isinstance(job, (jobs.StreamJob, jobs.MacroJob, jobs.SetParameterJob))


def _is_program(job: object) -> bool:
    """Whether `job` runs a program (the worker is built: app.window.device.jobs is imported)."""
    from app.window.device import jobs

    return isinstance(job, jobs.StreamJob)


def _may_run_beside(job: object, running: list[jobs.Job]) -> bool:
    """Whether `job` may be queued while the jobs that run alone in `running` are under way:
    reading the device, or more parameter writes beside parameter writes; nothing that moves."""
    from app.window.device import jobs

    if isinstance(job, (jobs.RefreshJob, jobs.StepperVersionJob)):
        return True
    return isinstance(job, jobs.SetParameterJob) and all(
        isinstance(other, jobs.SetParameterJob) for other in running
    )


class JobDesk(QObject):
    """Turns the operator's requests into jobs for one device's worker, and follows them."""

    def __init__(self, window: WindowParts, link: WorkerLink, machine: MachineState) -> None:
        super().__init__(window)  # type: ignore[arg-type]
        self.window = window
        self.workers = link
        self.machine = machine
        self.running_alone: list[jobs.Job] = []  # programs, macros, parameter writes queued
        self.controls_on = False  # connected to a device (not a bridge)
        self.jog_job: jobs.MoveByJob | None = None
        self.jog_repeat = False  # the step under way was sent because the jog was held
        self.jog_pressed_at = 0.0  # time.monotonic() of the last jog press
        self.jog_ended: jobs.Job | None = None  # a step whose end awaits the next decision
        self.saved_step: float | None = None  # the jog step as last saved
        self.off_text = ""  # "motion controls are off until ... ends", while it is shown
        link.wirers.append(self._wire_worker)
        jog, coordinates = window.jog_panel, window.coordinates
        jog.jog_requested.connect(self._on_jog)
        jog.jog_released.connect(self._on_jog_released)
        coordinates.go_requested.connect(self._on_go)
        coordinates.home_requested.connect(self._go_home)
        coordinates.set_home_requested.connect(self._set_home)
        coordinates.stop_requested.connect(self.stop)
        window.speed.speed_requested.connect(self._set_speed)

    def _wire_worker(self, w: SerialWorker) -> None:
        w.job_failed.connect(self._on_job_failed)
        w.job_stopped.connect(self._on_job_stopped)
        w.job_finished.connect(self._on_job_finished)

    def _tell(self, text: str, kind: str = status.INFO, note: bool = True) -> None:
        self.window.tell(text, kind, note)

    # -- submitting --------------------------------------------------------------------------
    def _needs_position(self, job: jobs.Job) -> bool:
        """Whether `job` moves from where the stage is on a device that moves only to absolute
        targets, while that place is unknown (the rule motionctl's jog follows)."""
        from app.window.device import jobs
        from drivers.device.position_count import needs_count

        info = self.machine.info
        if info is None or not self.machine.position_lost:
            return False
        relative = isinstance(job, (jobs.MoveByJob, jobs.MacroJob))  # (an arc goes to its start)
        return relative and needs_count("jog", info.capabilities)

    def submit(self, job: jobs.Job) -> bool:
        """Queue `job` for the worker; refused out loud (False) when not connected, or when a
        program, a macro or a parameter write is under way and `job` may not run beside it:
        the one check every control, key, macro and the console go through."""
        if not self.machine.connected:
            self._tell(
                fill(translate("MainWindow", "not connected: %1 not sent"), job.describe()),
                status.WARNING,
                note=False,
            )
            return False
        if _is_program(job) and self.machine.position_lost:
            # A program's coordinates are absolute: from an unknown place they go elsewhere.
            self._tell(
                fill(
                    translate(
                        "MainWindow",
                        "%1 refused: the position is unknown, so the program's coordinates "
                        "would not be where it goes; Home or Set Home first",
                    ),
                    job.describe(),
                ),
                status.WARNING,
            )
            return False
        if self._needs_position(job):
            # Absolute targets only (pi-frame): a jog from an unknown place goes elsewhere.
            self._tell(
                fill(
                    translate(
                        "MainWindow",
                        "%1 refused: the position is unknown and this device moves only to "
                        "absolute targets, so it would go elsewhere; Set Home, Home or Go to "
                        "first",
                    ),
                    job.describe(),
                ),
                status.WARNING,
            )
            return False
        running = list(self.running_alone)
        if running and not _may_run_beside(job, running):
            self._tell(
                fill(
                    translate(
                        "MainWindow", "%1 refused: %2 is under way; wait for its end or press Stop"
                    ),
                    job.describe(),
                    running[0].describe(),
                ),
                status.WARNING,
            )
            return False
        self.machine.busy_job = job
        if _runs_alone(job):
            self.running_alone.append(job)
            if not running:
                self.show_motion_allowed()
                self.off_text = fill(
                    translate(
                        "MainWindow", "motion controls are off until %1 ends (Stop ends it now)"
                    ),
                    job.describe(),
                )
                self._tell(self.off_text, note=False)
        self.workers.get().worker.submit(job)
        self.machine.show_status()
        return True

    def jobs_dropped(self, dropped: list[jobs.Job]) -> None:
        """Jobs taken off the worker's queue unrun (by a dock's Cancel): motion may be on again."""
        kept = [job for job in self.running_alone if all(job is not d for d in dropped)]
        if len(kept) != len(self.running_alone):
            self.running_alone = kept
            self.show_motion_allowed()

    def _motion_blocker(self) -> str:
        """Why motion is off while connected ("" when it is on)."""
        if not self.running_alone:
            return ""
        return fill(translate("MainWindow", "%1 is under way"), self.running_alone[0].describe())

    def show_motion_allowed(self) -> None:
        """Motion controls on while connected and nothing runs alone; Stop always on."""
        window = self.window
        reason = self._motion_blocker()
        allowed = self.controls_on and not reason
        if not allowed:
            window.jog_panel.release()
        for widget in (window.jog_panel, window.speed):
            widget.setEnabled(allowed)
        window.coordinates.setEnabled(self.controls_on)  # its Stop button too
        for button in (
            window.coordinates.go_button,
            window.coordinates.home_button,
            window.coordinates.set_home_button,
        ):
            button.setEnabled(not reason)
        window.keyboard_jog.set_motion_blocker(reason if self.controls_on else "")
        if self.controls_on:  # (when off, the tools turned the macros off themselves)
            window.tools.macros.set_runnable(allowed, reason)
        if built(window.devices):
            window.devices.set_motion_allowed(not reason, reason)
        if not reason and self.off_text:  # what ran alone ended: its notice goes with it
            if window.status_line.message() == self.off_text:
                window.status_line.show_message("")
            self.off_text = ""

    def set_controls_enabled(self, enabled: bool) -> None:
        """Controls on (connected to a device) or off (not connected, or bridging)."""
        self.controls_on = enabled
        self.window.console.set_send_enabled(enabled)
        self.window.tools.controls_enabled(enabled)
        self.show_motion_allowed()  # the jog hint follows: "keys off: not connected", or not

    def disconnected(self) -> None:
        """The link went: controls off, no jog under way, nothing runs alone any more."""
        self.set_controls_enabled(False)
        self.window.jog_panel.release()
        self.jog_job = None
        if self.running_alone:  # ended with the link (or dropped unreported)
            self.running_alone.clear()
            self.show_motion_allowed()

    # -- jogging -----------------------------------------------------------------------------
    def on_jog_refused(self, reason: str) -> None:
        """A jog key was pressed where it cannot jog: say why."""
        self._tell(fill(translate("MainWindow", "jog refused: %1"), reason), status.WARNING, False)

    def _on_jog(self, axis: str, distance: float) -> None:
        """A jog key or button was pressed: one step now, unless a step is under way (its end
        sends the next one only if the key or button is still held: a press never queues)."""
        step = self.window.jog_panel.step()
        if step != self.saved_step:  # written when it changes, not at every jog (a disk write)
            self.saved_step = step
            self.window.settings.setValue("jog_step", step)
        self.jog_pressed_at = time.monotonic()
        if self.jog_job is None:
            self.jog_repeat = False
            self._jog_step(axis, distance)

    def _jog_step(self, axis: str, distance: float) -> None:
        from app.window.device import jobs

        deltas = {"x": 0.0, "y": 0.0, "z": 0.0}
        deltas[axis] = distance
        job = jobs.MoveByJob(deltas["x"], deltas["y"], deltas["z"])
        self.jog_job = job if self.submit(job) else None
        if self.jog_job is None:
            self.window.jog_panel.release()  # refused: nothing to repeat

    def _jog_step_ended(self, job: jobs.Job) -> None:
        """A jog step ended: decide on the next one after the input events already received
        (a release waiting in the queue counts), one turn of the event loop later; a press
        meanwhile steps at once."""
        self.jog_job, self.jog_ended = None, job
        QTimer.singleShot(0, self, lambda: self._next_jog_step(job))

    def _next_jog_step(self, job: jobs.Job) -> None:
        """After the jog step `job`: the next one only if the jog is still held now."""
        if self.jog_job is not None or self.jog_ended is not job:
            return  # a press stepped meanwhile, or a later step ended
        self.jog_ended = None
        held = self.window.jog_panel.held()
        if held is not None and self.machine.connected:
            self.jog_repeat = True
            self._jog_step(*held)

    def _on_jog_released(self) -> None:
        """A jog key or button was let go: where the device has a stop, the step under way
        halts now if the jog was held (a repeated step, or a press longer than a tap); a tap
        moves its whole step."""
        info, serial = self.machine.info, self.workers.thread
        if self.jog_job is None or serial is None:
            return
        if not self.jog_repeat and time.monotonic() - self.jog_pressed_at < JOG_TAP_S:
            return
        if info is not None and info.capabilities.stop:
            serial.worker.stop_now()

    # -- the other controls ------------------------------------------------------------------
    def _on_go(self, mode: str, values: tuple[float, float, float]) -> None:
        from app.window.device import jobs

        if mode == "relative":
            self.submit(jobs.MoveByJob(*values, jog=False))
        else:
            self.submit(jobs.MoveToJob(*values))

    def _set_home(self) -> None:
        from app.window.device import jobs

        if self.submit(jobs.SetHomeJob()):
            self.machine.home_from = self.machine.last_position

    def _go_home(self) -> None:
        from app.window.device import jobs

        self.submit(jobs.HomeJob())

    def _set_speed(self, speed: float) -> None:
        from app.window.device import jobs

        self.submit(jobs.SetSpeedJob(speed))

    def send_raw(self, data: bytes) -> None:
        """The console's send line: bytes for the device as they are, through the motion guard
        (a move checked and followed like a typed one); bytes the protocol cannot read go,
        while a travel box is set, only once the operator confirms them."""
        from app.window.device import jobs
        from drivers.device.guard import unreadable

        travel = self.machine.travel
        reason = unreadable(self.window.console.index.protocol, data) if travel else None
        if reason is not None:
            from PySide6.QtWidgets import QMessageBox

            answer = QMessageBox.question(
                self.window,  # type: ignore[arg-type]
                translate("MainWindow", "Send unchecked bytes?"),
                fill(
                    translate(
                        "MainWindow",
                        "These bytes cannot be read as a command (%1), so they cannot be checked "
                        "against the travel limits (%2): they might move the stage outside "
                        "them.\n\nSend them anyway?",
                    ),
                    localized(reason),
                    travel.describe() if travel else "",
                ),
                QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
                QMessageBox.StandardButton.No,
            )
            if answer != QMessageBox.StandardButton.Yes:
                self._tell(
                    translate(
                        "MainWindow",
                        "not sent: the bytes could not be checked against the travel limits",
                    ),
                    status.WARNING,
                )
                return
        self.submit(jobs.RawJob(data, force=reason is not None))

    # -- stopping ----------------------------------------------------------------------------
    def stop(self) -> None:
        """Cancel what is queued and say what was not sent; where the device can stop, stop
        the move (or program) under way too."""
        self.window.jog_panel.release()
        serial = self.workers.thread  # (before the worker is built, nothing is queued or moving)
        dropped = serial.worker.cancel_pending() if serial is not None else []
        self.report_dropped(dropped)
        machine = self.machine
        can_stop = machine.info is not None and machine.info.capabilities.stop
        macro = serial is not None and _is_macro(machine.busy_job)
        if serial is not None and macro:
            serial.worker.stop_now()  # every device: the macro ends between steps
            text = translate("MainWindow", "stopping the macro under way")
            self._tell(text, status.WARNING, note=False)
        elif serial is not None and can_stop and (machine.busy_job is not None or machine.moving):
            serial.worker.stop_now()
            text = translate("MainWindow", "stopping the move under way")
            self._tell(text, status.WARNING, note=False)
        elif not dropped:
            text = translate("MainWindow", "nothing queued; the move under way finishes")
            self._tell(text, note=False)

    def report_dropped(self, dropped: list[jobs.Job]) -> None:
        """Jobs the worker dropped unrun: said, and forgotten by the docks."""
        if not dropped:
            return
        self.window.parameters.forget(dropped)
        names = ", ".join(job.describe() for job in dropped)
        self._tell(
            fill(
                translate("MainWindow", "stopped: %1 command(s) not sent: %2"), len(dropped), names
            ),
            status.WARNING,
        )
        if any(job is self.jog_job for job in dropped):
            self.jog_job = None
        if any(job is self.machine.busy_job for job in dropped):
            self.machine.busy_job = None  # never started: nothing is busy with it
        self.jobs_dropped(dropped)
        self.machine.show_status()

    # -- the worker's results ----------------------------------------------------------------
    def _job_ended(self, job: jobs.Job) -> None:
        self.machine.job_ended(job)
        if any(job is other for other in self.running_alone):
            self.running_alone = [other for other in self.running_alone if other is not job]
            if not self.running_alone:
                self.show_motion_allowed()
        if job is self.jog_job:
            self._jog_step_ended(job)

    def _on_job_failed(self, job: jobs.Job, message: str) -> None:
        self.machine.job_failed()
        if job is self.jog_job:
            self.window.jog_panel.release()  # e.g. refused at the travel limits: stop stepping
        described = job.describe()
        if described not in message:  # else the message names the job itself: said once
            message = fill(translate("MainWindow", "%1 failed: %2"), described, message)
        self._tell(message, status.FAILURE)
        self._job_ended(job)
        self.machine.show_status()

    def _on_job_stopped(self, job: jobs.Job, message: str) -> None:
        """A stop the operator asked for ended `job`: said as a stop, not as an error."""
        self.machine.job_stopped()
        if job is self.jog_job:
            self.window.jog_panel.release()
        if not _is_macro(job):  # a macro's stop names the macro and the step
            message = fill(translate("MainWindow", "%1: %2"), job.describe(), message)
        self._tell(message)
        self._job_ended(job)
        self.machine.show_status()

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        self.machine.job_finished(job, result)
        self._job_ended(job)
        self.machine.show_status()
