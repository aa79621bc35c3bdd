"""Guards against a broken Qt binding (PySide6 6.12.0 on Python 3.11 loses references to None)."""

from __future__ import annotations

import sys

import pytest
from PySide6.QtWidgets import QLabel

pytestmark = pytest.mark.timeout(20)


def test_void_calls_keep_none_alive(qtbot) -> None:
    label = QLabel()
    qtbot.addWidget(label)
    before = sys.getrefcount(None)
    for _ in range(2000):
        label.setText("x")
    # Each leaked reference brings the process closer to "Fatal Python error: none_dealloc".
    assert sys.getrefcount(None) >= before - 50
