"""Every exchange recorded from the real COXIRIS firmware holds byte for byte in the simulator."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from drivers.sim.clock import ManualClock
from drivers.sim.coxiris_device import CoxirisDevice

TRANSCRIPT = json.loads((Path(__file__).parent / "data" / "coxiris.json").read_text())


def _replay(device: CoxirisDevice, clock: ManualClock, sent: str) -> bytes:
    device.receive(sent.encode("latin-1"))
    clock.advance(1.0)
    return device.read_output()


def test_transcript_in_order_byte_for_byte() -> None:
    clock = ManualClock()
    device = CoxirisDevice(clock, instant=True)
    device.boot()
    assert device.read_output() == TRANSCRIPT["boot_output"].encode()
    for exchange in TRANSCRIPT["exchanges"]:
        got = _replay(device, clock, exchange["sent"])
        assert got == exchange["received"].encode("latin-1"), exchange["sent"]


@pytest.mark.parametrize("baud", [None, 115200])
def test_first_byte_time_matches_recording(baud: int | None) -> None:
    clock = ManualClock()
    device = CoxirisDevice(clock, baud=baud, instant=True)
    device.receive(b"GET_ID\n")
    due = device.next_due()
    assert due is not None
    # The recording saw the first byte after 0.02 s including the host's pty latency.
    assert 0.0 <= due <= 0.02
