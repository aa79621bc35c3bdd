"""The Program dock's controller: a file read off the GUI thread, drawn, measured and checked
against the travel box before anything is sent; run as a job with progress line by line."""

from __future__ import annotations

import logging
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import shiboken6
from PySide6.QtCore import QObject, Qt, QTimer, Signal
from PySide6.QtWidgets import QApplication, QDockWidget, QWidget

from app.common.messages import localized
from app.window.device import jobs
from app.window.keyboard_jog import arrow_key_user
from drivers.errors import BadInput
from drivers.toolpath.model import Dwell, Line, Toolpath
from drivers.toolpath.point_program import ProgramPoint, write_program
from drivers.toolpath.streaming import StreamProgress
from widgets._i18n import fill
from widgets.program_panel import ProgramPanel

if TYPE_CHECKING:
    from app.window.services import WindowServices
    from drivers.device.travel import TravelLimits
    from drivers.protocols.capabilities import Capabilities
    from drivers.toolpath.geometry import FlatPath, Summary

log = logging.getLogger(__name__)

PROGRESS_MS = 100  # the dock shows a running program's progress at most this often
# Of the instructions executed: the time left is the program's own estimate up to the first
# share, the rate measured from the second, a mix of the two between.
TRUST_RATE = (0.1, 0.5)
POINT_SUFFIXES = (".csv", ".json")  # programs of points: saved as the panel's JSON
REREAD_SUFFIXES = (".dxf", ".svg")  # their curves are flattened on reading: read again


@dataclass
class Reading:
    """What reading (or re-flattening, or checking) a program gave, for the GUI thread."""

    generation: int
    path: Path
    layers: list[str] | None
    tolerance: float
    toolpath: Toolpath | None = None
    flat: FlatPath | None = None
    summary: Summary | None = None
    error: Exception | None = None
    outside: Exception | None = None  # check_travel's refusal (None: inside the box)


def read_program(
    reading: Reading,
    kept: Toolpath | None,
    travel: TravelLimits | None,
    speed: float,
    axes: tuple[str, ...] = ("x", "y", "z"),
) -> Reading:
    """Read (or take `kept`), flatten, measure and check a program against the travel box and
    the device's axes: any thread."""
    from drivers.toolpath.geometry import check_fits, flatten, summarize
    from drivers.toolpath.loader import load_toolpath

    try:
        toolpath = kept
        if toolpath is None:
            toolpath = load_toolpath(
                reading.path, layers=reading.layers, tolerance=reading.tolerance
            )
        flat = flatten(toolpath, reading.tolerance)
        reading.toolpath, reading.flat = toolpath, flat
        reading.summary = summarize(toolpath, flat, speed)
        try:
            check_fits(toolpath, flat, axes, travel)
        except BadInput as exc:  # drawn all the same: the operator sees why it cannot run
            reading.outside = exc
    except (BadInput, OSError) as exc:
        reading.error = exc
    except Exception as exc:  # a reader's bug must not kill the thread silently
        log.exception("reading %s failed", reading.path)
        reading.error = exc
    return reading


class ProgramDock(QObject):
    """Loads the program the panel asks for, shows it, runs it and follows its progress."""

    _done_reading = Signal(object)  # a Reading, from the reading thread (queued)

    def __init__(self, panel: ProgramPanel, services: WindowServices, parent: QObject) -> None:
        super().__init__(parent)
        self.panel = panel
        self.services = services
        self.path: Path | None = None
        self.toolpath: Toolpath | None = None
        self.flat: FlatPath | None = None
        self.summary: Summary | None = None
        self.layers: list[str] | None = None  # the DXF layers chosen (None: all)
        self._all_layers: tuple[str, ...] = ()  # the DXF file's layers
        self.speed = 10.0  # mm/s: the device's, for the time estimate
        self.axes: tuple[str, ...] = ("x", "y", "z")  # the device's, checked when read
        self.arc_mode = False  # the device runs arcs as its own (one instruction each)
        self.running = False
        self._focus_before: QWidget | None = None  # where the keys were when the run began
        self._generation = 0  # of the last reading asked for: older ones are dropped
        self._reading = False
        self._pending: StreamProgress | None = None
        self._shown_at = 0.0
        self._progress_timer = QTimer(self)
        self._progress_timer.setSingleShot(True)
        self._progress_timer.timeout.connect(self._show_pending)
        self._done_reading.connect(self._on_read)
        panel.load_requested.connect(self.load)
        panel.save_requested.connect(self.save)
        panel.run_requested.connect(self.run)
        panel.pause_requested.connect(lambda: self._pause(True))
        panel.resume_requested.connect(lambda: self._pause(False))
        panel.stop_requested.connect(lambda: services.worker_thread.stream_stop())
        panel.tolerance_changed.connect(self._tolerance_changed)
        panel.layers_changed.connect(self._layers_changed)
        services.worker.job_finished.connect(self._on_job_finished)
        services.worker.job_failed.connect(self._on_job_failed)
        services.worker.stream_progress.connect(self._on_progress)
        panel.set_connected(False)  # until a device is ready (set_device)

    @property
    def tolerance(self) -> float:
        """The chord tolerance set (mm)."""
        return self.panel.tolerance.value()

    @property
    def reading(self) -> bool:
        """Whether a file is being read (or its path made again) now."""
        return self._reading

    # -- loading -------------------------------------------------------------------------------
    def load(self, path: str) -> None:
        """Read a program in the background and show it; nothing is sent."""
        file = Path(path)
        self.layers = None
        self._all_layers = ()
        self.panel.set_loading(file.name)
        self._start(file, None, None)

    def _start(self, path: Path, layers: list[str] | None, kept: Toolpath | None) -> None:
        """Read `path` (or flatten `kept` again) off the GUI thread; the result comes by
        signal."""
        self._generation += 1
        self._reading = True
        reading = Reading(self._generation, path, layers, self.tolerance)
        travel, speed, axes = self.services.travel, self.speed, self.axes

        def work() -> None:
            result = read_program(reading, kept, travel, speed, axes)
            try:
                self._done_reading.emit(result)
            except RuntimeError:  # the window closed meanwhile
                log.debug("a program read after its dock went: %s", path)

        threading.Thread(target=work, name="program-reader", daemon=True).start()

    def _on_read(self, reading: Reading) -> None:
        if reading.generation != self._generation:
            return  # a newer file or option was asked for since
        self._reading = False
        name = reading.path.name
        if reading.error is not None or reading.toolpath is None or reading.flat is None:
            text = localized(reading.error) if reading.error is not None else name
            self._clear()
            if reading.layers is not None and self._all_layers:
                # Other layers chosen, none of which can run: the list stays to choose again.
                self.path, self.layers = reading.path, reading.layers
                self.panel.set_layers(self._all_layers, reading.layers)
            self.panel.show_error(text)
            self.services.say(fill(self.tr("program %1 refused: %2"), name, text))
            return
        toolpath, flat = reading.toolpath, reading.flat
        self.path, self.toolpath, self.flat = reading.path, toolpath, flat
        self.summary = reading.summary
        self.layers = reading.layers
        sources = toolpath.sources
        kind = sources[0].kind if sources else "point"
        self.panel.set_program(name, len(sources), kind, self.instructions())
        self.panel.set_lines(sources)
        suffix = reading.path.suffix.lower()
        self._all_layers = toolpath.layers if suffix == ".dxf" else ()
        self.panel.set_layers(self._all_layers, reading.layers)
        self.panel.set_notices([localized(notice) for notice in toolpath.notices])
        self._show_summary()
        if suffix in POINT_SUFFIXES:
            self.panel.set_saveable(True)
        else:
            self.panel.set_saveable(
                False, self.tr("only programs of points (CSV, JSON) are saved as JSON")
            )
        self.services.show_program(flat)
        self._raise_dock()
        refusal = self._refusal(toolpath, reading.outside)
        self.panel.set_refused(refusal)
        if refusal:
            self.services.say(fill(self.tr("program %1 cannot run: %2"), name, refusal))
        else:
            loaded = self.tr("program %1: %2 segments, nothing sent yet")
            self.services.say(fill(loaded, name, len(flat) - 1))
        # The session log keeps what the operator loaded, in English, among the traffic.
        state = "refused" if refusal else "ready"
        self.services.worker_thread.note(
            f"program loaded: {name}, {len(flat) - 1} segments, {state}"
        )

    def _raise_dock(self) -> None:
        """Bring the Program dock to the front of its tabs: the operator sees what was read."""
        widget = self.panel.parentWidget()
        while widget is not None and not isinstance(widget, QDockWidget):
            widget = widget.parentWidget()
        if widget is not None:
            widget.raise_()

    def _refusal(self, toolpath: Toolpath, outside: Exception | None) -> str:
        """Why the program cannot run ("": it can)."""
        if outside is not None:
            return localized(outside)
        if not toolpath.steps:
            return self.tr("the program has no moves")
        return ""

    def _clear(self) -> None:
        """Nothing loaded."""
        self.path = self.toolpath = self.flat = self.summary = None
        self.panel.set_program("", 0)
        self.panel.set_layers((), None)
        self.panel.set_refused("")
        self.services.show_program(None)

    def _show_summary(self) -> None:
        summary = self.summary
        if summary is None:
            return
        self.panel.show_summary(
            summary.length,
            summary.travel_length,
            summary.low,
            summary.high,
            summary.seconds,
            self.speed,
            summary.segments,
        )

    def _tolerance_changed(self, _tolerance: float) -> None:
        """The path is made again with the new chord tolerance (the file read again where its
        curves were flattened on reading)."""
        if self.path is None or self.running:
            return
        kept = None if self.path.suffix.lower() in REREAD_SUFFIXES else self.toolpath
        self.panel.set_loading(self.path.name)
        self._start(self.path, self.layers, kept)

    def _layers_changed(self, layers: list[str]) -> None:
        """Other DXF layers chosen: the file is read again with them."""
        if self.path is None or self.running:
            return
        self.panel.set_loading(self.path.name)
        self._start(self.path, layers, None)

    def travel_changed(self) -> None:
        """New travel limits: the program loaded is checked against them again."""
        if self.path is not None and self.toolpath is not None and not self.running:
            self._start(self.path, self.layers, self.toolpath)

    def set_device(self, caps: Capabilities | None) -> None:
        """A device is ready (its capabilities), or none is (None): Run follows, the last
        run's figures go, and the program loaded is checked against the device again."""
        self.panel.set_connected(caps is not None)
        self.panel.set_pause_meaning(caps.streaming if caps is not None else None)
        self.panel.clear_figures()
        if caps is None:
            return
        self.arc_mode = caps.arcs and not caps.streaming  # as the toolpath runner's mode
        self.set_axes(caps.axes)

    def instructions(self) -> int:
        """What a run of the program loaded counts (the runner's count): its segments and
        dwells, or its steps where the device runs arcs itself; 0 with none."""
        toolpath, flat = self.toolpath, self.flat
        if toolpath is None or flat is None:
            return 0
        if self.arc_mode:
            return len(toolpath.steps)
        return len(flat.points) - 1 + sum(1 for s in toolpath.steps if type(s) is Dwell)

    def set_axes(self, axes: tuple[str, ...]) -> None:
        """The connected device's axes: a program moving another is refused when read."""
        self.axes = axes
        self.travel_changed()  # the program loaded is checked again

    def set_speed(self, speed: float) -> None:
        """The device's speed (mm/s): the time estimate follows it."""
        if speed > 0 and speed != self.speed:
            self.speed = speed
            if self.toolpath is not None and self.flat is not None:
                from drivers.toolpath.geometry import summarize

                self.summary = summarize(self.toolpath, self.flat, speed)
                self._show_summary()

    # -- saving --------------------------------------------------------------------------------
    def save(self, path: str) -> None:
        """Save the loaded program of points as the panel's JSON."""
        points = self._points()
        if points is None:
            return
        try:
            write_program(path, points)
        except BadInput as exc:
            self.panel.show_error(localized(exc))
            return
        self.services.say(fill(self.tr("program saved to %1 (%2 points)"), path, len(points)))

    def _points(self) -> list[ProgramPoint] | None:
        """The loaded program as points (None: it is not a program of points)."""
        toolpath = self.toolpath
        if toolpath is None or any(s.kind != "point" for s in toolpath.sources[:1]):
            return None
        points = []
        for step in toolpath.steps:
            if type(step) is not Line or step.speed is None:
                return None
            points.append(ProgramPoint(*step.end, step.speed))
        return points

    # -- running -------------------------------------------------------------------------------
    def run(self) -> None:
        """Run the loaded program (the worker runs it; progress comes by signal)."""
        if self.toolpath is None or self._reading or self.panel.refused():
            return
        name = self.path.name if self.path is not None else self.toolpath.name
        job = jobs.StreamJob(self.toolpath, self.tolerance, name)
        self._focus_before = QApplication.focusWidget()
        if self.services.submit_job(job):
            self.running = True
            self._pending = None
            self.panel.set_running(True)
            self.panel.show_line(None)
            self.services.show_program_done(0)

    def _pause(self, paused: bool) -> None:
        self.services.worker_thread.stream_pause(paused)
        self.panel.set_paused(paused)

    def _on_progress(self, state: StreamProgress) -> None:
        """Kept, and shown at most every PROGRESS_MS."""
        self._pending = state
        wait = PROGRESS_MS / 1000 - (time.monotonic() - self._shown_at)
        if wait <= 0:
            self._show_pending()
        elif not self._progress_timer.isActive():
            self._progress_timer.start(int(wait * 1000) + 1)

    def _show_pending(self) -> None:
        state = self._pending
        if state is not None:
            self._pending = None
            self._show_progress(state)

    def _show_progress(self, state: StreamProgress) -> None:
        self._shown_at = time.monotonic()
        self.panel.show_progress(
            state.sent,
            state.acknowledged,
            state.executed,
            state.rate,
            self._seconds_left(state),
            state.retransmissions,
            state.total,
        )
        self.panel.show_line(state.source)
        if self.flat is not None:
            self.services.show_program_done(state.row)

    def _seconds_left(self, state: StreamProgress) -> float | None:
        """The time left: at first the program's own estimate (its length at its speeds) for
        what is left, then more and more the rate measured (the first instruction alone, the
        move to the start and the device's set-up, said 125 s for a 9 s program)."""
        measured = state.seconds_left()
        summary, total = self.summary, max(state.total, 1)
        if summary is None or summary.seconds <= 0:
            return measured
        done = min(max(state.executed / total, 0.0), 1.0)
        planned = summary.seconds * (1.0 - done)
        if measured is None:
            return planned
        start, full = TRUST_RATE
        trust = min(max((done - start) / (full - start), 0.0), 1.0)
        return trust * measured + (1.0 - trust) * planned

    def _ended(self) -> None:
        self.running = False
        self._progress_timer.stop()
        self._pending = None
        self.panel.set_running(False)
        self._give_the_keys_back()

    def _give_the_keys_back(self) -> None:
        """The keys where they were when the run began: Run, Stop and the motion controls went
        off under the focus meanwhile, and Qt moved it on, to the dock's tab bar, whose arrow
        keys switch tabs instead of jogging."""
        before, self._focus_before = self._focus_before, None
        now = QApplication.focusWidget()
        if now is None or now is before or not arrow_key_user(now):
            return  # the keys jog (or the operator chose where they go since)
        if before is not None and self._takes_the_keys_back(before):
            before.setFocus(Qt.FocusReason.OtherFocusReason)
            return
        now.clearFocus()  # no widget takes the arrow keys: they jog

    @staticmethod
    def _takes_the_keys_back(widget: QWidget) -> bool:
        """Whether `widget` still exists, can have the focus and leaves the arrows to jog."""
        alive = shiboken6.isValid(widget) and widget.isEnabled() and widget.isVisible()
        return alive and not arrow_key_user(widget)

    def _on_job_failed(self, job: jobs.Job, message: str) -> None:
        if isinstance(job, jobs.StreamJob):
            self._ended()
            self.panel.show_error(fill(self.tr("the program stopped: %1"), message))

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        if not isinstance(job, jobs.StreamJob) or not isinstance(result, StreamProgress):
            return
        self._ended()
        self._show_progress(result)
        if result.finished:
            self.services.show_program_done(0)  # the whole path again, ready to run again
            done = self.tr("program %1 done: %2/%3 executed in %4 s")
        else:
            done = self.tr("program %1 stopped: %2/%3 executed in %4 s")
        text = fill(done, job.name, result.executed, result.total, f"{result.seconds:.1f}")
        if result.frames:
            frames = self.tr("%1; %2 frames, %3 retransmission(s)")
            text = fill(frames, text, result.frames, result.retransmissions)
        self.services.say(text)
