"""Issue 28 item 28: the positions a notice states follow the operator's units and the device's
resolution ("stopped at (19.7228, 5, 0) mm" was shown to an operator working in inches)."""

from __future__ import annotations

import pytest

from app.common.position_messages import Lengths, position_localized
from app.window.device.worker import SerialWorker
from drivers.errors import DeviceError
from drivers.messages import Message
from tests.widgets.test_units_shown import english_numbers  # noqa: F401 (autouse)

pytestmark = pytest.mark.timeout(30)

STOPPED = Message("stopped at ({x:g}, {y:g}, {z:g}) mm", x=19.7228, y=5.0, z=0.0)


def test_a_stop_position_in_mm_to_the_device_resolution(qapp) -> None:
    assert position_localized(STOPPED, Lengths("mm", 0.01)) == "stopped at (19.72, 5, 0) mm"


def test_a_stop_position_in_inches(qapp) -> None:
    said = position_localized(STOPPED, Lengths("in", 0.01))
    assert said == "stopped at (0.7765, 0.1969, 0) in"


def test_a_position_inside_an_error_follows_too(qapp) -> None:
    moved = Message("move to ({x:g}, {y:g}, {z:g}) mm", x=25.4, y=-12.7, z=1.0)
    error = DeviceError(Message("{what} failed: {reason}", what=moved, reason="busy"))
    assert (
        position_localized(error, Lengths("in", 0.001))
        == "move to (1, -0.5, 0.0394) in failed: busy"
    )


def test_messages_without_a_position_are_as_localized(qapp) -> None:
    plain = Message(
        "the device did not answer {command} within {seconds:g} s", command="GET_ID", seconds=2.5
    )
    assert (
        position_localized(plain, Lengths("in", 0.01))
        == "the device did not answer GET_ID within 2.5 s"
    )


def test_the_worker_says_a_stop_in_the_window_units(qapp) -> None:
    worker = SerialWorker()
    said: list[str] = []
    worker.notice.connect(said.append)
    worker.units = "in"
    worker._on_motion_notice(STOPPED)
    assert said == ["stopped at (0.7765, 0.1969, 0) in"]  # no device: 3 decimals of a mm


def test_the_window_gives_the_worker_its_units(window) -> None:
    assert window.worker.units == "mm"
    window.readout.set_display("in")
    assert window.worker.units == "in"
