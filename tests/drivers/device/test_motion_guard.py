"""The motion guard: raw frames read with each protocol's own decoder and checked like typed
moves; a raw move followed like a typed one; a stage outside its box may come back."""

from __future__ import annotations

import time

import pytest

from drivers.device.client import Client
from drivers.device.guard import MotionGuard, RawRefused, unreadable
from drivers.device.motion import Motion
from drivers.device.travel import TravelLimits
from drivers.errors import BadInput, FrameError
from drivers.link.transport import Link, open_link
from drivers.protocols import commands as cmd
from drivers.protocols.base import MoveSequence, Protocol
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.protocols.events import PositionReport
from drivers.protocols.firmata import FirmataProtocol, StepperStep, StepperVersion
from drivers.protocols.laser.protocol import GetStatus, LaserProtocol, QueuedGroup, move_instruction
from drivers.protocols.piframe import PiFrameProtocol
from drivers.protocols.visiomex.protocol import VisiomexProtocol
from drivers.toolpath.point_program import ProgramPoint
from drivers.toolpath.streaming import Streamer
from tests.conftest import Recorder

pytestmark = pytest.mark.timeout(30)

BOX = ((-50.0, 50.0), (-50.0, 50.0), (0.0, 10.0))


# -- the travel box, from outside ---------------------------------------------------------------
def test_a_stage_outside_the_box_may_come_back_closer() -> None:
    limits = TravelLimits(BOX)
    here = (100.0, 0.0, 5.0)
    target, note = limits.apply((90.0, 0.0, 5.0), "jog", here)
    assert target == (90.0, 0.0, 5.0)
    assert note is not None and "outside its travel limits" in note and "X 90 mm" in note
    assert limits.apply((40.0, 0.0, 5.0), "jog", here) == ((40.0, 0.0, 5.0), None)
    for farther in ((110.0, 0.0, 5.0), (100.0, 0.0, 5.0), (90.0, 60.0, 5.0), (-60.0, 0.0, 5.0)):
        with pytest.raises(BadInput, match="travel limits"):
            limits.apply(farther, "jog", here)
    with pytest.raises(BadInput, match="travel limits"):
        limits.apply((90.0, 0.0, 5.0), "jog")  # where the stage is not known: refused


def test_coming_back_is_not_clamped() -> None:
    clamping = TravelLimits(BOX, clamp=True)
    assert clamping.apply((90.0, 0.0, 0.0), "jog", (100.0, 0.0, 0.0))[0] == (90.0, 0.0, 0.0)
    assert clamping.apply((110.0, 0.0, 0.0), "jog", (100.0, 0.0, 0.0))[0] == (50.0, 0.0, 0.0)


# -- each protocol's decoder -----------------------------------------------------------------------
def _laser_frame(protocol: LaserProtocol, command: cmd.Command) -> bytes:
    return protocol.encode(command)


def _decoded(protocol: Protocol, data: bytes) -> cmd.Command | None:
    commands = protocol.sent_commands(data)
    assert len(commands) == 1
    return commands[0]


@pytest.mark.parametrize(
    ("data", "expected"),
    [
        (b"ABSOLUTE_MOVE 100 0 0\n", cmd.MoveTo(100.0, 0.0, 0.0)),
        (b"absolute_move -1.5 2 .5\r\n", cmd.MoveTo(-1.5, 2.0, 0.5)),
        (b"DELTA_MOVE 1 2 3\r", cmd.MoveBy(1.0, 2.0, 3.0)),
        (b"GO_HOME\x00\n", cmd.Home()),
        # A NUL does not end the line: the firmware runs what precedes it, ignores the rest.
        (b"ABSOLUTE_MOVE 5 0 0\x00ABSOLUTE_MOVE 100 0 0\n", cmd.MoveTo(5.0, 0.0, 0.0)),
        (b"DELTA_MOVE 1 2 3\x00 4\r\n", cmd.MoveBy(1.0, 2.0, 3.0)),
        (b"GET_ID\x00ABSOLUTE_MOVE 100 0 0\n", None),
        (b"GET\x00_ID\xff\n", None),  # what follows the NUL is not read, non-ASCII or not
        (b"GET_ID\n", None),
        (b"SET_SPEED 5\n", None),
        (b"FROB 1\n", None),  # the firmware answers "Unknown command": nothing moves
    ],
)
def test_coxiris_reads_what_moves(data: bytes, expected: cmd.Command | None) -> None:
    assert _decoded(CoxirisProtocol(), data) == expected


@pytest.mark.parametrize(
    "data",
    [
        b"ABSOLUTE_MOVE 100 0 0",
        b"ABSOLUTE_MOVE 1 2\n",
        b"DELTA_MOVE 1 2 3 4\n",
        b"DELTA_MOVE a 0 0\n",
        b"GO_HOME\x00",  # a NUL is no line end: the device would wait for the rest
        b"ABSOLUTE_MOVE 5\x00 0 0\n",  # the firmware reads `ABSOLUTE_MOVE 5`: missing parameters
        b"\x00ABSOLUTE_MOVE 100 0 0\n",  # an empty command: the firmware does nothing
    ],
)
def test_coxiris_cannot_read(data: bytes) -> None:
    with pytest.raises(FrameError):
        CoxirisProtocol().sent_commands(data)


def test_visiomex_reads_its_move_packets() -> None:
    for variant in ("seed", "board12"):
        protocol = VisiomexProtocol(variant)
        move = cmd.MoveBy(12.0, -3.0, 0.0)
        assert _decoded(protocol, protocol.encode(move)) == move
        steps = cmd.MoveBy(400.0, 0.0, 0.0, "steps")
        assert _decoded(protocol, protocol.encode(steps)) == steps
        assert _decoded(protocol, protocol.encode(cmd.SetParameter(21, 10))) is None
        assert _decoded(protocol, b"G") is None
    assert _decoded(VisiomexProtocol("board12"), b"DNNNNNNNNNNN") == cmd.Home()
    for bad in (b"MLX0010000P0000000", b"MLP001000", b"MQP0010000P0000000", b"MLP00a0000P0000000"):
        with pytest.raises(FrameError):
            VisiomexProtocol("seed").sent_commands(bad)


def test_piframe_reads_its_frames() -> None:
    protocol = PiFrameProtocol()
    linear = _decoded(protocol, protocol.encode(cmd.MoveTo(10.0, 5.0, 0.0, speed=10.0)))
    assert isinstance(linear, cmd.MoveTo) and (linear.x, linear.y, linear.z) == (10.0, 5.0, 0.0)
    assert linear.speed == pytest.approx(10.0, rel=0.05)
    arc = cmd.Arc(1.0, 2.0, 5.0, 0.0, 90.0, True, 1.0, 10.0)
    read = _decoded(protocol, protocol.encode(arc))
    assert isinstance(read, cmd.Arc) and (read.cx, read.cy, read.radius) == (1.0, 2.0, 5.0)
    assert (read.start, read.end, read.ccw, read.z) == (0.0, 90.0, True, 1.0)
    assert _decoded(protocol, protocol.encode(cmd.Dwell(100))) is None
    assert _decoded(protocol, protocol.encode(cmd.SetHome())) is None
    odd = bytearray(protocol.encode(cmd.SetHome()))
    odd[2] = 9  # an action the protocol does not document
    with pytest.raises(FrameError):
        protocol.sent_commands(bytes(odd))
    with pytest.raises(FrameError):
        protocol.sent_commands(protocol.encode(cmd.SetHome())[:20])  # not a whole frame


def test_firmata_reads_stepper_steps() -> None:
    protocol = FirmataProtocol()
    read = _decoded(protocol, protocol.encode(StepperStep(60, -800)))
    assert isinstance(read, cmd.MoveBy) and read.dx == -10.0  # 80 steps/mm
    assert _decoded(protocol, protocol.encode(StepperVersion())) is None
    with pytest.raises(FrameError):
        protocol.sent_commands(bytes((0xF0, 0x72, 0x01, 0x10, 0xF7)))


def test_laser_reads_its_queued_moves() -> None:
    protocol = LaserProtocol()
    read = _decoded(protocol, protocol.encode(cmd.MoveTo(1.0, 2.0, 3.0, speed=10.0)))
    assert read == cmd.MoveTo(1.0, 2.0, 3.0, 10.0)
    assert _decoded(protocol, protocol.encode(cmd.Home())) == cmd.Home()
    group = QueuedGroup((move_instruction(1, 0, 0, 5), move_instruction(2, 0, 0, 5)))
    sequence = _decoded(protocol, protocol.encode(group))
    assert isinstance(sequence, MoveSequence) and len(sequence.moves) == 2
    assert _decoded(protocol, protocol.encode(GetStatus())) is None
    assert _decoded(protocol, protocol.encode(cmd.Stop())) is None
    with pytest.raises(FrameError):
        protocol.sent_commands(b"not a frame")


# -- the guard -------------------------------------------------------------------------------------
def test_unreadable_bytes_go_only_without_a_box_or_with_force() -> None:
    protocol = CoxirisProtocol()
    unread = b"ABSOLUTE_MOVE 100 0"  # no line end: the device would wait for the rest
    assert unreadable(protocol, unread) is not None
    assert unreadable(protocol, b"GET_ID\n") is None
    assert MotionGuard().read_raw(protocol, unread) is None
    boxed = MotionGuard(TravelLimits(BOX))
    with pytest.raises(RawRefused, match=r"X -50\.\.50, Y -50\.\.50, Z 0\.\.10 mm"):
        boxed.read_raw(protocol, unread)
    assert boxed.read_raw(protocol, unread, force=True) is None
    assert boxed.read_raw(protocol, b"ABSOLUTE_MOVE 1 0 0\n") == cmd.MoveTo(1.0, 0.0, 0.0)
    with pytest.raises(BadInput, match="send a move alone"):
        boxed.read_raw(protocol, b"GET_ID\nABSOLUTE_MOVE 1 0 0\n")


def test_a_raw_move_is_checked_like_a_typed_one() -> None:
    protocol, guard = CoxirisProtocol(), MotionGuard(TravelLimits(BOX))
    notes: list[str] = []

    def planned(data: bytes, here: tuple[float, float, float]) -> tuple[float, float, float]:
        move = guard.read_raw(protocol, data)
        assert move is not None
        return guard.raw_move(protocol, move, here, 0.01, notes.append).target

    assert planned(b"ABSOLUTE_MOVE 10 0 0\n", (0.0, 0.0, 0.0)) == (10.0, 0.0, 0.0)
    assert planned(b"DELTA_MOVE 5 0 0\n", (10.0, 0.0, 0.0)) == (15.0, 0.0, 0.0)
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        planned(b"ABSOLUTE_MOVE 100 0 0\n", (0.0, 0.0, 0.0))
    with pytest.raises(BadInput, match="X 55 mm is outside"):
        planned(b"DELTA_MOVE 10 0 0\n", (45.0, 0.0, 0.0))
    with pytest.raises(BadInput, match=r"works to 0\.01 mm"):
        planned(b"ABSOLUTE_MOVE 1.005 0 0\n", (0.0, 0.0, 0.0))
    assert planned(b"DELTA_MOVE -10 0 0\n", (100.0, 0.0, 0.0)) == (90.0, 0.0, 0.0)
    assert notes and "outside its travel limits" in notes[-1]
    clamping = MotionGuard(TravelLimits(BOX, clamp=True))  # raw bytes are never clamped
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        move = clamping.read_raw(protocol, b"ABSOLUTE_MOVE 100 0 0\n")
        assert move is not None
        clamping.raw_move(protocol, move, (0.0, 0.0, 0.0), 0.01, notes.append)


def test_a_raw_move_cut_by_a_nul_is_checked_as_the_firmware_runs_it() -> None:
    """The firmware moves to 5, not 100: the guard checks a move to 5 (inside the box)."""
    protocol, guard = CoxirisProtocol(), MotionGuard(TravelLimits(BOX))
    notes: list[str] = []
    move = guard.read_raw(protocol, b"ABSOLUTE_MOVE 5 0 0\x00ABSOLUTE_MOVE 100 0 0\n")
    assert move == cmd.MoveTo(5.0, 0.0, 0.0)
    planned = guard.raw_move(protocol, move, (0.0, 0.0, 0.0), 0.01, notes.append)
    assert planned.target == (5.0, 0.0, 0.0) and notes == []
    # The other way round: what the firmware runs is outside the box, what follows is not.
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        hidden = guard.read_raw(protocol, b"ABSOLUTE_MOVE 100 0 0\x00ABSOLUTE_MOVE 5 0 0\n")
        assert hidden is not None
        guard.raw_move(protocol, hidden, (0.0, 0.0, 0.0), 0.01, notes.append)


def test_a_program_outside_the_box_is_refused_before_anything_is_sent() -> None:
    link = open_link("sim://laser-frame?instant=1", 115200)
    recorder = Recorder()
    link.listeners.append(recorder)
    try:
        points = [ProgramPoint(1, 1, 1, 10), ProgramPoint(80, 1, 1, 10)]
        streamer = Streamer(
            Client(link, LaserProtocol(), timeout=1.0),
            points,
            guard=MotionGuard(TravelLimits(BOX)),
        )
        with pytest.raises(BadInput, match="program point 2 refused: X 80 mm is outside"):
            streamer.run()
        assert recorder.sent() == b""
    finally:
        link.close()


# -- on the simulated COXIRIS device -----------------------------------------------------------
def test_raw_moves_outside_the_box_are_never_sent(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    motion.travel = TravelLimits(BOX)
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        motion.send_raw(b"ABSOLUTE_MOVE 100 0 0\n")
    with pytest.raises(RawRefused):
        motion.send_raw(b"ABSOLUTE_MOVE 100 0 0")  # no line end: cannot be read
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        motion.raw(b"ABSOLUTE_MOVE 100 0 0")  # motionctl raw, macros: the line end added
    assert b"MOVE" not in recorder.sent()
    report = motion.send_raw(b"ABSOLUTE_MOVE 10 0 0\n")
    assert isinstance(report, PositionReport) and (report.x, report.y) == (10.0, 0.0)


def test_a_raw_move_cut_by_a_nul_goes_where_the_firmware_takes_it(
    motion: Motion, sim_link: tuple[Link, Recorder]
) -> None:
    _, recorder = sim_link
    motion.travel = TravelLimits(BOX)
    data = b"ABSOLUTE_MOVE 5 0 0\x00ABSOLUTE_MOVE 100 0 0\n"
    report = motion.send_raw(data)
    assert isinstance(report, PositionReport) and (report.x, report.y, report.z) == (5.0, 0, 0)
    assert data in recorder.sent()
    assert motion.client.execute(cmd.GetPosition()).value == PositionReport(5.0, 0.0, 0.0)
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        motion.send_raw(b"ABSOLUTE_MOVE 100 0 0\x00ABSOLUTE_MOVE 5 0 0\n")
    assert motion.client.execute(cmd.GetPosition()).value == PositionReport(5.0, 0.0, 0.0)


@pytest.mark.sim_url("sim://coxiris?speed=2")
def test_a_slow_raw_move_is_followed_to_its_end(motion: Motion) -> None:
    """Item 2: 8 mm at 2 mm/s is 4 s, twice the client's timeout: no DeviceTimeout."""
    starts: list[float] = []
    motion.move_listeners.append(lambda move: starts.append(move.duration))
    began = time.monotonic()
    report = motion.send_raw(b"ABSOLUTE_MOVE 8 0 0\n")
    assert time.monotonic() - began >= 3.5
    assert isinstance(report, PositionReport) and (report.x, report.y, report.z) == (8.0, 0, 0)
    assert starts == [pytest.approx(4.0, rel=0.05)]
    assert motion.position().x == 8.0


def test_a_stage_outside_the_box_jogs_back(motion: Motion) -> None:
    notes: list[str] = []
    motion.notice_listeners.append(notes.append)
    motion.move_to(100.0, 0.0, 0.0)  # no box yet
    motion.travel = TravelLimits(BOX)
    assert motion.move_by(-10.0, 0.0, 0.0).x == 90.0
    assert any("outside its travel limits" in n for n in notes)
    with pytest.raises(BadInput, match="X 100 mm is outside"):
        motion.move_by(10.0, 0.0, 0.0)
    with pytest.raises(BadInput, match="Y 60 mm is outside"):
        motion.move_by(-10.0, 60.0, 0.0)
    assert motion.move_to(0.0, 0.0, 0.0).x == 0.0
