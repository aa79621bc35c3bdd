"""Faults on the line, for every protocol, seen in the window: a device that hangs, restarts,
sends noise, answers slowly or with another command's reply, or vanishes.

Each simulator runs in its own process on a real pty (`motionsim --control`), and the fault is
applied while the window talks to it. The window must end in a clear state, list the commands it
dropped, and, once the device answers again, re-read the position (or say that it is unknown).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from PySide6.QtCore import QObject, Slot
from PySide6.QtWidgets import QLabel, QPushButton

from app.window.device import jobs
from app.window.main_window import MainWindow
from drivers.protocols.registry import get_protocol_class
from tests.support.relay import wait_in_gui
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60)]

ANSWERING = ("coxiris", "laser-frame", "visiomex", "firmata")  # pi-frame never answers
FEEDBACK = ("coxiris", "laser-frame")  # the others' positions are only commanded
WAIT_MS = 20_000


class States(QObject):
    """Every connection state the worker reports, received in the GUI thread."""

    def __init__(self, window: MainWindow) -> None:
        super().__init__(window)
        self.seen: list[tuple[str, str]] = []
        self.ended = 0  # jobs finished or failed
        window.worker.state_changed.connect(self.add)
        window.worker.job_finished.connect(self.job_ended)
        window.worker.job_failed.connect(self.job_ended)

    @Slot(str, str)
    def add(self, state: str, detail: str) -> None:
        """Keep one state change."""
        self.seen.append((state, detail))

    @Slot(object, object)
    def job_ended(self, job: object, result: object) -> None:
        """Count a job that ended, either way."""
        self.ended += 1

    def errors(self) -> list[str]:
        """The details of every error state so far."""
        return [detail for state, detail in self.seen if state == "error"]


@contextmanager
def device(qtbot, window: MainWindow, protocol: str, *args: str) -> Iterator[SimProcess]:
    """`motionsim --control PROTOCOL --instant` with the window connected to it."""
    sim = SimProcess(protocol, "--instant", *args, control=True)
    port = args[args.index("--link") + 1] if "--link" in args else sim.path  # its own name
    try:
        with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
            window.connect_device(port, protocol, get_protocol_class(protocol).default_baud())
        window.worker.poll_idle_s = 0.2  # the idle position reads, sooner than the 1 s default
        if protocol == "firmata":  # the stepper is configured from its panel first
            window.findChild(QPushButton, "firmataConfigure").click()
            label = window.devices.firmata.findChild(QLabel, "firmataVersionLabel")
            qtbot.waitUntil(lambda: label.text() == "5", timeout=WAIT_MS)
        if protocol == "pi-frame":  # absolute targets: a jog needs a known place first
            with wait_in_gui(qtbot, window.worker.job_finished, timeout=WAIT_MS):
                window.coordinates.go_requested.emit("absolute", (0.0, 0.0, 0.0))
        yield sim
    finally:
        window.disconnect_device()
        if sim.proc.poll() is None:
            sim.stop()


def jog(qtbot, window: MainWindow, distance: float = 1.0) -> None:
    """One jog step along X, waited for."""
    with wait_in_gui(qtbot, window.worker.job_finished, timeout=WAIT_MS):
        window.jog_panel.jog_requested.emit("x", distance)


def wait_connected(qtbot, window: MainWindow) -> None:
    """Until the window is connected with its motion controls on."""
    qtbot.waitUntil(
        lambda: window.connection_bar.state() == "connected" and window.jog_panel.isEnabled(),
        timeout=WAIT_MS,
    )


def first_error(qtbot, states: States) -> str:
    """Until the worker reports an error state; its detail."""
    qtbot.waitUntil(lambda: bool(states.errors()), timeout=WAIT_MS)
    return states.errors()[0]


def console_text(window: MainWindow) -> str:
    """Everything the console shows, notes included."""
    window.console.flush()
    return window.console.text()


def received_bytes(window: MainWindow) -> int:
    """Bytes the console has shown as received."""
    window.console.flush()
    return sum(len(data) for direction, data, _ in window.console.records() if direction == "rx")


def assert_position_truthful(window: MainWindow, protocol: str, expected: float) -> None:
    """Re-read from the device where it can say; otherwise shown as unknown."""
    if protocol in FEEDBACK:
        assert window.readout.status() == "live"
        assert window.readout.position() == pytest.approx((expected, 0.0, 0.0))
    else:
        assert window.readout.status() == "lost"
        assert "position is unknown" in console_text(window)


@pytest.mark.parametrize("protocol", ANSWERING)
def test_a_device_that_stops_answering_is_an_error_then_found_again(
    qtbot, window: MainWindow, protocol: str
) -> None:
    states = States(window)
    with device(qtbot, window, protocol) as sim:
        jog(qtbot, window, 2.0)
        sim.fault("hang")
        with wait_in_gui(qtbot, window.worker.job_failed, timeout=WAIT_MS):
            if protocol == "firmata":  # only its queries are answered; a step gets no reply
                window.submit_job(jobs.StepperVersionJob())
            else:
                window.jog_panel.jog_requested.emit("x", 1.0)
            window.submit_job(jobs.HomeJob())  # queued behind it: dropped and listed
        error = first_error(qtbot, states)
        assert "did not" in error and "not sent: go home" in error
        assert "not sent: go home" in console_text(window)
        sim.fault("resume")
        wait_connected(qtbot, window)
        # The jog under way when the device hung was read by it or not: only a re-read knows.
        if protocol in FEEDBACK:
            assert window.readout.position()[0] in (2.0, 3.0)
            assert window.readout.status() == "live"
        else:
            assert window.readout.status() == "lost"


@pytest.mark.parametrize("protocol", ANSWERING)
def test_a_restarted_device_is_seen_and_read_again(
    qtbot, window: MainWindow, protocol: str
) -> None:
    states = States(window)
    with device(qtbot, window, protocol) as sim:
        jog(qtbot, window, 2.0)
        sim.fault("reboot")
        assert "restarted" in first_error(qtbot, states)
        wait_connected(qtbot, window)
        assert_position_truthful(window, protocol, 0.0)
        jog(qtbot, window, 1.0)  # and it works again
        if protocol in FEEDBACK:
            assert window.readout.position() == pytest.approx((1.0, 0.0, 0.0))


@pytest.mark.parametrize("protocol", ("coxiris", "laser-frame", "visiomex", "firmata", "pi-frame"))
def test_noise_on_the_line_is_shown_and_the_device_still_works(
    qtbot, window: MainWindow, protocol: str
) -> None:
    states = States(window)
    with device(qtbot, window, protocol) as sim:
        received = received_bytes(window)
        sim.fault("garbage 300")
        qtbot.waitUntil(lambda: received_bytes(window) >= received + 300, timeout=WAIT_MS)
        jog(qtbot, window, 1.5)
        wait_connected(qtbot, window)
        assert not states.errors()
        if protocol in FEEDBACK:
            assert window.readout.position() == pytest.approx((1.5, 0.0, 0.0))


@pytest.mark.parametrize("protocol", ("coxiris", "visiomex"))
def test_a_slow_device_within_its_timeout_keeps_working(
    qtbot, window: MainWindow, protocol: str
) -> None:
    states = States(window)
    with device(qtbot, window, protocol) as sim:
        sim.fault("slow 0.4")
        jog(qtbot, window, 1.0)
        jog(qtbot, window, 1.0)
        assert not states.errors()
        assert window.connection_bar.state() == "connected"


def test_a_device_slower_than_its_timeout_is_lost_then_found(qtbot, window: MainWindow) -> None:
    states = States(window)
    with device(qtbot, window, "laser-frame") as sim:  # its replies are due within 0.25 s
        sim.fault("slow 0.6")
        with wait_in_gui(qtbot, window.worker.job_failed, timeout=WAIT_MS):
            window.jog_panel.jog_requested.emit("x", 1.0)
        assert "3 tries" in first_error(qtbot, states)
        sim.fault("slow 0")
        wait_connected(qtbot, window)
        assert window.readout.status() == "live"


@pytest.mark.parametrize("protocol", ("coxiris", "laser-frame", "visiomex"))
def test_a_reply_to_another_command_never_leaves_a_false_position(
    qtbot, window: MainWindow, protocol: str
) -> None:
    states = States(window)
    with device(qtbot, window, protocol) as sim:
        jog(qtbot, window, 1.0)
        sim.fault("wrong")
        ended = states.ended
        window.jog_panel.jog_requested.emit("x", 1.0)
        qtbot.waitUntil(lambda: states.ended > ended, timeout=WAIT_MS)
        wait_connected(qtbot, window)
        if protocol == "coxiris":  # its replies name their command: the stray one is skipped
            assert not states.errors()
        if protocol in FEEDBACK:
            assert window.readout.status() == "live"
            assert window.readout.position()[0] in (1.0, 2.0)


@pytest.mark.parametrize("protocol", ("coxiris", "laser-frame", "visiomex", "firmata", "pi-frame"))
def test_a_vanished_device_is_an_error_and_reconnects_when_back_slot_only(
    qtbot, window: MainWindow, protocol: str, tmp_path: Path
) -> None:
    """Only the window's slot for a port the port list shows again; the worker's own watch for
    a lost port is tested with real processes in test_reconnect_real.py. The device comes back
    under the same name (`--link`), as a USB adapter does: a pty of another number would be
    another port, so another device, whatever else ran beside the test."""
    states = States(window)
    link = str(tmp_path / "ttyDEVICE")
    with device(qtbot, window, protocol, "--link", link) as sim:
        jog(qtbot, window, 2.0)
        sim.fault("vanish")
        first_error(qtbot, states)
        assert not window.jog_panel.isEnabled()
        last = window.connection.last
        window.disconnect_device()  # the worker watches no more: only the slot reconnects
        qtbot.waitUntil(lambda: window.worker._watch is None, timeout=WAIT_MS)
        window.connection.last = last
        back = SimProcess(protocol, "--instant", "--link", link)
        try:
            assert window.connection.last[0] == link
            with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
                window.port_watcher.port_added.emit(link)
            wait_connected(qtbot, window)
            assert_position_truthful(window, protocol, 0.0)
        finally:
            window.disconnect_device()
            back.stop()


def test_another_device_after_a_lost_link_is_a_fresh_connection(qtbot, window: MainWindow) -> None:
    """COXIRIS vanishes; the operator then connects a Visiomex board: its position is unknown
    because nothing is counted yet (fresh), not because "the link failed"."""
    states = States(window)
    with device(qtbot, window, "coxiris") as sim:
        jog(qtbot, window, 2.0)
        sim.fault("vanish")
        first_error(qtbot, states)
        assert window.machine.link_failed
    with qtbot.waitSignal(window.settled, timeout=WAIT_MS):
        window.connect_device("sim://visiomex?instant=1", "visiomex", 9600, "seed")
    assert window.readout.status() == "uncounted"
    assert "Home or Set Home to start counting" in window.status_line.message()
    window.disconnect_device()
