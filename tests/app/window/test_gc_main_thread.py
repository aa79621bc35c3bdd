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


def test_a_full_collection_waits_while_the_window_is_behind(qtbot, monkeypatch) -> None:
    """A full collection walks every live object (a traffic backlog's too): while the window
    catches up it waits, the young generations still collected, for FULL_DEFERRED_S at most."""
    from app.window import gc_main_thread

    collector = MainThreadCollector(interval_ms=60_000)  # called by hand here
    behind = [True]
    collector.behind = lambda: behind[0]
    full: list[int] = []
    monkeypatch.setattr(gc_main_thread.gc, "get_count", lambda: (800, 20, 20))
    monkeypatch.setattr(
        gc_main_thread.gc, "collect", lambda generation=2: full.append(generation) or 0
    )
    now = [100.0]
    monkeypatch.setattr(gc_main_thread.time, "monotonic", lambda: now[0])
    collector.collect()
    now[0] += gc_main_thread.FULL_DEFERRED_S - 1
    collector.collect()
    assert full == [1, 1]  # deferred
    now[0] += 2  # waited long enough: the full collection runs, behind or not
    collector.collect()
    behind[0] = False
    collector.collect()
    assert full == [1, 1, 2, 2]
    collector.deleteLater()


def test_a_burst_taken_in_while_behind_is_set_aside_not_walked(qtbot) -> None:
    """Real objects, the real collector: a burst of young objects while the window is behind
    is frozen (walked by no collection, now or later); the same burst while the window keeps
    up is collected as usual."""
    from app.window import gc_main_thread

    collector = MainThreadCollector(interval_ms=60_000)  # called by hand here
    gc.collect()
    behind = [False]
    collector.behind = lambda: behind[0]
    try:
        kept = [[index] for index in range(gc_main_thread.BURST_OBJECTS + 10)]
        collector.collect()
        assert gc.get_freeze_count() == 0 and collector.bursts_set_aside == 0  # walked
        behind[0] = True
        kept += [[index] for index in range(gc_main_thread.BURST_OBJECTS + 10)]
        frozen_before = gc.get_freeze_count()
        assert collector.collect() == 0
        assert collector.bursts_set_aside == 1
        assert gc.get_freeze_count() >= frozen_before + gc_main_thread.BURST_OBJECTS
        assert gc.get_count()[0] < gc.get_threshold()[0]  # nothing young left to walk
        collector.collect()
        assert collector.bursts_set_aside == 1  # no burst since
    finally:
        del kept
        gc.unfreeze()
        collector.deleteLater()
