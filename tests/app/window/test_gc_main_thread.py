"""Cyclic garbage is collected by a GUI-thread timer, not by whichever thread allocates."""

from __future__ import annotations

import gc

import pytest

from app.window.gc_main_thread import MainThreadCollector, collect_for

pytestmark = pytest.mark.timeout(30)


class _Cycle:
    def __init__(self) -> None:
        self.me = self


def test_automatic_collection_is_off_and_the_timer_collects(qtbot) -> None:
    collector = MainThreadCollector(interval_ms=10)
    assert not gc.isenabled()
    gc.collect()
    for _ in range(gc.get_threshold()[0] + 10):
        _Cycle()  # unreachable at once, freed only by a collection
    assert gc.get_count()[0] > gc.get_threshold()[0]
    qtbot.waitUntil(lambda: gc.get_count()[0] < gc.get_threshold()[0], timeout=5000)
    assert collector.collect() == 0  # nothing left past a threshold
    collector.deleteLater()


def test_settling_sets_the_start_up_objects_aside(qtbot) -> None:
    from PySide6.QtCore import QObject, Signal

    class Window(QObject):
        ready = Signal()

    window = Window()
    collector = collect_for(window, window.ready)
    try:
        assert gc.get_freeze_count() == 0
        window.ready.emit()
        assert gc.get_freeze_count() > 0  # a full collection no longer walks them
    finally:
        gc.unfreeze()
        collector.deleteLater()
