"""BridgeWatch: the positions bridged traffic tells, read from real traffic: a Bridge to a
simulated device, another program (a DeviceSession on the bridge's pty) moving the stage and
asking where it is."""

from __future__ import annotations

import threading
from collections.abc import Iterator

import pytest

from drivers.bridge.snoop import Bridge
from drivers.bridge.watch import COMMANDED, REPORTED, BridgeWatch, Observed
from drivers.link.records import TX, Traffic
from drivers.protocols.registry import create_protocol
from drivers.session.device_session import open_device

pytestmark = [pytest.mark.timeout(60), pytest.mark.usefixtures("settings_file")]


@pytest.fixture(params=["coxiris", "laser-frame"])
def bridged(request: pytest.FixtureRequest) -> Iterator[tuple[str, str, list[Traffic]]]:
    """A bridge to sim://PROTOCOL serving in a thread: (protocol, pty path, records tapped)."""
    name = request.param
    records: list[Traffic] = []
    bridge = Bridge(f"sim://{name}", tap=records.append, protocol=create_protocol(name))
    bridge.open()
    thread = threading.Thread(target=bridge.serve_forever, daemon=True)
    thread.start()
    yield name, bridge.path, records
    bridge.close()
    thread.join(5)


def _watched(name: str, records: list[Traffic]) -> list[Observed]:
    watch = BridgeWatch(create_protocol(name))
    return [seen for record in list(records) for seen in watch.feed(record)]


def test_a_move_and_a_position_asked_through_the_bridge_are_observed(bridged) -> None:
    name, path, records = bridged
    with open_device(path, name, timeout=5.0) as other:  # the other program
        other.move_to(5.0, 5.0, 0.0)
        asked = other.position()
    assert (asked.x, asked.y) == pytest.approx((5.0, 5.0), abs=0.01)
    seen = _watched(name, records)
    commanded = [s for s in seen if s.source == COMMANDED]
    reported = [s for s in seen if s.source == REPORTED]
    assert commanded and commanded[-1].point == pytest.approx((5.0, 5.0, 0.0))
    assert reported, [s for s in seen]
    assert seen[-1].source == REPORTED  # the last word: the device's answer to the last ask
    assert seen[-1].point == pytest.approx((asked.x, asked.y, asked.z), abs=1e-6)


def test_a_relative_move_is_observed_from_the_last_position_told() -> None:
    watch = BridgeWatch(create_protocol("coxiris"))
    assert watch.feed(Traffic(TX, b"DELTA_MOVE 1 0 0\n", 1.0)) == []  # from where: not known
    watch.feed(Traffic(TX, b"ABSOLUTE_MOVE 5 5 0\n", 2.0))
    (seen,) = watch.feed(Traffic(TX, b"DELTA_MOVE 1 -2 0\n", 3.0))
    assert (seen.point, seen.source) == ((6.0, 3.0, 0.0), COMMANDED)
    (home,) = watch.feed(Traffic(TX, b"GO_HOME\n", 4.0))
    assert home.point == (0.0, 0.0, 0.0)


def test_a_reply_split_across_reads_and_another_commands_answer_are_not_positions() -> None:
    watch = BridgeWatch(create_protocol("coxiris"))
    watch.feed(Traffic(TX, b"GET_SPEED\n", 1.0))
    assert watch.feed(Traffic("rx", b"ACK GET_SPEED\r\nDONE GET_SPEED: 7\r\n", 1.1)) == []
    watch.feed(Traffic(TX, b"GET_POSITION\n", 2.0))
    assert watch.feed(Traffic("rx", b"ACK GET_POSITION\r\nDONE GET_POS", 2.1)) == []
    (seen,) = watch.feed(Traffic("rx", b"ITION: 1.25 -3.50 0.00\r\n", 2.2))
    assert (seen.point, seen.source) == ((1.25, -3.5, 0.0), REPORTED)
