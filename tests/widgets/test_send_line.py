"""SendLine on its own: modes, line endings, enabling, history reset after sending."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from widgets.send_line import SendLine


@pytest.fixture
def line(qtbot) -> SendLine:
    widget = SendLine()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def test_ending_follows_mode_and_enabling(line: SendLine) -> None:
    assert line.ending_combo.isEnabled()
    line.set_mode("hex")
    line.setEnabled(False)
    line.setEnabled(True)
    assert not line.ending_combo.isEnabled()  # no line ending in hex mode, even re-enabled
    line.set_mode("text")
    assert line.ending_combo.isEnabled()
    with pytest.raises(ValueError):
        line.set_mode("binary")
    with pytest.raises(ValueError):
        line.set_line_ending(b"\n\n")


def test_data_and_send(line: SendLine, qtbot, record) -> None:
    calls = record(line.send_requested)
    line.edit.setText("GET_ID")
    assert line.data() == b"GET_ID\n"
    qtbot.mouseClick(line.button, Qt.MouseButton.LeftButton)
    assert calls == [(b"GET_ID\n",)]
    assert line.edit.history() == ["GET_ID"]
    line.setEnabled(False)
    line.edit.setText("X")
    line.send()
    assert calls == [(b"GET_ID\n",)]
