"""The session as the one device API: arcs, dwells, raw bytes through the guard, typed
subscriptions, control lines, and the front ends that drive nothing below it."""

from __future__ import annotations

import ast
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from drivers import BadInput, PositionReport, Traffic, open_device
from drivers.device.guard import RawRefused
from drivers.protocols import commands as cmd
from tests.support.simproc import ROOT, SimProcess

pytestmark = pytest.mark.timeout(60)

BOX = "-20:20,-20:20,0:5"


@pytest.fixture
def pi_frame() -> Iterator[SimProcess]:
    process = SimProcess("pi-frame", "--instant", control=True)
    yield process
    assert process.stop() == 0


def _where(sim: SimProcess, scale: float = 100.0) -> list[float]:
    """The simulator's own axes (`motionsim --control`, `where`), in mm (pi-frame: ticks)."""
    return [float(v) / scale for v in sim.fault("where").split()[2:]]


def test_an_arc_ends_where_the_simulators_axes_say(pi_frame: SimProcess) -> None:
    with open_device(pi_frame.path, "pi-frame", travel=BOX) as stage:
        stage.set_home()
        stage.speed(10)
        report = stage.arc(-10, 0, 10, 0, 90, ccw=True)  # from (0, 0) round to (-10, 10)
    assert (report.x, report.y) == pytest.approx((-10, 10), abs=0.01)
    assert _where(pi_frame)[:2] == pytest.approx([-10, 10], abs=0.011)


def test_an_arc_that_leaves_the_box_is_refused_before_anything_is_sent() -> None:
    sent: list[Traffic] = []
    with open_device("sim://pi-frame?instant=1", "pi-frame", travel="-15:15,-15:15,0:5") as stage:
        stage.set_home()
        stage.on_traffic(sent.append)
        with pytest.raises(BadInput, match="arc"):
            stage.arc(-10, 0, 10, 0, 270, ccw=True)  # from (0, 0) by (-20, 0): outside
        with pytest.raises(BadInput, match="arc"):
            stage.arc(-5, 0, 14, 0, 180, ccw=True)  # starts at (9, 0), ends at (-19, 0)
    assert [r for r in sent if r.direction == "tx"] == []


def test_dwell_waits_as_long_as_asked() -> None:
    with open_device("sim://pi-frame?instant=1", "pi-frame") as stage:
        began = time.monotonic()
        stage.dwell(0.3)
        waited = time.monotonic() - began
    assert waited >= 0.29


def test_a_raw_move_outside_the_box_is_refused_before_anything_is_sent() -> None:
    sent: list[Traffic] = []
    with open_device("sim://coxiris?instant=1", "coxiris", travel=BOX) as stage:
        stage.on_traffic(sent.append)
        outside = stage.protocol.encode(cmd.MoveTo(500, 0, 0))
        with pytest.raises(BadInput, match="raw move"):
            stage.check_raw(outside)
        with pytest.raises(BadInput, match="raw move"):
            stage.send_raw(outside)
        with pytest.raises(BadInput, match="raw move"):
            stage.raw(b"ABSOLUTE_MOVE 500 0 0")
        with pytest.raises(BadInput):
            stage.send(cmd.MoveTo(500, 0, 0))
        with pytest.raises(RawRefused):
            stage.send_raw(b"\x00garbage")  # unreadable bytes with a box: not sent unforced
        assert {r.data for r in sent if r.direction == "tx"} == {b"GET_POSITION\n"}  # asked only
        inside = stage.raw(b"ABSOLUTE_MOVE 5 0 0")
    assert isinstance(inside, PositionReport) and inside.x == pytest.approx(5)


def test_check_commands_follows_each_move_from_where_the_last_ends() -> None:
    with open_device("sim://coxiris?instant=1", "coxiris", travel=BOX) as stage:
        steps = [cmd.MoveBy(15, 0, 0), cmd.GetId(), cmd.MoveBy(15, 0, 0)]
        with pytest.raises(BadInput):
            stage.check_commands(steps)  # the second ends at x = 30
        assert stage.check_commands(steps[:2]) == (15, 0, 0)
        assert stage.check_commands([cmd.GetId()]) is None
        assert stage.position().x == 0  # nothing moved


def test_subscriptions_fire_and_unsubscribe() -> None:
    heard: dict[str, list[object]] = {
        name: [] for name in ("position", "started", "ended", "notice", "traffic", "event", "wait")
    }
    url = "sim://coxiris?speed=200&line_timing=0"
    with open_device(url, "coxiris", travel="-5:5,-5:5,0:5", clamp=True) as stage:
        stops = [
            stage.on_position(heard["position"].append),
            stage.on_move_started(heard["started"].append),
            stage.on_move_ended(heard["ended"].append),
            stage.on_notice(heard["notice"].append),
            stage.on_traffic(heard["traffic"].append),
            stage.on_event(lambda event, solicited: heard["event"].append(event)),
            stage.on_wait(lambda: heard["wait"].append(None)),
        ]
        stage.move_to(10, 0)  # clamped to x = 5: told as a notice
        assert all(heard.values()), {name: len(calls) for name, calls in heard.items()}
        assert heard["ended"][-1] == heard["position"][-1]
        assert "5" in str(heard["notice"][0])
        for stop in stops:
            stop()
            stop()  # again: nothing happens
        counts = {name: len(calls) for name, calls in heard.items()}
        stage.move_to(0, 0)
    assert {name: len(calls) for name, calls in heard.items()} == counts


def test_control_lines_are_read_and_driven_through_the_session() -> None:
    notes: list[str] = []
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        stop = stage.on_link_note(notes.append)
        stage.set_control("dtr", False)
        assert stage.control_lines().dtr is False
        stage.set_control("dtr", True)
        assert stage.control_lines().dtr is True
        stop()
        stage.set_control("rts", False)
    assert notes == ["DTR off", "DTR on"]


def test_a_stop_from_another_thread_ends_an_operation_of_many_steps() -> None:
    """`operation()` keeps a stop asked during it (a macro between its steps)."""
    import threading

    with open_device("sim://pi-frame?instant=1", "pi-frame") as stage:
        with stage.operation():
            assert not stage.stop_requested
            refused: list[BaseException] = []

            def stop() -> None:
                try:
                    stage.stop()
                except BadInput as exc:  # NoStop: the device finishes what it was sent
                    refused.append(exc)

            worker = threading.Thread(target=stop)
            worker.start()
            worker.join(10)
            assert len(refused) == 1
            assert stage.stop_requested  # pi-frame has no stop: the steps end all the same
            stage.position()  # a step's own operation keeps it
            assert stage.stop_requested
        with stage.operation():
            assert not stage.stop_requested  # a stop asked before an operation is not for it


# -- the front ends drive the session only ------------------------------------------------------
FRONT_ENDS = ("app/cli", "app/common", "bench", "app/window/device")
EXCLUDED: dict[str, str] = {}
LAYERS = ("motion", "client", "link")


def below_the_session(source: str) -> list[str]:
    """What code reaches below the session: `x.motion.y`, `x.client.y`, `x.link.y`, and
    anything of a `motion` or `client` (`motion.raw(...)`, `motion.notice_listeners`); imports,
    comments and docstrings are not code that reaches."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Attribute):
            continue
        if isinstance(node.value, ast.Attribute) and node.value.attr in LAYERS:
            found.append(f"line {node.lineno}: .{node.value.attr}.{node.attr}")
        elif isinstance(node.value, ast.Name) and node.value.id in ("motion", "client"):
            found.append(f"line {node.lineno}: {node.value.id}.{node.attr}")
    return found


def _front_end_files() -> Iterator[Path]:
    for name in FRONT_ENDS:
        path = ROOT / name
        yield from sorted(path.rglob("*.py")) if path.is_dir() else [path]


def test_the_front_ends_call_nothing_below_the_session() -> None:
    reaching = {}
    for path in _front_end_files():
        name = path.relative_to(ROOT).as_posix()
        if name in EXCLUDED:
            continue
        found = below_the_session(path.read_text(encoding="utf-8"))
        if found:
            reaching[name] = found
    assert reaching == {}


def test_the_scan_finds_calls_below_the_session() -> None:
    source = "session.motion.move_to(1, 2)\nmotion.raw(b'x')\nx = s.client.protocol\n"
    source += "motion.notice_listeners.append(print)\nclient.execute(c)\n"
    assert len(below_the_session(source)) == 5
    assert below_the_session("from drivers.bridge.snoop import Bridge\n# s.motion.x\n") == []
