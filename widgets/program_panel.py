"""A program: load it (G-code, DXF, SVG, CSV or JSON), see its figures and lines, run it with
progress line by line, pause, resume and stop."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from PySide6.QtCore import (
    QT_TRANSLATE_NOOP,
    Qt,
    QTimer,
    Signal,
)
from PySide6.QtGui import QStandardItem, QStandardItemModel
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDoubleSpinBox,
    QFileDialog,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QListView,
    QProgressBar,
    QVBoxLayout,
    QWidget,
)

from widgets._buttons import make_button
from widgets._i18n import fill
from widgets._number_field import wheel_needs_focus
from widgets.program_lines import ProgramLines, SourceLine

PROGRAM_FILTER = QT_TRANSLATE_NOOP(
    "ProgramPanel",
    "Programs (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;"
    "G-code (*.gcode *.nc *.ngc *.tap);;DXF drawings (*.dxf);;SVG drawings (*.svg);;"
    "Points (*.csv *.json);;All files (*)",
)
NO_PROGRAM = QT_TRANSLATE_NOOP("ProgramPanel", "no program loaded")  # both translated at use
ERROR_STYLE = "color: #c62828;"
TOLERANCE_DEFAULT = 0.01  # mm, as drivers/toolpath/model.py CHORD_TOLERANCE
TOLERANCE_SETTLE_MS = 400  # the path is made again once the tolerance stops changing


class ProgramPanel(QWidget):
    """Buttons, figures, lines and progress of a program; the app reads files and runs it."""

    load_requested = Signal(str)  # a path
    save_requested = Signal(str)  # a path (the panel's JSON)
    run_requested = Signal()
    pause_requested = Signal()
    resume_requested = Signal()
    stop_requested = Signal()
    tolerance_changed = Signal(float)  # mm, once it stops changing
    layers_changed = Signal(list)  # the DXF layers checked (names)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("programPanel")
        self._loaded = False
        self._running = False
        self._stopping = False  # Stop was pressed: the program ends now
        self._figures: tuple[int, int, int, float, float | None, int] | None = None
        self._blocked = ""  # why no program may start now ("": it may)
        self._offline = ""  # why there is no device to run it on ("": connected)
        self._unknown = ""  # why the stage's position is not known ("": it is)
        self._refused = ""  # why this program cannot run ("": it can)
        self._loading = False
        self._saveable = False
        self.file_label = QLabel(self.tr(NO_PROGRAM))
        self.file_label.setObjectName("programFile")
        self.file_label.setWordWrap(True)
        self.load_button = make_button(
            self.tr("&Load…"),
            "programLoad",
            self.tr(
                "Load a program: G-code, DXF or SVG, or points (CSV with x,y,z,speed in mm "
                "and mm/s, or JSON)"
            ),
        )
        self._save_tip = self.tr("Save the loaded program as JSON (x, y, z, speed per point)")
        self.save_button = make_button(self.tr("Save…"), "programSave", self._save_tip)
        self._run_tip = self.tr("Run the program on the device (checked against the box first)")
        self.run_button = make_button(self.tr("&Run"), "programRun", self._run_tip)
        self.pause_button = make_button(self.tr("P&ause"), "programPause", "")
        self.set_pause_meaning(None)
        self.stop_button = make_button(
            self.tr("&Stop"),
            "programStop",
            self.tr("Send nothing more and stop the device (its queue flushed)"),
        )
        self.tolerance = QDoubleSpinBox()
        self.tolerance.setObjectName("programTolerance")
        self.tolerance.setDecimals(3)
        self.tolerance.setRange(0.001, 1.0)
        self.tolerance.setSingleStep(0.005)
        self.tolerance.setValue(TOLERANCE_DEFAULT)
        self.tolerance.setSuffix(self.tr(" mm"))
        wheel_needs_focus(self.tolerance)
        self.tolerance.setToolTip(
            self.tr(
                "Chord tolerance: how far the straight moves an arc or curve is cut into may "
                "stray from it"
            )
        )
        self._tolerance_timer = QTimer(self)
        self._tolerance_timer.setSingleShot(True)
        self._tolerance_timer.setInterval(TOLERANCE_SETTLE_MS)
        self._tolerance_timer.timeout.connect(
            lambda: self.tolerance_changed.emit(self.tolerance.value())
        )
        self.tolerance.valueChanged.connect(lambda _value: self._tolerance_timer.start())
        self.progress = QProgressBar()
        self.progress.setObjectName("programProgress")
        self.progress.setToolTip(self.tr("Instructions executed by the device"))
        self.progress.setFormat(self.tr("%v / %m executed"))
        self.figures = QLabel()
        self.figures.setObjectName("programFigures")
        self.figures.setWordWrap(True)
        self.summary = QLabel()
        self.summary.setObjectName("programSummary")
        self.summary.setWordWrap(True)
        self.notices = QLabel()
        self.notices.setObjectName("programNotices")
        self.notices.setWordWrap(True)
        self.notices.hide()
        self.line_model = ProgramLines(self)
        self.lines = QListView()
        self.lines.setObjectName("programLines")
        self.lines.setModel(self.line_model)
        self.lines.setUniformItemSizes(True)
        self.lines.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.lines.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.lines.setFocusPolicy(Qt.FocusPolicy.NoFocus)  # the arrow keys stay with jogging
        self.lines.setMinimumHeight(90)
        self.lines.setToolTip(self.tr("The program's lines; the one under way is highlighted"))
        self.layer_model = QStandardItemModel(self)
        self.layers = QListView()
        self.layers.setObjectName("programLayers")
        self.layers.setModel(self.layer_model)
        self.layers.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.layers.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.layers.setToolTip(self.tr("The drawing's layers: the checked ones are run"))
        self.layers.setMaximumWidth(180)
        self.layers.hide()
        self.layer_model.itemChanged.connect(
            lambda _item: self.layers_changed.emit(self.checked_layers())
        )
        self.load_button.clicked.connect(self._load)
        self.save_button.clicked.connect(self._save)
        self.run_button.clicked.connect(self.run_requested)
        self.pause_button.clicked.connect(self._pause_clicked)
        self.stop_button.clicked.connect(self._stop_clicked)
        buttons = QHBoxLayout()
        for button in (
            self.load_button,
            self.save_button,
            self.run_button,
            self.pause_button,
            self.stop_button,
        ):
            buttons.addWidget(button)
        grid = QGridLayout()
        grid.addWidget(QLabel(self.tr("Program:")), 0, 0)
        grid.addWidget(self.file_label, 0, 1)
        tolerance_label = QLabel(self.tr("Chord tolerance:"))
        tolerance_label.setBuddy(self.tolerance)
        grid.addWidget(tolerance_label, 1, 0)
        grid.addWidget(self.tolerance, 1, 1, Qt.AlignmentFlag.AlignLeft)
        grid.setColumnStretch(1, 1)
        controls = QVBoxLayout()
        controls.addLayout(grid)
        controls.addLayout(buttons)
        controls.addWidget(self.progress)
        controls.addWidget(self.figures)
        controls.addWidget(self.summary)
        controls.addWidget(self.notices)
        controls.addStretch(1)
        layout = QHBoxLayout(self)  # the lines beside the controls: seen in a low dock too
        layout.addLayout(controls, 3)
        layout.addWidget(self.lines, 2)
        layout.addWidget(self.layers)
        self._paused = False
        self.set_program("", 0)
        self.set_running(False)

    # -- files ---------------------------------------------------------------------------------
    def _choose_path(self) -> str:
        path, _ = QFileDialog.getOpenFileName(
            self, self.tr("Load a program"), "", self.tr(PROGRAM_FILTER)
        )
        return path

    def _choose_save_path(self) -> str:
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Save the program"), "", self.tr("JSON (*.json)")
        )
        return path if not path or path.endswith(".json") else path + ".json"

    def _save(self) -> None:
        path = self._choose_save_path()
        if path:
            self.save_requested.emit(path)

    def _load(self) -> None:
        path = self._choose_path()
        if path:
            self.load_requested.emit(path)

    # -- buttons -------------------------------------------------------------------------------
    def _stop_clicked(self) -> None:
        self._stopping = True  # no time left is shown any more: the program ends now
        self._show_figures()
        self.stop_requested.emit()

    def _pause_clicked(self) -> None:
        if self._paused:
            self.resume_requested.emit()
        else:
            self.pause_requested.emit()

    # -- the program ---------------------------------------------------------------------------
    def set_loading(self, name: str) -> None:
        """A file is being read: say so; Run off until it is in."""
        self._loading = True
        self.file_label.setText(fill(self.tr("reading %1…"), name))
        self._show_run()

    def set_program(
        self, name: str, points: int, kind: str = "point", instructions: int | None = None
    ) -> None:
        """Show the loaded program (an empty name: none) and its count of `kind` ("point",
        "line", "entity", "element": what its sources are); the progress counts
        `instructions` (what a run will count; default `points`). The last run's figures go."""
        self._loading = False
        self.clear_figures()
        self._loaded = bool(name)
        if name:
            counts = {
                "line": self.tr("%1 (%2 lines)"),
                "entity": self.tr("%1 (%2 entities)"),
                "element": self.tr("%1 (%2 elements)"),
            }
            template = counts.get(kind, self.tr("%1 (%2 points)"))
            self.file_label.setText(fill(template, name, points))
        else:
            self.file_label.setText(self.tr(NO_PROGRAM))
            self.set_lines([])
            self.summary.clear()
            self.set_notices([])
        self.progress.setRange(0, max(points if instructions is None else instructions, 1))
        self.progress.setValue(0)
        self.progress.setFormat(self.tr("%v / %m executed") if name else self.tr("no program"))
        self._show_run()
        self.set_saveable(bool(name))

    def set_lines(self, sources: Sequence[SourceLine]) -> None:
        """List the program's lines (drivers.toolpath.Source: kind, number, text)."""
        labels = {
            "line": self.tr("line %1"),
            "entity": self.tr("entity %1"),
            "element": self.tr("element %1"),
            "point": self.tr("point %1"),
        }
        self.line_model.set_sources(sources, labels)

    def show_line(self, row: int | None) -> None:
        """Highlight the line under way (a row of the list; None: none) and scroll to it."""
        if row is None or not 0 <= row < self.line_model.rowCount():
            self.lines.clearSelection()
            return
        index = self.line_model.index(row, 0)
        if self.lines.currentIndex() == index:
            return
        self.lines.setCurrentIndex(index)
        self.lines.scrollTo(index, QAbstractItemView.ScrollHint.EnsureVisible)

    def current_line(self) -> int | None:
        """The row of the line highlighted (None: none)."""
        index = self.lines.currentIndex()
        return index.row() if index.isValid() else None

    def show_summary(
        self,
        length: float,
        travel: float,
        low: tuple[float, float, float],
        high: tuple[float, float, float],
        seconds: float,
        speed: float,
        segments: int,
    ) -> None:
        """The program's figures: length (travel part), box, time at `speed` mm/s, segments."""
        whole = round(seconds)
        clock = f"{whole // 3600}:{whole // 60 % 60:02d}:{whole % 60:02d}"
        lines = [
            fill(
                self.tr("length %1 mm (travel moves %2 mm), %3 segments"),
                f"{length:.1f}",
                f"{travel:.1f}",
                segments,
            ),
            fill(
                self.tr("box X %1 to %2, Y %3 to %4, Z %5 to %6 mm"),
                *(f"{value:.3g}" for pair in zip(low, high, strict=True) for value in pair),
            ),
            fill(
                self.tr("about %1 (h:mm:ss) at %2 mm/s where the program sets no speed"),
                clock,
                f"{speed:g}",
            ),
        ]
        self.summary.setText("\n".join(lines))

    def set_notices(self, notices: Sequence[str]) -> None:
        """What reading the file noticed (skipped codes, units assumed...); none: hidden."""
        self.notices.setText("\n".join(notices))
        self.notices.setVisible(bool(notices))

    def set_layers(self, layers: Sequence[str], chosen: Collection[str] | None) -> None:
        """The drawing's layers, `chosen` checked (None: all); none: the list is hidden."""
        model = self.layer_model
        model.blockSignals(True)
        model.clear()
        for name in layers:
            item = QStandardItem(name)
            item.setEditable(False)
            item.setCheckable(True)
            checked = chosen is None or name in chosen
            item.setCheckState(Qt.CheckState.Checked if checked else Qt.CheckState.Unchecked)
            model.appendRow(item)
        model.blockSignals(False)
        self.layers.reset()
        self.layers.setVisible(bool(layers))

    def checked_layers(self) -> list[str]:
        """The layers checked in the list."""
        model = self.layer_model
        items = (model.item(row) for row in range(model.rowCount()))
        return [i.text() for i in items if i.checkState() == Qt.CheckState.Checked]

    def set_saveable(self, saveable: bool, reason: str = "") -> None:
        """Save… on (a program of points) or off, saying why in its tooltip."""
        self._saveable = saveable
        self.save_button.setEnabled(saveable and not self._running)
        tip = self._save_tip
        if reason:
            tip = fill(self.tr("%1\nNot for this program: %2"), tip, reason)
        self.save_button.setToolTip(tip)

    def set_refused(self, reason: str) -> None:
        """Why the program loaded cannot run (it leaves the travel box...), in red and in
        Run's tooltip; "": it can."""
        self._refused = reason
        if reason:
            self.show_error(reason)
        elif self.figures.styleSheet():
            self.figures.clear()
            self.figures.setStyleSheet("")
        self._show_run()

    def refused(self) -> str:
        """Why the program loaded cannot run ("": it can)."""
        return self._refused

    def show_error(self, text: str) -> None:
        """A load or run problem, in red (it stays until the next progress)."""
        self._figures = None
        self.figures.setStyleSheet(ERROR_STYLE)
        self.figures.setText(text)

    # -- running -------------------------------------------------------------------------------
    def set_running(self, running: bool) -> None:
        """While a program runs: Run, Load, Save and the options off; Pause and Stop on."""
        self._running = running
        self._stopping = False
        for widget in (self.load_button, self.tolerance, self.layers):
            widget.setEnabled(not running)
        self.save_button.setEnabled(self._saveable and not running)
        self._show_run()
        self.pause_button.setEnabled(running)
        self.stop_button.setEnabled(running)
        if not running:
            self.set_paused(False)

    def set_connected(self, connected: bool) -> None:
        """Whether a device is connected to run a program on: Run off without one, saying so."""
        self._offline = "" if connected else self.tr("not connected to a device")
        self._show_run()

    def set_position_unknown(self, reason: str) -> None:
        """Run off while the position is unknown (a program's coordinates are absolute), with
        `reason` in its tooltip ("": known)."""
        self._unknown = reason
        self._show_run()

    def clear_figures(self) -> None:
        """The last run's counts and time go (another program, another device); the progress
        bar back to 0. An error shown stays."""
        self.progress.setValue(0)
        if self._figures is not None:
            self._figures = None
            self.figures.clear()

    def set_allowed(self, allowed: bool, reason: str = "") -> None:
        """Whether a program may start now (not while a macro or a parameter write runs), and
        why not: said in Run's tooltip."""
        self._blocked = "" if allowed else reason or self.tr("motion is off")
        self._show_run()

    def _show_run(self) -> None:
        self.run_button.setEnabled(
            self._loaded
            and not self._loading
            and not self._running
            and not self._blocked
            and not self._refused
            and not self._offline
            and not self._unknown
        )
        tip = self._run_tip
        if self._refused:
            tip = fill(self.tr("%1\nRefused: %2"), tip, self._refused)
        for reason in (self._offline, self._unknown, self._blocked):
            if reason:
                tip = fill(self.tr("%1\nNot now: %2"), tip, reason)
        self.run_button.setToolTip(tip)

    def set_pause_meaning(self, queued: bool | None) -> None:
        """Say in Pause's tooltip what it really does on the device connected: `queued` where
        the device runs a queue of moves it was sent (laser-frame), False where it takes one
        move at a time, None with no device. No protocol here has a feed hold."""
        if queued is None:
            tip = self.tr("Send nothing more until Resume (a device's queued moves go on)")
        elif queued:
            tip = self.tr(
                "Send nothing more until Resume. This device has no feed hold: it goes on "
                "running the moves it already holds (the status line says how many, and when "
                "it stands still); Stop flushes them"
            )
        else:
            tip = self.tr(
                "Send nothing more until Resume. The move under way finishes, then the stage "
                "stands still (this device has no feed hold)"
            )
        self.pause_button.setToolTip(tip)

    def set_paused(self, paused: bool) -> None:
        """Show Pause or Resume (and "paused" instead of the time left)."""
        self._paused = paused
        self.pause_button.setText(self.tr("Resume") if paused else self.tr("P&ause"))
        self._show_figures()

    def show_progress(
        self,
        sent: int,
        acknowledged: int,
        executed: int,
        rate: float,
        seconds_left: float | None,
        retransmissions: int,
        total: int | None = None,
    ) -> None:
        """Counts, rate, and the time left while the program runs ("paused" while paused;
        nothing once it is stopped or has ended); `total`: the instructions in all."""
        if total is not None and total != self.progress.maximum():
            self.progress.setRange(0, max(total, 1))
        self.progress.setValue(executed)
        self._figures = (sent, acknowledged, executed, rate, seconds_left, retransmissions)
        self._show_figures()

    def _show_figures(self) -> None:
        if self._figures is None:
            return
        sent, acknowledged, executed, rate, seconds_left, retransmissions = self._figures
        if not self._running or self._stopping:
            left = ""
        elif self._paused:
            left = self.tr(", paused")
        elif seconds_left is not None:
            left = fill(self.tr(", about %1 s left"), f"{seconds_left:.0f}")
        else:
            left = ""
        self.figures.setStyleSheet("")
        self.figures.setText(
            fill(
                self.tr(
                    "sent %1, acknowledged %2, executed %3; %4 instructions/s%5; "
                    "%6 retransmission(s)"
                ),
                sent,
                acknowledged,
                executed,
                f"{rate:.0f}",
                left,
                retransmissions,
            )
        )
