"""Widget tests run headless (offscreen) unless a display is there (Xvfb in CI, for GL tests)."""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

import pytest

# Before any QApplication exists; nothing above imports Qt.
if "DISPLAY" not in os.environ and "WAYLAND_DISPLAY" not in os.environ:
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from widgets.position_view_3d import share_opengl_contexts

share_opengl_contexts()  # as the application does: several GL views over the session

from app.window.console.traffic_console import RawConsole  # noqa: E402
from widgets.arc_entry import ArcEntry  # noqa: E402
from widgets.coordinate_entry import CoordinateEntry  # noqa: E402
from widgets.position_readout import PositionReadout  # noqa: E402
from widgets.speed_control import SpeedControl  # noqa: E402


@pytest.fixture
def record() -> Callable[[Any], list[tuple[Any, ...]]]:
    """`calls = record(widget.some_signal)`: every emission's arguments, appended to a list."""

    def _record(signal: Any) -> list[tuple[Any, ...]]:
        calls: list[tuple[Any, ...]] = []
        signal.connect(lambda *args: calls.append(args))
        return calls

    return _record


@pytest.fixture
def readout(qtbot) -> PositionReadout:
    """A shown PositionReadout."""
    widget = PositionReadout()
    qtbot.addWidget(widget)
    widget.show()
    return widget


@pytest.fixture
def entry(qtbot) -> CoordinateEntry:
    """A shown CoordinateEntry."""
    widget = CoordinateEntry()
    qtbot.addWidget(widget)
    widget.show()
    return widget


@pytest.fixture
def console(qtbot) -> RawConsole:
    """A shown traffic console decoding COXIRIS, its times from 0."""
    from drivers.protocols.registry import create_protocol

    widget = RawConsole()
    qtbot.addWidget(widget)
    widget.resize(900, 300)
    widget.show()
    widget.set_time_origin(0.0)
    widget.set_protocol(create_protocol("coxiris"))
    return widget


@pytest.fixture
def speed(qtbot) -> SpeedControl:
    """A shown speed control over 0 to 50 mm/s."""
    widget = SpeedControl()
    qtbot.addWidget(widget)
    widget.set_range(0.0, 50.0)
    widget.show()
    return widget


@pytest.fixture
def arc(qtbot) -> ArcEntry:
    """A shown arc entry."""
    widget = ArcEntry()
    qtbot.addWidget(widget)
    widget.show()
    return widget
