"""What each kind of job does with the device's session: one function per job type, in a table."""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable
from typing import Any, Protocol

from app.common.macros import run_macro
from app.common.stepper_config import configure_stepper, stepper_version
from app.window.device import jobs
from app.window.device.traffic_batch import TrafficBatch
from drivers.device.motion import KIND_UNITS
from drivers.errors import MotionError
from drivers.messages import Message
from drivers.protocols.base import Reply
from drivers.session.device_session import DeviceSession
from drivers.toolpath.streaming import StreamProgress


class JobHost(Protocol):
    """What a job's handler uses of the serial worker (app/window/device/worker.py)."""

    speed_changed: Any
    capabilities_changed: Any
    stream_progress: Any
    macro_step: Any
    batch: TrafficBatch

    def refresh(self) -> None:
        """Read the position, the speed and its limits."""


STREAM_POSITION_S = 0.2  # s between position reads while a program streams
STREAM_PROGRESS_S = 0.05  # s between progress reports to the window (it draws at 10 Hz)

Handler = Callable[[Any, DeviceSession, Any], object]


def _move_to(worker: JobHost, session: DeviceSession, job: jobs.MoveToJob) -> object:
    return session.move_to(job.x, job.y, job.z)


def _move_by(worker: JobHost, session: DeviceSession, job: jobs.MoveByJob) -> object:
    what = None
    if not job.jog:  # a relative Go to: not a "jog" in its messages
        what = Message(
            "relative move by ({dx:g}, {dy:g}, {dz:g}) {unit}",
            dx=job.dx,
            dy=job.dy,
            dz=job.dz,
            unit=KIND_UNITS.get(job.kind, job.kind),
        )
    return session.move_by(job.dx, job.dy, job.dz, job.kind, what=what)


def _set_speed(worker: JobHost, session: DeviceSession, job: jobs.SetSpeedJob) -> object:
    speed = session.speed(job.speed)
    worker.speed_changed.emit(speed)
    return speed


def _raw(worker: JobHost, session: DeviceSession, job: jobs.RawJob) -> object:
    # Through the motion guard: a move is checked and followed like a typed one.
    reply = session.send_raw(job.data, job.force)
    return reply.value if isinstance(reply, Reply) else reply


def _arc(worker: JobHost, session: DeviceSession, job: jobs.ArcJob) -> object:
    a = job.arc
    return session.arc(a.cx, a.cy, a.radius, a.start, a.end, ccw=a.ccw, z=a.z)


def _dwell(worker: JobHost, session: DeviceSession, job: jobs.DwellJob) -> object:
    session.dwell(job.ms / 1000)
    return None


def _settings(worker: JobHost, session: DeviceSession, job: jobs.SettingsJob) -> object:
    worker.capabilities_changed.emit(session.configure(job.values))
    return None


def _refresh(worker: JobHost, session: DeviceSession, job: jobs.RefreshJob) -> object:
    worker.refresh()
    return None


def _macro(worker: JobHost, session: DeviceSession, job: jobs.MacroJob) -> object:
    """Run a macro, telling each step before it starts; the traffic goes out as it runs."""
    macro = job.macro
    count = len(macro.steps)

    def step(number: int, text: str) -> None:
        worker.batch.flush()
        worker.macro_step.emit(macro.name, number, count, text)

    return run_macro(session, macro, step)


def _stream(worker: JobHost, session: DeviceSession, job: jobs.StreamJob) -> StreamProgress:
    """Run a program, its progress told at most every STREAM_PROGRESS_S; where moves run from
    the device's queue, the position read along the way."""
    last_emit = last_position = 0.0
    queued = session.capabilities.streaming  # moves run elsewhere report their own position

    def progress(state: StreamProgress) -> None:
        nonlocal last_emit, last_position
        now = time.monotonic()
        if now - last_emit >= STREAM_PROGRESS_S or state.finished:
            last_emit = now  # the final state comes with job_finished anyway
            worker.stream_progress.emit(dataclasses.replace(state))
        if queued and now - last_position >= STREAM_POSITION_S:
            last_position = now
            session.position()  # the live position moves along the program
        worker.batch.flush_if_due()

    # Stopped early, the device is stopped (its queue flushed); the position is read at the end.
    return session.run_program(job.toolpath, progress, tolerance=job.tolerance)


DISPATCH: dict[type[jobs.Job], Handler] = {
    jobs.MoveToJob: _move_to,
    jobs.MoveByJob: _move_by,
    jobs.HomeJob: lambda worker, session, job: session.home(),
    jobs.SetHomeJob: lambda worker, session, job: session.set_home(),
    jobs.SetSpeedJob: _set_speed,
    jobs.RawJob: _raw,
    jobs.SetParameterJob: lambda worker, session, job: session.set_parameter(
        job.param_id, job.value
    ),
    jobs.ArcJob: _arc,
    jobs.DwellJob: _dwell,
    jobs.SettingsJob: _settings,
    jobs.StreamJob: _stream,
    jobs.StepperConfigJob: lambda worker, session, job: configure_stepper(
        session, job.steps_per_rev, job.pins
    ),
    jobs.StepperVersionJob: lambda worker, session, job: stepper_version(session),
    jobs.RefreshJob: _refresh,
    jobs.MacroJob: _macro,
}


def dispatch(worker: JobHost, session: DeviceSession, job: jobs.Job) -> object:
    """Carry out `job` on the session; its result (MotionError for a job of no known kind)."""
    handler = DISPATCH.get(type(job))
    if handler is None:
        raise MotionError(Message("unknown job {job!r}", job=job))
    return handler(worker, session, job)
