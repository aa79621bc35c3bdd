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


def _assert_copies_agree(buffer: PositionBuffer) -> None:
    """Every kept row is identical in both halves of the doubled storage."""
    cap = buffer.capacity
    start = (buffer._next - len(buffer)) % cap
    for i in range(start, start + len(buffer)):
        primary = i % cap
        np.testing.assert_array_equal(buffer._data[primary], buffer._data[primary + cap])


def test_shift_without_wraparound() -> None:
    buffer = PositionBuffer(capacity=10)
    for i in range(4):
        buffer.append(i, i, 10 * i, -i)
    version = buffer.version
    buffer.shift(1.5, -2.0, 3.0)
    assert buffer.version != version
    assert buffer.view().tolist() == [[i, i + 1.5, 10 * i - 2.0, -i + 3.0] for i in range(4)]
    assert buffer.last() == pytest.approx((3, 4.5, 28.0, 0.0))
    _assert_copies_agree(buffer)


@pytest.mark.parametrize("appended", [5, 6, 7, 9, 10, 13])
def test_shift_after_wraparound_shifts_both_copies(appended: int) -> None:
    buffer = PositionBuffer(capacity=5)
    for i in range(appended):
        buffer.append(i, i, 2 * i, 3 * i)
    before = buffer.view().copy()
    buffer.shift(10.0, 20.0, 30.0)
    expected = before + np.array([0.0, 10.0, 20.0, 30.0])
    np.testing.assert_array_equal(buffer.view(), expected)
    _assert_copies_agree(buffer)
    # Later appends wrap over the shifted rows: the view must still read shifted data, which
    # breaks if only one copy of the doubled storage was shifted.
    for k in range(1, 5):
        buffer.append(100 + k, -k, -k, -k)
        view = buffer.view()
        np.testing.assert_array_equal(view[: 5 - k], expected[k:])
        assert view[-1].tolist() == [100 + k, -k, -k, -k]
        _assert_copies_agree(buffer)


def test_shift_after_clear_keep_last_and_capacity_one() -> None:
    buffer = PositionBuffer(capacity=1)
    buffer.append(0, 1, 2, 3)
    buffer.append(1, 4, 5, 6)
    buffer.shift(-4, -5, -6)
    assert buffer.view().tolist() == [[1, 0, 0, 0]]
    _assert_copies_agree(buffer)

    buffer = PositionBuffer(capacity=4)
    for i in range(7):
        buffer.append(i, i, i, i)
    buffer.clear(keep_last=True)
    buffer.shift(1, 1, 1)
    assert buffer.view().tolist() == [[6, 7, 7, 7]]
    _assert_copies_agree(buffer)


def test_shift_of_an_empty_buffer_bumps_the_version_only() -> None:
    buffer = PositionBuffer(capacity=3)
    version = buffer.version
    buffer.shift(1, 2, 3)
    assert buffer.version != version
    assert len(buffer) == 0
    buffer.append(0, 0, 0, 0)  # rows added after a shift are not shifted
    assert buffer.view().tolist() == [[0, 0, 0, 0]]


@settings(max_examples=60, deadline=None)
@given(
    capacity=st.integers(1, 8),
    ops=st.lists(
        st.one_of(st.floats(-1e3, 1e3), st.none(), st.tuples(st.integers(-50, 50))),
        max_size=40,
    ),
)
def test_shift_matches_a_list_model(capacity: int, ops: list[float | tuple[int] | None]) -> None:
    buffer = PositionBuffer(capacity=capacity)
    model: list[list[float]] = []
    for op in ops:
        if op is None:
            buffer.clear()
            model.clear()
        elif isinstance(op, tuple):
            d = float(op[0])
            buffer.shift(d, 2 * d, -d)
            model = [[t, x + d, y + 2 * d, z - d] for t, x, y, z in model]
        else:
            row = [op, op + 1, op + 2, op + 3]
            buffer.append(*row)
            model = ([*model, row])[-capacity:]
        assert buffer.view().tolist() == model
        _assert_copies_agree(buffer)
