"""The console's feed: what arrives joins what waits in time order, a turn's work bounded."""

from __future__ import annotations

from collections import deque

import pytest
from PySide6.QtCore import QObject

from app.window.console.pacing import ARRIVALS_A_TURN, FeedPacer
from drivers.link.records import Note, Record, Traffic

pytestmark = pytest.mark.timeout(30)
_OWNERS: list[QObject] = []  # the pacers' parents, kept for the tests' length


def _pacer(qapp, taken: list[Record], per_turn: int | None = None) -> FeedPacer:
    def take(pending: deque[Record], deadline: float | None) -> int:
        count = len(pending) if per_turn is None else min(per_turn, len(pending))
        taken.extend(list(pending)[:count])
        return count

    _OWNERS.append(QObject())
    return FeedPacer(_OWNERS[-1], take, lambda: None)


def test_records_are_taken_in_time_order_ties_in_arrival_order(qapp) -> None:
    taken: list[Record] = []
    pacer = _pacer(qapp, taken)
    note = Note("connected", 2.0)
    pacer.add(note)  # stamped when added: later than traffic batched before it
    batch = [Traffic("tx", b"A\n", 1.0), Traffic("rx", b"B\n", 2.0), Traffic("rx", b"C\n", 3.0)]
    pacer.extend(batch)
    pacer.flush()
    assert taken == [batch[0], note, batch[1], batch[2]]
    assert pacer.backlog() == 0


def test_a_burst_is_put_in_order_a_bounded_number_a_turn(qapp) -> None:
    taken: list[Record] = []
    pacer = _pacer(qapp, taken, per_turn=1000)
    burst = [Traffic("rx", b"x\n", float(i)) for i in range(3 * ARRIVALS_A_TURN)]
    pacer.extend(burst)
    pacer.take_pending(0.001)
    assert len(pacer.pending) == ARRIVALS_A_TURN - 1000  # the rest still arriving
    assert len(pacer.incoming) == 2 * ARRIVALS_A_TURN
    while pacer.backlog():
        pacer.take_pending(0.001)
    assert taken == burst
    assert pacer.records() == burst[-len(pacer.records()) :]
