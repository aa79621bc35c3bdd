"""The NUL bytes recorded from the real COXIRIS firmware hold byte for byte in the simulator:
only CR and LF end a line; a NUL counts toward the 63 characters and cuts the command (§1)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from drivers.sim.clock import ManualClock
from drivers.sim.coxiris_device import BUFFER_SIZE, CoxirisDevice
from drivers.sim.device import BITS_PER_BYTE
from tests.drivers.sim.test_sim_coxiris_transcript import _replay, replay_transcript

pytestmark = pytest.mark.timeout(60)

TRANSCRIPT = json.loads(
    (Path(__file__).resolve().parents[2] / "data" / "coxiris-nul.json").read_text()
)
EXCHANGES: list[dict] = TRANSCRIPT["exchanges"]


def _unknown_reply(name: bytes) -> bytes:
    """The recorded unknown-command reply (to `GET\\0_ID`, read as `GET`), for `name`."""
    recorded = next(e for e in EXCHANGES if e["sent"] == "GET\0_ID\n")["received"]
    return recorded.encode("latin-1").replace(b"\r\nGET\r\n", b"\r\n" + name + b"\r\n", 1)


def _expected(sent: bytes, received: bytes, timed: bool) -> bytes:
    """The recorded reply; on a timed line, an over-long line's tail is a command of its own."""
    line = sent.rstrip(b"\r\n")
    if timed and len(line) >= BUFFER_SIZE:
        # Recorded behind a pty, where the parser drops the rest of the line; on a UART the
        # rest arrives later and is read as a new command, itself cut at a NUL.
        tail = line[BUFFER_SIZE:].split(b"\0", 1)[0].strip(b" ").upper()
        return received + (_unknown_reply(tail.split(b" ")[0]) if tail else b"")
    return received


def test_the_transcript_holds_the_five_nul_cases() -> None:
    nul_lines = [e["sent"] for e in EXCHANGES if "\0" in e["sent"]]
    assert len(EXCHANGES) == 8 and len(nul_lines) == 5
    assert max(len(s.rstrip("\n")) for s in nul_lines) == BUFFER_SIZE + 3  # 67: too long


@pytest.mark.parametrize("blocking", [True, False], ids=["blocking", "background"])
@pytest.mark.parametrize("baud", [None, 115200], ids=["untimed", "115200"])
def test_nul_transcript_in_order_byte_for_byte(baud: int | None, blocking: bool) -> None:
    def line_in(sent: bytes) -> float:
        """Recorded behind a pty, where the whole line is in at once: timed from the byte the
        parser answers (the line end, or the 64th character of a line too long)."""
        answered = BUFFER_SIZE if len(sent.rstrip(b"\r\n")) >= BUFFER_SIZE else len(sent)
        return answered * BITS_PER_BYTE / baud if baud else 0.0

    replay_transcript(TRANSCRIPT, baud, blocking, _expected, line_in)


@pytest.mark.parametrize("baud", [None, 115200], ids=["untimed", "115200"])
def test_a_nul_does_not_end_the_line(baud: int | None) -> None:
    """`GET_ID\\0` then, later, `\\n`: one line, answered only when the LF comes."""
    clock = ManualClock()
    device = CoxirisDevice(clock, baud, instant=True)
    device.boot()
    assert _replay(device, clock, b"GET_ID\0") == (None, b"")
    first, got = _replay(device, clock, b"\n")
    assert got == b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n" and first is not None


def test_a_break_is_a_nul_in_the_line() -> None:
    """A break reaches the parser as a NUL: the command before it still runs at the LF."""
    clock = ManualClock()
    device = CoxirisDevice(clock, instant=True)
    device.boot()
    device.receive(b"GET_ID")
    device.receive_break()
    assert _replay(device, clock, b" 1 2\n")[1] == b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"
