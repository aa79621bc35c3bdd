"""TrafficIndex over simulated sessions: kinds, reply pairing, retransmissions, filters."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.errors import DeviceError
from drivers.link.records import Note, Traffic, TrafficLogWriter
from drivers.link.transport import open_link
from drivers.protocols import commands as cmd
from drivers.protocols.registry import create_protocol
from drivers.traffic.index import TrafficIndex
from drivers.traffic.log_reader import read_log
from drivers.traffic.search import FilterError, compile_filter

pytestmark = [pytest.mark.timeout(60), pytest.mark.usefixtures("settings_file")]


def _index(tmp_path: Path, url: str, name: str, run, variant: str | None = None) -> TrafficIndex:  # type: ignore[no-untyped-def]
    """Run a session against a simulator, log it, and index the log read back."""
    log = tmp_path / f"{name}.log"
    protocol = create_protocol(name, variant)
    link = open_link(url, protocol.default_baud(variant))
    with log.open("a", encoding="utf-8") as stream:
        link.listeners.append(TrafficLogWriter(stream))
        try:
            run(Motion(Client(link, protocol)))
        finally:
            link.close()
    index = TrafficIndex(create_protocol(name, variant))
    index.add_records(read_log(log))
    return index


def _lines(index: TrafficIndex) -> list:  # type: ignore[type-arg]
    return [index.line(n) for n in range(len(index))]


def test_coxiris_kinds_and_pairs(tmp_path: Path) -> None:
    def run(m: Motion) -> None:
        m.position()
        m.move_to(1, 2, 3)
        with pytest.raises(DeviceError, match="does not know the command 'FOO'"):
            m.client.send_raw(b"FOO\n")

    index = _index(tmp_path, "sim://coxiris?instant=1", "coxiris", run)
    lines = _lines(index)
    move = next(x for x in lines if x.meaning == "ABSOLUTE_MOVE 1 2 3")
    assert move.kind == "motion" and move.direction == "tx"
    reply = index.line(move.pair)
    assert reply.meaning == "ACK ABSOLUTE_MOVE" and reply.pair == move.number
    assert reply.kind == "motion" and reply.latency_ms > 0
    polls = [x for x in lines if x.kind == "poll"]
    assert polls and all("GET_POSITION" in x.meaning for x in polls)
    foo = next(x for x in lines if x.meaning == "FOO")
    assert index.line(foo.pair).kind == "error"
    assert any(x.kind == "debug" and "Available commands" in x.meaning for x in lines)
    errors = index.select(kinds={"error"})
    assert [index.line(int(n)).pair for n in errors] == [foo.number]


def test_laser_retransmissions_link_to_their_first_copy(tmp_path: Path) -> None:
    def run(m: Motion) -> None:
        for _ in range(8):
            m.position()

    # replies dropped: the client sends the same frame again
    index = _index(
        tmp_path, "sim://laser-frame?instant=1&drop_reply=0.5&seed=3", "laser-frame", run
    )
    lines = _lines(index)
    copies = [x for x in lines if x.first_copy >= 0]
    assert copies, "the seeded faults should have forced a retransmission"
    for copy in copies:
        first = index.line(copy.first_copy)
        assert first.data == copy.data and first.direction == "tx" and first.pair < 0
    answered = [x for x in lines if x.direction == "rx" and not math.isnan(x.latency_ms)]
    assert answered and all(index.line(x.pair).direction == "tx" for x in answered)


def test_visiomex_replies_pair_with_their_packets(tmp_path: Path) -> None:
    def run(m: Motion) -> None:
        m.client.execute(cmd.SetParameter(3, 38.2))

    index = _index(tmp_path, "sim://visiomex?instant=1", "visiomex", run)
    lines = _lines(index)
    packet = next(x for x in lines if x.direction == "tx" and x.meaning.startswith("set "))
    assert packet.kind == "setting"
    assert "FS0003" in index.line(packet.pair).data.decode()


def test_piframe_frames_are_motion_and_expect_nothing(tmp_path: Path) -> None:
    index = _index(tmp_path, "sim://pi-frame?instant=1", "pi-frame", lambda m: m.move_to(1, 2, 0))
    sent = [x for x in _lines(index) if x.direction == "tx"]
    assert sent and all(x.kind in ("motion", "setting") and x.pair < 0 for x in sent)


def test_filters_and_search_over_the_spool(tmp_path: Path) -> None:
    index = TrafficIndex(create_protocol("coxiris"), spool_dir=tmp_path)
    for i in range(3000):
        index.add("tx", f"DELTA_MOVE {i} 0 0\n".encode(), i * 0.1)
        index.add("rx", b"ACK DELTA_MOVE\r\nDONE DELTA_MOVE\r\n", i * 0.1 + 0.01)
    assert list(tmp_path.iterdir()) == []  # the spool is unlinked: nothing left after a crash
    hits = index.select(pattern=compile_filter(r"DELTA_MOVE 12\d\b"))
    assert [index.line(int(n)).meaning for n in hits] == [
        f"DELTA_MOVE {i} 0 0" for i in range(120, 130)
    ]
    sparse = index.select(directions={"tx"}, pattern=compile_filter("move 2999 "))
    assert len(sparse) == 1 and index.line(int(sparse[0])).meaning == "DELTA_MOVE 2999 0 0"
    assert len(index.select(directions={"rx"})) == 6000
    with pytest.raises(FilterError, match="not a regular expression"):
        compile_filter("[")
    index.close()


def test_a_frame_split_across_reads_keeps_its_terminator(tmp_path: Path) -> None:
    index = TrafficIndex(create_protocol("coxiris"))
    index.add("rx", b"ACK GET_", 1.0)
    index.add("rx", b"ID\r", 1.1)
    index.add("rx", b"\nDONE GET_ID: X\r\n", 1.2)
    # a line end that comes in a later read than its line is not shown with it (the log has it)
    assert [index.line(n).data for n in range(len(index))] == [b"ACK GET_ID", b"DONE GET_ID: X\r\n"]


def test_repeated_frames_are_decoded_once_and_unique_ones_not_kept(monkeypatch) -> None:
    """A frame is decoded once it crosses again (its meaning and spool line kept on it); a flood
    of lines that never repeat (a counter in debug output) keeps nothing per line behind."""
    protocol = create_protocol("coxiris")
    decoded: list[bytes] = []
    decode = protocol.decode
    monkeypatch.setattr(protocol, "decode", lambda frame: decoded.append(frame) or decode(frame))
    index = TrafficIndex(protocol)
    for i in range(5000):
        index.add("rx", f"dbg {i} loop ok\r\nACK GET_ID\r\n".encode(), i * 0.001)
    assert len(index) == 10_000
    assert decoded.count(b"ACK GET_ID") == 2  # seen, then kept
    assert len(decoded) == 5002  # each unique line once
    decoder = index._decoder
    assert decoder is not None and len(decoder._cache["rx"]) == 1  # only the one that repeats
    assert index.line(9998).meaning == "the line 'dbg 4999 loop ok'"
    assert index.line(9999).meaning == "ACK GET_ID" and index.line(9999).data == b"ACK GET_ID\r\n"
    index.close()


def test_batches_keep_the_order_and_stop_at_the_deadline() -> None:
    """add_many takes records (and notes) in order, a batch joining the columns and the spool
    at once, and stops after the record during which its deadline passed."""
    index = TrafficIndex(create_protocol("coxiris"))
    records: list[Traffic | Note] = [Traffic("tx", b"GET_ID\n", 0.1, 1000.1), Note("a note", 0.2)]
    records += [Traffic("rx", b"ACK GET_ID\r\nDONE GET_ID: X\r\n", 0.3, None)]
    assert index.add_many(records) == 3
    assert [index.line(n).meaning for n in range(len(index))] == [
        "GET_ID",
        "a note",
        "ACK GET_ID",
        "DONE GET_ID: X",
    ]
    assert index.line(0).pair == 2 and index.wall_offset == pytest.approx(1000.0)
    assert index.counts["query"] == 3 and index.counts["note"] == 1
    assert index.add_many([Traffic("tx", b"GET_ID\n", 1.0)] * 5, deadline=0.0) == 1  # passed
    assert len(index) == 5
    index.close()
