"""The 81 exchanges recorded from the Visiomex firmware at 902bd4d (33 cases, each from a fresh
start) hold in the simulator byte for byte, each line in time; the driver's estimate agrees."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from drivers.errors import BadInput
from drivers.protocols.commands import MoveBy, Raw, SetParameter
from drivers.protocols.visiomex.model import parse_atol
from drivers.protocols.visiomex.protocol import VisiomexProtocol
from drivers.sim.clock import ManualClock
from drivers.sim.visiomex_device import VisiomexDevice

pytestmark = pytest.mark.timeout(60)

TRANSCRIPT = json.loads(
    (Path(__file__).resolve().parents[2] / "data" / "visiomex-moves.json").read_text()
)
TOLERANCE = 0.10  # of each line's recorded time after the 1 s silence
SILENCE = 1.0
SETTLE = 0.3  # s between exchanges, after the reply


def _reply_offsets(exchange: dict[str, Any]) -> list[int | None]:
    """Per line: the bytes the reply had sent when its LF arrived (None: after stepping)."""
    offsets: list[int | None] = []
    sent = 0
    for _, text in exchange["lines_with_seconds_after_write"]:
        sent += len(text.encode("latin-1"))
        offsets.append(None if text == "FA0001\r\n" else sent)
    return offsets


def _recorded_spread() -> dict[int, float]:
    """How far apart the recording itself put lines that ended at the same byte of a reply
    (before stepping): the firmware sent the same bytes in the same time, so this is jitter."""
    seen: dict[int, list[float]] = {}
    for exchange in TRANSCRIPT["exchanges"]:
        recorded = exchange["lines_with_seconds_after_write"]
        for (at, _), offset in zip(recorded, _reply_offsets(exchange), strict=True):
            if offset is not None:
                seen.setdefault(offset, []).append(at)
    return {offset: max(times) - min(times) for offset, times in seen.items()}


SPREAD = _recorded_spread()


def _allowed(recorded_at: float, offset: int | None) -> float:
    """±10 % of the time after the silence, or the recording's own jitter where that is more."""
    jitter = SPREAD.get(offset, 0.0) if offset is not None else 0.0
    return max(TOLERANCE * (recorded_at - SILENCE), jitter)


def _cases() -> list[tuple[str, list[dict[str, Any]]]]:
    """The exchanges grouped by case: a `fresh_start` begins one."""
    cases: list[tuple[str, list[dict[str, Any]]]] = []
    for exchange in TRANSCRIPT["exchanges"]:
        if exchange.get("fresh_start"):
            cases.append((exchange["case"], []))
        cases[-1][1].append(exchange)
    return cases


CASES = _cases()


def _lines(device: VisiomexDevice, clock: ManualClock, start: float) -> list[tuple[float, str]]:
    """Run the device until it is idle; each line with the time its LF arrived after `start`."""
    lines: list[tuple[float, str]] = []
    pending = b""
    while (due := device.next_due()) is not None:
        clock.now = max(clock.now, due)
        for byte in device.read_output():
            pending += bytes((byte,))
            if byte == 0x0A:
                lines.append((clock.now - start, pending.decode("latin-1")))
                pending = b""
    assert pending == b"", pending
    return lines


def _exchange(device: VisiomexDevice, clock: ManualClock, exchange: dict[str, Any]) -> float:
    """Write the exchange's packet (in its parts, at their offsets); when its last byte arrived."""
    begin = clock.now
    byte_time = 10 / device.baud if device.baud else 0.0
    arrival = begin
    for offset, text in exchange.get("sent_parts") or [[0.0, exchange["sent"]]]:
        clock.now = begin + offset
        device.receive(text.encode("latin-1"))
        arrival = clock.now + len(text) * byte_time  # the line is idle before each part
    return arrival


def test_the_transcript_has_81_exchanges_in_33_cases() -> None:
    assert len(TRANSCRIPT["exchanges"]) == 81
    assert len(CASES) == 33


@pytest.mark.parametrize(("case", "exchanges"), CASES, ids=[name for name, _ in CASES])
def test_case_replays_byte_for_byte_and_in_time(case: str, exchanges: list[dict[str, Any]]) -> None:
    clock = ManualClock()
    device = VisiomexDevice(clock, 9600)
    device.boot()
    clock.advance(0.1)
    assert device.read_output() == TRANSCRIPT["boot_output"].encode()
    for exchange in exchanges:
        sent = exchange["sent"]
        start = _exchange(device, clock, exchange)
        lines = _lines(device, clock, start)
        assert "".join(text for _, text in lines) == exchange["received"], sent
        recorded = exchange["lines_with_seconds_after_write"]
        assert [text for _, text in lines] == [text for _, text in recorded], sent
        timed = zip(lines, recorded, _reply_offsets(exchange), strict=True)
        for (at, text), (recorded_at, _), offset in timed:
            assert abs(at - recorded_at) <= _allowed(recorded_at, offset), (sent, text)
        clock.advance(SETTLE)


def test_all_but_3_of_415_lines_are_within_10_percent_after_the_silence() -> None:
    """The 3 others ended at a byte where the recording's own times spread wider (10-13 ms)."""
    beyond = []
    for _, exchanges in CASES:
        clock = ManualClock()
        device = VisiomexDevice(clock, 9600)
        device.boot()
        clock.advance(0.1)
        device.read_output()
        for exchange in exchanges:
            start = _exchange(device, clock, exchange)
            lines = _lines(device, clock, start)
            timed = zip(lines, exchange["lines_with_seconds_after_write"], strict=True)
            for (at, text), (recorded_at, _) in timed:
                if abs(at - recorded_at) > TOLERANCE * (recorded_at - SILENCE):
                    beyond.append((exchange["sent"], text))
            clock.advance(SETTLE)
    assert len(beyond) == 3, beyond
    assert {text for _, text in beyond} == {"FS0014\r\n", "Driving Mechanism: 1\r\n", "EP0003\r\n"}


def test_the_board_uart_pace_is_faster_than_the_recording() -> None:
    """`pace="uart"`: the STM32 board's 9600 baud, not the recording host's slower pacing."""
    times = {}
    for pace in ("recorded", "uart"):
        clock = ManualClock()
        device = VisiomexDevice(clock, 9600, pace=pace)
        device.receive(b"S05000200NNNNNNNNN")
        times[pace] = _lines(device, clock, clock.now)[0][0]
    assert times["uart"] < times["recorded"]
    assert times["recorded"] - times["uart"] == pytest.approx(8 * 0.06 * 10 / 9600, rel=0.01)


@pytest.mark.parametrize(("case", "exchanges"), CASES, ids=[name for name, _ in CASES])
def test_case_replays_byte_for_byte_untimed(case: str, exchanges: list[dict[str, Any]]) -> None:
    clock = ManualClock()
    device = VisiomexDevice(clock)
    for exchange in exchanges:
        start = _exchange(device, clock, exchange)
        received = "".join(text for _, text in _lines(device, clock, start))
        assert received == exchange["received"], exchange["sent"]
        clock.advance(SETTLE)


def _set(protocol: VisiomexProtocol, packet: str) -> None:
    """A set packet as the panel would have confirmed it (as the firmware reads it otherwise)."""
    ident, value = parse_atol(packet[1:3]), parse_atol(packet[3:9])
    try:
        parameter = protocol.parameter(ident)
        protocol.parameter_written(SetParameter(ident, parameter.from_wire(value)))
    except BadInput:
        protocol.firmware.set(ident, value)


MOVES = [
    (case, index)
    for case, exchanges in CASES
    for index, exchange in enumerate(exchanges)
    if exchange["received"].endswith("FA0001\r\n")
]


@pytest.mark.parametrize(("case", "index"), MOVES, ids=[f"{c}#{i}" for c, i in MOVES])
def test_driver_estimate_agrees_with_the_recorded_fa0001(case: str, index: int) -> None:
    exchanges = dict(CASES)[case]
    protocol = VisiomexProtocol()
    for exchange in exchanges[:index]:
        sent = exchange["sent"]
        if exchange["received"].startswith("FS"):
            _set(protocol, sent)
        elif exchange["received"].endswith("FA0001\r\n"):
            protocol.on_sent(Raw(sent.encode("latin-1")))
    exchange = exchanges[index]
    recorded = exchange["lines_with_seconds_after_write"][-1][0]
    assert protocol.move_packet_seconds(exchange["sent"]) == pytest.approx(recorded, rel=0.10)


def test_move_timing_of_a_typed_move_is_the_packet_estimate_plus_its_transmission() -> None:
    protocol = VisiomexProtocol()
    for ident, value in ((21, 6000), (22, 6000), (23, 1), (24, 1)):
        protocol.parameter_written(SetParameter(ident, value))
    move = MoveBy(5.0, 5.0, 0.0)
    delay, duration = protocol.move_timing(move, (0, 0, 0), (5, 5, 0))
    transmit = 18 * 10 / 9600
    assert delay + duration - transmit == pytest.approx(2.192, rel=0.03)  # recorded FA0001
    protocol.on_sent(move)  # the ramps left the delays short: the same move is faster
    delay, duration = protocol.move_timing(move, (0, 0, 0), (5, 5, 0))
    assert delay + duration - transmit == pytest.approx(1.471, rel=0.03)
