"""PositionBuffer: order, wrap-around, no copies, bounded memory."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from widgets.position_buffer import DEFAULT_CAPACITY, PositionBuffer


def test_empty() -> None:
    buffer = PositionBuffer()
    assert buffer.capacity == DEFAULT_CAPACITY == 20_000
    assert len(buffer) == 0
    assert buffer.view().shape == (0, 4)
    assert buffer.last() is None


def test_appends_in_order_without_copying() -> None:
    buffer = PositionBuffer(capacity=10)
    for i in range(4):
        buffer.append(i, i + 0.1, i + 0.2, i + 0.3)
    view = buffer.view()
    assert view.shape == (4, 4)
    assert view[:, 0].tolist() == [0, 1, 2, 3]
    assert view[2].tolist() == pytest.approx([2, 2.1, 2.2, 2.3])
    assert np.shares_memory(view, buffer._data)  # a view of the storage, not a copy
    assert buffer.last() == pytest.approx((3, 3.1, 3.2, 3.3))


def test_wraparound_keeps_the_newest_oldest_first() -> None:
    buffer = PositionBuffer(capacity=5)
    for i in range(12):
        buffer.append(i, -i, 2 * i, 0)
        assert buffer.view()[:, 0].tolist() == list(range(max(0, i - 4), i + 1))
    assert len(buffer) == 5
    view = buffer.view()
    assert view[:, 1].tolist() == [-7, -8, -9, -10, -11]
    assert np.shares_memory(view, buffer._data)  # still no copy after wrapping


def test_view_is_read_only() -> None:
    buffer = PositionBuffer(capacity=3)
    buffer.append(0, 1, 2, 3)
    with pytest.raises(ValueError):
        buffer.view()[0, 0] = 5


def test_memory_is_bounded() -> None:
    buffer = PositionBuffer(capacity=100)
    storage = buffer._data
    for i in range(1000):
        buffer.append(i, i, i, i)
    assert buffer._data is storage
    assert storage.nbytes == 2 * 100 * 4 * 8
    assert len(buffer) == 100


def test_clear_and_version() -> None:
    buffer = PositionBuffer(capacity=4)
    v0 = buffer.version
    buffer.append(0, 1, 2, 3)
    buffer.append(1, 4, 5, 6)
    assert buffer.version == v0 + 2
    buffer.clear(keep_last=True)
    assert buffer.view().tolist() == [[1, 4, 5, 6]]
    buffer.clear()
    assert len(buffer) == 0
    assert buffer.version > v0 + 2


def test_bad_capacity() -> None:
    with pytest.raises(ValueError):
        PositionBuffer(capacity=0)


@settings(max_examples=60, deadline=None)
@given(
    capacity=st.integers(1, 8),
    ops=st.lists(st.one_of(st.floats(-1e6, 1e6), st.none()), max_size=40),
)
def test_matches_a_list_model(capacity: int, ops: list[float | None]) -> None:
    buffer = PositionBuffer(capacity=capacity)
    model: list[list[float]] = []
    for op in ops:
        if op is None:
            buffer.clear()
            model.clear()
        else:
            row = [op, op + 1, op + 2, op + 3]
            buffer.append(*row)
            model = ([*model, row])[-capacity:]
        assert buffer.view().tolist() == model
        assert len(buffer) == len(model)
