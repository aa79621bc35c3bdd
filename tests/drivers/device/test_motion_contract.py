"""Motion over protocols of every completion style, using a scripted in-memory protocol.

These prove the contract the later protocols plug into: a write-only device (no reply, commanded
positions, completion by estimate) and a device whose feedback packet says when a move ended.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.errors import Aborted, BadInput
from drivers.framers.lines import LineFramer
from drivers.link.transport import Link
from drivers.protocols import commands as cmd
from drivers.protocols.base import Exchange, Protocol
from drivers.protocols.capabilities import Capabilities, Completion
from drivers.protocols.events import Event, Feedback, PositionReport, TextLine
from tests.support.fakes import ScriptedPort

pytestmark = pytest.mark.timeout(20)


class NoReply(Exchange):
    """A write-only device's exchange: finished as soon as it exists."""

    def __init__(self, command: cmd.Command) -> None:
        super().__init__(command)
        self.finish()

    def handle(self, event: Event) -> bool:
        return False


class UntilFeedback(Exchange):
    """Finished by a `DONE` line (a feedback packet standing in for Visiomex FA0001)."""

    def handle(self, event: Event) -> bool:
        if isinstance(event, TextLine) and event.text == "DONE":
            self.finish()
            return True
        return False


class ScriptedProtocol(Protocol):
    """Lines out; the exchange style is chosen per instance."""

    name = "scripted"
    capabilities = Capabilities(axes=("x", "y"))

    def __init__(self, capabilities: Capabilities, exchange: type[Exchange]) -> None:
        self.capabilities = capabilities  # type: ignore[misc]
        self._exchange = exchange

    def new_framer(self) -> LineFramer:
        return LineFramer()

    def encode(self, command: cmd.Command) -> bytes:
        return repr(command).encode() + b"\n"

    def decode(self, frame: bytes) -> list[Event]:
        if frame.startswith(b"FA"):
            return [Feedback(frame.decode())]
        return [TextLine(frame.decode())]

    def exchange(self, command: cmd.Command) -> Exchange:
        return self._exchange(command)


WRITE_ONLY = Capabilities(
    axes=("x", "y", "z"),
    position_feedback=False,
    completion=Completion.ESTIMATE,
    speed_readback=False,
    identity_queryable=False,
    speed_range=(1.0, 50.0),
    default_speed=10.0,
)


def _motion(caps: Capabilities, exchange: type[Exchange], answer: bytes = b""):
    port = ScriptedPort(answer)
    client = Client(Link(port, "fake"), ScriptedProtocol(caps, exchange))  # type: ignore[arg-type]
    waits: list[float] = []
    motion = Motion(client, wait=lambda s: waits.append(s) or False)
    return motion, port, waits


def test_write_only_device_reports_commanded_positions_after_the_estimate() -> None:
    motion, port, waits = _motion(WRITE_ONLY, NoReply)
    assert motion.identify() == "scripted device"
    # Where the session began is no known place; an absolute target is one.
    assert motion.position() == PositionReport(0.0, 0.0, 0.0, measured=False, known=False)
    assert motion.move_to(30, 40, 0) == PositionReport(30.0, 40.0, 0.0, measured=False)
    assert waits == [pytest.approx(5.0)]  # 50 mm at the default 10 mm/s
    assert motion.move_by(0, 0, 10) == PositionReport(30.0, 40.0, 10.0, measured=False)
    assert motion.set_speed(20) == 20
    assert motion.speed() == 20
    assert b"GetPosition" not in port.written and b"GetSpeed" not in port.written


def test_write_only_device_refuses_speeds_outside_its_declared_range() -> None:
    motion, port, _ = _motion(WRITE_ONLY, NoReply)
    with pytest.raises(BadInput, match="1 to 50"):
        motion.set_speed(80)
    assert port.written == b""


def test_feedback_completion_waits_for_the_packet() -> None:
    caps = replace(
        WRITE_ONLY,
        completion=Completion.FEEDBACK,
        position_feedback=False,
        identity_queryable=False,
    )
    motion, port, waits = _motion(caps, UntilFeedback, answer=b"debug line\nDONE\n")
    assert motion.move_to(3, 4, 0) == PositionReport(3.0, 4.0, 0.0, measured=False, confirmed=True)
    assert waits == []  # no estimate wait: the packet said it
    assert port.written.count(b"MoveTo") == 1


def test_aborted_estimate_wait_raises() -> None:
    port = ScriptedPort()
    client = Client(Link(port, "fake"), ScriptedProtocol(WRITE_ONLY, NoReply))  # type: ignore[arg-type]
    motion = Motion(client, wait=lambda s: True)
    with pytest.raises(Aborted, match="abandoned"):
        motion.move_to(1, 0, 0)
