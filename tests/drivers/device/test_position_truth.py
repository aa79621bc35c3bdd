"""What a session knows of the position (`session.where()`): live, estimated during a move,
unknown until counted, lost with the link (the estimate at the loss) — read by every front end."""

from __future__ import annotations

import threading
import time

import pytest

from drivers.device.motion import MoveStart
from drivers.device.position_truth import (
    ESTIMATED,
    LIVE,
    LOST,
    LOST_MOVING,
    STALE,
    UNCOUNTED,
    UNREAD,
    PositionTruth,
)
from drivers.errors import CommunicationError, MotionError
from drivers.session.device_session import open_device
from tests.support.simproc import SimProcess

pytestmark = pytest.mark.timeout(60)


def test_a_device_that_reports_is_live_and_estimated_while_moving() -> None:
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        assert stage.where().status == UNREAD and not stage.where().known
        stage.move_to(3, 4)
        here = stage.where()
        assert (here.status, here.point, here.known) == (LIVE, (3.0, 4.0, 0.0), True)
        moves: list[object] = []
        stage.motion.move_listeners.append(moves.append)
        stage.move_by(1, 0)
        assert moves and stage.where().status == LIVE  # its end was reported: no estimate


def test_an_estimate_follows_the_move_started_handler_only() -> None:
    """The move-start the motion layer gives its listeners, fed by hand with a clock: proves
    the arithmetic of the estimate, not that motion starts one (the test below does that)."""
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        stage.position()
        now = [100.0]
        truth = PositionTruth(stage.motion, clock=lambda: now[0])

        for listener in stage.motion.move_listeners:
            if getattr(listener, "__self__", None) is truth:
                listener(MoveStart((0, 0, 0), (10, 0, 0), 5.0, 100.0, 2.0))
        now[0] = 101.0
        assert (truth.now().status, truth.now().point) == (ESTIMATED, (5.0, 0.0, 0.0))
        truth.link_lost()
        now[0] = 150.0
        assert (truth.now().status, truth.now().point) == (LOST_MOVING, (5.0, 0.0, 0.0))


def test_a_counted_device_is_uncounted_until_set_home_and_lost_after_a_loss() -> None:
    with open_device("sim://visiomex?instant=1", "visiomex") as board:
        assert board.where().status == UNCOUNTED and not board.where().known
        board.set_home()
        board.move_by(1, 0)
        assert board.where().status == LIVE and board.where().point == (1.0, 0.0, 0.0)
        board.truth.link_lost()
        assert board.where().status == STALE
        board.truth.found_again()  # the same device answers again: its count is not trusted
        assert board.where().status == LOST and not board.where().known
        assert not board.position().known  # the motion layer agrees: counted from nowhere
        board.set_home()
        assert board.where().status == LIVE
    with open_device("sim://firmata?instant=1", "firmata", after_loss=True) as board:
        assert board.where().status == LOST


def test_a_link_lost_mid_move_leaves_the_estimate_at_the_loss() -> None:
    """The real mechanism: motionsim in another process is killed during a 2 mm/s move; the
    session's move fails and `where` says where the move had got to, marked, not its start."""
    sim = SimProcess("coxiris", "--speed", "2", control=True)
    try:
        with open_device(sim.path, "coxiris") as stage:
            stage.move_to(1, 0)
            start = stage.where().point
            assert start == (1.0, 0.0, 0.0)
            failed: list[MotionError] = []

            def far() -> None:
                try:
                    stage.move_to(9, 0)
                except MotionError as exc:
                    failed.append(exc)

            mover = threading.Thread(target=far)
            mover.start()
            deadline = time.monotonic() + 10
            x = 1.0
            while x < 3.0:  # the device's own axes: 1 s at 2 mm/s
                assert time.monotonic() < deadline, x
                time.sleep(0.02)  # polling the simulator's axes for a condition, with a deadline
                x = float(sim.fault("where").split()[2])
            sim.kill()
            mover.join(30)
            assert failed and isinstance(failed[0], CommunicationError), failed
            lost = stage.where()
            assert lost.status == LOST_MOVING and not lost.known
            assert lost.point is not None and x - 0.05 <= lost.point[0] <= x + 0.5, (x, lost)
    finally:
        if sim.proc.poll() is None:
            sim.stop()
