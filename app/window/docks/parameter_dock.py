"""The parameter editor's dock in the window: rows from the protocol, writes through the worker."""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, Qt, Signal
from PySide6.QtWidgets import QDockWidget, QMainWindow

from app.common.messages import localized
from app.common.settings import read_parameters, write_parameters
from app.window.device import jobs
from app.window.device.connect_options import DeviceInfo
from app.window.layout.dock_layout import empty_dock
from drivers.device.param_profile import read_profile, write_profile
from drivers.errors import BadInput
from drivers.messages import message_of
from drivers.protocols.base import Protocol
from drivers.protocols.parameters import Parameter, ParameterWritten
from drivers.protocols.registry import create_protocol
from widgets._i18n import fill
from widgets.parameter_editor import ParameterEditor, ParameterRow
from widgets.parameter_values import AFTER_SET, AT_MOVE, CANCELLED, CONFIRMED, ERROR, TIMED_OUT

if TYPE_CHECKING:
    from app.window.services import WindowServices
    from drivers.device.motion import MoveStart

log = logging.getLogger(__name__)

SECONDS_PER_PACKET = 1.05  # Visiomex: the reply comes 1 s after the packet, then the next goes
FORCED_NOTE = QT_TRANSLATE_NOOP(
    "ParameterDock", "the device now holds %1: the firmware forces it after every set"
)  # translated at use, %1 the value


# The one unit of the parameters that is a word (the others are symbols: mm, µs, ×).
UNIT_WORDS = {"steps": QT_TRANSLATE_NOOP("ParameterDock", "steps")}


def unit_shown(unit: str) -> str:
    """A parameter's unit as the editor shows it (a word in the interface's language)."""
    word = UNIT_WORDS.get(unit)
    return QCoreApplication.translate("ParameterDock", word) if word else unit


def editor_rows(
    parameters: tuple[Parameter, ...], protocol: Protocol | None = None
) -> list[ParameterRow]:
    """The editor's plain rows for a protocol's parameters: with their power-on values, and
    the protocol's warning for those whose written value will not do what it says."""
    return [
        ParameterRow(
            p.id,
            p.name,
            unit_shown(p.unit),
            p.minimum,
            p.maximum,
            p.step,
            p.output,
            localized(p.description),
            power_on=p.default,
            warning=localized(protocol.write_warning(p.id)) if protocol is not None else "",
        )
        for p in parameters
    ]


def shown_derivation(
    derive: Callable[[dict[str, float]], list[tuple[str, str]]],
) -> Callable[[dict[str, float]], list[tuple[str, str]]]:
    """`derive` with its figures and its refusals in the interface's language (the editor, a
    widget, shows what it is given)."""

    def shown(values: dict[str, float]) -> list[tuple[str, str]]:
        try:
            rows = derive(values)
        except KeyError:
            raise  # the editor names the value that is missing
        except (ValueError, ArithmeticError, LookupError) as exc:
            if message_of(exc) is None:
                raise
            raise ValueError(localized(exc)) from exc
        return [(localized(label), localized(text)) for label, text in rows]

    return shown


DOCK_NAME = "parameterEditor"


def make_dock(window: QMainWindow) -> QDockWidget:
    """The parameter editor's dock, empty and hidden, at the bottom of `window`."""
    dock = QDockWidget(QCoreApplication.translate("ParameterDock", "Parameters"), window)
    dock.setObjectName(DOCK_NAME)
    dock.setFeatures(
        QDockWidget.DockWidgetFeature.DockWidgetMovable
        | QDockWidget.DockWidgetFeature.DockWidgetFloatable
        | QDockWidget.DockWidgetFeature.DockWidgetClosable
    )
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, dock)
    dock.hide()
    return dock


class ParameterDock(QObject):
    """Shows the editor when the device has parameters; turns its requests into jobs."""

    device_speed = Signal(float)  # mm/s the device steps at, as what it holds now gives it

    def __init__(self, window: QMainWindow, services: WindowServices) -> None:
        super().__init__(window)
        self.window = window  # the docks' and dialogs' parent
        self.services = services
        self.editor = ParameterEditor(window)
        self.dock = empty_dock(window, DOCK_NAME, make_dock)
        self.dock.setWidget(self.editor)
        self.protocol: Protocol | None = None
        self.info: DeviceInfo | None = None
        self._writing: list[jobs.SetParameterJob] = []
        self.editor.write_requested.connect(self.write)
        self.editor.cancel_requested.connect(self.cancel)
        self.editor.load_requested.connect(self.load)
        self.editor.save_requested.connect(self.save)
        w = services.worker
        w.parameter_written.connect(self._on_written)
        w.job_finished.connect(self._on_job_finished)
        w.job_failed.connect(self._on_job_failed)
        w.job_timed_out.connect(self._on_job_timed_out)
        w.move_started.connect(self._on_move_started)

    # -- connection --------------------------------------------------------------------------
    def device_ready(self, info: DeviceInfo) -> None:
        """Show the editor for a device with parameters (rows, last written, derived values)."""
        self.info = info
        if not info.parameters:
            self.protocol = None
            self.dock.hide()
            return
        self.protocol = create_protocol(info.protocol, info.variant or None)
        self.editor.set_parameters(editor_rows(info.parameters, self.protocol))
        last = read_parameters(self.services.settings, info.protocol, info.port)
        self.protocol.assume_parameters(last)
        defaults = {p.name: p.default for p in info.parameters}
        self.editor.set_values({**defaults, **last})
        self.editor.set_last_written(last)
        self.editor.set_derivation(shown_derivation(self.protocol.derived_values))
        self.editor.set_connected(True)
        self.dock.setWindowTitle(fill(self.tr("Parameters (%1)"), info.protocol))
        self.dock.setToolTip(fill(self.tr("%1 on %2"), info.identity, info.port))
        # Shown (and put in front) by the window's layout if it has the editor (layouts.py):
        # shown here in another layout's place, it would widen the window for good.

    def disconnected(self) -> None:
        """No device: writing is off (the table stays editable, for profiles)."""
        self.editor.set_connected(False)
        if self._writing:
            self._writing.clear()
            self.editor.end_write()

    # -- writing -----------------------------------------------------------------------------
    def write(self, items: list[tuple[int, float]]) -> None:
        """Queue one set job per parameter; the progress bar counts them."""
        if self.protocol is None or not items or self._writing:
            return
        submitted = []
        for param_id, value in items:
            parameter = self.protocol.parameter(param_id)
            job = jobs.SetParameterJob(parameter.id, value, parameter.name, parameter.unit)
            if not self.services.submit_job(job):
                break
            self._writing.append(job)
            submitted.append(parameter.id)
        if submitted:
            self.editor.begin_write(submitted, SECONDS_PER_PACKET)

    def cancel(self) -> None:
        """Drop the sets not sent yet; the one in flight finishes (its reply is awaited)."""
        dropped = self.services.worker.cancel_pending()
        keep = [job for job in dropped if not isinstance(job, jobs.SetParameterJob)]
        for job in keep:
            self.services.worker.submit(job)  # only the parameter writes are cancelled
        cancelled = [job for job in dropped if isinstance(job, jobs.SetParameterJob)]
        self.forget(cancelled)
        self.services.jobs_dropped(cancelled)  # motion is on again once none is left
        self.services.say(fill(self.tr("parameter writing cancelled: %1 not sent"), len(cancelled)))

    def forget(self, dropped: list[jobs.Job]) -> None:
        """Jobs that will never run (cancelled or stopped): their rows say so."""
        for job in dropped:
            if job in self._writing:
                self._writing.remove(job)
                self.editor.set_status(job.param_id, CANCELLED, self.tr("not sent"))
        self._end_if_done()

    def _end_if_done(self) -> None:
        if not self._writing and self.editor.writing():
            self.editor.end_write()

    def _on_written(self, written: ParameterWritten) -> None:
        """The device confirmed a value (from the editor, or the speed control's 21/22)."""
        info = self.info
        if info is None or self.protocol is None:
            return
        name = written.parameter.name
        values = {name: written.value, **written.device_values}
        write_parameters(self.services.settings, info.protocol, info.port, values)
        self.protocol.assume_parameters(values)
        self._speed_follows()
        self.editor.set_status(
            written.parameter.id, CONFIRMED, "; ".join(localized(note) for note in written.notes)
        )
        outputs = {row.name for row in self.editor.parameters() if row.output}
        untouched = set(outputs) - set(self.editor.changed_names())
        self.editor.set_last_written({**self.editor.last_written(), **values})
        # An output the firmware recomputed shows its new value where it was not edited.
        recomputed = {n: v for n, v in written.device_values.items() if n in untouched}
        if recomputed:
            self.editor.set_values(recomputed)
        self.editor.set_computed(written.device_values, AFTER_SET)
        for other, value in written.device_values.items():
            self.editor.set_row_note(other, fill(self.tr(FORCED_NOTE), f"{value:g}"))

    def _on_move_started(self, move: MoveStart) -> None:
        """A move went out: what the firmware recomputes as it makes it (Visiomex 15, 16, 19,
        20) is what the device holds from now on, shown marked computed and kept."""
        info = self.info
        if info is None or self.protocol is None or not move.recomputed:
            return
        held = {row.name: row.power_on for row in self.editor.parameters()}
        held.update(self.editor.last_written())
        changed = {n: v for n, v in move.recomputed.items() if held.get(n) != v}
        if not changed:
            return
        write_parameters(self.services.settings, info.protocol, info.port, changed)
        self.protocol.assume_parameters(changed)
        self._speed_follows()
        self.editor.set_computed(changed, AT_MOVE)
        for name in changed:
            self.editor.set_row_note(name, self.tr("recomputed by the firmware at the last move"))

    def _speed_follows(self) -> None:
        """A device that times its moves from its parameters (Visiomex 15, 16): the speed it
        moves at now, from what it holds, to the Speed panel."""
        speed = self.protocol.moving_speed() if self.protocol is not None else None
        if speed is not None:
            self.device_speed.emit(speed)

    def _on_job_finished(self, job: jobs.Job, result: object) -> None:
        if job in self._writing:
            self._writing.remove(job)
            self._end_if_done()

    def _on_job_timed_out(self, job: jobs.Job) -> None:
        if isinstance(job, jobs.SetParameterJob) and job in self._writing:
            self.editor.set_status(job.param_id, TIMED_OUT, self.tr("the device did not answer"))

    def _on_job_failed(self, job: jobs.Job, message: str) -> None:
        if job not in self._writing:
            return
        self._writing.remove(job)
        assert isinstance(job, jobs.SetParameterJob)
        if self.editor.status(job.param_id) != TIMED_OUT:
            self.editor.set_status(job.param_id, ERROR, message)
        self._end_if_done()

    # -- profiles ----------------------------------------------------------------------------
    def load(self, path: str) -> None:
        """Put a profile's values in the editor (nothing is sent)."""
        if self.protocol is None:
            self.editor.show_message(
                self.tr("connect to a device with parameters first"), error=True
            )
            return
        outputs: list[str] = []
        try:
            values = read_profile(path, self.protocol.parameters, self.protocol.name, outputs)
        except BadInput as exc:
            self.editor.show_message(localized(exc), error=True)
            return
        self.editor.set_values(values)
        loaded = fill(
            self.tr("loaded %1 values from %2; nothing sent (Write changed sends them)"),
            len(values),
            path,
        )
        if outputs:
            skipped = self.tr("left out, computed by the firmware: %1")
            loaded = f"{loaded}; {fill(skipped, ', '.join(outputs))}"
        self.editor.show_message(loaded)

    def save(self, path: str) -> None:
        """Save the editor's values as a profile."""
        if self.protocol is None:
            return
        values = self.editor.values()
        try:
            count = write_profile(path, values, self.protocol.parameters, self.protocol.name)
        except BadInput as exc:
            self.editor.show_message(localized(exc), error=True)
            return
        saved = fill(self.tr("saved %1 values to %2"), count, path)
        if count < len(values):
            saved = fill(self.tr("%1 (firmware outputs are never saved)"), saved)
        self.editor.show_message(saved)
