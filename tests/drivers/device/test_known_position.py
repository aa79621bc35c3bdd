"""A position known fresh is not asked again; anything that may have changed it is.

A position is known when it was read, or when a move ended whose reply the device has shown to
mean arrival (Completion.REPLY: COXIRIS's blocking sketch); it holds until anything else is
written or the device says something unasked. A position taken from a reply is reported as
commanded and confirmed (`measured=False, confirmed=True`), never as measured.
"""

from __future__ import annotations

import time
from collections.abc import Iterator

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.errors import DeviceTimeout
from drivers.link.transport import Link, open_link
from drivers.protocols.capabilities import Completion
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.protocols.events import PositionReport
from drivers.protocols.laser.protocol import LaserProtocol
from drivers.protocols.registry import create_protocol, protocol_names
from tests.conftest import Recorder

pytestmark = pytest.mark.timeout(30)

INSTANT = "sim://coxiris?instant=1&line_timing=0"
CONFIRMED = {"measured": False, "confirmed": True}


class Session:
    """A Motion on a simulated device, with what it sent and what its listeners were told."""

    def __init__(self, url: str, protocol: object = None, timeout: float = 1.0) -> None:
        self.link: Link = open_link(url, 115200)
        self.recorder = Recorder()
        self.link.listeners.append(self.recorder)
        self.client = Client(self.link, protocol or CoxirisProtocol(), timeout=timeout)  # type: ignore[arg-type]
        self.motion = Motion(self.client)
        self.reports: list[PositionReport] = []
        self.notices: list[str] = []
        self.motion.position_listeners.append(self.reports.append)
        self.motion.notice_listeners.append(self.notices.append)
        self._mark = 0

    @property
    def device(self):  # type: ignore[no-untyped-def]
        return self.link.port.device  # type: ignore[attr-defined]

    def sent(self) -> list[str]:
        """The command names written since the last call."""
        lines = self.recorder.sent().decode().splitlines()[self._mark :]
        self._mark += len(lines)
        return [line.split(" ", 1)[0] for line in lines]

    def learn(self) -> None:
        """Moves long enough to show how the device replies (at most four tries), then to 5."""
        for x in (20.0, 0.0, 20.0, 0.0):
            self.motion.move_to(x, 0, 0)
            if self.motion.arrives_on_reply:
                break
        self.motion.move_to(5, 0, 0)
        self.sent()


@pytest.fixture
def session() -> Iterator[Session]:
    s = Session(INSTANT)
    s.learn()
    assert s.motion.arrives_on_reply
    yield s
    s.link.close()


def test_every_protocol_falls_under_one_rule() -> None:
    rules = {
        (Completion.REPLY, True),  # COXIRIS, laser: known once the reply is shown to mean arrival
        (Completion.FEEDBACK, False),  # Visiomex: the target, commanded and confirmed
        (Completion.ESTIMATE, False),  # pi-frame, Firmata: the target, commanded, estimated
    }
    for name in protocol_names():
        caps = create_protocol(name).capabilities
        assert (caps.completion, caps.position_feedback) in rules, name


def test_a_jog_after_a_jog_sends_only_the_move(session: Session) -> None:
    assert session.motion.move_by(0.1, 0, 0) == PositionReport(5.1, 0.0, 0.0, **CONFIRMED)
    assert session.motion.move_by(-0.2, 0, 0.5) == PositionReport(4.9, 0.0, 0.5, **CONFIRMED)
    assert session.motion.home() == PositionReport(0.0, 0.0, 0.0, **CONFIRMED)
    assert session.sent() == ["DELTA_MOVE", "DELTA_MOVE", "GO_HOME"]


def test_the_position_from_a_reply_is_told_as_commanded_and_confirmed(session: Session) -> None:
    session.reports.clear()
    session.motion.move_by(1, 0, 0)
    assert session.reports == [PositionReport(6.0, 0.0, 0.0, **CONFIRMED)]
    assert session.motion.position() == PositionReport(6.0, 0.0, 0.0)  # the idle poll: measured
    assert session.sent() == ["DELTA_MOVE", "GET_POSITION"]
    session.motion.move_by(1, 0, 0)
    assert session.sent() == ["DELTA_MOVE"]  # the measured position was still known


def test_a_line_the_device_says_unasked_makes_the_next_move_ask(session: Session) -> None:
    session.device.emit(b"dbg 1 loop ok\r\n", time.monotonic())
    session.client.poll()  # the worker's idle loop reads it
    session.motion.move_by(0.5, 0, 0)
    assert session.sent() == ["GET_POSITION", "DELTA_MOVE"]


def test_a_timeout_makes_the_next_move_ask() -> None:
    s = Session(INSTANT, timeout=0.2)
    s.learn()
    s.device.mute = True  # the move is lost: where the stage is, nobody knows
    with pytest.raises(DeviceTimeout):
        s.motion.move_by(1, 0, 0)
    s.device.mute = False
    s.sent()
    s.motion.move_by(1, 0, 0)
    assert s.sent() == ["GET_POSITION", "DELTA_MOVE"]
    s.link.close()


def test_a_device_error_makes_the_next_move_ask(session: Session) -> None:
    session.device.faults = ["Motor X overheated"]
    with pytest.raises(Exception, match="overheated"):
        session.motion.check()
    session.motion.move_by(1, 0, 0)
    assert session.sent() == ["CHECK_ERRORS", "GET_POSITION", "DELTA_MOVE"]


def test_other_writes_make_the_next_move_ask(session: Session) -> None:
    session.motion.set_speed(20)
    session.motion.raw(b"GET_ID")
    session.sent()
    session.motion.move_by(1, 0, 0)
    assert session.sent() == ["GET_POSITION", "DELTA_MOVE"]


def test_a_stop_asked_during_a_move_makes_it_confirmed_by_reading(session: Session) -> None:
    session.motion.stop_requested.set()  # COXIRIS has no stop: the move finishes, then is read
    assert session.motion.move_by(1, 0, 0) == PositionReport(6.0, 0.0, 0.0)
    assert session.sent() == ["DELTA_MOVE", "GET_POSITION"]


def test_a_device_elsewhere_than_its_reply_said_is_no_longer_believed(session: Session) -> None:
    session.motion.move_by(1, 0, 0)
    session.device.stage.set_position((2.0, 0.0, 0.0), time.monotonic())  # behind our back
    assert session.motion.position() == PositionReport(2.0, 0.0, 0.0)
    assert not session.motion.arrives_on_reply
    assert "not where its last move ended" in session.notices[-1]
    session.sent()
    assert session.motion.move_by(1, 0, 0) == PositionReport(3.0, 0.0, 0.0)
    assert session.sent() == ["DELTA_MOVE", "GET_POSITION"]


def test_a_new_connection_starts_by_asking(session: Session) -> None:
    motion = Motion(Client(session.link, CoxirisProtocol()))  # a reconnect makes a new Motion
    assert not motion.arrives_on_reply
    motion.move_by(1, 0, 0)
    assert session.sent() == ["GET_POSITION", "GET_SPEED", "DELTA_MOVE", "GET_POSITION"]


def test_short_moves_show_nothing_so_they_are_read() -> None:
    s = Session(INSTANT)
    for _ in range(3):
        s.motion.move_by(0.1, 0, 0)  # 10 ms at 10 mm/s: too short to tell replies apart
    assert not s.motion.arrives_on_reply
    assert s.sent().count("GET_POSITION") == 4  # the first position, then one after each move
    s.link.close()


def test_a_blocking_device_is_known_by_its_late_reply() -> None:
    s = Session("sim://coxiris?speed=100&line_timing=0")
    s.motion.move_to(20, 0, 0)  # DONE 0.2 s after ACK: once could be a host that stalled
    assert not s.motion.arrives_on_reply
    s.learn()  # again
    assert s.motion.arrives_on_reply
    assert s.motion.move_by(0.1, 0, 0).confirmed
    assert s.sent() == ["DELTA_MOVE"]
    s.link.close()


def test_a_non_blocking_device_is_read_after_every_move() -> None:
    s = Session("sim://coxiris?speed=100&blocking=0&line_timing=0")
    s.learn()  # DONE at the start: the first poll finds the stage on its way
    assert not s.motion.arrives_on_reply
    assert s.motion.move_by(0.1, 0, 0) == PositionReport(5.1, 0.0, 0.0)
    assert s.sent()[:2] == ["DELTA_MOVE", "GET_POSITION"]
    s.link.close()


def test_a_queue_acknowledgement_is_not_arrival() -> None:
    s = Session("sim://laser-frame?line_timing=0", LaserProtocol())
    for x in (2.0, 0.0, 2.0):  # 0.2 s each at 10 mm/s: acknowledged when queued
        assert s.motion.move_to(x, 0, 0) == PositionReport(x, 0.0, 0.0)
    assert not s.motion.arrives_on_reply
    s.link.close()
