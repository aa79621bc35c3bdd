"""One device's machine state as the window shows it: connected or not, what it is doing, where it
is (reported, estimated, counted or unknown) and the travel box it must stay in."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, Qt

from app.common.messages import localized
from app.common.settings import write_counted_position
from widgets import status_line as status
from widgets._i18n import fill
from widgets.lazy_view import built

if TYPE_CHECKING:
    from app.window.device import jobs
    from app.window.device.connect_options import DeviceInfo
    from app.window.device.move_estimate import MoveEstimate
    from app.window.device.program_pause import ProgramPause
    from app.window.device.worker import SerialWorker
    from app.window.device.worker_link import WorkerLink
    from app.window.services import Point, WindowParts
    from drivers.device.motion import MoveStart
    from drivers.device.position_truth import Whereabouts
    from drivers.device.travel import TravelLimits
    from drivers.protocols.events import PositionReport

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"


def _known_again(job: jobs.Job | None) -> str:
    """What replaces "position unknown" once `job` reached a known place."""
    from app.window.device import jobs

    if isinstance(job, jobs.SetHomeJob):
        return translate("MainWindow", "home set: the position is counted from here")
    if isinstance(job, jobs.HomeJob):
        return translate("MainWindow", "home confirmed: the position is counted from here")
    return translate("MainWindow", "an absolute point reached: the position is counted from here")


class MachineState(QObject):
    """The state of the device connected, in one place: the status line, the position readout,
    the trail and the target mark follow it."""

    def __init__(self, window: WindowParts, link: WorkerLink) -> None:
        super().__init__(window)  # type: ignore[arg-type]
        self.window = window
        self.t0 = time.monotonic()
        self.connected = False
        self.info: DeviceInfo | None = None
        self.travel: TravelLimits | None = None
        self.busy_job: jobs.Job | None = None
        self.moving = False
        self.failed = False
        self.link_failed = False  # the connection failed since the device was last ready
        # What is known comes from the device session (drivers/device/position_truth.py): its
        # reports
        # say whether they are known, its Whereabouts why not (uncounted, lost) and, at a lost
        # link, where a move under way had got to.
        self._position_lost = False  # a device with no position feedback does not know it
        self.lost_status = "lost"  # or "uncounted": a fresh connection, nothing counted yet
        self.last_position: Point | None = None
        self.true_position: Point | None = None  # reported, not estimated
        self.count_kept: Point | None = None  # (Visiomex, Firmata, pi-frame: keep_count)
        self.resumed_from: Point | None = None  # the kept position the connection goes on from
        self.at_loss: Whereabouts | None = None  # the session's account when its link went
        self.unconfirmed_move = False  # a move started whose end no position has confirmed
        self.trail_device: tuple[str, str, str] | None = None  # port, protocol, identity
        self.home_from: Point | None = None
        self.estimate: MoveEstimate | None = None  # built with the worker
        self.pause: ProgramPause | None = None  # built with the worker
        self.bridging = False  # bridge mode: the readout follows the traffic (BridgeReadout)
        self.held_back = False  # the device is ready, shown once the window's docks are built
        link.wirers.append(self._wire)

    @property
    def position_lost(self) -> bool:
        """Whether the device cannot tell where it is and no known place was reached."""
        return self._position_lost

    @position_lost.setter
    def position_lost(self, lost: bool) -> None:
        if lost != self._position_lost:
            self._position_lost = lost
            self.show_unknown_to_program()

    def show_unknown_to_program(self) -> None:
        """The Program dock's Run is off while the position is unknown, saying why."""
        devices = self.window.devices
        if built(devices):
            unknown = translate(
                "MainWindow",
                "the position is unknown: this device cannot report it; home it or set home",
            )
            devices.program.set_position_unknown(unknown if self._position_lost else "")

    def _wire(self, w: SerialWorker) -> None:
        """The worker's reports of where the stage is and what it does, to bound methods (queued
        to the GUI thread); the estimate is built with the worker (it imports the motion engine)."""
        from app.window.device.move_estimate import MoveEstimate
        from app.window.device.program_pause import ProgramPause

        self.estimate = MoveEstimate(self)
        self.estimate.estimated.connect(self._on_estimate)
        self.pause = ProgramPause(self)
        self.pause.wire(w)
        w.position_changed.connect(self._on_position)
        w.whereabouts_changed.connect(self._on_whereabouts)
        w.target_changed.connect(self.show_target)
        w.speed_changed.connect(self._on_speed)
        w.speed_limits_changed.connect(self.window.speed.set_range)
        w.move_started.connect(self._on_move_started)
        w.notice.connect(self._on_notice)
        readout = self.window.readout  # the positions in notices in the units it shows
        readout.shown_changed.connect(lambda: setattr(w, "units", readout.units()))
        w.units = readout.units()
        w.device_error.connect(self._on_device_error)
        w.device_note.connect(self._on_device_note)

    def _tell(self, text: str, kind: str = status.INFO, note: bool = True) -> None:
        self.window.tell(text, kind, note)

    # -- the status line ---------------------------------------------------------------------
    def show_status(self, connection: str = "", detail: str = "") -> None:
        """The status line: the connection's state, or moving, busy, failed or idle."""
        line = self.window.status_line
        if not self.connected and self.bridging:
            return  # the bridge's own state stands (set when it began)
        if not self.connected:
            name = connection or self.window.connection_bar.state()
            line.set_state(name if name != "connected" else status.IDLE, detail)
        elif self.held_back:  # not idle before its controls are on
            line.set_state(status.CONNECTING, detail)
        elif self.pause is not None and self.pause.paused and self.busy_job is not None:
            line.set_state(status.PAUSED, self.busy_job.describe())
        elif self.moving:
            line.set_state(status.MOVING)
        elif self.busy_job is not None:
            line.set_state(status.BUSY, self.busy_job.describe())
        elif self.failed:
            line.set_state(status.ERROR, line.message())
        else:
            line.set_state(status.IDLE)

    def _on_notice(self, text: str) -> None:
        self._tell(text, status.WARNING)

    def _on_device_error(self, message: str) -> None:
        self.failed = True
        text = translate("MainWindow", "the device reported an error: %1")
        self._tell(fill(text, message), status.FAILURE)
        self.show_status()

    def _on_device_note(self, text: str) -> None:
        self.window.console.append_note(fill(translate("MainWindow", "device: %1"), text))

    def _on_speed(self, speed: float) -> None:
        self.window.speed.set_reported(speed)
        self.window.speed.set_value(speed)
        self.window.devices.set_speed(speed)

    # -- the connection ----------------------------------------------------------------------
    def link_lost(self) -> None:
        """No device any more: the move under way is not confirmed, the trail breaks, nothing
        runs, and the position shown is stale."""
        if self.unconfirmed_move:
            self.undo_move()
        at_loss, self.at_loss = self.at_loss, None
        self.window.buffer.break_trail()  # the next connection's positions: a new segment
        self.show_target(None)
        self.end_move()
        self.busy_job = None  # the worker dropped what was queued: nothing runs after this
        if self.pause is not None:
            self.pause.ended()
        if at_loss is not None and at_loss.status == "lost-moving" and at_loss.point is not None:
            self.window.readout.set_position(*at_loss.point)  # the estimate then, marked
            self.window.readout.set_status("lost-moving")
        elif self.last_position is not None and not self.bridging:
            self.window.readout.set_status("stale")

    def _on_whereabouts(self, where: Whereabouts) -> None:
        self.at_loss = where

    def device_ready(self, info: DeviceInfo) -> None:
        """A device answered: whether its position is known (read again, or lost, or not yet
        counted), said once."""
        from drivers.device.position_count import (  # (after the paint)
            counts_position,
            keeps_position,
        )
        from drivers.device.position_truth import LIVE, UNKNOWN

        self.info = info
        device = (info.port, info.protocol, info.identity)
        another = self.trail_device is not None and device != self.trail_device
        if another:
            self.window.buffer.clear(keep_last=True)  # another device: a trail of its own
        self.trail_device = device
        self.count_kept = None  # until a known place is reached
        kept, self.resumed_from = self.resumed_from, None
        where = info.whereabouts  # the session's: known, not counted yet, or lost
        known_as = where.status if where is not None else LIVE
        self.position_lost = known_as in UNKNOWN
        self.lost_status = known_as if self.position_lost else "lost"
        if self.link_failed and not another:  # the same device after a lost link or a restart
            self._tell(
                translate(
                    "MainWindow",
                    "the position is unknown: this device cannot report it; home it or set home",
                )
                if self.position_lost
                else fill(
                    translate("MainWindow", "connected again to %1: the position was read again"),
                    localized(info.identity),
                ),
                status.WARNING if self.position_lost else status.INFO,
            )
        elif keeps_position(info.capabilities) and not self.position_lost and kept is not None:
            self.count_kept = kept  # left there, and kept
            self._tell(
                fill(
                    translate(
                        "MainWindow",
                        "the device cannot be asked where it is: it goes on from (%1, %2, %3) mm, "
                        "where it was left on this port (kept, not measured)",
                    ),
                    *(f"{axis:g}" for axis in kept),
                )
            )
        elif self.position_lost and counts_position(info.protocol, info.capabilities):
            self._tell(  # fresh: nothing counted yet
                translate(
                    "MainWindow",
                    "position unknown: the device cannot be asked; Home or Set Home to start "
                    "counting",
                ),
                status.WARNING,
            )
        elif self.position_lost:  # fresh, absolute targets and nothing kept
            self._tell(
                translate(
                    "MainWindow",
                    "position unknown: the device cannot be asked and its frames carry absolute "
                    "targets, so a jog is refused; Set Home where the stage stands, Home, or Go "
                    "to an absolute point first",
                ),
                status.WARNING,
            )
        self.link_failed = False
        self.window.readout.set_status(self.settled_status())
        caps = info.capabilities  # a speed the device sets itself (Visiomex): the field is off
        self.window.speed.set_fixed(localized(caps.speed_note) if caps.speed_fixed else "")
        if caps.speed_fixed and info.parameters:  # its speed follows what the table writes
            unique = Qt.ConnectionType.UniqueConnection  # and what each move leaves
            self.window.parameters.device_speed.connect(self._on_speed, unique)

    def was_on(self, port: str, protocol: str) -> bool:
        """Whether the last device connected was on this port, with this protocol."""
        return self.trail_device is not None and self.trail_device[:2] == (port, protocol)

    def known_position(self) -> Point | None:
        """The position as last shown, unless the device lost track of it."""
        return None if self.position_lost else self.last_position

    # -- travel limits -----------------------------------------------------------------------
    def apply_travel(self, limits: TravelLimits | None) -> None:
        """The travel box for the device (None: none): the worker, the entry and views follow."""
        self.travel = limits
        self.show_outside()
        box = limits.box if limits is not None else None
        self.window.to_worker(lambda thread: thread.set_travel(limits))
        self.window.coordinates.set_box(box)
        self.window.view2d.set_workspace(box)
        self.window.view3d.set_workspace(box)

    def show_outside(self) -> None:
        """The readout says so while the position reported is outside the travel limits."""
        here, travel = self.last_position, self.travel
        outside = travel.outside(here) if here is not None and travel is not None else []
        self.window.readout.show_outside(outside)

    # -- the position ------------------------------------------------------------------------
    def _on_position(self, report: PositionReport) -> None:
        self.true_position = (report.x, report.y, report.z)
        self.unconfirmed_move = False
        self._follow_known(report)
        window = self.window
        window.buffer.keep_provisional()  # the estimate so far was the stage's way
        if self.home_from is not None and (report.x, report.y, report.z) == (0.0, 0.0, 0.0):
            # Set Home: the trail moves into the new coordinates, with no false jump.
            x, y, z = self.home_from
            self.home_from = None
            window.buffer.shift(-x, -y, -z)
            self.show_target(None)
            window.console.append_note(
                fill(
                    translate("MainWindow", "new home: the trail is shifted by (%1, %2, %3) mm"),
                    f"{-x:g}",
                    f"{-y:g}",
                    f"{-z:g}",
                )
            )
            window.tools.home_moved((x, y, z))
        if self.estimate is not None and self.estimate.active():
            self._end_move_estimate()
        devices = window.devices
        if built(devices) and devices.arc_dock.isVisible() and devices.arc.start_z() != report.z:
            devices.arc.set_start_z(report.z)  # the arc preview starts at the stage's Z
        if self.info is not None:  # measured, or where the last move's reply said it ended
            window.readout.set_measured(report.measured, report.confirmed or None)
        self._show_position(report.x, report.y, report.z)
        self.show_outside()
        self.keep_count()

    def keep_count(self) -> None:
        """A device that cannot be asked where it is (Visiomex, Firmata, pi-frame): the position
        counted, or commanded, since a known place (Home, Set Home, an absolute move on the
        pi-frame) is kept with the settings, for motionctl to go on from."""
        from drivers.device.position_count import keeps_position

        info, here = self.info, self.true_position
        if info is None or not keeps_position(info.capabilities) or here is None:
            return
        if self.position_lost or here == self.count_kept:
            return
        self.count_kept = here
        write_counted_position(self.window.settings, info.protocol, info.port, here)

    def _show_position(self, x: float, y: float, z: float) -> None:
        self.last_position = (x, y, z)
        if self.connected and not self.position_lost:
            self.window.tools.position((x, y, z))
        self.window.readout.set_position(x, y, z)
        self.window.coordinates.set_known_position(x, y, z)
        self.window.buffer.append(time.monotonic() - self.t0, x, y, z)

    def _follow_known(self, report: PositionReport) -> None:
        """A device that cannot be asked: the session says when its position became known (a
        Home, a Set Home, an absolute target), or was not (moves counted from nowhere)."""
        info = self.info
        if info is None or info.capabilities.position_feedback or self.bridging:
            return
        was_lost, self.position_lost = self.position_lost, not report.known
        if was_lost and report.known:
            if self.window.readout.status() in ("lost", "uncounted"):
                self.window.readout.set_status("live")
            self._tell(_known_again(self.busy_job))

    def _on_move_started(self, move: MoveStart) -> None:
        self.moving = True
        self.unconfirmed_move = True
        self.show_status()
        if move.duration > 0 and self.estimate is not None:
            self.window.buffer.begin_provisional()  # taken back should the move fail
            self.estimate.start(move)

    def undo_move(self) -> None:
        """A move failed (or its link went) before a position confirmed it: its estimate is
        taken back from the trail, its target mark goes, and the readout shows the last
        position reported again."""
        self.unconfirmed_move = False
        if self.estimate is not None:
            self.estimate.stop()
        self.window.buffer.drop_provisional()
        self.show_target(None)
        readout = self.window.readout
        if readout.status() == "estimated":
            self._mark_estimated(False)
        true = self.true_position
        if true is not None and true != self.last_position:
            self.last_position = true
            if self.connected and not self.position_lost:
                self.window.tools.position(true)
            readout.set_position(*true)
            self.window.coordinates.set_known_position(*true)

    def _on_estimate(self, x: float, y: float, z: float) -> None:
        if self.window.readout.status() != "estimated":
            # Marked at the first estimate: a move over before it (a short jog step) restyles
            # nothing, which halved the GUI's event-loop gaps while jogging.
            self._mark_estimated(True)
        self._show_position(x, y, z)

    def settled_status(self) -> str:
        """The readout's status when no move is being estimated."""
        return self.lost_status if self.position_lost else "live"

    def _mark_estimated(self, estimated: bool) -> None:
        self.window.readout.set_status("estimated" if estimated else self.settled_status())
        self.window.view2d.set_estimated(estimated)
        self.window.view3d.set_estimated(estimated)

    def _end_move_estimate(self) -> None:
        if self.estimate is not None:
            self.estimate.stop()
        if self.window.readout.status() == "estimated":
            self._mark_estimated(False)

    def end_move(self) -> None:
        """Nothing moves (any more): its estimate ends."""
        self.moving = False
        if self.estimate is not None and self.estimate.active():
            self._end_move_estimate()

    def show_target(self, target: Point | None) -> None:
        """The target of the move under way, marked in the views (None: no mark)."""
        self.window.view2d.set_target(target)
        self.window.view3d.set_target(target)

    # -- jobs --------------------------------------------------------------------------------
    def job_failed(self) -> None:
        """A job failed: the move it started is taken back; the status says failed."""
        if self.unconfirmed_move:
            self.undo_move()
        self.failed = True

    def job_stopped(self) -> None:
        """The operator's stop ended a job: a move it had started and no position confirmed
        is taken back, and nothing failed."""
        if self.unconfirmed_move:
            self.undo_move()

    def job_ended(self, job: jobs.Job) -> None:
        """`job` ended (done or failed): nothing it started moves any more, and unless a job
        submitted after it waits its turn, nothing runs."""
        from app.window.device import jobs

        if job is self.busy_job:  # a Home clicked during a jog's tap is busy once the jog ends
            self.busy_job = None
        if self.pause is not None:
            self.pause.ended()
        if self.moving:  # one job at a time: when it ends, nothing moves (arcs and jogs alike)
            self.end_move()
        if isinstance(job, jobs.SetHomeJob):
            self.home_from = None

    def job_finished(self, job: jobs.Job, result: object) -> None:
        """`job` was done: where that makes the position known again, it is."""
        from app.window.device import jobs

        self.failed = False
        self.window.status_line.clear_error()
        self.keep_count()  # Home, Set Home: counting starts
        if isinstance(job, jobs.SetSpeedJob) and isinstance(result, float) and result != job.speed:
            self._tell(
                fill(
                    translate(
                        "MainWindow", "speed %1 mm/s reads back as %2 mm/s (the device rounds)"
                    ),
                    f"{job.speed:g}",
                    f"{result:g}",
                ),
                note=False,
            )
