"""Every exchange recorded from the real COXIRIS firmware holds byte for byte in the simulator."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from drivers.sim.clock import ManualClock
from drivers.sim.coxiris_device import BUFFER_SIZE, CoxirisDevice

pytestmark = pytest.mark.timeout(60)

TRANSCRIPT = json.loads((Path(__file__).resolve().parents[2] / "data" / "coxiris.json").read_text())
EXCHANGES: list[dict] = TRANSCRIPT["exchanges"]
SETTLE = 1.0  # seconds given to every exchange; the recording's replies came within 0.03 s


def _unknown_reply(name: bytes) -> bytes:
    """The recorded unknown-command reply (to `FOO 1`), for the command `name`."""
    recorded = next(e for e in EXCHANGES if e["sent"] == "FOO 1\n")["received"].encode("latin-1")
    return recorded.replace(b"\r\nFOO\r\n", b"\r\n" + name + b"\r\n", 1)


def _expected(sent: bytes, received: bytes, timed: bool) -> bytes:
    """The recorded reply; on a timed line, an over-long line's tail is a command of its own."""
    line = sent.rstrip(b"\r\n")
    if timed and len(line) >= BUFFER_SIZE:
        # Recorded behind a pty, where the whole write is in the buffer at once and the parser
        # drops the rest of the line. On a UART the sketch reads faster than bytes arrive, so the
        # rest of the line is parsed as a new (unknown) command (drivers/protocols/README.md §1).
        return received + _unknown_reply(line[BUFFER_SIZE:].upper())
    return received


def _replay(device: CoxirisDevice, clock: ManualClock, sent: bytes) -> tuple[float | None, bytes]:
    """Write `sent`; return when the first byte of the reply came (None: none) and the reply."""
    start = clock.now
    device.receive(sent)
    first, out = None, b""
    while (due := device.next_due()) is not None and due <= start + SETTLE:
        clock.now = max(clock.now, due)
        chunk = device.read_output()
        if chunk and first is None:
            first = clock.now - start
        out += chunk
    clock.now = start + SETTLE
    return first, out + device.read_output()


def replay_transcript(
    transcript: dict,
    baud: int | None,
    blocking: bool,
    expected: Callable[[bytes, bytes, bool], bytes],
    line_in: Callable[[bytes], float] = lambda sent: 0.0,
) -> None:
    """Replay `transcript`'s exchanges in order on a fresh device: each reply as `expected`
    makes it of the recorded one, its first byte no later than recorded, timed from
    `line_in(sent)` seconds after the write began (the byte the parser answers)."""
    clock = ManualClock()
    # The recorded sketch: instant moves, speeds 1 to 100, initial speed 10 (the defaults).
    device = CoxirisDevice(clock, baud, blocking=blocking, instant=True)
    device.boot()
    assert device.read_output() == transcript["boot_output"].encode()
    for exchange in transcript["exchanges"]:
        sent = exchange["sent"].encode("latin-1")
        first, got = _replay(device, clock, sent)
        assert got == expected(sent, exchange["received"].encode("latin-1"), baud is not None), sent
        recorded_first = exchange["first_byte_after_s"]
        if recorded_first is None:
            assert first is None, sent
        else:
            # The recording's time includes the host's pty latency: the device is no slower.
            assert first is not None and 0.0 <= first - line_in(sent) <= recorded_first, sent


@pytest.mark.parametrize("blocking", [True, False], ids=["blocking", "background"])
@pytest.mark.parametrize("baud", [None, 115200], ids=["untimed", "115200"])
def test_transcript_in_order_byte_for_byte(baud: int | None, blocking: bool) -> None:
    replay_transcript(TRANSCRIPT, baud, blocking, _expected)
