"""The scripting API counts a Visiomex move as the firmware makes it (issue 28, items 1 and 6):
`DeviceSession.position()` after Y moves at power-on and after 22 = 6000, 24 = 1 equals where the
simulated stage is, a move it will not make as asked is said before it is sent, and the values
the firmware recomputes at a move (19, 20) are among the session's kept parameters."""

from __future__ import annotations

import pytest

import drivers

pytestmark = pytest.mark.timeout(60)
STEP = 0.025  # mm a step at power-on: 10 mm a turn, 400 full steps, ×1


def test_position_and_parameters_follow_the_firmware() -> None:
    with drivers.open_device("sim://visiomex?instant=1", "visiomex") as stage:
        device = stage.link.port.device  # type: ignore[attr-defined]
        said: list[str] = []
        stage.motion.notice_listeners.append(said.append)
        sent_before: list[int] = []
        stage.motion.move_listeners.append(lambda move: sent_before.append(len(said)))
        stage.set_home()

        here = stage.move_by(1, 1)
        assert (here.x, here.y) == (1.0, 0.0) == device.position()
        assert said and said[0].startswith("Y will not move")
        assert sent_before == [1]  # said before the move was told as started (and sent)
        assert stage.parameters.kept()["step_count_acceleration_y"] == 0  # was 50 at power-on

        stage.parameters.set(22, 6000)
        stage.parameters.set(24, 1)
        here = stage.move_by(0.99, 1)
        assert (here.x, here.y) == pytest.approx((1 + 39 * STEP, 14 * STEP))
        assert (here.x, here.y) == pytest.approx(device.position())
        assert stage.position().y == pytest.approx(0.35)
        kept = stage.parameters.kept()
        assert kept["step_count_acceleration_y"] == 14 == device.parameters[20]
        assert kept["step_delay_instantaneous_y"] == device.parameters[16]
        assert "X moves 0.975 mm" in said[-1] and "Y moves 0.350 mm" in said[-1]


def test_speed_is_the_one_the_step_delays_give() -> None:
    with drivers.open_device("sim://visiomex?instant=1", "visiomex") as stage:
        assert stage.speed() == pytest.approx(STEP / 0.008)  # 4000 + 4000 µs a step
        stage.parameters.set(15, 1000)
        stage.parameters.set(16, 1500)
        assert stage.speed() == pytest.approx(STEP / 0.0025)
