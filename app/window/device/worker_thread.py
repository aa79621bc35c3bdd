"""Running a SerialWorker on its own QThread, and stopping it cleanly."""

from __future__ import annotations

from PySide6.QtCore import QObject, QThread, Signal

from app.window.device.worker import SerialWorker


class WorkerThread(QObject):
    """Owns a QThread with a SerialWorker in it; the GUI calls these methods, never the port."""

    open_requested = Signal(str, str, int, object)
    close_requested = Signal()
    shutdown_requested = Signal()
    travel_requested = Signal(object)
    session_log_requested = Signal(object)
    control_line_requested = Signal(str, bool)
    break_requested = Signal()
    poll_rates_requested = Signal(float, float)
    note_requested = Signal(str)

    def __init__(self, worker: SerialWorker | None = None, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.worker = worker or SerialWorker()
        self.thread = QThread()
        self.thread.setObjectName("serialWorker")
        self.worker.moveToThread(self.thread)
        self.thread.started.connect(self.worker.start)
        self.open_requested.connect(self.worker.open_port)
        self.close_requested.connect(self.worker.close_port)
        self.shutdown_requested.connect(self.worker.shutdown)
        self.travel_requested.connect(self.worker.set_travel)
        self.session_log_requested.connect(self.worker.set_session_log)
        self.control_line_requested.connect(self.worker.set_control_line)
        self.break_requested.connect(self.worker.send_break)
        self.poll_rates_requested.connect(self.worker.set_poll_rates)
        self.note_requested.connect(self.worker.add_note)
        self.thread.start()

    def open(self, url: str, protocol: str, baud: int, options: object = None) -> None:
        """Ask the worker to connect (`options`: a ConnectOptions, or None for the defaults)."""
        self.worker.abort_clear()
        self.open_requested.emit(url, protocol, baud, options)

    def set_session_log(self, stream: object) -> None:
        """Hand the worker the session log's stream (it writes it from then on)."""
        self.session_log_requested.emit(stream)

    def set_travel(self, limits: object) -> None:
        """Ask the worker to use these travel limits (a TravelLimits, or None)."""
        self.travel_requested.emit(limits)

    def set_control_line(self, name: str, on: bool) -> None:
        """Ask the worker to drive DTR or RTS (between jobs)."""
        self.control_line_requested.emit(name, on)

    def send_break(self) -> None:
        """Ask the worker to send a 250 ms break (between jobs)."""
        self.break_requested.emit()

    def set_poll_rates(self, moving_hz: float, idle_s: float) -> None:
        """Ask the worker to poll at these rates from now on."""
        self.poll_rates_requested.emit(moving_hz, idle_s)

    def note(self, text: str) -> None:
        """Write a note (English) into the session log."""
        self.note_requested.emit(text)

    def stream_pause(self, paused: bool) -> None:
        """Pause or resume the program under way."""
        self.worker.stream_pause(paused)

    def stream_stop(self) -> None:
        """Stop the program under way (the device's queue is flushed)."""
        self.worker.stream_stop()

    def close(self) -> None:
        """Ask the worker to disconnect (a wait in progress is abandoned)."""
        self.worker.cancel_pending()
        self.worker.abort()
        self.close_requested.emit()

    def stop(self, timeout_ms: int = 5000) -> bool:
        """Shut the worker down and end the thread; True when it ended in time."""
        if not self.thread.isRunning():
            return True
        self.worker.cancel_pending()
        self.worker.abort()
        self.shutdown_requested.emit()  # the worker quits its thread when done
        return self.thread.wait(timeout_ms)
