"""A program of points: load it, see it, stream it with progress, pause, resume and stop."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, Signal
from PySide6.QtWidgets import (
    QFileDialog,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QProgressBar,
    QVBoxLayout,
    QWidget,
)

from widgets._buttons import make_button
from widgets._i18n import fill

PROGRAM_FILTER = QT_TRANSLATE_NOOP("ProgramPanel", "Programs (*.csv *.json);;All files (*)")
NO_PROGRAM = QT_TRANSLATE_NOOP("ProgramPanel", "no program loaded")  # both translated at use


class ProgramPanel(QWidget):
    """Buttons and progress for streaming; the app loads files and runs the stream."""

    load_requested = Signal(str)  # a path
    save_requested = Signal(str)  # a path (the panel's JSON)
    run_requested = Signal()
    pause_requested = Signal()
    resume_requested = Signal()
    stop_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("programPanel")
        self._loaded = False
        self._running = False
        self._stopping = False  # Stop was pressed: the program is ending
        self._figures: tuple[int, int, int, float, float | None, int] | None = None
        self._blocked = ""  # why a program cannot start now ("": it can)
        self.file_label = QLabel(self.tr(NO_PROGRAM))
        self.file_label.setObjectName("programFile")
        self.file_label.setWordWrap(True)
        self.load_button = make_button(
            self.tr("&Load…"),
            "programLoad",
            self.tr("Load a program: CSV with x,y,z,speed (mm, mm/s) or JSON"),
        )
        self.save_button = make_button(
            self.tr("Save…"),
            "programSave",
            self.tr("Save the loaded program as JSON (x, y, z, speed per point)"),
        )
        self._run_tip = self.tr("Stream the program to the device, 7 moves a frame")
        self.run_button = make_button(self.tr("&Run"), "programRun", self._run_tip)
        self.pause_button = make_button(
            self.tr("P&ause"),
            "programPause",
            self.tr("Send nothing more until Resume (queued moves go on)"),
        )
        self.stop_button = make_button(
            self.tr("&Stop"),
            "programStop",
            self.tr("Send nothing more and flush the device's queue (STOP)"),
        )
        self.progress = QProgressBar()
        self.progress.setObjectName("programProgress")
        self.progress.setToolTip(self.tr("Instructions executed by the device"))
        self.progress.setFormat(self.tr("%v / %m executed"))
        self.figures = QLabel()
        self.figures.setObjectName("programFigures")
        self.figures.setWordWrap(True)
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
        grid.setColumnStretch(1, 1)
        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addLayout(buttons)
        layout.addWidget(self.progress)
        layout.addWidget(self.figures)
        layout.addStretch(1)
        self._paused = False
        self.set_program("", 0)
        self.set_running(False)

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

    def _stop_clicked(self) -> None:
        self._stopping = True  # no time left is shown any more: the program ends now
        self._show_figures()
        self.stop_requested.emit()

    def _pause_clicked(self) -> None:
        if self._paused:
            self.resume_requested.emit()
        else:
            self.pause_requested.emit()

    def set_program(self, name: str, points: int) -> None:
        """Show the loaded program (an empty name: none)."""
        self._loaded = bool(name)
        if name:
            self.file_label.setText(fill(self.tr("%1 (%2 points)"), name, points))
        else:
            self.file_label.setText(self.tr(NO_PROGRAM))
        self.progress.setRange(0, max(points, 1))
        self.progress.setValue(0)
        self.progress.setFormat(self.tr("%v / %m executed") if name else self.tr("no program"))
        self._show_run()
        self.save_button.setEnabled(bool(name))

    def show_error(self, text: str) -> None:
        """A load or run problem, in red (it stays until the next progress)."""
        self._figures = None
        self.figures.setStyleSheet("color: #c62828;")
        self.figures.setText(text)

    def set_running(self, running: bool) -> None:
        """While streaming: Run and Load off, Pause and Stop on."""
        self._running = running
        self._stopping = False
        self.load_button.setEnabled(not running)
        self._show_run()
        self.pause_button.setEnabled(running)
        self.stop_button.setEnabled(running)
        if not running:
            self.set_paused(False)

    def set_allowed(self, allowed: bool, reason: str = "") -> None:
        """Whether a program may start now (not while a macro or a parameter write runs), and
        why not: said in Run's tooltip."""
        self._blocked = "" if allowed else reason or self.tr("motion is off")
        self._show_run()

    def _show_run(self) -> None:
        self.run_button.setEnabled(self._loaded and not self._running and not self._blocked)
        tip = self._run_tip
        if self._blocked:
            tip = fill(self.tr("%1\nNot now: %2"), tip, self._blocked)
        self.run_button.setToolTip(tip)

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
    ) -> None:
        """Counts, rate, and the time left while the program runs ("paused" while paused;
        nothing once it is stopped or has ended)."""
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
