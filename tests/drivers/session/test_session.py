"""The device session (drivers.open_device): set-up, typed operations, guard, tap, stop, close."""

from __future__ import annotations

import threading
from pathlib import Path

import pytest

import drivers
from drivers.device.travel import TravelLimits
from drivers.errors import BadInput, PortError, UnknownProtocol
from drivers.link.records import RX, TX, Traffic
from drivers.protocols.laser.protocol import GetStatus
from drivers.session.device_session import DeviceSession, NoPrograms, NoStop, open_device
from drivers.toolpath.point_program import ProgramPoint
from drivers.toolpath.streaming import StreamProgress

pytestmark = pytest.mark.timeout(60)


def test_the_package_exports_the_session() -> None:
    assert drivers.open_device is open_device
    assert drivers.DeviceSession is DeviceSession
    with pytest.raises(AttributeError):
        _ = drivers.no_such_name  # type: ignore[attr-defined]


def test_a_coxiris_session_moves_and_reports_where_it_is() -> None:
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        assert stage.identify()
        assert stage.capabilities.axes == ("x", "y", "z")
        here = stage.move_to(3.0, -2.0, 1.0)
        assert (here.x, here.y, here.z) == (3.0, -2.0, 1.0)
        here = stage.move_by(1.0, 1.0)
        assert (here.x, here.y, here.z) == (4.0, -1.0, 1.0)
        read = stage.position()
        assert (read.x, read.y, read.z) == (4.0, -1.0, 1.0)
        assert stage.speed(20) == 20
        assert stage.speed() == 20
        stage.set_home()
        assert stage.position().x == 0.0
        stage.move_to(2.0, 0.0)
        assert stage.home().x == 0.0
        assert not stage.closed
    assert stage.closed


def test_the_guard_refuses_a_move_outside_the_box_before_anything_is_sent() -> None:
    sent: list[Traffic] = []
    box = "-10:10,-10:10,0:5"
    with open_device("sim://coxiris?instant=1", "coxiris", travel=box) as stage:
        stage.move_to(1.0, 1.0)
        stage.add_listener(lambda record: sent.append(record) if record.direction == TX else None)
        with pytest.raises(BadInput, match=r"outside -10\.\.10 mm"):
            stage.move_to(50.0, 0.0)
        with pytest.raises(BadInput, match="outside"):
            stage.move_by(0.0, 20.0)
        assert sent == []  # refused before the position was even asked
        assert stage.travel == TravelLimits(((-10, 10), (-10, 10), (0, 5)))
        stage.move_to(2.0, 2.0)
        assert sent  # a move inside goes


def test_clamp_takes_a_move_to_the_edge_of_the_box() -> None:
    with open_device("sim://coxiris?instant=1", "coxiris", travel="-5:5,-5:5,0:5", clamp=True) as s:
        here = s.move_to(9.0, 0.0)
        assert (here.x, here.y) == (5.0, 0.0)


def test_the_tap_sees_every_byte_and_the_log_is_a_hexdump(tmp_path: Path) -> None:
    seen: list[Traffic] = []
    log = tmp_path / "traffic.log"
    with open_device("sim://coxiris", "coxiris", listeners=[seen.append], log=log) as stage:
        stage.position()
        stage.tap.note("a note of the script")
    directions = {record.direction for record in seen}
    assert directions == {TX, RX}
    assert b"GET_POSITION" in b"".join(r.data for r in seen if r.direction == TX)
    text = log.read_text(encoding="utf-8")
    assert " TX   " in text and " RX   " in text and "GET_POSITION" in text
    assert "# a note of the script" in text


def test_stop_ends_a_laser_program_and_flushes_the_device_queue() -> None:
    points = [ProgramPoint(10.0 * (i % 2), 0.0, 0.0, 50.0) for i in range(40)]  # 0.2 s each
    with open_device("sim://laser-frame", "laser-frame") as laser:
        device = laser.link.port.device

        def progress(state: StreamProgress) -> None:
            if state.frames >= 1:
                laser.stop()  # from the progress callback: the program ends, then STOP goes

        state = laser.run_program(points, progress=progress)
        assert not state.finished
        assert state.sent < len(points)
        status = laser.client.execute(GetStatus()).value
        assert isinstance(status, dict)
        assert status["queue"] == 0 and not status["moving"]  # the queue was flushed
        assert len(device.executed) < state.sent
        laser.stop()  # nothing under way: STOP is sent and acknowledged all the same


def test_stop_where_the_device_has_none_is_a_clear_error_and_sends_nothing() -> None:
    sent: list[Traffic] = []
    with open_device("sim://coxiris", "coxiris") as stage:
        stage.add_listener(sent.append)
        with pytest.raises(NoStop, match="coxiris has no stop command"):
            stage.stop()
    assert isinstance(NoStop("x"), BadInput)
    assert sent == []


def test_a_device_without_a_queue_runs_a_program_move_by_move() -> None:
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        state = stage.run_program(
            [ProgramPoint(1.0, 1.0, 0.0, 10.0), ProgramPoint(2.0, -1.0, 0.0, 12.0)]
        )
        here = stage.position()
        assert state.finished and state.executed == state.total == 2
        assert (here.x, here.y, here.z) == (2.0, -1.0, 0.0)
        assert stage.speed() == 10.0  # the panel's speed is set back after the program
    assert issubclass(NoPrograms, BadInput)  # kept for scripts that catch it; never raised now


def test_a_program_outside_the_box_is_refused_whole() -> None:
    sent: list[Traffic] = []
    points = [ProgramPoint(1.0, 1.0, 0.0, 100.0), ProgramPoint(30.0, 0.0, 0.0, 100.0)]
    with open_device("sim://laser-frame", "laser-frame", travel="-20:20,-20:20,0:5") as laser:
        laser.add_listener(sent.append)
        with pytest.raises(BadInput, match="program point 2"):
            laser.run_program(points)
    assert sent == []


def test_the_session_closes_when_the_block_ends_with_an_exception(tmp_path: Path) -> None:
    log = tmp_path / "t.log"
    with (
        pytest.raises(RuntimeError, match="the script failed"),
        open_device("sim://coxiris", "coxiris", log=log) as stage,
    ):
        stage.position()
        assert not stage.tap.logs[0].stream.closed
        raise RuntimeError("the script failed")
    assert stage.closed
    assert stage.tap.logs[0].stream.closed  # the log file the session opened, closed too
    assert "GET_POSITION" in log.read_text(encoding="utf-8")


def test_set_up_errors_are_named_and_leave_nothing_open() -> None:
    with pytest.raises(UnknownProtocol):
        open_device("sim://coxiris", "no-such-protocol")
    with pytest.raises(PortError):
        open_device("/dev/no-such-port-here", "coxiris")
    with pytest.raises(BadInput, match="variant"):
        open_device("sim://visiomex", "visiomex", variant="nonsense")
    with pytest.raises(BadInput, match="travel limits"):
        open_device("sim://coxiris", "coxiris", travel="1:2")
    with pytest.raises(BadInput, match="timeout"):
        open_device("sim://coxiris", "coxiris", timeout=0)


def test_a_sim_device_speaks_the_variant_asked_for() -> None:
    with open_device("sim://visiomex", "visiomex", variant="prefixed") as stage:
        assert "variant=prefixed" in stage.port
        assert stage.protocol.variant is not None and stage.protocol.variant.name == "prefixed"
        assert stage.identify()


def test_parameters_kept_and_written_on_visiomex() -> None:
    with open_device("sim://visiomex", "visiomex", parameters={"pulley_diameter_x": 40.0}) as s:
        assert s.parameters.kept() == {"pulley_diameter_x": 40.0}
        assert any(p.name == "pulley_diameter_y" for p in s.parameters.all)
        with pytest.raises(BadInput):
            s.parameters.write({"pulley_diameter_y": 38.2, "pulley_diameter_x": -1.0})
        written = s.parameters.set("pulley_diameter_y", 38.2)
        assert written.parameter.name == "pulley_diameter_y"
        assert s.parameters.kept()["pulley_diameter_y"] == 38.2


def test_not_started_then_started_by_the_caller() -> None:
    abort = threading.Event()
    with open_device("sim://coxiris", "coxiris", start=False, abort=abort) as stage:
        assert stage.client.writes == 0  # nothing sent until the caller talks
        assert stage.client.abort is abort
        stage.start()
        assert stage.position().x == 0.0


def test_stop_from_another_thread_halts_the_move_being_waited_on() -> None:
    with open_device("sim://laser-frame", "laser-frame") as laser:
        laser.speed(20)  # 50 mm take 2.5 s
        started = threading.Event()
        laser.motion.move_listeners.append(lambda move: started.set())

        def stop_once_started() -> None:
            assert started.wait(10)
            laser.stop()

        stopper = threading.Thread(target=stop_once_started)
        stopper.start()
        here = laser.move_to(50.0, 0.0)
        stopper.join(10)
        assert here.x < 50.0  # stopped on the way, where the device says it is
        assert laser.position().x == here.x


def test_stop_ends_a_program_on_a_device_without_a_stop_command() -> None:
    points = [ProgramPoint(float(i), 0.0, 0.0, 10.0) for i in range(1, 30)]
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        seen: list[int] = []

        def progress(state: StreamProgress) -> None:
            seen.append(state.executed)
            if state.executed == 3:
                stage.stop()  # from the progress callback: the program ends, no NoStop

        state = stage.run_program(points, progress)
        assert not state.finished and state.executed == 3
        assert stage.position().x == 3.0  # the move under way finished; nothing more was sent
        with pytest.raises(NoStop):
            stage.stop()  # no program now: COXIRIS has no stop command
