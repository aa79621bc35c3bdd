"""Arbitrary bytes from a device never raise anything but the project's own errors."""

from __future__ import annotations

import contextlib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from drivers.device.client import Client
from drivers.errors import MotionError
from drivers.link.transport import Link
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from tests.support.fakes import ScriptedPort

P = CoxirisProtocol()
COMMANDS = [
    cmd.GetId(),
    cmd.GetPosition(),
    cmd.GetSpeed(),
    cmd.Help(),
    cmd.MoveTo(1, 2, 3),
    cmd.CheckErrors(),
    cmd.Raw(b"FOO"),
]
LINES = st.sampled_from(
    [
        b"ACK GET_ID",
        b"DONE GET_ID: X",
        b"ACK GET_POSITION",
        b"DONE GET_POSITION: 1.00 2.00 3.00",
        b"DONE GET_POSITION: ovf",
        b"ERROR: Unknown command - ",
        b"FOO",
        b"ERROR: Command too long",
        b"DONE GET_SPEED: nan",
        b"ACK HELP",
        b"DONE",
        b"ACK",
    ]
)
CHUNKS = st.lists(st.one_of(st.binary(max_size=40), LINES.map(lambda b: b + b"\r\n")), max_size=20)


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=200))
def test_decoder_takes_any_bytes(data: bytes) -> None:
    frames, _ = P.new_framer().split(data)
    for frame in frames:
        with contextlib.suppress(MotionError):
            P.decode(frame)


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(COMMANDS), CHUNKS)
def test_exchange_takes_any_reply(command: cmd.Command, chunks: list[bytes]) -> None:
    exchange = P.exchange(command)
    frames, _ = P.new_framer().split(b"".join(chunks))
    for frame in frames:
        try:
            events = P.decode(frame)
        except MotionError:
            continue
        for event in events:
            exchange.on_event(event)
    if exchange.finished:
        with contextlib.suppress(MotionError):
            exchange.result()


class FakeClock:
    """Each reading moves time on by 10 ms, so a silent device times out without waiting."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        self.now += 0.01
        return self.now


@pytest.mark.timeout(60)
@settings(max_examples=200, deadline=None)
@given(st.sampled_from(COMMANDS), CHUNKS)
def test_client_ends_with_a_reply_or_a_project_error(
    command: cmd.Command, chunks: list[bytes]
) -> None:
    link = Link(ScriptedPort(b"".join(chunks)), "scripted")  # type: ignore[arg-type]
    client = Client(link, P, timeout=0.5, clock=FakeClock())
    with contextlib.suppress(MotionError):
        client.execute(command)
