"""The pacer: one heavy piece of GUI-thread work a turn of the event loop, a little apart."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QCoreApplication, QTimer

from widgets._pacer import RETRY_MS, Pacer, pacer, run_paced


@pytest.mark.timeout(30)
def test_one_slot_a_turn_freed_by_the_next_turn(qtbot) -> None:
    paced = Pacer(spacing=0.0)
    assert paced.take()
    assert paced.busy()
    assert not paced.take()  # the second job in the same turn waits
    QCoreApplication.sendPostedEvents(paced)  # the turn is over
    assert not paced.busy()
    assert paced.take()
    QCoreApplication.sendPostedEvents(paced)


@pytest.mark.timeout(30)
def test_jobs_are_spaced(qtbot) -> None:
    now = [10.0]
    paced = Pacer(spacing=0.006, clock=lambda: now[0])
    assert paced.take()
    QCoreApplication.sendPostedEvents(paced)
    now[0] += 0.002
    assert not paced.take()  # a new turn, but too soon after the last job
    assert paced.wait_ms() == 4
    now[0] += 0.004
    assert paced.take()
    QCoreApplication.sendPostedEvents(paced)


@pytest.mark.timeout(30)
def test_a_refused_job_tries_again_on_its_timer(qtbot) -> None:
    QCoreApplication.sendPostedEvents(pacer())
    pacer().spacing, spacing = 0.0, pacer().spacing
    try:
        timer = QTimer()
        timer.setSingleShot(True)
        assert run_paced(timer)
        assert not timer.isActive()
        assert not run_paced(timer)  # the same turn
        assert timer.isActive() and timer.interval() == RETRY_MS
        timer.stop()
    finally:
        pacer().spacing = spacing
        QCoreApplication.sendPostedEvents(pacer())
